"""A bench campaign serially, on a local process pool and on a local two-node Ray cluster, side by side.

    python benchmarks/campaign.py [--base 4] [--refined 25] [--workers 2] [--rounds 1] [--out DIR]

Runs ``roadlogic bench`` on the paper's seven scenarios (``--base`` + ``--refined`` instances
each: 203 cases by default, no artifacts) three ways in each round, in turn: serially, with
``--jobs W`` and with ``--ray ADDRESS`` on a Ray cluster of W nodes of one CPU each, started on
this machine before the rounds (as a user's cluster would be running before a campaign). Prints
each run's wall and CPU seconds (this process's children: the Ray nodes' CPU is not counted),
the wall ratios serial/pool and serial/Ray, whether each run's verdicts are the serial run's
(every instance's outcome, values, robustness, horizon and message), and from the serial run's
per-case seconds what a campaign of 10,000 such cases would take on 100 nodes.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ROADLOGIC = [sys.executable, "-m", "pytest_roadlogic.cli"]


def verdicts(results: Path) -> list[tuple]:
    data = json.loads(results.read_text())
    return [
        (
            r["scenario"],
            r["strategy"],
            r["index"],
            r["outcome"],
            json.dumps(r["values"], sort_keys=True),
            r["robustness"],
            r["horizon"],
            r["message"],
        )
        for r in data["instances"]
    ]


def bench(args: argparse.Namespace, out: Path, extra: list[str]) -> tuple[float, float, list[tuple], Path]:
    """One bench run: (wall seconds, CPU seconds of the children, verdicts, results file)."""
    paths = sorted(str(p) for p in (ROOT / "scenarios").glob("*.osc"))
    command = [
        *ROADLOGIC,
        "bench",
        *paths,
        "--base",
        str(args.base),
        "--refined",
        str(args.refined),
        "--no-artifacts",
        "--out",
        str(out),
        *extra,
    ]
    before = os.times()
    started = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, cwd=ROOT)
    wall = time.perf_counter() - started
    after = os.times()
    if done.returncode not in (0, 1):
        sys.exit(f"{' '.join(command)} failed:\n{done.stderr}")
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return wall, cpu, verdicts(out / "results.json"), out / "results.json"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base", type=int, default=4)
    parser.add_argument("--refined", type=int, default=25)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--rounds", type=int, default=1)
    parser.add_argument("--out", type=Path, default=None)
    args = parser.parse_args()
    from ray.cluster_utils import Cluster

    cluster = Cluster(initialize_head=True, head_node_args={"num_cpus": 1, "include_dashboard": False})
    for _ in range(args.workers - 1):
        cluster.add_node(num_cpus=1)
    cluster.wait_for_nodes()
    top = args.out or Path(tempfile.mkdtemp(prefix="campaign-"))
    runs = {"serial": [], f"--jobs {args.workers}": [], f"--ray ({args.workers} nodes)": []}
    flags = {
        "serial": [],
        f"--jobs {args.workers}": ["--jobs", str(args.workers)],
        f"--ray ({args.workers} nodes)": ["--ray", cluster.address],
    }
    try:
        for round_ in range(args.rounds):
            for name, extra in flags.items():
                out = top / f"round{round_}-{name.split()[0].strip('-')}"
                runs[name].append(bench(args, out, extra))
                wall, cpu, found, _ = runs[name][-1]
                print(
                    f"round {round_ + 1} {name:>18}: {len(found)} cases, wall {wall:7.1f} s, CPU here {cpu:7.1f} s",
                    flush=True,
                )
    finally:
        cluster.shutdown()
    serial = runs["serial"]
    reference = serial[0][2]
    print()
    for name, results in runs.items():
        same = all(r[2] == reference for r in results)
        ratio = statistics.median(s[0] / r[0] for s, r in zip(serial, results, strict=True))
        print(
            f"{name:>18}: median wall {statistics.median(r[0] for r in results):7.1f} s, serial/this "
            f"{ratio:4.2f}, verdicts {'identical to the serial run' if same else 'DIFFERENT'}"
        )
    data = json.loads(serial[0][3].read_text())
    per_case = [sum(r["seconds"].values()) for r in data["instances"]]
    mean = statistics.mean(per_case)
    print(
        f"\nserial per case: mean {mean:.2f} s, median {statistics.median(per_case):.2f} s, "
        f"longest {max(per_case):.2f} s"
    )
    cores = 100 * 2
    print(
        f"10,000 such cases on 100 nodes of 2 cores ({cores} workers), each sample a job: about "
        f"{10_000 * mean / cores:.0f} s of work per worker (plus its start), against {10_000 * mean / 3600:.1f} h "
        "serially"
    )


if __name__ == "__main__":
    main()
