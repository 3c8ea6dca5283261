"""The vehicles' shape: one box for every car, shared by the simulation, the monitor's incidents,
the plots, the exports and the occupancy grid, so that they all mean the same car.

Positions are of the box's centre; ``corners`` and ``boxes_overlap`` read any object with ``x``,
``y`` and ``heading`` (a ``VehicleState``).
"""

from __future__ import annotations

import math

import numpy as np

from ..dimensions import CAR_LENGTH, CAR_WIDTH

__all__ = ["CAR_LENGTH", "CAR_WIDTH", "MAX_STEER", "WHEELBASE", "boxes_overlap", "corners"]
WHEELBASE = 2.7  # m, for the kinematic checks of motion planners
# rad: a car's front wheels at full lock (40 degrees: a 3.2 m radius at the rear axle at this
# wheelbase, a turning circle of about 10 m, a compact car's). A town's corner drawn for such a
# car (CARLA's Town04: 4.5 m at the lane's centre) needs 0.56 rad; a car steering at most that
# could not correct the least drift there
MAX_STEER = 0.7


def boxes_overlap(a, b, margin: float = 0.0) -> bool:
    """Separating-axis test of two oriented vehicle rectangles (two boxes further apart than
    their circumscribed circles' radii together are apart without it)."""
    reach = 2 * math.hypot(CAR_LENGTH / 2 + margin, CAR_WIDTH / 2 + margin)
    if (a.x - b.x) ** 2 + (a.y - b.y) ** 2 > reach * reach:
        return False
    ca, cb = corners(a, margin), corners(b, margin)
    for box in (ca, cb):
        for i in range(2):
            edge = box[i + 1] - box[i]
            axis = np.array([-edge[1], edge[0]])
            pa, pb = ca @ axis, cb @ axis
            if pa.max() < pb.min() or pb.max() < pa.min():
                return False
    return True


def corners(state, margin: float = 0.0) -> np.ndarray:
    """The box's four corners in road coordinates, grown by ``margin`` on every side: front left,
    rear left, rear right, front right."""
    half_l, half_w = CAR_LENGTH / 2 + margin, CAR_WIDTH / 2 + margin
    c, s = math.cos(state.heading), math.sin(state.heading)
    along_x, along_y, across_x, across_y = half_l * c, half_l * s, -half_w * s, half_w * c
    x, y = state.x, state.y
    return np.array(
        [
            [x + along_x + across_x, y + along_y + across_y],
            [x - along_x + across_x, y - along_y + across_y],
            [x - along_x - across_x, y - along_y - across_y],
            [x + along_x - across_x, y + along_y - across_y],
        ]
    )
