"""The concrete scenario as a CommonRoad file: the road, every vehicle's driven trajectory as a
dynamic obstacle, the planning problems the vehicles were driven through, and stationary objects as
static obstacles.

A CommonRoad goal region is reached by reaching *any* of its states, so a sequence of waypoints
cannot be one problem's goal. Each waypoint is its own planning problem instead, chained: the
first starts from standstill, each later one from the planned state at the previous waypoint, and
its goal is the waypoint's region (a cell of the lane, ``reach`` metres either way) in its time
window. Problem ids are ``2000 + 100 * vehicle index + waypoint index``."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..roads.road import Road
from ..simulation.geometry import CAR_LENGTH, CAR_WIDTH
from ..simulation.interface import Simulation
from .files import replaced

FIRST_OBSTACLE_ID = 1000
FIRST_PROBLEM_ID = 2000


def commonroad_scenario(simulation: Simulation):
    import shapely
    from commonroad.common.common_scenario import ScenarioID
    from commonroad.common.util import AngleInterval, Interval
    from commonroad.geometry.obstacle_shapes.rect_obstacle_shape import RectObstacleShape
    from commonroad.geometry.occupancy.rect_occupancy import RectOccupancy
    from commonroad.planning.goal import GoalRegion
    from commonroad.planning.planning_problem import PlanningProblem, PlanningProblemSet
    from commonroad.prediction.prediction import TrajectoryPrediction
    from commonroad.scenario.obstacle import DynamicObstacle, ObstacleType, StaticObstacle
    from commonroad.scenario.scenario import Scenario
    from commonroad.scenario.state import CustomState, InitialState
    from commonroad.scenario.trajectory import Trajectory

    scenario = Scenario(dt=simulation.dt, scenario_id=ScenarioID(country_id="ZAM", map_name="RoadLogic", map_id=1))
    scenario.add_objects(lanelet_network(simulation.road))
    trace = simulation.trace
    shape = RectObstacleShape(width=CAR_WIDTH, length=CAR_LENGTH)
    problems = PlanningProblemSet()
    dt = simulation.dt
    x, y, heading = ("world_x", "world_y", "world_heading") if trace.on_map else ("x", "y", "heading")
    for index, (vehicle, columns) in enumerate(trace.actors.items()):
        states = [
            CustomState(
                time_step=k,
                position=np.array([columns[x][k], columns[y][k]]),
                orientation=float(columns[heading][k]),
                velocity=float(columns["speed"][k]),
                acceleration=float(columns["acceleration"][k]),
            )
            for k in range(len(trace))
        ]
        initial = InitialState(
            time_step=0,
            position=states[0].position,
            orientation=states[0].orientation,
            velocity=0.0,
            acceleration=0.0,
            yaw_rate=0.0,
            slip_angle=0.0,
        )
        if vehicle in simulation.stationary:
            scenario.add_objects(StaticObstacle(FIRST_OBSTACLE_ID + index, ObstacleType.PARKED_VEHICLE, shape, initial))
            continue
        prediction = TrajectoryPrediction(Trajectory(1, states[1:]), shape)
        scenario.add_objects(DynamicObstacle(FIRST_OBSTACLE_ID + index, ObstacleType.CAR, shape, initial, prediction))
        start = initial
        road = simulation.road_of(vehicle)
        for k, goal in enumerate(simulation.references[vehicle].waypoints):
            # on a map, in its coordinates, turned as the route is there (on the straight road: unchanged)
            gx, gy, along = (float(v) for v in road.world(goal.position, road.center_y(goal.lane)))
            goal_state = CustomState(
                time_step=Interval(max(0, math.ceil(goal.earliest / dt - 1e-9)), math.floor(goal.latest / dt + 1e-9)),
                position=RectOccupancy(shapely.Point(gx, gy), road.lane_width, 2 * goal.reach, along),
                orientation=AngleInterval(along - 0.3, along + 0.3),
            )
            problem_id = FIRST_PROBLEM_ID + 100 * index + k
            problems.add_planning_problem(PlanningProblem(problem_id, start, GoalRegion([goal_state])))
            start = InitialState(
                time_step=int(round(goal.time / dt)),
                position=np.array([gx, gy]),
                orientation=along,
                velocity=goal.speed,
                acceleration=0.0,
                yaw_rate=0.0,
                slip_angle=0.0,
            )
    return scenario, problems


def write_commonroad_xml(simulation: Simulation, path: str | Path) -> Path:
    """Write the scenario as CommonRoad XML, atomically (never a half-written file)."""
    from commonroad.common.file_writer import CommonRoadFileWriter, OverwriteExistingFile
    from commonroad.common.util import FileFormat
    from commonroad.scenario.scenario import Tag

    path = Path(path)
    scenario, problems = commonroad_scenario(simulation)
    writer = CommonRoadFileWriter(
        scenario,
        problems,
        author="pytest-roadlogic",
        affiliation="",
        source="pytest-roadlogic",
        # a list in a fixed order, not a set: the writer writes tags in the order it iterates them,
        # and a set of enums iterates in the order PYTHONHASHSEED gives (scenario.xml would differ
        # between processes)
        tags=sorted((Tag.HIGHWAY, Tag.MULTI_LANE), key=lambda tag: tag.value),
        file_format=FileFormat.XML,
    )
    with replaced(path) as temporary:
        writer.write_to_file(temporary, OverwriteExistingFile.ALWAYS)
    return path


def lanelet_network(road: Road):
    """``road`` as a CommonRoad lanelet network: one lanelet per lane, adjacent same-direction (on a
    map, in its coordinates: each lane's lines every 2 m along the route)."""
    from commonroad.scenario.lanelet import Lanelet, LaneletNetwork, LaneletType, LineMarking

    network = LaneletNetwork()
    if road.route is None:
        xs = np.linspace(road.x_start, road.x_end, 2)
    else:
        xs = np.linspace(road.x_start, road.x_end, max(2, int((road.x_end - road.x_start) / 2.0) + 1))

    def line(y: float) -> np.ndarray:
        wx, wy, _ = road.world(xs, np.full_like(xs, y))
        return np.stack([wx, wy], axis=1)

    for lane in range(road.lanes):
        top = (road.lanes - lane) * road.lane_width
        bottom = top - road.lane_width
        left, right = line(top), line(bottom)
        center = (left + right) / 2
        network.add_lanelet(
            Lanelet(
                left_vertices=left,
                center_vertices=center,
                right_vertices=right,
                lanelet_id=lanelet_id(lane),
                adjacent_left=lanelet_id(lane - 1) if lane > 0 else None,
                adjacent_left_same_direction=True if lane > 0 else None,
                adjacent_right=lanelet_id(lane + 1) if lane < road.lanes - 1 else None,
                adjacent_right_same_direction=True if lane < road.lanes - 1 else None,
                line_marking_left_vertices=LineMarking.SOLID if lane == 0 else LineMarking.DASHED,
                line_marking_right_vertices=LineMarking.SOLID if lane == road.lanes - 1 else LineMarking.DASHED,
                lanelet_type={LaneletType.HIGHWAY},
            )
        )
    return network


def lanelet_id(lane: int) -> int:
    """The id of ``lane``'s lanelet."""
    return 100 + lane
