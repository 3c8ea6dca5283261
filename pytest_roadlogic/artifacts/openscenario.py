"""The concrete scenario as ASAM OpenSCENARIO XML 1.2 with its road as ASAM OpenDRIVE, for the tools
a tester runs next (esmini, CARLA, a vehicle-in-the-loop rig), written with ``scenariogeneration``.

What a replay needs is what the vehicles did, so every driven vehicle follows its *simulated*
trajectory: a ``FollowTrajectoryAction`` over a polyline with one timed vertex per trace sample
(absolute times, following mode ``position``), not the plan's waypoints, which a player would have
to drive by its own controller and so not reproduce the trace. A standing vehicle is teleported to
its place and never moves.

Positions follow OpenSCENARIO's convention: a vehicle's reference point is the centre of its rear
axle, and its bounding box's centre lies ``WHEELBASE / 2`` ahead of it (the trace and the CommonRoad
file give the box's centre). The road is the simulated straight road: an OpenDRIVE road whose
reference line runs along the left road edge (y = road width) in +x, with all lanes on its right
(ids -1 .. -N, right-hand traffic driving in +x), so that world coordinates are the trace's.
"""

from __future__ import annotations

import datetime
import math
from pathlib import Path

from ..roads.opendrive_out import opendrive_xml
from ..simulation.geometry import CAR_LENGTH, CAR_WIDTH, WHEELBASE
from ..simulation.interface import Simulation
from .files import replaced

OPENSCENARIO_MINOR_VERSION = 2  # 1.2: read by esmini and the current XSD-based tools
# the file header's date: fixed, so that one seed writes the same bytes on every run and machine
# (the header's creation time would differ on every replay of a case)
CREATION_DATE = datetime.datetime(2026, 1, 1)
CAR_HEIGHT = 1.5  # m; the box's height, which OpenSCENARIO requires and nothing here uses
ROAD_FILE = "road.xodr"


def road_opendrive(simulation: Simulation):
    """The straight road as a ``scenariogeneration.xodr.OpenDrive``."""
    from scenariogeneration import xodr

    road = simulation.road
    marks = xodr.RoadMark(xodr.RoadMarkType.solid, 0.12)
    opendrive_road = xodr.create_road(
        xodr.Line(road.x_end - road.x_start),
        id=1,
        left_lanes=0,
        right_lanes=road.lanes,
        lane_width=road.lane_width,
        center_road_mark=marks,
    )
    opendrive_road.planview.set_start_point(road.x_start, road.width, 0.0)
    opendrive_road.add_elevation(0.0, 0.0, 0.0, 0.0, 0.0)  # OpenDRIVE requires one in an elevationProfile
    opendrive = xodr.OpenDrive("pytest-roadlogic straight road")
    opendrive.add_road(opendrive_road)
    opendrive.adjust_roads_and_lanes()
    return opendrive


def rear_axle(x: float, y: float, heading: float) -> tuple[float, float]:
    """The reference point of OpenSCENARIO (rear axle centre) of a box centred at (x, y)."""
    return x - math.cos(heading) * WHEELBASE / 2, y - math.sin(heading) * WHEELBASE / 2


