"""A road's reference line (``ReferenceLine``): the plan view's geometries, from s to the world.

Each geometry starts at a length ``s`` along the line, a point and a heading, and runs ``length``
metres: a straight line, an arc of constant curvature, a spiral (clothoid: curvature changing
linearly from ``curvature_start`` to ``curvature_end``), a cubic in local coordinates (poly3: v as
a cubic of u) or a parametric cubic (paramPoly3: u and v each a cubic of p, p running over the
length or over 0..1). The line and the arc are evaluated in closed form, the others by integrating
their heading along s in steps of at most ``STEP`` metres (a clothoid's integral has no closed
form; the error of the integration is far below a lane's centimetre at these steps).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

STEP = 0.25  # m, of the numerical integration of the curved geometries


@dataclass(frozen=True)
class Geometry:
    """One plan-view record: ``kind`` one of line, arc, spiral, poly3, param_poly3, and its
    coefficients (``curvature``; ``curvature_start``, ``curvature_end``; ``a``..``d`` of poly3;
    ``u``, ``v`` (four each) and ``normalized`` of param_poly3)."""

    s: float
    x: float
    y: float
    heading: float
    length: float
    kind: str
    curvature: float = 0.0
    curvature_start: float = 0.0
    curvature_end: float = 0.0
    poly: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    u: tuple[float, float, float, float] = (0.0, 1.0, 0.0, 0.0)
    v: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    normalized: bool = True

    def sample(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """x, y, heading and curvature at the distances ``ds`` (0..length) from its start."""
        if self.kind == "line":
            zeros = np.zeros_like(ds)
            return (
                self.x + ds * math.cos(self.heading),
                self.y + ds * math.sin(self.heading),
                zeros + self.heading,
                zeros,
            )
        if self.kind == "arc" and self.curvature != 0.0:
            k = self.curvature
            heading = self.heading + k * ds
            return (
                self.x + (np.sin(heading) - math.sin(self.heading)) / k,
                self.y - (np.cos(heading) - math.cos(self.heading)) / k,
                heading,
                np.zeros_like(ds) + k,
            )
        if self.kind == "arc":
            return dataclasses.replace(self, kind="line").sample(ds)
        return self._integrated(ds)

    def _integrated(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The curved geometries: heading and curvature as functions of s, position integrated."""
        n = max(2, int(math.ceil(self.length / STEP)) + 1)
        grid = np.linspace(0.0, self.length, n)
        if self.kind == "spiral":
            rate = (self.curvature_end - self.curvature_start) / self.length if self.length else 0.0
            heading = self.heading + self.curvature_start * grid + rate * grid**2 / 2
            curvature = self.curvature_start + rate * grid
        else:
            heading, curvature = self._polynomial(grid)
        # trapezoidal integration of the unit heading vector
        cos_h, sin_h = np.cos(heading), np.sin(heading)
        steps = np.diff(grid)
        x = self.x + np.concatenate([[0.0], np.cumsum(steps * (cos_h[1:] + cos_h[:-1]) / 2)])
        y = self.y + np.concatenate([[0.0], np.cumsum(steps * (sin_h[1:] + sin_h[:-1]) / 2)])
        return (
            np.interp(ds, grid, x),
            np.interp(ds, grid, y),
            np.interp(ds, grid, np.unwrap(heading)),
            np.interp(ds, grid, curvature),
        )

    def _polynomial(self, grid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Heading and curvature along a poly3 or paramPoly3, at arc lengths ``grid``: the curve is
        sampled densely in its parameter, its arc length measured, and read at ``grid``."""
        p = np.linspace(0.0, 1.0 if (self.kind == "param_poly3" and self.normalized) else self.length, 4 * len(grid))
        if self.kind == "poly3":
            a, b, c, d = self.poly
            u, du, ddu = p, np.ones_like(p), np.zeros_like(p)
            v, dv, ddv = a + b * p + c * p**2 + d * p**3, b + 2 * c * p + 3 * d * p**2, 2 * c + 6 * d * p
        else:
            (au, bu, cu, du_), (av, bv, cv, dv_) = self.u, self.v
            u, du, ddu = au + bu * p + cu * p**2 + du_ * p**3, bu + 2 * cu * p + 3 * du_ * p**2, 2 * cu + 6 * du_ * p
            v, dv, ddv = av + bv * p + cv * p**2 + dv_ * p**3, bv + 2 * cv * p + 3 * dv_ * p**2, 2 * cv + 6 * dv_ * p
        arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(u), np.diff(v)))])
        scale = self.length / arc[-1] if arc[-1] > 0 else 1.0
        local_heading = np.unwrap(np.arctan2(dv, du))
        speed = np.hypot(du, dv)
        curvature = (du * ddv - dv * ddu) / np.maximum(speed**3, 1e-12)
        return (
            self.heading + np.interp(grid, arc * scale, local_heading),
            np.interp(grid, arc * scale, curvature),
        )


@dataclass(frozen=True)
class ReferenceLine:
    """A road's reference line: its geometries in order of s, sampled every ``step`` metres.
    ``against``: the line read from its end (s from there, heading turned round, left and right
    exchanged), as a road driven against its reference line has it."""

    geometries: tuple[Geometry, ...]
    step: float = 0.5
    samples: dict = field(default_factory=dict, compare=False, repr=False)
    against: bool = False

    def reversed(self) -> ReferenceLine:
        """The same line read from its other end."""
        return dataclasses.replace(self, against=not self.against, samples={})

    @property
    def length(self) -> float:
        last = self.geometries[-1]
        return last.s + last.length

    def sampled(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """s, x, y, heading (unwrapped) and curvature every ``step`` metres, both ends included."""
        if not self.samples:
            parts = []
            for geometry in self.geometries:
                n = max(2, int(math.ceil(geometry.length / self.step)) + 1)
                ds = np.linspace(0.0, geometry.length, n)
                x, y, heading, curvature = geometry.sample(ds)
                parts.append((geometry.s + ds, x, y, heading, curvature))
            s, x, y, heading, curvature = (np.concatenate([p[i] for p in parts]) for i in range(5))
            keep = np.concatenate([[True], np.diff(s) > 1e-9])  # each geometry's start is its predecessor's end
            s, x, y, heading, curvature = s[keep], x[keep], y[keep], heading[keep], curvature[keep]
            if self.against:
                s = (s[-1] - s)[::-1]
                x, y, heading, curvature = x[::-1], y[::-1], heading[::-1] + math.pi, -curvature[::-1]
            self.samples["all"] = (s, x, y, np.unwrap(heading), curvature)
        return self.samples["all"]

    def pose(self, s, t=0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """World x, y and heading of the points ``t`` metres left of the line at lengths ``s``;
        before its start and past its end the line runs on straight (as the simulation's road)."""
        line_s, x, y, heading, _ = self.sampled()
        s = np.asarray(s, dtype=float)
        inside = np.clip(s, line_s[0], line_s[-1])
        h = np.interp(inside, line_s, heading)
        beyond = s - inside
        px = np.interp(inside, line_s, x) + np.cos(h) * beyond
        py = np.interp(inside, line_s, y) + np.sin(h) * beyond
        return px - np.sin(h) * t, py + np.cos(h) * t, h

    def curvature(self, s) -> np.ndarray:
        line_s, _, _, _, curvature = self.sampled()
        return np.interp(s, line_s, curvature)

    def sharpest(self, start: float = 0.0, end: float | None = None) -> float:
        """The greatest curvature (1/m, either side) between ``start`` and ``end`` metres along it."""
        s, _, _, _, curvature = self.sampled()
        inside = (s >= start) & (s <= (self.length if end is None else end))
        return float(np.abs(curvature[inside]).max()) if inside.any() else 0.0


JOINED = 1e-3  # m between a line's end and the next one's start within which they are one point
STEP_APART = 1e-6  # m along a joined line between the two points of a step sideways


@dataclass(frozen=True)
class JoinedLine(ReferenceLine):
    """Reference lines one after another (a route over several roads: each road's line as the
    route drives it, the next starting where the last ends), read as one line: s runs on over
    them."""

    parts: tuple[ReferenceLine, ...] = ()

    @property
    def length(self) -> float:
        return sum(part.length for part in self.parts)

    def reversed(self) -> ReferenceLine:
        return JoinedLine((), self.step, {}, False, tuple(part.reversed() for part in reversed(self.parts)))

    def sampled(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        if not self.samples:
            parts, start = [], 0.0
            for k, part in enumerate(self.parts):
                s, x, y, heading, curvature = part.sampled()
                s = s - s[0] + start
                if k and math.hypot(x[0] - parts[-1][1][-1], y[0] - parts[-1][2][-1]) <= JOINED:
                    keep = slice(1, None)  # a part's start is its predecessor's end
                else:
                    # the first line, or one that starts beside its predecessor's end (two roads whose
                    # lanes continue one another with lane offsets of their own): the line steps
                    # sideways in the micrometre before the joint, where it is the next road's, as
                    # the lane offsets and sections of a route are
                    keep = slice(None)
                    if k:
                        parts[-1][0][-1] -= STEP_APART
                parts.append((s[keep], x[keep], y[keep], heading[keep], curvature[keep]))
                start += part.length
            s, x, y, heading, curvature = (np.concatenate([p[i] for p in parts]) for i in range(5))
            self.samples["all"] = (s, x, y, np.unwrap(heading), curvature)
        return self.samples["all"]
