"""What the artifacts of one run cost beside the run itself (issue 21).

    python benchmarks/artifacts.py [--seed 1] [paths...]

For each scenario (default: the paper's overtake and the three-car overtake_third_actor), in a
fresh process as ``roadlogic run`` has it (so first-use imports count): the pipeline's stages, then
each artifact writer in the order ``artifacts.writer`` calls them, in seconds. Then the wall time of
``roadlogic run scenarios/overtake.osc --out ...`` itself against the planning, simulation and
monitoring it reports. Targets: the GIF of a 15 s three-car run under 1 s; all artifacts of
overtake under 1.5 s; run's wall time under twice planning, simulation and monitoring together. Last, the
fixed cost of a run (a process that starts, imports and reads the scenario) and the ratio it alone allows.
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DEFAULT = ("scenarios/overtake.osc", "scenarios/overtake_third_actor.osc")
WRITERS = ("plan+trace+verdict", "commonroad", "openscenario", "plot", "animation")


def measure_one(path: str, seed: int) -> dict:
    """Run ``path`` and time each artifact writer (called in a fresh process)."""
    import pytest_roadlogic.artifacts as _  # noqa: F401  (imported by the CLI before it runs)
    from pytest_roadlogic.artifacts.animation import animate_simulation
    from pytest_roadlogic.artifacts.commonroad import write_commonroad_xml
    from pytest_roadlogic.artifacts.files import write_text

    try:
        from pytest_roadlogic.artifacts.openscenario import write_openscenario
    except ImportError:  # a checkout from before issue 21, measured for the "before" figures
        write_openscenario = None
    from pytest_roadlogic.artifacts.plot import plot_simulation
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    outcome = run_scenario(load_scenario(ROOT / path), seed=seed)
    simulation, verdict, name = outcome.simulation, outcome.verdict, outcome.scenario.name
    seconds = {}
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder)
        steps = {
            "plan+trace+verdict": lambda: (
                write_text(out / "plan.json", outcome.plan.to_json()),
                write_text(out / "trace.csv", simulation.trace.to_csv()),
                write_text(out / "verdict.json", json.dumps(verdict.to_dict())),
            ),
            "commonroad": lambda: write_commonroad_xml(simulation, out / "scenario.xml"),
            "openscenario": lambda: write_openscenario(simulation, out, name) if write_openscenario else None,
            "plot": lambda: plot_simulation(simulation, verdict, out / "trajectories.png", title=name),
            "animation": lambda: animate_simulation(simulation, verdict, out / "simulation.gif", title=name),
        }
        for writer in WRITERS:
            started = time.perf_counter()
            steps[writer]()
            seconds[writer] = time.perf_counter() - started
        gif_kb = (out / "simulation.gif").stat().st_size / 1024
    return {
        "scenario": name,
        "vehicles": len(simulation.trace.actors),
        "trace_s": float(simulation.trace.times[-1]),
        "accepted": verdict.accepted,
        "stages": {s: outcome.seconds[s] for s in ("planning", "simulation", "monitoring")},
        "writers": seconds,
        "gif_kb": gif_kb,
    }


def measure_together(path: str, seed: int, forked: bool) -> float:
    """Seconds of ``writer.write_artifacts`` as ``roadlogic run`` calls it (called in a fresh process):
    the OpenSCENARIO writer in a forked process beside the others, or (``forked`` false) after them,
    as before it was forked."""
    from pytest_roadlogic.artifacts import writer
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    if not forked:
        writer.beside = writer.in_turn
    outcome = run_scenario(load_scenario(ROOT / path), seed=seed)
    with tempfile.TemporaryDirectory() as folder:
        started = time.perf_counter()
        writer.write_artifacts(outcome, Path(folder) / "o")
        return time.perf_counter() - started


def cli_run(seed: int) -> tuple[float, float]:
    """(wall seconds of `roadlogic run scenarios/overtake.osc`, its planning+simulation+monitoring)."""
    with tempfile.TemporaryDirectory() as folder:
        started = time.perf_counter()
        result = subprocess.run(
            [
                sys.executable,
                "-m",
                "pytest_roadlogic.cli",
                "run",
                "scenarios/overtake.osc",
                "--seed",
                str(seed),
                "--out",
                f"{folder}/o",
            ],
            capture_output=True,
            text=True,
            cwd=ROOT,
        )
        wall = time.perf_counter() - started
    stages = sum(float(m) for m in re.findall(r"(?:planning|simulation|monitoring)\s+([0-9.]+) s", result.stdout))
    if result.returncode != 0 or not stages:
        raise SystemExit(f"roadlogic run failed or printed no stage times:\n{result.stdout}{result.stderr}")
    return wall, stages


# what every `roadlogic run` does before and around its stages whatever it writes: the interpreter,
# the imports of the command line, the pipeline, the planner (clingo, HiGHS) and the simulator
# (frenetix), reading the standard library and the scenario
FIXED_COST = (
    "from pytest_roadlogic import cli, pipeline\n"
    "from pytest_roadlogic.planning.encodings.continuous import linear, planner as continuous\n"
    "import frenetix, pytest_roadlogic.simulation.frenetix.driver\n"
    "pipeline.load_scenario('scenarios/overtake.osc')\n"
)


def fixed_cost() -> float:
    """Wall seconds of a process that does only what every run does besides its stages and artifacts."""
    started = time.perf_counter()
    subprocess.run([sys.executable, "-c", FIXED_COST], check=True, cwd=ROOT)
    return time.perf_counter() - started


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--one", help=argparse.SUPPRESS)  # the measuring child process
    parser.add_argument(
        "--together", choices=("forked", "in-turn"), help=argparse.SUPPRESS
    )  # likewise, write_artifacts whole
    parser.add_argument("paths", nargs="*")
    args = parser.parse_args(argv)
    if args.one and args.together:
        print(json.dumps(measure_together(args.one, args.seed, args.together == "forked")))
        return 0
    if args.one:
        print(json.dumps(measure_one(args.one, args.seed)))
        return 0
    print(f"seed {args.seed}; seconds, each writer's first call in a fresh process (imports included)")
    print(
        f"{'scenario':22} {'cars':>4} {'trace s':>7} {'pipeline':>8} "
        + " ".join(f"{w:>18}" for w in WRITERS)
        + f" {'all':>6} {'gif KB':>6}"
    )
    for path in args.paths or DEFAULT:
        child = subprocess.run(
            [sys.executable, __file__, "--one", path, "--seed", str(args.seed)],
            capture_output=True,
            text=True,
            cwd=ROOT,
        )
        if child.returncode != 0:
            print(f"{path}: failed\n{child.stderr}")
            continue
        row = json.loads(child.stdout.strip().splitlines()[-1])
        writers = row["writers"]
        print(
            f"{row['scenario']:22} {row['vehicles']:>4} {row['trace_s']:>7.1f} {sum(row['stages'].values()):>8.2f} "
            + " ".join(f"{writers[w]:>18.2f}" for w in WRITERS)
            + f" {sum(writers.values()):>6.2f} {row['gif_kb']:>6.0f}"
        )
    print(
        "\nwrite_artifacts whole, as run calls it, in a fresh process: the OpenSCENARIO writer after the others / forked beside them"
    )
    for path in args.paths or DEFAULT:
        seconds = []
        for mode in ("in-turn", "forked"):
            child = subprocess.run(
                [sys.executable, __file__, "--one", path, "--together", mode, "--seed", str(args.seed)],
                capture_output=True,
                text=True,
                cwd=ROOT,
            )
            seconds.append(float(child.stdout.strip().splitlines()[-1]) if child.returncode == 0 else float("nan"))
        print(f"{Path(path).stem:22} {seconds[0]:6.2f} s  {seconds[1]:6.2f} s")
    wall, stages = cli_run(args.seed)
    print(
        f"roadlogic run scenarios/overtake.osc: wall {wall:.2f} s; planning+simulation+monitoring {stages:.2f} s; ratio {wall / stages:.1f}"
    )
    fixed = min(fixed_cost() for _ in range(3))
    print(
        f"a process that only starts, imports and reads the scenario: {fixed:.2f} s (best of 3); with the stages and no artifact "
        f"at all a run's ratio would be {(fixed + stages) / stages:.1f}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
