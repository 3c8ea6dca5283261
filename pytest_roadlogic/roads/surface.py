"""The driving surface of a junction: where in the world a car is on the road though outside its
own route's lanes.

A car that turns at a town's corner sweeps wider than its lane (its front corner swings out by
up to a metre round a 4.5 m bend): it is then over the junction's other lanes, on the road, not
off it. ``DrivingSurface`` holds the driving lanes, both ways, of the roads of a junction and of
those meeting it (``Route.junction_roads``); ``contains`` says which world points lie on them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .opendrive_in import DRIVING, MapRoad

SAMPLE = 0.5  # m between the points at which a road's extent across is read


@dataclass(frozen=True)
class _Strip:
    """One road's driving lanes as points along its lane offset line: where (x, y), heading, and
    how far they reach to the left (``left``) and to the right (``right``, negative) of it."""

    x: np.ndarray
    y: np.ndarray
    heading: np.ndarray
    left: np.ndarray
    right: np.ndarray

    def contains(self, px: np.ndarray, py: np.ndarray) -> np.ndarray:
        """Which points (px, py) lie across the strip's nearest point within its reach (and, nearest
        its first or last point, no further than half a sampling step before or past it)."""
        dx = px[:, None] - self.x[None, :]
        dy = py[:, None] - self.y[None, :]
        nearest = np.argmin(dx * dx + dy * dy, axis=1)
        rows = np.arange(len(px))
        c, s = np.cos(self.heading[nearest]), np.sin(self.heading[nearest])
        along = dx[rows, nearest] * c + dy[rows, nearest] * s
        across = -dx[rows, nearest] * s + dy[rows, nearest] * c
        within = ((nearest > 0) | (along >= -SAMPLE / 2)) & ((nearest < len(self.x) - 1) | (along <= SAMPLE / 2))
        return within & (across <= self.left[nearest] + 1e-6) & (across >= self.right[nearest] - 1e-6)


def _reach(road: MapRoad, s: np.ndarray, left: bool) -> np.ndarray:
    """Metres from the lane offset line to the outer edge of the outermost driving lane on one side
    of ``road`` at lengths ``s`` (0 where that side has none)."""
    reach = np.zeros_like(s)
    for section in road.sections:
        inside = (s >= section.s - 1e-9) & (s <= section.end + 1e-9)
        if not inside.any():
            continue
        width, outermost = np.zeros_like(s), np.zeros_like(s)
        for lane in section.left if left else section.right:
            width = width + lane.width(s - section.s)
            if lane.type == DRIVING:
                outermost = width.copy()
        reach = np.where(inside, outermost, reach)
    return reach


def _strip(road: MapRoad) -> _Strip | None:
    s = np.linspace(0.0, road.length, max(2, int(np.ceil(road.length / SAMPLE)) + 1))
    left, right = _reach(road, s, left=True), _reach(road, s, left=False)
    if not (left > 0).any() and not (right > 0).any():
        return None
    x, y, heading = road.reference_line.pose(s, road.offset(s))
    return _Strip(x, y, heading, left, -right)


@dataclass(frozen=True)
class DrivingSurface:
    """The driving lanes of some roads of a map (``of``): ``contains`` is true of a world point on
    any of them."""

    strips: tuple[_Strip, ...]

    @classmethod
    def of(cls, roads: tuple[MapRoad, ...]) -> DrivingSurface:
        return cls(tuple(strip for strip in map(_strip, roads) if strip is not None))

    def contains(self, x, y) -> np.ndarray:
        """Whether each world point (``x``, ``y``: arrays alike) lies on one of the driving lanes."""
        px, py = np.atleast_1d(np.asarray(x, dtype=float)), np.atleast_1d(np.asarray(y, dtype=float))
        inside = np.zeros(len(px), dtype=bool)
        for strip in self.strips:
            inside |= strip.contains(px, py)
            if inside.all():
                break
        return inside
