"""First-try acceptance on a map against the straight road, scenario by scenario.

    python benchmarks/roads.py [--map scenarios/roads/maps/curved_highway.xodr] [--samples 10]
        [FILE.osc ...]   (default: the paper's seven, scenarios/*.osc)

For each file, ``--samples`` refined samples (Hypothesis, seed 1, as the plugin draws them) are
planned and simulated once each (one try, no retry on rejection) on the straight road and on the
map's route; prints, per file and in total, how many the monitor accepted, how many had no plan,
and the seconds of each column.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypothesis import HealthCheck, Phase, given, settings  # noqa: E402
from hypothesis import seed as seeded  # noqa: E402

from pytest_roadlogic.frontend import OscError  # noqa: E402
from pytest_roadlogic.pipeline import load_scenario, run_instances  # noqa: E402
from pytest_roadlogic.planning import NoPlanError  # noqa: E402
from pytest_roadlogic.sampling import strategy  # noqa: E402


def samples(scenario, count: int) -> list[dict]:
    drawn = []

    @seeded(1)
    @settings(
        max_examples=count,
        database=None,
        deadline=None,
        phases=[Phase.generate],
        suppress_health_check=list(HealthCheck),
    )
    @given(strategy(scenario))
    def collect(values):
        drawn.append(values)

    collect()
    return drawn[:count]


def first_tries(path: Path, values: list[dict], road_map: str | None) -> tuple[int, int, float]:
    """(accepted, no plan, seconds) of one try per sample."""
    try:
        scenario = load_scenario(path, road_map=road_map)
    except OscError as error:  # the map has no route for it: every sample counts as no plan
        print(f"  {path.name}: {error.diagnostics[0].message}")
        return 0, len(values), 0.0
    accepted = no_plan = 0
    started = time.perf_counter()
    for v in values:
        try:
            outcome = next(run_instances(scenario, 1, seed=1, values=v, max_tries=1))
        except NoPlanError:
            no_plan += 1
            continue
        accepted += outcome.verdict.accepted
    return accepted, no_plan, time.perf_counter() - started


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path)
    parser.add_argument("--map", default=str(ROOT / "scenarios" / "roads" / "maps" / "curved_highway.xodr"))
    parser.add_argument("--samples", type=int, default=10)
    args = parser.parse_args()
    files = args.files or sorted((ROOT / "scenarios").glob("*.osc"))
    print(f"first-try acceptance, {args.samples} refined samples each: straight road against {Path(args.map).name}")
    print(f"{'scenario':<24} {'straight':>9} {'no plan':>8} {'s':>6}   {'map':>9} {'no plan':>8} {'s':>6}")
    totals = [0, 0, 0, 0, 0]
    for path in files:
        values = samples(load_scenario(path), args.samples)
        straight = first_tries(path, values, None)
        mapped = first_tries(path, values, args.map)
        n = len(values)
        totals = [
            totals[0] + n,
            totals[1] + straight[0],
            totals[2] + mapped[0],
            totals[3] + straight[1],
            totals[4] + mapped[1],
        ]
        print(
            f"{path.stem:<24} {straight[0]:>4} of {n:<2} {straight[1]:>8} {straight[2]:6.1f}   "
            f"{mapped[0]:>4} of {n:<2} {mapped[1]:>8} {mapped[2]:6.1f}",
            flush=True,
        )
    n = totals[0]
    print(
        f"{'all':<24} {totals[1]:>4} of {n:<2} ({100 * totals[1] / n:.0f}%)   {totals[2]:>4} of {n:<2} "
        f"({100 * totals[2] / n:.0f}%); no plan {totals[3]} / {totals[4]}"
    )


if __name__ == "__main__":
    main()
