"""The road a simulation drives on: all lanes in one direction along +x, in road coordinates.

Lane 0 is the leftmost (largest y), lane ``lanes - 1`` the rightmost; the right road edge is y = 0.
On the straight road these are the world's coordinates too. On a map (``route``: a
``roads.Route``) x is the length along the route's reference line less ``route_shift`` (the
route's length at which the plan's position 0 lies) and y the metres left of its lanes' right edge;
``world`` maps them to the map's coordinates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..dimensions import LANE_WIDTH

if TYPE_CHECKING:
    from .route import Route


@dataclass(frozen=True)
class Road:
    lanes: int = 3
    x_start: float = -200.0
    x_end: float = 400.0
    lane_width: float = LANE_WIDTH
    route: Route | None = None  # the map's route it lies along; None: the straight road
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
        """Whether a box's ``corners`` lie between the road's edges (which move where a map's lanes
        begin or end)."""
        ys = corners[:, 1]
        if self.route is None:  # the straight road's edges are y = 0 and its width throughout
            return bool(ys.min() >= -0.05 and ys.max() <= self.width + 0.05)
        xs = corners[:, 0]
        return bool((ys >= self.right_edge(xs) - 0.05).all() and (ys <= self.left_edge(xs) + 0.05).all())

    def on_junction(self, world_corners: np.ndarray) -> bool:
        """Whether a box's corners in the world (``world_corners``) lie on the driving lanes of the
        junction its route turns at, or of the roads meeting it (``Route.junction_surface``): a car
        sweeping wide of its lane round the turn is on the road there. False off any such route."""
        surface = self.route.junction_surface if self.route is not None else None
        return surface is not None and bool(surface.contains(world_corners[:, 0], world_corners[:, 1]).all())

    def right_edge(self, x) -> np.ndarray:
        """``y`` of the right edge of the driving lanes at ``x`` (0 but where a map's lanes begin or end)."""
        if self.route is None:
            return np.zeros_like(np.asarray(x, dtype=float))
        return self.route.right_edge(np.asarray(x, dtype=float) + self.route_shift)

    def left_edge(self, x) -> np.ndarray:
        """``y`` of the left edge of the driving lanes at ``x`` (the road's width but where a map's
        lanes on the left begin or end: a road of 2+1 lanes)."""
        if self.route is None:
            return np.full_like(np.asarray(x, dtype=float), self.width)
        return self.route.left_edge(np.asarray(x, dtype=float) + self.route_shift)

    def world(self, x, y, heading=0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """World x, y and heading of road coordinates (on the straight road, the same). On a map the
        heading is within -pi..pi (a route's own runs on unwrapped: 7.9 rad along a long one, which
        CommonRoad refuses)."""
        if self.route is None:
            x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
            return x, y, np.asarray(heading, dtype=float) + 0.0 * x
        wx, wy, wh = self.route.pose(np.asarray(x, dtype=float) + self.route_shift, y)
        return wx, wy, (wh + heading + np.pi) % (2 * np.pi) - np.pi
