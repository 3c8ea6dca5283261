"""The realistic scenarios as the planner and the pipeline meet them today: issue 17's benchmark.

For every .osc file under scenarios/realistic/ (the team's twelve, kept unchanged) prints one row:
whether the front end reads it (or its first error), whether its automaton builds, and for the base
strategy the planning time to the first plan over --seeds (median and max, planning alone), how
that planning ended, and how many first plans the simulation accepted.

    python benchmarks/realistic.py [--seeds 5] [--plan-timeout 30] [--simulate] [--encoding grid|continuous|both] [--paper] [FILES...]
    python benchmarks/realistic.py --refined 20 [--paper] [FILES...]

``--refined N`` times instead the first plan of N samples of each file's logical parameters (drawn
as the refined strategy draws them, seed 11), through the fallbacks a run takes before it says
"no plan" (thinner margins, a finer step, relaxed limits), and prints the median and the maximum
and the samples without a plan: the issue-41 target is no feasible sample over 2 s.

Planning is what issue 17 replaced: --encoding both prints the grid encoding (asp/grid/) and
the continuous one (asp/continuous/, the default) side by side; --paper adds the paper's seven scenarios.
--simulate adds a simulation and monitoring of each first plan (a grid plan after its run-up from
standstill, a continuous plan from its first state).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from pytest_roadlogic.automaton import build_automaton  # noqa: E402
from pytest_roadlogic.evaluation.bench import conftest_dialect  # noqa: E402
from pytest_roadlogic.frontend import OscError, check_file  # noqa: E402
from pytest_roadlogic.planning import (  # noqa: E402  # noqa: E402
    ContinuousPlanner,
    ContinuousSettings,
    GridPlanner,
    GridSettings,
    NoPlanError,
    PlanningTimeout,
    UnsatisfiableScenario,
)

REALISTIC = ROOT / "scenarios" / "realistic"


def first_error(report: str) -> str:
    for line in report.splitlines():
        if ": error: " in line:
            return line.split(": error: ", 1)[1][:70]
    return report.splitlines()[0][:70] if report else "?"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path, default=sorted(REALISTIC.rglob("*.osc")))
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--plan-timeout", type=float, default=30.0)
    parser.add_argument("--simulate", action="store_true")
    parser.add_argument("--encoding", choices=("grid", "continuous", "both"), default="continuous")
    parser.add_argument("--paper", action="store_true", help="also the paper's seven scenarios (scenarios/*.osc)")
    parser.add_argument("--refined", type=int, default=0, help="time the first plans of this many samples per file")
    args = parser.parse_args()
    files = [*(sorted((ROOT / "scenarios").glob("*.osc")) if args.paper else []), *args.files]
    encodings = ("grid", "continuous") if args.encoding == "both" else (args.encoding,)
    print(f"{'scenario':<22} {'encoding':<11} {'first plan (s): median max':<28} {'ends':<40} accepted")
    for path in files:
        if path.name == "lib.osc":
            continue
        name = path.stem
        dialect = conftest_dialect(path, [ROOT / "scenarios"])  # as the folder's conftest.py chooses
        try:
            checked = check_file(path, dialect=dialect)
        except OscError as error:
            print(f"{name:<22} syntax: {first_error(error.report())}")
            continue
        if checked.errors:
            print(f"{name:<22} refused: {first_error(checked.report())}")
            continue
        try:
            scenario = checked.scenario_to_run()
            automaton = build_automaton(scenario)
        except OscError as error:
            print(f"{name:<22} automaton: {first_error(error.report())}")
            continue
        if args.refined:
            refined_row(name, scenario, args.refined)
            continue
        medians = {}
        for encoding in encodings:
            try:
                medians[encoding] = row(name, encoding, automaton, args)
            except OscError as error:  # a construct this encoding cannot express (the grid: headways)
                print(f"{name:<22} {encoding:<11} refused: {first_error(error.report())}")
                medians[encoding] = None
        if None not in medians.values() and len(medians) == 2 and medians["grid"] > 0:
            print(
                f"{'':<22} {'ratio':<11} {medians['continuous'] / medians['grid']:8.2f}x (continuous / grid, medians)"
            )
    return 0


def refined_row(name: str, scenario, count: int, seed: int = 11) -> None:
    """Prints the seconds to the first plan of ``count`` samples (median, max) and how many have none."""
    from driver import samples

    from pytest_roadlogic.planning import settings_for
    from pytest_roadlogic.planning.fallbacks import planned
    from pytest_roadlogic.problem import problem_for
    from pytest_roadlogic.settings import RunSettings

    settings = settings_for(RunSettings(), explain_unsatisfiable=False)
    seconds, without, slowest = [], 0, None
    for values in samples(scenario, count, seed):
        started = time.perf_counter()
        problem = problem_for(scenario, values, settings, seed)
        try:
            found = next(planned(problem.guide, problem.settings, problem.seed, 1), None) is not None
        except NoPlanError:
            found = False
        elapsed = time.perf_counter() - started
        if not found:
            without += 1
            continue
        seconds.append(elapsed)
        if slowest is None or elapsed > slowest[0]:
            slowest = (elapsed, values)
    timing = f"{statistics.median(seconds):8.3f} {max(seconds):8.3f}" if seconds else "       -        -"
    print(
        f"{name:<22} {'refined':<11} {timing:<28} {without} of {count} without a plan; slowest at {slowest[1] if slowest else '-'}",
        flush=True,
    )


def row(name: str, encoding: str, automaton, args) -> float:
    """Prints the row; returns the median seconds to the first plan."""
    seconds, endings, accepted = [], [], 0
    for seed in range(0, args.seeds + 1):  # seed 0 warms the imports and caches up, and is not counted
        if encoding == "grid":
            planner = GridPlanner(automaton, GridSettings(time_limit=args.plan_timeout), seed)
        else:
            planner = ContinuousPlanner(automaton, ContinuousSettings(time_limit=args.plan_timeout), seed)
        started = time.perf_counter()
        try:
            plan = planner.first()
            ending = f"plan, {plan.horizon} steps"
        except UnsatisfiableScenario as error:
            plan, ending = None, "no plan: " + str(error).splitlines()[-1].strip()[:60]
        except PlanningTimeout:
            plan, ending = None, f"timed out ({args.plan_timeout:g} s)"
        except NoPlanError as error:
            plan, ending = None, f"no plan: {error}"[:60]
        if seed == 0:
            continue
        seconds.append(time.perf_counter() - started)
        endings.append(ending)
        if plan is not None and args.simulate:
            from pytest_roadlogic.monitor import monitor
            from pytest_roadlogic.simulation import simulate

            accepted += monitor(automaton, simulate(plan).trace).accepted
    common = max(set(endings), key=endings.count)
    timing = f"{statistics.median(seconds):8.3f} {max(seconds):8.3f}"
    shown = f"{accepted}/{args.seeds}" if args.simulate else "-"
    print(f"{name:<22} {encoding:<11} {timing:<28} {common:<40} {shown}", flush=True)
    return statistics.median(seconds)


if __name__ == "__main__":
    raise SystemExit(main())
