"""The test corpus as a user meets it: which files check, how long parse plus check takes, and which
run end to end (plan, simulate, monitor: accepted) at one seed. Issue 18's acceptance table.

    python benchmarks/corpus.py [--seed 1] [--check-only] [--dialect carla|standard] [FILES...]

A file that uses set_map (written for CARLA's scenario runner) is read in CARLA's dialect, as its
conftest or --dialect carla would; every other file in the standard's, unless --dialect names one
for all (CARLA's examples without a map, run as its runner reads them). A file with no scenario to
run (a library) is listed as such; one that does not parse, with its first syntax error.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from pytest_roadlogic.frontend import OscError, check_file  # noqa: E402
from pytest_roadlogic.pipeline import run_scenario  # noqa: E402
from pytest_roadlogic.planning import NoPlanError  # noqa: E402

CORPUS = ROOT / "tests" / "corpus"


def dialect_of(path: Path) -> str:
    return "carla" if ".set_map(" in path.read_text(encoding="utf-8") else "standard"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="*", type=Path)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--check-only", action="store_true")
    parser.add_argument("--dialect", choices=("carla", "standard"), help="read every file in this dialect")
    args = parser.parse_args()
    files = args.files or sorted(CORPUS.glob("*.osc"))
    started = time.perf_counter()
    slowest = (0.0, "")
    runs = accepted = 0
    print(f"{'file':34} {'dialect':8} {'check s':>8}  outcome")
    for path in files:
        dialect = args.dialect or dialect_of(path)
        t0 = time.perf_counter()
        try:
            result = check_file(path, dialect=dialect)
        except OscError as error:  # a syntax error: no tree to check
            print(
                f"{path.name:34} {dialect:8} {time.perf_counter() - t0:8.3f}  syntax: {len(error.diagnostics)} errors"
            )
            continue
        seconds = time.perf_counter() - t0
        slowest = max(slowest, (seconds, path.name))
        if result.errors:
            print(f"{path.name:34} {dialect:8} {seconds:8.3f}  check: {len(result.errors)} errors")
            continue
        runnable = [s for s in result.scenarios if s.scenario.behavior is not None]
        if args.check_only or not runnable:
            print(f"{path.name:34} {dialect:8} {seconds:8.3f}  {'checks' if runnable else 'library (nothing to run)'}")
            continue
        scenario = runnable[0]
        runs += 1
        t0 = time.perf_counter()
        try:
            outcome = run_scenario(scenario, seed=args.seed)
            text = f"{'accepted' if outcome.verdict.accepted else 'rejected'} after {outcome.tries} tries"
            accepted += outcome.verdict.accepted
        except NoPlanError as error:
            text = f"no plan: {str(error).splitlines()[0][:70]}"
        except OscError as error:
            text = f"refused: {error.report().splitlines()[0].split(': error: ')[-1][:70]}"
        print(f"{path.name:34} {dialect:8} {seconds:8.3f}  {text} ({time.perf_counter() - t0:.1f} s)")
    print(
        f"\n{len(files)} files; check of the whole corpus {time.perf_counter() - started:.1f} s in all"
        if args.check_only
        else f"\n{len(files)} files, {runs} run, {accepted} accepted at seed {args.seed}"
    )
    print(f"slowest parse + check: {slowest[1]} {slowest[0]:.3f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
