"""The road: one straight highway, all lanes in one direction along +x.

Lane 0 is the leftmost (largest y), lane ``lanes - 1`` the rightmost; the right road edge is y = 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..logic.dimensions import LANE_WIDTH


@dataclass(frozen=True)
class Road:
    lanes: int = 3
    x_start: float = -200.0
    x_end: float = 400.0
    lane_width: float = LANE_WIDTH

    @property
    def width(self) -> float:
        return self.lanes * self.lane_width

    def center_y(self, lane: int) -> float:
        return (self.lanes - 1 - lane) * self.lane_width + self.lane_width / 2

    def lane_at(self, y: float) -> int:
        """The lane containing lateral position y (clamped to the road)."""
        index = self.lanes - 1 - math.floor(y / self.lane_width)
        return min(self.lanes - 1, max(0, index))

    def on_road(self, corners: np.ndarray) -> bool:
        ys = corners[:, 1]
        return bool(ys.min() >= -0.05 and ys.max() <= self.width + 0.05)

    def lanelet_network(self):
        """The road as a CommonRoad lanelet network: one lanelet per lane, adjacent same-direction."""
        from commonroad.scenario.lanelet import Lanelet, LaneletNetwork, LaneletType, LineMarking

        network = LaneletNetwork()
        xs = np.linspace(self.x_start, self.x_end, 2)
        for lane in range(self.lanes):
            top = (self.lanes - lane) * self.lane_width
            bottom = top - self.lane_width
            left = np.stack([xs, np.full_like(xs, top)], axis=1)
            right = np.stack([xs, np.full_like(xs, bottom)], axis=1)
            center = (left + right) / 2
            network.add_lanelet(
                Lanelet(
                    left_vertices=left,
                    center_vertices=center,
                    right_vertices=right,
                    lanelet_id=self.lanelet_id(lane),
                    adjacent_left=self.lanelet_id(lane - 1) if lane > 0 else None,
                    adjacent_left_same_direction=True if lane > 0 else None,
                    adjacent_right=self.lanelet_id(lane + 1) if lane < self.lanes - 1 else None,
                    adjacent_right_same_direction=True if lane < self.lanes - 1 else None,
                    line_marking_left_vertices=LineMarking.SOLID if lane == 0 else LineMarking.DASHED,
                    line_marking_right_vertices=LineMarking.SOLID if lane == self.lanes - 1 else LineMarking.DASHED,
                    lanelet_type={LaneletType.HIGHWAY},
                )
            )
        return network

    @staticmethod
    def lanelet_id(lane: int) -> int:
        return 100 + lane
