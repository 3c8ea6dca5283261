"""The road: all lanes in one direction along +x, in road coordinates.

Lane 0 is the leftmost (largest y), lane ``lanes - 1`` the rightmost; the right road edge is y = 0.
On the straight road these are the world's coordinates too. On a map (``route``: a
``roads.Route``) x is the length along the route's reference line less ``route_shift`` (the
route's length at which the plan's position 0 lies) and y the metres left of its lanes' right edge;
``world`` maps them to the map's coordinates.
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
    route: object = None  # roads.Route, None: the straight road
    route_shift: float = 0.0  # m along the route of x = 0

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
        """Whether a box's ``corners`` lie between the road's edges (the right one moves where a
        map's lanes begin or end)."""
        ys = corners[:, 1]
        return bool((ys >= self.right_edge(corners[:, 0]) - 0.05).all() and ys.max() <= self.width + 0.05)

    def right_edge(self, x) -> np.ndarray:
        """``y`` of the right edge of the driving lanes at ``x`` (0 but where a map's lanes begin or end)."""
        if self.route is None:
            return np.zeros_like(np.asarray(x, dtype=float))
        return self.route.right_edge(np.asarray(x, dtype=float) + self.route_shift)

    def world(self, x, y, heading=0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """World x, y and heading of road coordinates (on the straight road, the same)."""
        if self.route is None:
            x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
            return x, y, np.asarray(heading, dtype=float) + 0.0 * x
        wx, wy, wh = self.route.pose(np.asarray(x, dtype=float) + self.route_shift, y)
        return wx, wy, wh + heading

    def lanelet_network(self):
        """The road as a CommonRoad lanelet network: one lanelet per lane, adjacent same-direction
        (on a map, in its coordinates: each lane's lines every 2 m along the route)."""
        from commonroad.scenario.lanelet import Lanelet, LaneletNetwork, LaneletType, LineMarking

        network = LaneletNetwork()
        if self.route is None:
            xs = np.linspace(self.x_start, self.x_end, 2)
        else:
            xs = np.linspace(self.x_start, self.x_end, max(2, int((self.x_end - self.x_start) / 2.0) + 1))

        def line(y: float) -> np.ndarray:
            wx, wy, _ = self.world(xs, np.full_like(xs, y))
            return np.stack([wx, wy], axis=1)

        for lane in range(self.lanes):
            top = (self.lanes - lane) * self.lane_width
            bottom = top - self.lane_width
            left, right = line(top), line(bottom)
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
