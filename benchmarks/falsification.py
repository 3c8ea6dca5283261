"""Falsification: how fast each search finds a defective vehicle under test's failure, and how often
the scenario happens around a good one.

    python benchmarks/falsification.py [--scenario benchmarks/scenarios/rear_braking_rare.osc]
        [--max-braking 5 | --delay SECONDS | --defective NAME] [--seeds 10] [--budget 200]
        [--searches random,cross-entropy,hypothesis] [--replan-period 0] [--jobs 2 | --ray ADDRESS]
        [--samples 0] [--periods 0.25,1,0]

Prints two tables:

1. simulations to the first failure of a defective driver, per search (the ``--roadlogic-search``
   values, each run as the plugin runs it: ``Runner.refined`` with the oracles' margin as
   Hypothesis's target; no shrinking): median, quartiles and range over ``--seeds`` sampling
   seeds (a seed that finds none within ``--budget`` samples counts the budget), and the ratio of
   each search's median to random's. The default defect, an adaptive cruise control that never
   brakes harder than 5 m/s^2, fails in about 2% of ``rear_braking_rare``'s space (a corner: fast,
   close, the car ahead braking gently and long; the good driver passes everywhere): a rare
   failure region. ``--replan-period 0``: that scenario's car ahead does not react to the vehicle
   under test, so its first plan is its plan (a simulation costs tenths of a second);
2. with ``--samples N``, the good driver (``acc``): the share of N samples in which the scenario
   happened (the monitor accepted the trace, one try each), reactive (the other vehicles replanned
   every ``--periods`` seconds) against open loop (period 0: they follow their first plan), the
   replanning seconds per call (median, 95th percentile) against the period, the replans that
   found no plan and those whose run so far had to be the old plan's (no run of the automaton went
   through the states seen at the planning steps), and the table row's wall-clock seconds.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypothesis import HealthCheck, Phase, given, settings  # noqa: E402
from hypothesis import seed as seeded  # noqa: E402

from pytest_roadlogic.dut import UnderTest  # noqa: E402
from pytest_roadlogic.executors import executor  # noqa: E402
from pytest_roadlogic.outcomes import DUT_FAILED  # noqa: E402
from pytest_roadlogic.pipeline import load_scenario, run_instances  # noqa: E402
from pytest_roadlogic.planning import NoPlanError  # noqa: E402
from pytest_roadlogic.reactive import replanning_seconds  # noqa: E402
from pytest_roadlogic.runner import Runner  # noqa: E402
from pytest_roadlogic.sampling import strategy  # noqa: E402
from pytest_roadlogic.settings import HYPOTHESIS_SEARCH, SEARCHES, RunSettings  # noqa: E402


class Found(Exception):
    pass


def defective(delay: float | None, max_braking: float | None):
    """A driver factory: the reference ACC acting ``delay`` seconds late, or never braking harder
    than ``max_braking`` m/s^2, drives the vehicle under test."""
    from pytest_roadlogic.dut.reference_drivers import AdaptiveCruiseControl

    flaws = {"reaction_delay": delay, "max_braking": max_braking}
    Defective = type("Defective", (AdaptiveCruiseControl,), {k: v for k, v in flaws.items() if v is not None})

    return lambda vehicle: Defective() if vehicle in ("dut.car", "dut") else None


def first_failure(
    path: str, search: str, seed: int, budget: int, driver: str, delay, max_braking, replan_period: float
) -> tuple[int, int, float]:
    """(samples, simulations, seconds) until the first failure of the vehicle under test in a
    property search ``search`` with sampling seed ``seed``; the budget when none."""
    scenario = load_scenario(path)
    bench = settings(
        database=None,
        deadline=None,
        phases=[Phase.generate, Phase.target] if search == HYPOTHESIS_SEARCH else [Phase.generate],
        suppress_health_check=list(HealthCheck),
    )
    settings.register_profile("falsification-bench", bench)
    settings.load_profile("falsification-bench")
    run_settings = RunSettings(search=search, examples=budget, tries=1, replan_period=replan_period, dut_driver=driver)
    drivers = defective(delay, max_braking) if delay is not None or max_braking is not None else None
    runner = Runner(scenario, run_settings, drivers=drivers, explain=False)
    samples = simulations = 0
    found: tuple[int, int, float] | None = None
    started = time.perf_counter()

    def each(result) -> None:
        nonlocal samples, simulations, found
        samples += 1
        simulations += result.run is not None
        if result.outcome == DUT_FAILED:
            if found is None:
                found = (samples, simulations, time.perf_counter() - started)
            raise Found()

    try:
        runner.refined(each, count=budget, search=True, sampling_seed=seed)
    except Found:
        pass
    return found or (budget, simulations, time.perf_counter() - started)


def quartiles(values: list[float]) -> tuple[float, float, float]:
    low, median, high = statistics.quantiles(values, n=4, method="inclusive")
    return low, median, high


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
    parser.add_argument("--scenario", default=str(ROOT / "benchmarks" / "scenarios" / "rear_braking_rare.osc"))
    parser.add_argument("--defective", default="acc", help="a reference driver's name (with neither of the next two)")
    parser.add_argument("--delay", type=float, default=None, help="the reference ACC this many seconds late")
    parser.add_argument("--max-braking", type=float, default=5.0, help="the reference ACC braking at most this (m/s^2)")
    parser.add_argument("--searches", default="random,cross-entropy", help=f"of {', '.join(SEARCHES)}")
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--budget", type=int, default=200, help="samples per seed before giving up")
    parser.add_argument("--replan-period", type=float, default=0.0)
    parser.add_argument("--jobs", type=int, default=2, help="processes running seeds side by side")
    parser.add_argument(
        "--ray", default=None, help="run the seeds' searches on this Ray cluster instead (docs/cluster.md)"
    )
    parser.add_argument("--samples", type=int, default=0, help="samples for the share that happened (0: none)")
    parser.add_argument(
        "--periods", default="0.25,1,0", help="replanning periods (s) of the share that happened; 0: open loop"
    )
    args = parser.parse_args()
    if args.delay is not None or args.defective != "acc":
        args.max_braking = None
    name = (
        f"acc {args.delay:g} s late"
        if args.delay is not None
        else f"acc braking at most {args.max_braking:g} m/s^2"
        if args.max_braking is not None
        else args.defective
    )
    searches = args.searches.split(",")
    if args.seeds:
        print(f"{Path(args.scenario).name}: first failure of {name}, {args.seeds} seeds, budget {args.budget}")
        tasks = [
            (args.scenario, search, seed, args.budget, args.defective, args.delay, args.max_braking, args.replan_period)
            for seed in range(args.seeds)
            for search in searches  # interleaved, so that each search meets the same load
        ]
        # each search learns from its own samples only: the seeds' searches are independent jobs
        with executor(args.jobs, args.ray) as chosen:
            results = list(chosen.results([(first_failure, task) for task in tasks]))
        by_search = {search: [r for t, r in zip(tasks, results) if t[1] == search] for search in searches}
        print(
            f"{'search':<14} {'simulations to the first failure: median':>41} {'quartiles':>13} {'range':>11} "
            f"{'found':>8} {'s/seed':>7} {'random/this':>12}"
        )
        random_median = statistics.median(s for _, s, _ in by_search["random"]) if "random" in by_search else None
        for search, rows in by_search.items():
            counts = [s for _, s, _ in rows]
            low, median, high = quartiles(counts)
            found = sum(n < args.budget for n, _, _ in rows)
            ratio = f"{random_median / median:12.1f}" if random_median is not None and median else f"{'':>12}"
            print(
                f"{search:<14} {median:41.1f} {low:6.1f}-{high:<6.1f} {min(counts):>4}-{max(counts):<6} "
                f"{found:>3} of {len(rows):<2} {statistics.mean(t for _, _, t in rows):7.1f} {ratio}",
                flush=True,
            )
            print(f"{'':<14} per seed: {counts}")
    if not args.samples:
        return
    scenario = load_scenario(args.scenario)
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
        label = f"every {period:g} s" if period else "open loop"
        print(
            f"{label:<16} {accepted:>5} of {simulated:<4} {len(replans):>8} {median:9.3f} {p95:7.3f} "
            f"{sum(r.plan is None for r in replans):>5} {sum(r.plan is not None and not r.seen for r in replans):>9} "
            f"{seconds:8.1f}",
            flush=True,
        )


if __name__ == "__main__":
    main()
