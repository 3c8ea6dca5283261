"""What loading the pytest plugin costs every pytest session: wall time and heavy modules loaded.

Prints, as the fastest of --repeat fresh processes (start-up times on a shared machine vary by tens of
ms; the fastest run is the least disturbed):
- ``pytest --version`` with the plugin, and with ``-p no:roadlogic`` (the plugin not loaded);
- ``pytest --collect-only`` of an empty folder, both ways (a whole session that runs nothing);
- ``python -c "import pytest_roadlogic.plugin"``, and the heavy packages that import pulls in.

``--source DIR`` measures the package in DIR instead (a checkout of an older commit, for a
before/after comparison in one run):

    git worktree add /tmp/before <commit>
    python benchmarks/plugin_import.py --source /tmp/before
    python benchmarks/plugin_import.py
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time

HEAVY = ("clingo", "clingodl", "frenetix", "commonroad", "matplotlib", "antlr4", "hypothesis", "numpy")


def timed(command: list[str], env: dict[str, str], repeat: int, ok: tuple[int, ...] = (0,)) -> float:
    times = []
    for _ in range(repeat):
        started = time.perf_counter()
        done = subprocess.run(command, env=env, capture_output=True)
        times.append(time.perf_counter() - started)
        if done.returncode not in ok:
            raise SystemExit(f"{' '.join(command)} failed ({done.returncode}): {done.stderr.decode()[-500:]}")
    return min(times)  # the least disturbed run: start-up noise here is tens of ms


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=10)
    parser.add_argument("--source", help="a directory holding the pytest_roadlogic package to measure instead")
    args = parser.parse_args()
    env = dict(os.environ)
    if args.source:
        env["PYTHONPATH"] = os.pathsep.join(filter(None, [args.source, env.get("PYTHONPATH")]))
    # run from a neutral folder: the current one comes first on sys.path and would shadow --source
    os.chdir(tempfile.gettempdir())
    where = subprocess.run(
        [sys.executable, "-c", "import pytest_roadlogic; print(pytest_roadlogic.__file__)"],
        env=env,
        capture_output=True,
        text=True,
        check=True,
    )
    print(f"package: {where.stdout.strip()}")
    with_plugin = timed([sys.executable, "-m", "pytest", "--version"], env, args.repeat)
    without = timed([sys.executable, "-m", "pytest", "--version", "-p", "no:roadlogic"], env, args.repeat)
    with tempfile.TemporaryDirectory() as empty:  # a session that collects nothing: every plugin loaded, no .osc file
        session = [
            sys.executable,
            "-m",
            "pytest",
            "--collect-only",
            "-q",
            "-p",
            "no:cacheprovider",
            "--rootdir",
            empty,
            empty,
        ]
        collect_with = timed(session, env, args.repeat, ok=(0, 5))
        collect_without = timed([*session, "-p", "no:roadlogic"], env, args.repeat, ok=(0, 5))
    plugin = timed([sys.executable, "-c", "import pytest_roadlogic.plugin"], env, args.repeat)
    bare = timed([sys.executable, "-c", "import pytest"], env, args.repeat)
    heavy = subprocess.run(
        [
            sys.executable,
            "-c",
            f"import sys, pytest_roadlogic.plugin; print(' '.join(sorted({{m.split('.')[0] for m in sys.modules}} & set({HEAVY!r}))))",
        ],
        env=env,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    print(f"pytest --version                      {with_plugin * 1000:7.0f} ms (fastest of {args.repeat})")
    print(f"pytest --version -p no:roadlogic      {without * 1000:7.0f} ms")
    print(f"pytest --collect-only (no tests)      {collect_with * 1000:7.0f} ms")
    print(f"  the same with -p no:roadlogic       {collect_without * 1000:7.0f} ms")
    print(f"import pytest_roadlogic.plugin        {plugin * 1000:7.0f} ms  (import pytest alone: {bare * 1000:.0f} ms)")
    print(f"heavy packages the plugin loads:      {heavy or 'none'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
