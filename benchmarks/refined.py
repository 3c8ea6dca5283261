"""The realistic scenarios under the refined strategy, as ``pytest`` runs them: issue 19's table.

For every .osc file under scenarios/realistic/ runs ``pytest FILE --roadlogic-examples N`` in a
subprocess (so each checkout runs its own plugin) and prints one row from the item's JUnit
properties: examples run, accepted (conformant), no plan, rejected (non-conformant), timed out,
set aside (samples whose values together have no concrete scenario, or discarded by
``--roadlogic-no-plan discard``), the item's result, its wall time and, for a failing item, the
kind of failure and the minimal values it reports.

    python benchmarks/refined.py [--examples 20] [--seed 1] [--tree DIR ...] [FILES...]

Each ``--tree`` is a checkout (``git worktree add /tmp/before <commit>``) run beside the others,
row by row, for before/after tables; the default is this checkout. FILES are relative to
scenarios/realistic/ or absolute.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
REALISTIC = Path("scenarios") / "realistic"


def run(tree: Path, file: Path, examples: int, seed: int, extra: list[str]) -> dict[str, str]:
    """The JUnit properties of one file's item run in ``tree``, with ``result`` and ``seconds``."""
    with tempfile.TemporaryDirectory() as scratch:
        junit = Path(scratch) / "junit.xml"
        command = [
            sys.executable,
            "-m",
            "pytest",
            str(file),
            "-q",
            "-p",
            "no:cacheprovider",
            "--roadlogic-examples",
            str(examples),
            "--roadlogic-seed",
            str(seed),
            "--junitxml",
            str(junit),
            "--basetemp",
            str(Path(scratch) / "tmp"),
            *extra,
        ]
        start = time.perf_counter()
        done = subprocess.run(command, cwd=tree, capture_output=True, text=True)
        seconds = time.perf_counter() - start
        if not junit.exists():
            return {"result": f"no report (exit {done.returncode})", "seconds": f"{seconds:.0f}"}
        case = ET.parse(junit).find(".//testcase")
        if case is None:
            return {"result": "not collected", "seconds": f"{seconds:.0f}"}
        properties = {p.get("name", ""): p.get("value", "") for p in case.iter("property")}
        properties["result"] = (
            "failed" if case.find("failure") is not None or case.find("error") is not None else "passed"
        )
        properties["seconds"] = f"{seconds:.0f}"
        return properties


def values(properties: dict[str, str]) -> str:
    try:
        failing = json.loads(properties.get("failing_values", "") or "{}")
    except json.JSONDecodeError:
        return "?"
    return ", ".join(f"{k}={v:.1f}" if isinstance(v, float) else f"{k}={v}" for k, v in failing.items())


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path)
    parser.add_argument("--examples", type=int, default=20)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--tree", type=Path, action="append", help="a checkout to run (repeatable); default this one")
    parser.add_argument("--pytest-arg", action="append", default=[], help="passed on to pytest (repeatable)")
    args = parser.parse_args()
    trees = args.tree or [ROOT]
    files = [f if f.is_absolute() else REALISTIC / f for f in args.files] or sorted(
        p.relative_to(ROOT) for p in (ROOT / REALISTIC).rglob("*.osc") if p.name != "lib.osc"
    )
    print(f"{args.examples} refined examples, seed {args.seed}")
    print(
        f"{'scenario':<22} {'tree':<14} {'ex':>3} {'acc':>4} {'nopl':>4} {'rej':>4} {'tout':>4} {'aside':>5} {'result':<7} {'s':>4}  failure"
    )
    for file in files:
        for tree in trees:
            p = run(tree.resolve(), file, args.examples, args.seed, args.pytest_arg)
            failure = f"{p.get('failure_kind', p.get('verdict', ''))}: {values(p)}" if p["result"] == "failed" else ""
            print(
                f"{file.stem:<22} {tree.resolve().name[:14]:<14} {p.get('examples', '-'):>3} {p.get('conformant', '-'):>4} {p.get('no_plan', '-'):>4} "
                f"{p.get('non_conformant', '-'):>4} {p.get('timed_out', '-'):>4} {p.get('discarded', '-'):>5} {p['result']:<7} {p['seconds']:>4}  {failure}",
                flush=True,
            )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
