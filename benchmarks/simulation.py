"""The whole pipeline (plan, simulate, monitor; retry on rejection) per benchmark scenario.

    python benchmarks/simulation.py [--seeds 10] [--profile] [paths...]

Runs the base strategy (parameters left as ranges for the planner) with seeds 1..N on every
scenario in ``scenarios/`` and prints, per scenario: how many instances the monitor accepted,
tries per accepted instance, and the median and maximum seconds of planning, simulation,
monitoring and the total per instance. Targets on a 2-core machine: 10 of 10 accepted; median total
under 5 s with two vehicles and under 8 s with three; no instance over 30 s. ``--profile`` adds
where the simulation's time per step goes (cProfile of one instance per scenario).
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import statistics
import time
from pathlib import Path

from pytest_roadlogic.pipeline import load_scenario, run_scenario

ROOT = Path(__file__).resolve().parent.parent
STAGES = ("planning", "simulation", "monitoring")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--profile", action="store_true")
    parser.add_argument("paths", nargs="*", type=Path)
    args = parser.parse_args(argv)
    paths = args.paths or sorted((ROOT / "scenarios").glob("*.osc"))
    header = f"{'scenario':22} {'actors':>6} {'accepted':>8} {'tries':>5} " + " ".join(
        f"{s[:5] + ' med/max s':>16}" for s in (*STAGES, "total")
    )
    print(f"base strategy, seeds 1..{args.seeds}")
    print(header)
    for path in paths:
        scenario = load_scenario(path)
        accepted, tries, times = 0, [], {s: [] for s in (*STAGES, "total")}
        for seed in range(1, args.seeds + 1):
            started = time.perf_counter()
            outcome = run_scenario(scenario, seed=seed)
            times["total"].append(time.perf_counter() - started)
            for stage in STAGES:
                times[stage].append(outcome.seconds[stage])
            if outcome.verdict.accepted:
                accepted += 1
                tries.append(outcome.tries)
        cells = " ".join(f"{statistics.median(times[s]):7.2f} /{max(times[s]):7.2f}" for s in (*STAGES, "total"))
        mean_tries = f"{statistics.mean(tries):5.2f}" if tries else "    -"
        actors = len(outcome.automaton.actors)
        print(f"{path.stem:22} {actors:6d} {accepted:4d}/{args.seeds:<3d} {mean_tries} {cells}", flush=True)
    if args.profile:
        for path in paths:
            scenario = load_scenario(path)
            profile = cProfile.Profile()
            profile.enable()
            outcome = run_scenario(scenario, seed=1, max_tries=1)
            profile.disable()
            steps = len(outcome.simulation.trace)
            print(
                f"\n{path.stem}: {steps} simulation steps, {outcome.seconds['simulation'] / steps * 1000:.1f} ms per step"
            )
            pstats.Stats(profile).sort_stats("tottime").print_stats(8)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
