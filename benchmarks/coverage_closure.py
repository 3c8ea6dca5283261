"""Coverage closure against random sampling: simulations until every reachable cover bucket is hit.

    python benchmarks/coverage_closure.py [--seeds 1 2 3 4 5] [--samples 10] [--cap 150] [FILE ...]

For each scenario file (default: the town's junction scenario, whose cover item has a bucket per
way the ego may take, and scenarios/coverage/catch_up_from_behind.osc, whose cross has narrow
combinations) and each seed, side by side in one run:

- random: the refined strategy's samples, one after the other, until every bucket that is not
  proved unreachable has been hit its target times (or ``--cap`` samples, then reported as such);
- closure: ``--samples`` samples of the same seed, then one case asked for each bucket still not
  hit (``evaluation.closure``), as ``pytest --roadlogic-coverage-closure yes`` runs them.

Each counts simulations (cases that were planned and simulated; a sample without a plan costs no
simulation) and prints the median over the seeds and the ratio random / closure.
"""

from __future__ import annotations

import argparse
import statistics
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from pytest_roadlogic.evaluation.closure import closed, closing_values  # noqa: E402
from pytest_roadlogic.evaluation.coverage import ScenarioCoverage  # noqa: E402
from pytest_roadlogic.evaluation.reach import unreachable  # noqa: E402
from pytest_roadlogic.frontend import load_file  # noqa: E402
from pytest_roadlogic.outcomes import NO_PLAN  # noqa: E402
from pytest_roadlogic.runner import Runner  # noqa: E402
from pytest_roadlogic.settings import REFINED, RunSettings  # noqa: E402

DEFAULT = [
    ROOT / "scenarios" / "junctions" / "turn_at_a_junction_of_the_town.osc",
    ROOT / "scenarios" / "coverage" / "catch_up_from_behind.osc",
]


def proved(scenario, settings) -> dict[str, dict[str, str]]:
    """Per cover item on logical parameters, its buckets proved unreachable (asked once)."""
    found = {}
    for item in scenario.coverage:
        if item.kind == "cover" and item.observed is None:
            found[item.name] = unreachable(scenario, item, [b.label for b in item.buckets], settings, settings.seed)
    return found


def fresh(scenario, ruled_out) -> ScenarioCoverage:
    coverage = ScenarioCoverage.of(scenario.name, scenario.coverage)
    for name, labels in ruled_out.items():
        coverage.items[name].unreachable.update(labels)
    return coverage


def complete(scenario, coverage) -> bool:
    return all(closed(item, coverage) for item in scenario.coverage if item.kind == "cover" and item.observed is None)


def by_random(scenario, seed: int, cap: int, ruled_out) -> int | None:
    """Simulations of the refined samples until the buckets are closed; None within ``cap`` samples."""
    coverage, simulations, done = fresh(scenario, ruled_out), [0], [None]

    def each(result) -> None:
        if done[0] is not None:
            return
        simulations[0] += result.run is not None
        coverage.add(scenario.coverage, result.case.values, result.outcome, result.run)
        if complete(scenario, coverage):
            done[0] = simulations[0]

    Runner(scenario, RunSettings(seed=seed)).refined(each, count=cap, search=False)
    return done[0]


def by_closure(scenario, seed: int, samples: int, ruled_out) -> tuple[int, bool]:
    """Simulations of ``samples`` refined samples and then one case per bucket still open."""
    coverage, simulations = fresh(scenario, ruled_out), [0]
    runner = Runner(scenario, RunSettings(seed=seed))

    def each(result) -> None:
        simulations[0] += result.run is not None
        coverage.add(scenario.coverage, result.case.values, result.outcome, result.run)

    runner.refined(each, count=samples, search=False)
    for _, _, tries in closing_values(scenario, coverage):
        for values in tries:
            result = runner.run_case(runner.case(strategy=REFINED, values=values))
            each(result)
            if result.outcome != NO_PLAN:
                break
    return simulations[0], complete(scenario, coverage)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path, default=DEFAULT)
    parser.add_argument("--seeds", nargs="+", type=int, default=[1, 2, 3, 4, 5])
    parser.add_argument("--samples", type=int, default=10)
    parser.add_argument("--cap", type=int, default=150)
    args = parser.parse_args()
    for path in args.files:
        scenario = load_file(path).scenario_to_run(None)
        ruled_out = proved(scenario, RunSettings(seed=1))
        buckets = sum(len(i.buckets) for i in scenario.coverage if i.kind == "cover" and i.observed is None)
        unreach = sum(len(v) for v in ruled_out.values())
        print(f"{path.name}: {buckets} buckets, {unreach} proved unreachable")
        randoms, closures = [], []
        for seed in args.seeds:
            r = by_random(scenario, seed, args.cap, ruled_out)
            c, ok = by_closure(scenario, seed, args.samples, ruled_out)
            randoms.append(r if r is not None else float("inf"))
            closures.append(c if ok else float("inf"))
            shown = r if r is not None else f">{args.cap} samples"
            print(f"  seed {seed}: random {shown} simulations, closure {c} ({'closed' if ok else 'NOT closed'})")
        mr, mc = statistics.median(randoms), statistics.median(closures)
        print(f"  median: random {mr}, closure {mc}, ratio {mr / mc:.2f}")


if __name__ == "__main__":
    main()
