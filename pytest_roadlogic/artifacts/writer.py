"""Writing what a run produced to a directory: plan, trace, the concrete scenario (CommonRoad;
OpenSCENARIO XML with its OpenDRIVE road), plot, animation, verdict."""

from __future__ import annotations

import json
import re
from pathlib import Path

from ..pipeline import Outcome
from .animation import animate_simulation
from .commonroad import write_commonroad_xml
from .files import write_text
from .openscenario import write_openscenario

# every name a run writes into its output folder (run --instances: a folder per instance), and
# what an interrupted write leaves: what `run` may replace there (files.replaced_directory)
ARTIFACT_NAMES = re.compile(r"plan\.json|trace\.csv|scenario\.xml|scenario\.xosc|road\.xodr|trajectories\.png|verdict\.json|simulation\.gif|case\.json|instance-\d+|\..*\.partial.*")
from .plot import plot_simulation


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
        **dict(zip(("openscenario", "opendrive"), write_openscenario(outcome.simulation, directory, name))),
        "plot": plot_simulation(outcome.simulation, outcome.verdict, directory / "trajectories.png", title=name),
        "verdict": write_text(directory / "verdict.json", json.dumps(verdict, indent=2)),
    }
    if animation:
        paths["animation"] = animate_simulation(outcome.simulation, outcome.verdict, directory / "simulation.gif", title=name)
    return paths
