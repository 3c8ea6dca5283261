"""Which OpenDRIVE maps others publish carry the project's scenarios: a table, map by map.

    python benchmarks/public_maps.py MAP.xodr ... [--seed 1] [--jobs 2] [--scenarios FILE.osc ...]

Each map is read (``roads.opendrive_in.read_map``), then every scenario (default: the paper's
seven, ``scenarios/*.osc``, and the junction suite, ``scenarios/junctions/*.osc``) is run on it as
``roadlogic run FILE --map MAP --seed S`` would (the base strategy's first plan, every vehicle
following it, retries on rejection), one map per worker process. Per map: its roads, junctions
and widest driving road one way; per suite, how many runs the monitor accepted; and, grouped, why
the others did not run: refused where the map is read or the route chosen (the reason, as the
message says it), no plan, rejected, past a time limit, or accepted on ways that never meet (two
paths the map has no ways for that cross, join or part: not counted).

Maps are not part of the repository: fetch them (CARLA's towns from carla-simulator/map,
esmini's samples from esmini/esmini's resources/xodr) and name them here.
"""

from __future__ import annotations

import argparse
import collections
import re
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from multiprocessing import get_context
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SEVEN = sorted((ROOT / "scenarios").glob("*.osc"))
JUNCTIONS = sorted((ROOT / "scenarios" / "junctions").glob("*.osc"))


def _reason(error: BaseException) -> str:
    """The first line of an error's message, with the map's path, its roads' and junctions' ids and
    names made general, so that equal reasons group; lengths and lane counts are kept."""
    text = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
    text = re.sub(r"\S+\.xodr(:\d+:\d+)?:?", "MAP:", text)
    text = re.sub(r"\b(road|junction) -?\d+", r"\1 #", text)
    text = re.sub(r"\('[^']*'\)", "('...')", text)
    return text[:240]


def _map_summary(path: Path) -> tuple[str, str | None]:
    """(roads, junctions and widest road one way; or '-') and the reason the map cannot be read."""
    from pytest_roadlogic.roads.opendrive_in import MapError, read_map

    try:
        road_map = read_map(path)
    except MapError as error:
        return "-", _reason(error)
    widest = max(
        (
            max(sum(1 for lane in side if lane.type == "driving") for side in (section.left, section.right))
            for road in road_map.roads.values()
            for section in road.sections
        ),
        default=0,
    )
    return f"{len(road_map.roads)} roads, {len(road_map.junctions)} junctions, up to {widest} lanes one way", None


def run_map(path: Path, scenarios: list[Path], seed: int) -> dict:
    """Every scenario run on the map ``path``: {scenario: (outcome, reason)} and the map's summary."""
    from pytest_roadlogic.confinement import ReadRoots
    from pytest_roadlogic.frontend import OscError
    from pytest_roadlogic.pipeline import load_scenario, run_scenario
    from pytest_roadlogic.planning import NoPlanError, PlanningTimeout
    from pytest_roadlogic.simulation import SimulationTimeout

    summary, unreadable = _map_summary(path)
    results: dict[str, tuple[str, str]] = {}
    seconds = time.perf_counter()
    for scenario_path in scenarios:
        if unreadable is not None:
            results[scenario_path.name] = ("refused", unreadable)
            continue
        try:
            scenario = load_scenario(scenario_path, roots=ReadRoots.of(ROOT, path), road_map=path)
            outcome = run_scenario(scenario, seed=seed)
            # two paths the map gave no ways that meet (check warns): a crossing run as two cars
            # that pass each other is not the scenario its author wrote, and is not counted
            apart = scenario.ways is not None and not scenario.ways.meet
            accepted = "accepted on ways that never meet" if apart else "accepted"
            results[scenario_path.name] = (accepted, "") if outcome.verdict.accepted else ("rejected", "")
        except OscError as error:
            first = error.errors[0].message if error.errors else str(error)
            results[scenario_path.name] = ("refused", _reason(first))
        except (PlanningTimeout, SimulationTimeout) as error:
            results[scenario_path.name] = ("timeout", _reason(error))
        except NoPlanError as error:
            results[scenario_path.name] = ("no plan", _reason(error))
    return {"map": path.name, "summary": summary, "results": results, "seconds": time.perf_counter() - seconds}


def _row(row: dict, suites: dict[str, list[Path]]) -> list[str]:
    lines = [f"{row['map']:<34} {row['summary']}  ({row['seconds']:.0f} s)"]
    for suite, files in suites.items():
        grouped: dict[tuple[str, str], list[str]] = collections.defaultdict(list)
        for f in files:
            grouped[row["results"][f.name]].append(f.stem)
        accepted = sum(len(names) for (kind, _), names in grouped.items() if kind == "accepted")
        lines.append(f"    {suite:<10} {accepted}/{len(files)} accepted")
        for (kind, reason), names in sorted(grouped.items(), key=lambda item: -len(item[1])):
            if kind != "accepted":
                lines.append(
                    f"        {len(names)} {kind}" + (f": {reason}" if reason else "") + f" ({', '.join(names)})"
                )
    return lines


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("maps", nargs="+", type=Path)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--scenarios", nargs="*", type=Path, help="instead of the seven and the junction suite")
    args = parser.parse_args(argv)
    suites = {"scenarios": args.scenarios} if args.scenarios else {"seven": SEVEN, "junctions": JUNCTIONS}
    scenarios = [f for files in suites.values() for f in files]
    maps = [m.resolve() for m in args.maps]
    totals = collections.Counter()
    carrying = collections.Counter()
    with ProcessPoolExecutor(args.jobs, mp_context=get_context("spawn")) as pool:
        for row in pool.map(run_map, maps, [scenarios] * len(maps), [args.seed] * len(maps)):
            print("\n".join(_row(row, suites)), flush=True)
            for suite, files in suites.items():
                accepted = sum(1 for f in files if row["results"][f.name][0] == "accepted")
                totals[suite] += accepted
                carrying[suite] += accepted > 0
    for suite, files in suites.items():
        print(
            f"{suite}: {totals[suite]} of {len(files) * len(maps)} runs accepted; "
            f"{carrying[suite]} of {len(maps)} maps carry at least one"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
