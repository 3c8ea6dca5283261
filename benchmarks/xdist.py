"""How much faster `pytest -n 2 scenarios/` is than `pytest scenarios/` at the same seed.

Runs both (fresh Hypothesis database each, so neither replays the other's examples), checks that
they end with the same outcomes, and prints wall-clock times and the speedup. Target: at least 1.7x
on two cores.

    python benchmarks/xdist.py [--examples N] [--seed S] [--workers W]
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def run(workers: int, examples: int, seed: int) -> tuple[float, list[str]]:
    with tempfile.TemporaryDirectory() as scratch:
        for path in (ROOT / "scenarios").glob("*.osc"):
            shutil.copy(path, scratch)
        command = [
            sys.executable,
            "-m",
            "pytest",
            scratch,
            "-q",
            "-rA",
            "-p",
            "no:cacheprovider",
            "--rootdir",
            scratch,
            "--roadlogic-examples",
            str(examples),
            "--roadlogic-seed",
            str(seed),
        ]
        if workers > 1:
            command += ["-n", str(workers)]
        started = time.perf_counter()
        result = subprocess.run(command, capture_output=True, text=True, cwd=scratch)
        seconds = time.perf_counter() - started
    outcomes = sorted(
        line.split(" - ")[0] for line in result.stdout.splitlines() if line.startswith(("PASSED", "FAILED"))
    )
    return seconds, outcomes


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--examples", type=int, default=10)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--workers", type=int, default=2)
    args = parser.parse_args()
    serial, serial_outcomes = run(1, args.examples, args.seed)
    parallel, parallel_outcomes = run(args.workers, args.examples, args.seed)
    print(f"pytest scenarios/ ({args.examples} examples per scenario, seed {args.seed})")
    print(f"  serial          {serial:6.1f} s   {len(serial_outcomes)} items")
    print(f"  -n {args.workers}            {parallel:6.1f} s   {len(parallel_outcomes)} items")
    print(f"  speedup         {serial / parallel:6.2f}x  (target >= 1.7x)")
    print(f"  same outcomes   {serial_outcomes == parallel_outcomes}")


if __name__ == "__main__":
    main()
