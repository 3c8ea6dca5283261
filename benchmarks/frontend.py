"""Front-end speed: parse and check time per .osc file (the median of several runs).

python benchmarks/frontend.py [PATH ...]     (default: scenarios/ and tests/corpus/)
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

from pytest_roadlogic.frontend import OscError, check_file
from pytest_roadlogic.frontend.semantics.physical import parse_with_declared_units

ROOT = Path(__file__).resolve().parent.parent
REPEATS = 20


def median_ms(action) -> float:
    samples = []
    for _ in range(REPEATS):
        started = time.perf_counter()
        action()
        samples.append((time.perf_counter() - started) * 1000)
    return statistics.median(samples)


def main(argv: list[str]) -> int:
    roots = [Path(a) for a in argv] or [ROOT / "scenarios", ROOT / "tests" / "corpus"]
    files = [p for root in roots for p in (sorted(root.glob("*.osc")) if root.is_dir() else [root])]
    print(f"{'file':40} {'bytes':>6} {'parse ms':>9} {'check ms':>9}")
    rows = []
    for path in files:
        try:
            # the parse the checker does: with the units the file or its imports declare (a file
            # that declares yard had stopped the benchmark with a traceback)
            parse = median_ms(lambda path=path: parse_with_declared_units(path))
        except OscError as error:  # a file the front end refuses is a row, not the end of the run
            print(f"{path.name:40} {path.stat().st_size:6d} refused: {error.report().splitlines()[0]}")
            continue
        check = median_ms(lambda path=path: check_file(path))
        rows.append((path, path.stat().st_size, parse, check))
        print(f"{path.name:40} {path.stat().st_size:6d} {parse:9.2f} {check:9.2f}")
    largest = max(rows, key=lambda r: r[1])
    print(
        f"largest: {largest[0].name} ({largest[1]} bytes): parse {largest[2]:.2f} ms, parse+check {largest[3]:.2f} ms"
    )
    print(
        f"all {len(rows)} files: median parse {statistics.median(r[2] for r in rows):.2f} ms, median parse+check {statistics.median(r[3] for r in rows):.2f} ms"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
