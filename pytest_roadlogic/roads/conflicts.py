"""Where two routes of one map meet (``conflicts``): the stretches of each on which a car of one
could touch a car of the other, as the planner orders vehicles through them.

Two cars touch when their boxes (``dimensions.CAR_LENGTH`` by ``CAR_WIDTH``, grown by ``MARGIN``
on every side) overlap, each centred on one of its route's driving lanes and headed along it. A
meeting is one stretch of each route where that can happen, of one of two kinds:

- a **crossing** (two turns through a junction that cross, a turn across the oncoming lane): cars
  are in it only while they pass; the planner lets one pass before the other enters;
- a **shared** stretch (two routes that join in one lane, or leave one lane): the routes run
  together, a metre of one being a metre of the other (``offset``: the first route's metres less
  the second's at one place); the planner keeps one ahead of the other in it by a gap.

Routes that only run side by side in lanes of their own (a road's two directions) never meet.

Routes that meet are laid onto each other where they meet (``alignments``): a metre of one where
the meeting begins is the same position as that of the other, so that a position relating cars of
two routes says how much nearer to the meeting one is than the other.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from ..dimensions import CAR_LENGTH, CAR_WIDTH
from .route import Route

MARGIN = 0.5  # m around each car: closer than this, two cars are in each other's way
STEP = 0.5  # m along a route at which its lanes' centres are sampled
SPLIT = 2.0  # m: samples further apart along a route than this belong to two meetings
ALIGNED = np.radians(30.0)  # headings closer than this run together (a shared stretch)
SHARED_LENGTH = 10.0  # m: a meeting of aligned lanes at least this long is a shared stretch


@dataclass(frozen=True)
class Meeting:
    """Routes ``first`` and ``second`` (their indices in the scenario's routes) meet over
    ``first_span`` metres along the first and ``second_span`` along the second; ``kind`` is
    "crossing" or "shared"; on a shared stretch ``offset`` is the first route's metres less the
    second's at one place (0 for a crossing)."""

    first: int
    second: int
    first_span: tuple[float, float]
    second_span: tuple[float, float]
    kind: str
    offset: float = 0.0

    def describe(self) -> str:
        what = "cross" if self.kind == "crossing" else "share a lane"
        return (
            f"routes {self.first + 1} and {self.second + 1} {what} from {self.first_span[0]:.0f} to "
            f"{self.first_span[1]:.0f} m along route {self.first + 1}"
        )


def lane_centres(route: Route) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Every driving lane's centre of ``route`` sampled every ``STEP`` metres: (metres along the
    route, world x, world y, heading), all lanes' samples one after the other."""
    s = np.arange(0.0, route.length + STEP / 2, STEP)
    along, xs, ys, headings = [], [], [], []
    for lane in range(route.lanes):
        x, y, heading = route.pose(s, np.full_like(s, route.width - (lane + 0.5) * route.lane_width))
        along.append(s), xs.append(x), ys.append(y), headings.append(heading)
    return np.concatenate(along), np.concatenate(xs), np.concatenate(ys), np.concatenate(headings)


def boxes_touch(x1, y1, h1, x2, y2, h2, margin: float = MARGIN) -> np.ndarray:
    """Whether car boxes centred at (x1, y1) headed h1 and at (x2, y2) headed h2 (arrays of one
    shape) overlap, each grown by ``margin``: the separating-axis test, elementwise."""
    half = np.array([CAR_LENGTH / 2 + margin, CAR_WIDTH / 2 + margin])
    centre = np.stack([x2 - x1, y2 - y1], axis=-1)
    axes1 = np.stack([np.stack([np.cos(h1), np.sin(h1)], -1), np.stack([-np.sin(h1), np.cos(h1)], -1)], -2)
    axes2 = np.stack([np.stack([np.cos(h2), np.sin(h2)], -1), np.stack([-np.sin(h2), np.cos(h2)], -1)], -2)
    touching = np.ones(np.shape(x1), dtype=bool)
    for axes in (axes1, axes2):
        for k in range(2):
            axis = axes[..., k, :]
            reach = (
                half[0] * np.abs(np.sum(axes1[..., 0, :] * axis, -1))
                + half[1] * np.abs(np.sum(axes1[..., 1, :] * axis, -1))
                + half[0] * np.abs(np.sum(axes2[..., 0, :] * axis, -1))
                + half[1] * np.abs(np.sum(axes2[..., 1, :] * axis, -1))
            )
            touching &= np.abs(np.sum(centre * axis, -1)) <= reach
    return touching


