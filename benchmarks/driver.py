"""The default driver's settings, side by side: how many refined samples' first plans it makes accepted.

For every scenario file, draws N samples of its logical parameters (as the bench draws them: the
seed fixes them, so every variant drives the same samples), plans each once and simulates the
first plan with one try per driver variant, and prints per file and variant: samples accepted,
collisions, and samples without a plan (the same for every variant). A variant is a JSON object
of ``FrenetixDriver`` class attributes; ``{}`` is the driver as it is.

    python benchmarks/driver.py [--samples 20] [--seed 11] [--variant JSON ...] [FILES...]
        (default files: the paper's seven and the realistic ones the front end reads)

The driver's settings cite what this printed (simulation/frenetix/driver.py).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from pytest_roadlogic.automaton import build_automaton  # noqa: E402
from pytest_roadlogic.frontend import OscError, load_file  # noqa: E402
from pytest_roadlogic.monitor import monitor  # noqa: E402
from pytest_roadlogic.planning import NoPlanError, planner_for, settings_for  # noqa: E402
from pytest_roadlogic.problem import problem_for  # noqa: E402
from pytest_roadlogic.sampling import drawn  # noqa: E402
from pytest_roadlogic.settings import RunSettings  # noqa: E402
from pytest_roadlogic.simulation import SimulationLimits  # noqa: E402
from pytest_roadlogic.simulation.backends import simulator  # noqa: E402
from pytest_roadlogic.simulation.frenetix.driver import FrenetixDriver  # noqa: E402


def samples(scenario, count: int, seed: int) -> list[dict]:
    """``count`` samples drawn as ``Runner.refined(search=False)`` draws them."""
    return drawn(scenario, count, seed)


def plans(scenario, values: list[dict], seed: int):
    """The first plan of each sample (None where it has none within the planner's margins and limits)."""
    settings = settings_for(RunSettings(), explain_unsatisfiable=False)
    specification = build_automaton(scenario)
    found = []
    for sample in values:
        problem = problem_for(scenario, sample, settings, seed)
        try:
            found.append(
                next(planner_for(problem.guide(problem.settings), problem.settings, problem.seed).plans(limit=1), None)
            )
        except NoPlanError:
            found.append(None)
    return specification, found


def drive(specification, plan, variant: dict) -> tuple[bool, bool, float]:
    """(accepted, collided, seconds simulating) of one simulation of ``plan`` with the driver set to ``variant``."""
    saved = {name: getattr(FrenetixDriver, name) for name in variant}
    try:
        for name, value in variant.items():
            setattr(FrenetixDriver, name, tuple(value) if isinstance(value, list) else value)
        started = time.perf_counter()
        trace = simulator().simulate(plan, SimulationLimits(time_limit=120.0)).trace
        seconds = time.perf_counter() - started
    finally:
        for name, value in saved.items():
            setattr(FrenetixDriver, name, value)
    return monitor(specification, trace).accepted, any(i.kind == "collision" for i in trace.incidents), seconds


def default_files() -> list[Path]:
    realistic = sorted(
        p for p in (ROOT / "scenarios" / "realistic").glob("*.osc") if not p.name.startswith("infeasible")
    )
    return sorted((ROOT / "scenarios").glob("*.osc")) + realistic


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path)
    parser.add_argument("--samples", type=int, default=20)
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument(
        "--variant",
        action="append",
        type=json.loads,
        help="FrenetixDriver attributes as JSON ({} is the driver as it is)",
    )
    args = parser.parse_args(argv)
    variants = args.variant or [{}]
    totals = [[0, 0, 0.0] for _ in variants]
    planned = 0
    print(
        "file".ljust(24),
        "plans".rjust(5),
        *(f"v{i}: accepted/collisions/sim s".rjust(30) for i in range(len(variants))),
    )
    for path in args.files or default_files():
        try:
            scenario = load_file(path).scenario_to_run()
        except OscError as error:
            print(f"{path.stem:<24} not read: {error}".splitlines()[0])
            continue
        started = time.perf_counter()
        specification, found = plans(scenario, samples(scenario, args.samples, args.seed), args.seed)
        found = [plan for plan in found if plan is not None]
        planned += len(found)
        cells = []
        for index, variant in enumerate(variants):
            results = [drive(specification, plan, variant) for plan in found]
            accepted, collided = sum(r[0] for r in results), sum(r[1] for r in results)
            seconds = sum(r[2] for r in results)
            totals[index][0] += accepted
            totals[index][1] += collided
            totals[index][2] += seconds
            cells.append(f"{accepted}/{collided}/{seconds:.1f}".rjust(30))
        print(
            f"{path.stem:<24}", str(len(found)).rjust(5), *cells, f"  {time.perf_counter() - started:.0f} s", flush=True
        )
    print(f"{'all':<24}", str(planned).rjust(5), *(f"{a}/{c}/{t:.1f}".rjust(30) for a, c, t in totals))
    for index, variant in enumerate(variants):
        print(f"v{index}: {json.dumps(variant)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
