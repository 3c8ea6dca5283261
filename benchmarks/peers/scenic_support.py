"""What the Scenic programs beside this file share: a driver for Scenic's Newtonian car model (its
throttle, brake and steering) that holds a speed and a lane, and the progress of a scenario's
phases as a monitor sees them.

Scenic's own ``FollowLaneBehavior`` left this straight road at 20-30 m/s and its lane change still
swung 1.3 m 15 s after changing (measured when the peer was first set up), so the programs drive
with this one. The road runs east along x from x = 0; its three lanes are 3.5 m wide with their
centres at y = 1.75 (lane 1, the rightmost), 5.25 and 8.75.
"""

from __future__ import annotations

import math

LANE_WIDTH = 3.5
CAR_LENGTH, CAR_WIDTH = 4.5, 1.8
EAST = -math.pi / 2  # Scenic's heading of a car driving east (headings count from north, leftwards)
MAX_ACCELERATION, MAX_BRAKING = 5.6, 6.8  # the Newtonian simulator's


def lane_y(lane: int) -> float:
    """The centre of lane ``lane`` (1 the rightmost)."""
    return (lane - 0.5) * LANE_WIDTH


def lane_of(y: float) -> int:
    return int(y // LANE_WIDTH) + 1


def controls(x_speed: float, heading: float, y: float, speed: float, target_speed: float, target_y: float):
    """(throttle, brake, steer) that bring the car to ``target_speed`` (m/s, at most 3 m/s^2 up and
    6 m/s^2 down) and to the lateral position ``target_y`` (a lane change takes about 3 s)."""
    wanted = max(-6.0, min(3.0, 1.5 * (target_speed - speed)))
    throttle = max(0.0, wanted) / MAX_ACCELERATION
    brake = max(0.0, -wanted) / MAX_BRAKING
    offset = heading - EAST  # > 0: pointing left of the road's direction
    lateral_speed = max(-1.6, min(1.6, 1.0 * (target_y - y)))  # m/s towards the target
    wanted_offset = math.asin(max(-0.5, min(0.5, lateral_speed / max(speed, 1.0))))
    yaw_rate = 3.0 * (wanted_offset - offset)
    # the model turns at -speed * sin(steer * pi/2) / length rad/s
    sine = -yaw_rate * CAR_LENGTH / max(speed, 1.0)
    steer = 2 / math.pi * math.asin(max(-1.0, min(1.0, sine)))
    return min(throttle, 1.0), min(brake, 1.0), steer


def write_road(path) -> None:
    """The programs' map: a straight road of three lanes, 1,500 m long, as OpenDRIVE."""
    from scenariogeneration import xodr

    marks = xodr.RoadMark(xodr.RoadMarkType.solid, 0.12)
    road = xodr.create_road(
        xodr.Line(1500.0), id=1, left_lanes=0, right_lanes=3, lane_width=LANE_WIDTH, center_road_mark=marks
    )
    road.planview.set_start_point(0.0, 3 * LANE_WIDTH, 0.0)
    opendrive = xodr.OpenDrive("pytest-roadlogic peer benchmark road")
    opendrive.add_road(road)
    opendrive.adjust_roads_and_lanes()
    opendrive.write_xml(str(path))


def collided(a, b) -> bool:
    """Whether two cars driving along the road overlap (their boxes, axis-aligned)."""
    return abs(a.position.x - b.position.x) < CAR_LENGTH and abs(a.position.y - b.position.y) < CAR_WIDTH


class Progress:
    """Which of a scenario's phases a monitor has seen end, in order; ``done`` once all have."""

    def __init__(self, phases: int) -> None:
        self.phases = phases
        self.reset()

    def reset(self) -> None:
        """A program's objects are made once, its monitors start anew with every simulation."""
        self.ended = 0
        self.collision = False

    def advance(self, condition: bool) -> None:
        if condition and self.ended < self.phases:
            self.ended += 1

    @property
    def done(self) -> bool:
        return self.ended >= self.phases and not self.collision