def touching_pairs(a, b, margin: float = MARGIN) -> tuple[np.ndarray, np.ndarray]:
    """The index pairs (i, j), in order of i then j, of car poses ``a`` and ``b`` (each a tuple of
    world x, y and heading arrays) whose boxes, grown by ``margin``, overlap: the pairs whose
    centres are near enough (a KD-tree), then the separating-axis test (``boxes_touch``)."""
    (xa, ya, ha), (xb, yb, hb) = a, b
    # two boxes overlap only if their centres are within the sum of their half-diagonals
    reach = float(np.hypot(CAR_LENGTH + 2 * margin, CAR_WIDTH + 2 * margin))
    near = cKDTree(np.stack([xb, yb], -1)).query_ball_point(np.stack([xa, ya], -1), reach, return_sorted=True)
    i = np.repeat(np.arange(len(xa)), [len(n) for n in near])
    if not len(i):
        return i, i
    j = np.concatenate([np.asarray(n, dtype=int) for n in near])
    touching = boxes_touch(xa[i], ya[i], ha[i], xb[j], yb[j], hb[j], margin)
    return i[touching], j[touching]


def _runs(values: np.ndarray) -> list[np.ndarray]:
    """Indices of ``values`` grouped into runs whose sorted values lie within ``SPLIT`` of each other."""
    order = np.argsort(values, kind="stable")
    breaks = np.flatnonzero(np.diff(values[order]) > SPLIT) + 1
    return np.split(order, breaks)


def meetings_of(first: int, a: Route, second: int, b: Route) -> list[Meeting]:
    """Where routes ``a`` (index ``first``) and ``b`` (index ``second``) meet, in order along ``a``."""
    sa, xa, ya, ha = lane_centres(a)
    sb, xb, yb, hb = lane_centres(b)
    i, j = touching_pairs((xa, ya, ha), (xb, yb, hb))
    found: list[Meeting] = []
    if not len(i):
        return found
    for run in _runs(sa[i]):
        for part in _runs(sb[j[run]]):
            ia, jb = i[run][part], j[run][part]
            turn = np.abs((ha[ia] - hb[jb] + np.pi) % (2 * np.pi) - np.pi)
            span_a = (float(sa[ia].min()), float(sa[ia].max()))
            span_b = (float(sb[jb].min()), float(sb[jb].max()))
            aligned = turn < ALIGNED
            if aligned.mean() > 0.5 and span_a[1] - span_a[0] >= SHARED_LENGTH:
                # the places where the two lanes' centres coincide say how the metres correspond
                gap = np.hypot(xa[ia] - xb[jb], ya[ia] - yb[jb])
                closest = gap <= gap.min() + 0.5
                offset = float(np.median(sa[ia][closest] - sb[jb][closest]))
                found.append(Meeting(first, second, span_a, span_b, "shared", offset))
            else:
                found.append(Meeting(first, second, span_a, span_b, "crossing"))
    return sorted(found, key=lambda m: m.first_span)


@functools.lru_cache(maxsize=32)
def conflicts(routes: tuple[Route, ...]) -> tuple[Meeting, ...]:
    """Every meeting of every two of ``routes`` (one map's), by route pair then along the first.
    Kept for the routes last asked about: the planner's settings ask again for every sample of a
    scenario (5 ms for two turns, against 7 us to look them up)."""
    return tuple(
        meeting
        for first in range(len(routes))
        for second in range(first + 1, len(routes))
        for meeting in meetings_of(first, routes[first], second, routes[second])
    )


@dataclass(frozen=True)
class Alignment:
    """Route ``route``'s positions laid onto route ``onto``'s at ``meeting``: a plan's positions on
    the two are one when the routes' origins (the metres along each of position 0) differ by
    ``offset``, route's less onto's. At a crossing the two ways' starts of the meeting are then the
    same position, so a position relating cars of the two is their difference in distance to it;
    on a shared lane the routes' metres are one along it (the meeting's ``offset``)."""

    route: int
    onto: int
    offset: float
    meeting: Meeting


def alignments(routes: tuple[Route, ...]) -> tuple[Alignment, ...]:
    """How ``routes`` (one map's; the first the scenario's) are laid onto each other: from the
    first, each route that meets one already laid, at the first meeting of the two along the one
    laid. A route that meets none keeps positions of its own (its first vehicle at its origin)."""
    meetings = conflicts(routes)
    laid, found = {0}, []
    grew = True
    while grew:
        grew = False
        for meeting in meetings:
            ends = {meeting.first, meeting.second}
            if len(ends & laid) != 1:
                continue
            onto = meeting.first if meeting.first in laid else meeting.second
            route = meeting.second if onto == meeting.first else meeting.first
            offset = meeting.offset if meeting.kind == "shared" else meeting.first_span[0] - meeting.second_span[0]
            # the meeting's offset is its first route's metres less its second's
            found.append(Alignment(route, onto, offset if route == meeting.first else -offset, meeting))
            laid.add(route)
            grew = True
    return tuple(found)
