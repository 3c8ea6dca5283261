"""The concrete scenario as a CommonRoad file: the road, every vehicle's driven trajectory as a
dynamic obstacle, each vehicle's planning problem (standstill start, its final waypoint as goal),
and stationary objects as static obstacles."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from .driver import CAR_LENGTH, CAR_WIDTH
from .simulator import Simulation

FIRST_OBSTACLE_ID = 1000
FIRST_PROBLEM_ID = 2000


def commonroad_scenario(simulation: Simulation):
    from commonroad.common.common_scenario import ScenarioID
    from commonroad.common.util import AngleInterval, Interval
    import shapely
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
    scenario.add_objects(simulation.road.lanelet_network())
    trace = simulation.trace
    shape = RectObstacleShape(width=CAR_WIDTH, length=CAR_LENGTH)
    problems = PlanningProblemSet()
    for index, (vehicle, columns) in enumerate(trace.actors.items()):
        states = [
            CustomState(
                time_step=k,
                position=np.array([columns["x"][k], columns["y"][k]]),
                orientation=float(columns["heading"][k]),
                velocity=float(columns["speed"][k]),
                acceleration=float(columns["acceleration"][k]),
            )
            for k in range(len(trace))
        ]
        initial = InitialState(
            time_step=0, position=states[0].position, orientation=states[0].orientation,
            velocity=0.0, acceleration=0.0, yaw_rate=0.0, slip_angle=0.0,
        )
        if vehicle in simulation.stationary:
            scenario.add_objects(StaticObstacle(FIRST_OBSTACLE_ID + index, ObstacleType.PARKED_VEHICLE, shape, initial))
            continue
        prediction = TrajectoryPrediction(Trajectory(1, states[1:]), shape)
        scenario.add_objects(DynamicObstacle(FIRST_OBSTACLE_ID + index, ObstacleType.CAR, shape, initial, prediction))
        goal = simulation.references[vehicle].waypoints[-1]
        steps = int(round(goal.time / simulation.dt))
        goal_state = CustomState(
            time_step=Interval(max(0, steps - 20), steps + 20),
            position=RectOccupancy(shapely.Point(goal.position, simulation.road.center_y(goal.lane)), simulation.road.lane_width, 8.0, 0.0),
            orientation=AngleInterval(-0.3, 0.3),
        )
        problems.add_planning_problem(PlanningProblem(FIRST_PROBLEM_ID + index, initial, GoalRegion([goal_state])))
    return scenario, problems


def write_commonroad_xml(simulation: Simulation, path: str | Path) -> Path:
    """Write the scenario as CommonRoad XML, atomically (never a half-written file)."""
    from commonroad.common.file_writer import CommonRoadFileWriter, OverwriteExistingFile
    from commonroad.common.util import FileFormat
    from commonroad.scenario.scenario import Tag

    path = Path(path)
    scenario, problems = commonroad_scenario(simulation)
    writer = CommonRoadFileWriter(
        scenario, problems, author="pytest-roadlogic", affiliation="", source="pytest-roadlogic",
        tags={Tag.HIGHWAY, Tag.MULTI_LANE}, file_format=FileFormat.XML,
    )
    temporary = path.parent / f".{path.name}.{os.getpid()}.partial.xml"
    try:
        writer.write_to_file(temporary, OverwriteExistingFile.ALWAYS)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
    return path
