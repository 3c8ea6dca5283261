"""Writing what a run produced to a directory: plan, trace, the concrete scenario (CommonRoad;
OpenSCENARIO XML with its OpenDRIVE road), plot, animation, verdict."""

from __future__ import annotations

import json
import os
import re
import signal
from collections.abc import Callable
from pathlib import Path

from ..pipeline import SimulatedInstance
from .animation import animate_simulation
from .commonroad import write_commonroad_xml
from .files import write_text
from .openscenario import openscenario_paths, write_openscenario
from .plot import plot_simulation

# every name a run writes into its output folder (run --instances: a folder per instance), and
# what an interrupted write leaves: what `run` may replace there (files.replaced_directory)
ARTIFACT_NAMES = re.compile(
    r"plan\.json|trace\.csv|scenario\.xml|scenario\.xosc|road\.xodr|trajectories\.png|verdict\.json|simulation\.gif|case\.json|instance-\d+|\..*\.partial.*"
)


def write_artifacts(
    outcome: SimulatedInstance,
    directory: str | Path,
    animation: bool = True,
    level: str = "all",
    recorded: dict[str, str] | None = None,
) -> dict[str, Path]:
    """The artifacts of a run at ``level`` (``settings.ARTIFACT_LEVELS``): with ``essential``, the
    plan, the trace and the verdict; with ``all``, every one, the GIF (seconds to render) only when
    ``animation`` is set. ``recorded``: what the case recorded (``evaluation.coverage.recorded_values``),
    written into the verdict."""
    if level == "none":
        return {}
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
        # on a map: which, the road the route runs along (which way, with how many oncoming lanes),
        # and the metres along it of the plan's position 0
        **(
            {
                "map": {
                    "file": str(outcome.simulation.road.route.source),
                    "road": outcome.simulation.road.route.road.id,
                    # driven against its reference line (its left lanes), and how many of the
                    # scenario's lanes (its leftmost) are the other direction's
                    "against_reference_line": outcome.simulation.road.route.road.against,
                    "oncoming_lanes": outcome.simulation.road.route.road.oncoming,
                    "origin_m": round(outcome.simulation.road.route_shift, 3),
                }
            }
            if outcome.simulation.road.route is not None
            else {}
        ),
        # the scenario's record() items, each as the coverage report shows its value
        **({"recorded": recorded} if recorded else {}),
        # did the vehicle under test fail: every oracle's value, failed or not (oracles.DutReport)
        **({"vehicle_under_test": outcome.dut.values()} if outcome.dut is not None else {}),
        # the reactive execution's replans: when, how long each took, whether it found a plan and why
        # not, whether the run so far went through what was seen (else it was the old plan's), whether
        # the vehicle under test was predicted (else planned as any car)
        **(
            {
                "replans": [
                    {
                        "time": round(r.time, 6),
                        "seconds": round(r.seconds, 4),
                        "found": r.plan is not None,
                        "run_seen": r.seen,
                        "predicted": r.predicted,
                        "why": r.why,
                    }
                    for r in outcome.simulation.replans
                ]
            }
            if outcome.simulation.replans
            else {}
        ),
    }

    def essential() -> dict[str, Path]:
        return {
            "plan": write_text(directory / "plan.json", outcome.plan.to_json()),
            "trace": write_text(directory / "trace.csv", outcome.simulation.trace.to_csv()),
            "verdict": write_text(directory / "verdict.json", json.dumps(verdict, indent=2)),
        }

    if level == "essential":
        return essential()
    scenario_xosc, road_xodr = openscenario_paths(directory)
    lanes = outcome.simulation.road.lanes

    def lane_number(index: int) -> int:  # as the scenario's dialect numbers lanes
        return outcome.scenario.registry.lane_number(index, lanes)

    openscenario = beside(lambda: write_openscenario(outcome.simulation, directory, name))
    try:
        paths = {
            **essential(),
            "commonroad": write_commonroad_xml(outcome.simulation, directory / "scenario.xml"),
            "openscenario": scenario_xosc,  # written by the forked process, waited for below
            "opendrive": road_xodr,
            "plot": plot_simulation(
                outcome.simulation,
                outcome.verdict,
                directory / "trajectories.png",
                title=name,
                lane_number=lane_number,
                dut=outcome.dut,
            ),
        }
        if animation:
            paths["animation"] = animate_simulation(
                outcome.simulation, outcome.verdict, directory / "simulation.gif", title=name, lane_number=lane_number
            )
    except BaseException:
        openscenario(cancel=True)
        raise
    openscenario()
    return paths


def in_turn(write: Callable[[], object]) -> Callable[..., None]:
    """``write`` run here and now, with ``beside``'s interface (where there is no fork, or one core)."""
    write()
    return lambda cancel=False: None


def beside(write: Callable[[], object]) -> Callable[..., None]:
    """``write`` run in a forked process while this one writes the rest; returns a function that
    waits for it and raises its error (or, with ``cancel``, stops it).

    Why: the OpenSCENARIO writer's first call is mostly the import of ``scenariogeneration`` (0.8 s
    on a slow machine, 0.5 s of it scipy.integrate, which its OpenDRIVE geometry imports), and the
    plot's is matplotlib's; on two cores the two overlap (docs/decisions.md).
    The child writes its files through ``files.replaced`` like every writer and returns nothing but
    its exit status and, when it fails, the error's text. Without fork (or on one core) it runs here.
    """
    if not hasattr(os, "fork") or (os.cpu_count() or 1) < 2:
        return in_turn(write)
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: write, report a failure on the pipe, and leave without running any
        os.close(read_end)  # of the parent's exit handlers or flushing its buffers twice
        code = 0
        try:
            write()
        except BaseException as error:  # noqa: BLE001 (reported to the parent, which raises it)
            os.write(write_end, f"{type(error).__name__}: {error}".encode()[:4000])
            code = 1
        finally:
            os._exit(code)
    os.close(write_end)

    def wait(cancel: bool = False):
        if cancel:
            os.kill(pid, signal.SIGKILL)
        with os.fdopen(read_end, "rb") as pipe:
            message = pipe.read().decode(errors="replace")
        _, status = os.waitpid(pid, 0)
        if cancel:
            return None
        if os.waitstatus_to_exitcode(status) != 0:
            raise OSError(
                message or f"the OpenSCENARIO writer's process ended with status {os.waitstatus_to_exitcode(status)}"
            )

    return wait
