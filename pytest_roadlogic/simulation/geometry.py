"""The vehicles' shape: one box for every car, shared by the simulation, the monitor's incidents,
the plots, the exports and the occupancy grid, so that they all mean the same car.

Positions are of the box's centre; ``corners`` and ``boxes_overlap`` read any object with ``x``,
``y`` and ``heading`` (a ``VehicleState``).
"""

from __future__ import annotations

import numpy as np

from ..dimensions import CAR_LENGTH, CAR_WIDTH

__all__ = ["CAR_LENGTH", "CAR_WIDTH", "WHEELBASE", "boxes_overlap", "corners"]
WHEELBASE = 2.7  # m, for the kinematic checks of motion planners


def boxes_overlap(a, b, margin: float = 0.0) -> bool:
    """Separating-axis test of two oriented vehicle rectangles."""
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
    """The box's four corners in road coordinates, grown by ``margin`` on every side."""
    half_l, half_w = CAR_LENGTH / 2 + margin, CAR_WIDTH / 2 + margin
    c, s = np.cos(state.heading), np.sin(state.heading)
    local = np.array([[half_l, half_w], [-half_l, half_w], [-half_l, -half_w], [half_l, -half_w]])
    return local @ np.array([[c, s], [-s, c]]) + np.array([state.x, state.y])
