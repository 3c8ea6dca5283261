"""Fingerprints of the plans and traces the pipeline produces: a refactoring must not change them.

For every scenario file given (default: scenarios/*.osc) and every seed, prints one line per run:
the scenario, the seed, the strategy, the SHA-256 (first 16 hex digits) of the plan's JSON
(without the solver's statistics) and of the trace's CSV, the tries, the verdict and the size of
the ground program (clingo's rule count). Two strategies are run: ``base`` (the planner's first plan) and
``refined`` with one fixed sample (the midpoint of every logical parameter on the sampling grid,
the first choice of every enum), which exercises the random start and the guidance.

    python benchmarks/fingerprints.py [--seeds 1 2 3] [--encoding grid|continuous] [FILES...] > before.txt
    ... change the code ...
    python benchmarks/fingerprints.py [--seeds 1 2 3] [FILES...] > after.txt
    diff before.txt after.txt        # no output: byte-identical plans and traces

``--encoding`` picks the planner's encoding (default: the pipeline's). Timing is printed to stderr only, so the two outputs compare equal when the results do.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from pytest_roadlogic.pipeline import load_scenario, run_scenario  # noqa: E402
from pytest_roadlogic.planning import NoPlanError, settings_for  # noqa: E402
from pytest_roadlogic.sampling import STEP, UnknownParameter, logical_parameters  # noqa: E402
from pytest_roadlogic.settings import ENCODINGS, RunSettings  # noqa: E402


def digest(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def plan_text(plan) -> str:
    """The plan's JSON without the solver's statistics (seconds differ from run to run, and the
    ground program's size is printed on its own)."""
    data = plan.to_dict()
    data.pop("stats")
    return json.dumps(data, indent=2)


def midpoint_sample(checked) -> dict:
    """One fixed sample: the middle of every range (on the sampling grid), the first of every choice."""
    values = {}
    for parameter in logical_parameters(checked):
        if parameter.choices:
            values[parameter.name] = parameter.choices[0]
        elif parameter.integer:
            values[parameter.name] = int(math.floor((parameter.low + parameter.high) / 2))
        else:
            values[parameter.name] = round(round((parameter.low + parameter.high) / 2 / STEP) * STEP, 6)
    return values


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path, default=sorted((ROOT / "scenarios").glob("*.osc")))
    parser.add_argument("--seeds", nargs="+", type=int, default=[1, 2, 3])
    parser.add_argument("--encoding", choices=ENCODINGS, default=RunSettings.encoding)
    args = parser.parse_args()
    settings = settings_for(RunSettings(encoding=args.encoding))
    started = time.perf_counter()
    for path in args.files:
        checked = load_scenario(path)
        for seed in args.seeds:
            for strategy, values in (("base", None), ("refined", midpoint_sample(checked))):
                try:
                    outcome = run_scenario(checked, seed=seed, settings=settings, values=values)
                except NoPlanError as error:  # a midpoint sample may have none: its message is its print
                    print(f"{path.stem:<22} seed {seed} {strategy:<7} no plan {digest(str(error))}", flush=True)
                    continue
                except UnknownParameter as error:  # the first of each choice may not go together (a map's ways)
                    print(f"{path.stem:<22} seed {seed} {strategy:<7} refused {digest(str(error))}", flush=True)
                    continue
                verdict = "accepted" if outcome.verdict.accepted else "rejected"
                print(
                    f"{path.stem:<22} seed {seed} {strategy:<7} plan {digest(plan_text(outcome.plan))} trace {digest(outcome.simulation.trace.to_csv())} tries {outcome.tries} {verdict} rules {int(outcome.plan.stats.get('rules', 0))}",
                    flush=True,
                )
    print(f"{time.perf_counter() - started:.1f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
