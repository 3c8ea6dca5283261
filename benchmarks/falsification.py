"""Falsification: how fast the search finds a defective vehicle under test's failure, and how often
the scenario happens around a good one.

    python benchmarks/falsification.py [--scenario scenarios/dut/cut_in.osc] [--seeds 10] [--budget 30]
        [--defective late-acc | --delay SECONDS] [--samples 20] [--periods 0.25,1,0]

Prints two tables:

1. samples and seconds to the first failure of the defective driver (``--defective``, default
   ``weak-braking-acc``; or, with ``--delay``, the reference one acting that many seconds late: a
   milder defect, whose failures are rarer than the shipped variants' and so worth searching for), Hypothesis steered by the oracles' margin (``hypothesis.target``, as the
   plugin runs it) against plain random sampling of the same strategy, mean over ``--seeds`` seeds
   (a seed that finds none within ``--budget`` samples counts the budget);
2. with the good driver (``acc``), the share of ``--samples`` samples in which the scenario happened
   (the monitor accepted the trace, one try each), reactive (the other vehicles replanned every
   ``--periods`` seconds) against open loop (period 0: they follow their first plan), the replanning
   seconds per call (median, 95th percentile) against the period, the replans that found no plan
   and those whose run so far had to be the old plan's (no run of the automaton went through the
   states seen at the planning steps), and the table row's wall-clock seconds.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypothesis import HealthCheck, Phase, given, settings, target  # noqa: E402
from hypothesis import seed as seeded  # noqa: E402

from pytest_roadlogic.dut import UnderTest  # noqa: E402
from pytest_roadlogic.pipeline import load_scenario, run_instances  # noqa: E402
from pytest_roadlogic.planning import NoPlanError  # noqa: E402
from pytest_roadlogic.reactive import replanning_seconds  # noqa: E402
from pytest_roadlogic.sampling import strategy  # noqa: E402


class Found(Exception):
    pass


def late_by(delay: float):
    """A driver factory: the reference ACC acting ``delay`` seconds late drives the vehicle under test."""
    from pytest_roadlogic.dut.reference_drivers import AdaptiveCruiseControl

    class Late(AdaptiveCruiseControl):
        reaction_delay = delay

    return lambda vehicle: Late() if vehicle in ("dut.car", "dut") else None


def first_failure(scenario, driver, seed: int, budget: int, targeted: bool) -> tuple[int, float]:
    """(samples, seconds) until the first failure of ``driver`` (a reference driver's name, or a
    driver factory); (budget, seconds) when none."""
    count, started = 0, time.perf_counter()
    phases = [Phase.generate, Phase.target] if targeted else [Phase.generate]

    @seeded(seed)
    @settings(max_examples=budget, database=None, deadline=None, phases=phases, suppress_health_check=list(HealthCheck))
    @given(strategy(scenario))
    def sample(values):
        nonlocal count
        count += 1
        try:
            if isinstance(driver, str):
                run = next(run_instances(scenario, 1, seed=1, values=values, under_test=UnderTest(driver=driver)))
            else:
                run = next(run_instances(scenario, 1, seed=1, values=values, under_test=UnderTest(), drivers=driver))
        except NoPlanError:
            return
        if targeted:
            target(-run.dut.margin(), label="closeness of the vehicle under test to failing")
        if run.dut.failed:
            raise Found()

    try:
        sample()
    except Found:
        return count, time.perf_counter() - started
    return budget, time.perf_counter() - started


def happened(scenario, samples: int, period: float) -> tuple[int, int, list]:
    """(samples the scenario happened in, samples simulated, replans) with the good driver."""
    values = []

    @seeded(1)
    @settings(max_examples=samples, database=None, deadline=None, phases=[Phase.generate])
    @given(strategy(scenario))
    def collect(v):
        values.append(v)

    collect()
    accepted, simulated, replans = 0, 0, []
    for v in values[:samples]:
        try:
            run = next(
                run_instances(scenario, 1, seed=1, values=v, under_test=UnderTest(replan_period=period), max_tries=1)
            )
        except NoPlanError:
            continue
        simulated += 1
        accepted += run.verdict.accepted and not run.dut.hit_by_others
        replans += run.simulation.replans
    return accepted, simulated, replans


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=str(ROOT / "scenarios" / "dut" / "cut_in.osc"))
    parser.add_argument("--defective", default="weak-braking-acc")
    parser.add_argument("--delay", type=float, default=None, help="instead: the reference ACC this many seconds late")
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--budget", type=int, default=30, help="samples per seed before giving up")
    parser.add_argument("--samples", type=int, default=20, help="samples for the share that happened")
    parser.add_argument(
        "--periods", default="0.25,1,0", help="replanning periods (s) of the share that happened; 0: open loop"
    )
    args = parser.parse_args()
    scenario = load_scenario(args.scenario)
    driver = args.defective if args.delay is None else late_by(args.delay)
    name = args.defective if args.delay is None else f"acc {args.delay:g} s late"
    if args.seeds:
        print(f"{Path(args.scenario).name}: first failure of {name}, {args.seeds} seeds, budget {args.budget}")
        print(f"{'search':<10} {'samples (mean)':>15} {'seconds (mean)':>15} {'seeds failed':>13}")
    for targeted in (True, False) if args.seeds else ():
        results = [first_failure(scenario, driver, s, args.budget, targeted) for s in range(args.seeds)]
        found = sum(n < args.budget for n, _ in results)
        print(
            f"{'targeted' if targeted else 'random':<10} {statistics.mean(n for n, _ in results):15.1f} "
            f"{statistics.mean(t for _, t in results):15.1f} {found:>8} of {args.seeds}",
            flush=True,
        )
    print(f"\n{Path(args.scenario).name}: the good driver (acc), {args.samples} samples, one try each")
    print(
        f"{'execution':<16} {'happened':>12} {'replans':>8} {'median s':>9} {'p95 s':>7} {'none':>5} "
        f"{'kept run':>9} {'seconds':>8}"
    )
    for period in (float(p) for p in args.periods.split(",")):
        started = time.perf_counter()
        accepted, simulated, replans = happened(scenario, args.samples, period)
        seconds = time.perf_counter() - started
        median, p95 = replanning_seconds(replans)
        name = f"every {period:g} s" if period else "open loop"
        print(
            f"{name:<16} {accepted:>5} of {simulated:<4} {len(replans):>8} {median:9.3f} {p95:7.3f} "
            f"{sum(r.plan is None for r in replans):>5} {sum(r.plan is not None and not r.seen for r in replans):>9} "
            f"{seconds:8.1f}",
            flush=True,
        )


if __name__ == "__main__":
    main()
