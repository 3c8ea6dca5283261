"""Writing what a run produced to a directory: plan, trace, CommonRoad scenario, plot, verdict.

Every file is written to a temporary name and renamed into place, so an interrupted run never
leaves a half-written artifact behind.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from .animation import animate_simulation
from .pipeline import Outcome
from .plotting import plot_simulation
from .simulation.commonroad_export import write_commonroad_xml


def write_text(path: Path, text: str) -> Path:
    temporary = path.parent / f".{path.name}.{os.getpid()}.partial"
    temporary.write_text(text, encoding="utf-8")
    os.replace(temporary, path)
    return path


def write_artifacts(outcome: Outcome, directory: str | Path, animation: bool = True) -> dict[str, Path]:
    """Every artifact of a run; the GIF (seconds to render) only when ``animation`` is set."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    name = outcome.scenario.name
    verdict = {
        "scenario": name,
        # the planner's own seed: the run's seed for the base strategy, one made of the run's seed
        # and the sample for the refined strategy (pipeline.run_instances)
        "planner_seed": outcome.plan.seed,
        "tries": outcome.tries,
        # when each vehicle reached each of its waypoints (null: missed)
        "goals": {v: [g.reached_at for g in records] for v, records in outcome.simulation.goals.items()},
        "seconds": outcome.seconds,
        **outcome.verdict.to_dict(),
    }
    paths = {
        "plan": write_text(directory / "plan.json", outcome.plan.to_json()),
        "trace": write_text(directory / "trace.csv", outcome.simulation.trace.to_csv()),
        "commonroad": write_commonroad_xml(outcome.simulation, directory / "scenario.xml"),
        "plot": plot_simulation(outcome.simulation, outcome.verdict, directory / "trajectories.png", title=name),
        "verdict": write_text(directory / "verdict.json", json.dumps(verdict, indent=2)),
    }
    if animation:
        paths["animation"] = animate_simulation(outcome.simulation, outcome.verdict, directory / "simulation.gif", title=name)
    return paths
