"""Planning speed and plan diversity, per benchmark scenario.

    python benchmarks/planning.py [--plans 10] [--repeats 5] [--max-speed 40]

Prints the horizon of the first plan, grounding and solving time, the ground program's size, the
median time to the first plan and the time to N plans (base strategy: parameters left as ranges),
and the mean pairwise Jaccard similarity of the N plans' occupied cells (vehicle, step, lane, 1 m
cell; lower is more diverse). Targets: first plan under 0.2 s; similarity under 0.3.
"""

from __future__ import annotations

import argparse
import dataclasses
import itertools
import statistics
import time
from pathlib import Path

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.evaluation import jaccard
from pytest_roadlogic.frontend import load_file
from pytest_roadlogic.planning import GridPlanner, GridSettings
from pytest_roadlogic.planning.plan import Plan

ROOT = Path(__file__).resolve().parent.parent


def occupancy(plan: Plan, grid: float = 1.0) -> set[tuple]:
    return {
        (vehicle, step, state.lane, int(round(state.position / grid)))
        for vehicle, states in plan.states.items()
        for step, state in enumerate(states)
    }


def mean_jaccard(plans: list[Plan]) -> float | None:
    cells = [occupancy(p) for p in plans]
    pairs = [jaccard(a, b) for a, b in itertools.combinations(cells, 2)]
    return statistics.mean(pairs) if pairs else None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--plans", type=int, default=10)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--max-speed", type=float, default=None)
    parser.add_argument("--initial-speed", type=float, nargs=2, default=None, metavar=("LOW", "HIGH"))
    parser.add_argument("paths", nargs="*", type=Path)
    args = parser.parse_args(argv)
    settings = GridSettings()
    if args.max_speed is not None:
        settings = dataclasses.replace(settings, max_speed=args.max_speed)
    if args.initial_speed is not None:
        settings = dataclasses.replace(settings, initial_speed=tuple(args.initial_speed))
    paths = args.paths or sorted((ROOT / "scenarios").glob("*.osc"))
    print(
        f"max speed {settings.max_speed:g} m/s, grid {settings.grid:g} m, step {settings.dt:g} s; first plan: median of {args.repeats} seeds"
    )
    print(
        f"{'scenario':24} {'horizon':>7} {'ground s':>8} {'solve s':>8} {'rules':>8} {'first s':>8} {f'{args.plans} plans s':>10} {'jaccard':>8} {'distinct':>8}"
    )
    for path in paths:
        automaton = build_automaton(load_file(path).scenarios[0])
        firsts = []
        for seed in range(1, args.repeats + 1):
            planner = GridPlanner(automaton, settings, seed)
            started = time.perf_counter()
            plan = planner.first()
            firsts.append(time.perf_counter() - started)
        planner = GridPlanner(automaton, settings, seed=1)
        started = time.perf_counter()
        plans = list(planner.plans(limit=args.plans))
        many = time.perf_counter() - started
        similarity = mean_jaccard(plans)
        distinct = len({frozenset(occupancy(p)) for p in plans})
        shown = f"{similarity:.2f}" if similarity is not None else "-"
        print(
            f"{path.stem:24} {plan.horizon:7d} {plan.stats.get('ground_s', 0):8.3f} {plan.stats.get('solve_s', 0):8.3f} "
            f"{int(plan.stats.get('rules', 0)):8d} {statistics.median(firsts):8.3f} {many:10.2f} {shown:>8} {distinct:8d}"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