def openscenario(simulation: Simulation, name: str = "roadlogic", road_file: str = ROAD_FILE):
    """The concrete scenario as a ``scenariogeneration.xosc.Scenario`` (its road in ``road_file``)."""
    from scenariogeneration import xosc

    trace = simulation.trace
    entities = xosc.Entities()
    init = xosc.Init()
    story = xosc.Story("simulated trajectories")
    end = float(trace.times[-1])
    act_start = xosc.ValueTrigger(
        "at start", 0, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(0, xosc.Rule.greaterOrEqual)
    )
    act = xosc.Act("drive", act_start)
    on_map = trace.on_map
    for vehicle, columns in trace.actors.items():
        if on_map:  # the poses in the map's coordinates
            columns = {
                "x": columns["world_x"],
                "y": columns["world_y"],
                "heading": columns["world_heading"],
                **{k: v for k, v in columns.items() if k in ("speed",)},
            }
        box = xosc.BoundingBox(CAR_WIDTH, CAR_LENGTH, CAR_HEIGHT, WHEELBASE / 2, 0.0, CAR_HEIGHT / 2)
        front = xosc.Axle(0.6, 0.65, 1.6, WHEELBASE, 0.325)
        rear = xosc.Axle(0.0, 0.65, 1.6, 0.0, 0.325)
        entities.add_scenario_object(
            vehicle, xosc.Vehicle(vehicle, xosc.VehicleCategory.car, box, front, rear, 70.0, 10.0, 10.0)
        )
        x0, y0 = rear_axle(float(columns["x"][0]), float(columns["y"][0]), float(columns["heading"][0]))
        init.add_init_action(
            vehicle, xosc.TeleportAction(xosc.WorldPosition(x0, y0, 0.0, float(columns["heading"][0])))
        )
        init.add_init_action(
            vehicle,
            xosc.AbsoluteSpeedAction(
                float(columns["speed"][0]),
                xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0),
            ),
        )
        if vehicle in simulation.stationary:
            continue
        positions = [
            xosc.WorldPosition(*rear_axle(float(x), float(y), float(h)), 0.0, float(h))
            for x, y, h in zip(columns["x"], columns["y"], columns["heading"])
        ]
        trajectory = xosc.Trajectory(f"{vehicle} simulated", False)
        trajectory.add_shape(xosc.Polyline([float(t) for t in trace.times], positions))
        follow = xosc.FollowTrajectoryAction(
            trajectory, xosc.FollowingMode.position, xosc.ReferenceContext.absolute, 1, 0
        )
        event = xosc.Event(f"{vehicle} follows", xosc.Priority.override)
        event.add_action(f"{vehicle} trajectory", follow)
        event.add_trigger(
            xosc.ValueTrigger(
                f"{vehicle} starts",
                0,
                xosc.ConditionEdge.none,
                xosc.SimulationTimeCondition(0, xosc.Rule.greaterOrEqual),
            )
        )
        maneuver = xosc.Maneuver(f"{vehicle} maneuver")
        maneuver.add_event(event)
        group = xosc.ManeuverGroup(f"{vehicle} group")
        group.add_actor(vehicle)
        group.add_maneuver(maneuver)
        act.add_maneuver_group(group)
    story.add_act(act)
    stop = xosc.ValueTrigger(
        "trace ends", 0, xosc.ConditionEdge.rising, xosc.SimulationTimeCondition(end, xosc.Rule.greaterThan), "stop"
    )
    storyboard = xosc.StoryBoard(init, stop)
    storyboard.add_story(story)
    return xosc.Scenario(
        name,
        "pytest-roadlogic",
        xosc.ParameterDeclarations(),
        entities,
        storyboard,
        xosc.RoadNetwork(roadfile=road_file),
        xosc.Catalog(),
        osc_minor_version=OPENSCENARIO_MINOR_VERSION,
        creation_date=CREATION_DATE,
    )


def openscenario_paths(directory: str | Path) -> tuple[Path, Path]:
    """Where ``write_openscenario`` writes the scenario and its road in ``directory``."""
    return Path(directory) / "scenario.xosc", Path(directory) / ROAD_FILE


def write_openscenario(simulation: Simulation, directory: str | Path, name: str = "roadlogic") -> tuple[Path, Path]:
    """Write ``scenario.xosc`` and ``road.xodr`` into ``directory``, each atomically."""
    directory = Path(directory)
    scenario_path, road_path = openscenario_paths(directory)
    with replaced(road_path) as temporary:
        route = simulation.road.route
        # on a map, the map itself, as it was read
        opendrive = route.opendrive if route is not None else opendrive_xml(road_opendrive(simulation))
        Path(temporary).write_bytes(opendrive)
    with replaced(scenario_path) as temporary:
        openscenario(simulation, name).write_xml(str(temporary))
    return scenario_path, road_path
