"""The road a scenario runs on (``Route``): a road of a map (``MapRoad``) as a route drives it.

A route runs along a road in the direction of its reference line (right-hand traffic: the road's
right lanes), its lanes numbered as the planner numbers them: 0 the leftmost, then rightward. Its
driving lanes begin at their inner edge: the road's lane offset, and right of the lanes that are
not for driving between it and them (a motorway's median border, e6mini's). Its coordinates are
the ones every stage reads: ``x`` metres along the reference line from the route's start and ``y``
metres left of the right edge of its lanes where they are most (on the straight road, exactly the
coordinates the tool has always used). ``pose`` maps them to the world.

A lane keeps its number all along the route, also where lanes begin or end beside it: where a
lane section has fewer driving lanes than the route, its lanes are those that continue the
neighbouring section's where they meet (a road of 2+1 lanes opens its passing lane on the inside,
left of the lane that runs on, which stays lane 1 from the left; a slip road ends on the outside).
``y`` is laid from the left edge of the leftmost lane that runs the whole route.

A route is one road driven one way (``directions``) or roads that continue one another
(``chains``); ``choice.pick_route`` picks the one a scenario runs on.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from .opendrive_in import DRIVING, LaneSection, MapLane, MapRoad
from .reference_line import ReferenceLine
from .surface import DrivingSurface

USABLE_WIDTH = 2.8  # m: a lane at least this wide takes a car (1.8 m) with half a metre each side
STEP = 1.0  # m along the route at which lane widths are read
HALF_CAR = 3.0  # m: half a car's 4.5 m and some
NARROW = 0.5  # m: a lane narrower than this where two lane sections meet is beginning or ending there
# m kept between every planned vehicle and the route's ends: the simulation starts its road 30 m
# behind the rearmost vehicle, and a car's half length and its driver's look-ahead need road
ROUTE_MARGIN = 30.0
# m/s^2 of lateral acceleration a planned car holds in a curve (0.2 g: 114 kph in a 500 m curve).
# Above it the passing cars of the overtakes lag their plans in a curve (docs/decisions.md).
MAX_LATERAL_ACCELERATION = 2.0
# 1/m: a bend sharper than a 100 m radius (a turn at a junction, a town's corner) is a slow stretch
# of its own: a car keeps to its speed only there (``Route.slow_stretches``); gentler curves bound
# the speed all along the route (``curve_speed``)
SLOW_CURVE = 1 / 100.0


@dataclass(frozen=True)
class Route:
    """One road of ``source`` (a map file), driven along its reference line.

    ``lanes``: its driving lanes (lanes 0..lanes-1: the most it has anywhere; those beyond the ones
    that run its whole length begin or end on it), ``lane_width`` their width at its widest;
    ``sections``: its lane sections as the map has them; ``speed_limit`` in m/s when the map gives
    one."""

    source: Path
    road: MapRoad
    lanes: int
    lane_width: float
    opendrive: bytes = field(default=b"", repr=False, compare=False)  # the map's file as read
    # where the scenario starts (its first vehicle's first position, metres along the route), when
    # it asks for a curve (path_curve): that curve's stretch; None: anywhere that fits
    start_within: tuple[float, float] | None = None
    # a route that turns at a junction (``junctions.turn_route``): the junction's first and last
    # metre along it, the turn as a message says it, and the vehicles that drive through it
    # (``along(path)`` on their drive): each starts short of it and ends past it
    junction_span: tuple[float, float] | None = None
    # the stretch of it a scenario's cars drive on (first and last metre along it): around a
    # junction, between the corners before and after it (``junctions.Turn.room``); None: all of it
    within: tuple[float, float] | None = None
    turn: str = ""
    crossers: frozenset[str] = frozenset()
    # the roads of that junction and those meeting it, as the map has them (the plot draws them)
    junction_roads: tuple[MapRoad, ...] = field(default=(), repr=False, compare=False)

    @property
    def name(self) -> str:
        return f"{self.road.label} of {self.source.name}"

    @cached_property
    def junction_surface(self) -> DrivingSurface | None:
        """The driving lanes of ``junction_roads`` (None: a route that turns at no junction): where
        a car that sweeps wide of its lane round the turn is still on the road."""
        return DrivingSurface.of(self.junction_roads) if self.junction_roads else None

    @property
    def length(self) -> float:
        return self.road.length

    @property
    def reference_line(self) -> ReferenceLine:
        return self.road.reference_line

    @property
    def sections(self) -> tuple[LaneSection, ...]:
        return self.road.sections

    @property
    def speed_limit(self) -> float | None:
        return self.road.speed_limit

    @property
    def closed(self) -> bool:
        """Whether the route is a loop: its reference line ends where it starts, heading the same way."""
        x, y, heading = self.reference_line.pose(np.array([0.0, self.length]))
        turn = (heading[1] - heading[0] + np.pi) % (2 * np.pi) - np.pi
        return bool(np.hypot(x[1] - x[0], y[1] - y[0]) < 1.0 and abs(turn) < 0.1)

    @property
    def width(self) -> float:
        """The width of its lanes where they are most: ``y`` = 0 is their right edge there."""
        return self.lanes * self.lane_width

    def pose(self, x, y) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """World x, y and heading of the route's points (``x`` along, ``y`` left of its lanes' right edge)."""
        return self.reference_line.pose(np.asarray(x, dtype=float), self.lateral(x, y))

    def lateral(self, x, y) -> np.ndarray:
        """Metres left of the reference line of the route's points (``x`` along, ``y`` left of its
        lanes' right edge): from the left edge of the leftmost lane that runs the whole route
        (``y`` = the lanes' width less those left of it), ``y`` less that."""
        _, anchor = self._numbering
        return (
            self._left_edge_of(anchor, np.asarray(x, dtype=float))
            + np.asarray(y, dtype=float)
            - (self.lanes - anchor) * self.lane_width
        )

    @cached_property
    def _numbering(self) -> tuple[tuple[int, ...], int]:
        """Per lane section, the route's number of its first driving lane (from the left); and
        the leftmost lane of the route that every section has. Sections are numbered from the
        one with the most lanes outwards, each lane that continues a neighbour's lane where the
        two meet (within half a lane's width) taking its number. Where that leaves the numbers
        ambiguous (no lane continues, or more lanes than the route's), every section's lanes are
        numbered from the left, and the anchor is lane 0."""
        fallback = (tuple(0 for _ in self.sections), 0)
        counts = [len(driving_lanes(section)[1]) for section in self.sections]
        if len(set(counts)) <= 1:
            return fallback
        most = counts.index(max(counts))
        first: dict[int, int] = {most: 0}
        order = sorted(range(len(counts)), key=lambda i: abs(i - most))
        for i in order[1:]:
            known = i - 1 if i - 1 in first else i + 1
            shift = _continued(self.road, self.sections[min(i, known)], self.sections[max(i, known)])
            if shift is None:
                return fallback
            # a lane continued is one number: the later section's first lane is ``shift`` lanes left
            # of the earlier one's
            first[i] = first[known] + (-shift if i > known else shift)
        low = min(first.values())
        numbers = tuple(first[i] - low for i in range(len(counts)))
        if max(n + c for n, c in zip(numbers, counts)) > self.lanes:
            return fallback
        everywhere = [k for k in range(self.lanes) if all(n <= k < n + c for n, c in zip(numbers, counts))]
        return (numbers, everywhere[0]) if everywhere else fallback

    def _left_edge_of(self, lane: int, s) -> np.ndarray:
        """Metres left of the reference line of ``lane``'s left edge, at lengths ``s`` along the
        route (where a section lacks the lanes left of it: as if they were there at no width)."""
        s = np.clip(np.asarray(s, dtype=float), 0.0, self.length)
        edge = self.inner_edge(s)
        if lane == 0:  # nothing left of it (every route but one whose lanes open on the inside)
            return edge
        sections, _ = self._numbering
        for section, number in zip(self.sections, sections):
            if lane <= number:
                continue
            last = section is self.sections[-1]
            inside = (s >= section.s - 1e-9) & ((s < section.end - 1e-9) | last)
            if not inside.any():
                continue
            _, driving = driving_lanes(section)
            left = sum(driving[k].width(s - section.s) for k in range(min(lane - number, len(driving))))
            edge = edge - np.where(inside, left, 0.0)
        return edge

    def inner_edge(self, s) -> np.ndarray:
        """Metres left of the reference line at which the driving lanes begin, at lengths ``s`` along
        the route: the lane offset, less the lanes between it and them that are not for driving.
        Before its start and past its end, its first and last values."""
        return inner_edge(self.road, np.clip(np.asarray(s, dtype=float), 0.0, self.length))

    def curvature(self, s) -> np.ndarray:
        """The reference line's curvature (1/m, positive to the left) at lengths ``s`` along the route."""
        return self.reference_line.curvature(np.clip(np.asarray(s, dtype=float), 0.0, self.length))

    def spans(self) -> dict[int, tuple[float, float]]:
        """Where a car's centre may be in each lane that begins or ends on the route: where the lane
        is at least ``USABLE_WIDTH`` wide, less half a car (``HALF_CAR``) at each end: lane ->
        (first, last) metres along the route. A lane that runs the whole route at that width has none.
        A lane wide enough in several stretches (parking bays drawn as a driving lane that widens
        and narrows again, esmini's parking_demo) is kept to the longest of them: a car between two
        stretches would be off the road."""
        s = np.arange(0.0, self.length + STEP / 2, STEP)
        result = {}
        for lane in range(self.lanes):
            usable = self.lane_width_at(lane, s) >= USABLE_WIDTH
            if usable.all():
                continue
            if not usable.any():
                result[lane] = (0.0, -1.0)  # nowhere
                continue
            # runs of consecutive usable samples: (first index, index past the last)
            edges = np.flatnonzero(np.diff(np.concatenate([[0], usable.astype(int), [0]])))
            first, past = max(zip(edges[::2], edges[1::2]), key=lambda run: run[1] - run[0])
            result[lane] = (float(s[first]) + HALF_CAR, float(s[past - 1]) - HALF_CAR)
        return result

    def lane_width_at(self, lane: int, s) -> np.ndarray:
        """The width of ``lane`` (0 at the reference line) at lengths ``s`` along the route (0 where
        it does not exist, or is not a driving lane). Before its start and past its end the route's
        first and last lanes run on, as the simulation's road does (a vehicle's last seconds may
        take it past the end of the map)."""
        s = np.clip(np.atleast_1d(np.asarray(s, dtype=float)), 0.0, self.length)
        width = np.zeros_like(s)
        sections, _ = self._numbering
        for section, number in zip(self.sections, sections):
            inside = (s >= section.s - 1e-9) & (s <= section.end + 1e-9)
            _, driving = driving_lanes(section)
            if not inside.any() or not 0 <= lane - number < len(driving):
                continue
            width = np.where(inside, driving[lane - number].width(s - section.s), width)
        return width

    def right_edge(self, s) -> np.ndarray:
        """``y`` of the right edge of the driving lanes at lengths ``s`` along the route (0 where every
        lane is there at full width; above 0 where lanes on the right have ended or not yet begun)."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        _, anchor = self._numbering
        total = sum(self.lane_width_at(lane, s) for lane in range(anchor, self.lanes))
        return (self.lanes - anchor) * self.lane_width - total

    def left_edge(self, s) -> np.ndarray:
        """``y`` of the left edge of the driving lanes at lengths ``s`` along the route (the lanes'
        width where every lane is there at full width; below it where lanes on the left have ended
        or not yet begun: a road of 2+1 lanes outside its passing stretch)."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        _, anchor = self._numbering
        total = sum((self.lane_width_at(lane, s) for lane in range(anchor)), np.zeros_like(s))
        return (self.lanes - anchor) * self.lane_width + total

    def greatest_curvature(self, start: float = 0.0, end: float | None = None) -> float:
        """The greatest curvature (1/m, either side) between ``start`` and ``end`` metres along it."""
        return self.reference_line.sharpest(start, end)

    def lane_curvature(self, s) -> np.ndarray:
        """The greatest curvature (1/m, either side) of a lane's centre line at lengths ``s`` along
        the route: the reference line's k, at t metres left of it, is k / (1 - k t) (a right turn's
        inner lane bends more sharply than the road's centre)."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        k = self.curvature(s)
        sharpest = np.zeros_like(s)
        for lane in range(self.lanes):
            t = self.lateral(s, self.width - (lane + 0.5) * self.lane_width)
            sharpest = np.maximum(sharpest, np.abs(k / np.maximum(1.0 - k * t, 0.1)))
        return sharpest

    @cached_property
    def slow_stretches(self) -> tuple[tuple[float, float, float], ...]:
        """The stretches of the route whose lanes bend more sharply than ``SLOW_CURVE`` (a turn at a
        junction): (first metre, last metre, the speed in m/s at which a car holds the sharpest of
        it), each widened by half a car at both ends (a car's centre is where its plan is). Worked
        out once per route: the planner's settings, the speed limit and every driver read them."""
        s = np.arange(0.0, self.length + STEP / 2, STEP)
        bending = self.lane_curvature(s)
        sharp = bending > SLOW_CURVE
        edges = np.flatnonzero(np.diff(np.concatenate([[0], sharp.astype(int), [0]])))
        stretches: list[tuple[float, float, float]] = []
        for first, last in zip(edges[::2], edges[1::2]):
            begin = max(0.0, float(s[first]) - HALF_CAR)
            end = min(self.length, float(s[last - 1]) + HALF_CAR)
            speed = holding_speed(float(bending[first:last].max()))
            if stretches and begin <= stretches[-1][1]:  # widened, two bends close together are one
                before = stretches.pop()
                begin, speed = before[0], min(speed, before[2])
            stretches.append((begin, end, speed))
        return tuple(stretches)

    def gentle_curvature(self) -> float:
        """The greatest curvature (1/m, either side) of the route outside its slow stretches."""
        bounds = [0.0]
        for first, last, _ in self.slow_stretches:
            bounds += [first, last]
        bounds.append(self.length)
        gaps = [(a, b) for a, b in zip(bounds[::2], bounds[1::2]) if b > a]
        return max((self.greatest_curvature(a, b) for a, b in gaps), default=0.0)


def holding_speed(curvature: float) -> float:
    """The greatest speed (m/s) at which a car holds a curve of ``curvature`` (1/m) at
    ``MAX_LATERAL_ACCELERATION`` (v^2 k = a); infinite on a straight."""
    return (MAX_LATERAL_ACCELERATION / curvature) ** 0.5 if curvature > 0 else float("inf")


def curve_speed(route: Route) -> float:
    """The greatest speed (m/s) at which a car holds the route's sharpest curve outside its slow
    stretches (those bound a car only where they are)."""
    return holding_speed(route.gentle_curvature())


def inner_edge(road: MapRoad, s) -> np.ndarray:
    """Metres left of ``road``'s reference line at which its driving lanes begin, at lengths ``s``
    (inside the road) along it: its lane offset, less the lanes between it and them that are not
    for driving."""
    s = np.asarray(s, dtype=float)
    edge = np.asarray(road.offset(s), dtype=float)
    for section in road.sections:
        inner, _ = driving_lanes(section)
        if not inner:
            continue
        last = section is road.sections[-1]
        inside = (s >= section.s - 1e-9) & ((s < section.end - 1e-9) | last)
        edge = edge - np.where(inside, sum(lane.width(s - section.s) for lane in inner), 0.0)
    return edge


def driving_lanes(section: LaneSection) -> tuple[tuple[MapLane, ...], tuple[MapLane, ...]]:
    """A section's right lanes as a route takes them: (the lanes not for driving between the
    reference line and the first driving lane, the driving lanes from there on, side by side)."""
    first = next((k for k, lane in enumerate(section.right) if lane.type == DRIVING), len(section.right))
    driving = []
    for lane in section.right[first:]:
        if lane.type != DRIVING:
            break
        driving.append(lane)
    return section.right[:first], tuple(driving)


def _continued(road: MapRoad, before: LaneSection, after: LaneSection) -> int | None:
    """Where two consecutive lane sections meet: the index among ``after``'s driving lanes of the
    lane that continues ``before``'s first one that is there (wider than ``NARROW``), less that
    lane's index in ``before``; None when no lane continues one of ``before``'s."""
    shifts = _shifts(road, before, after)
    return shifts[0] if shifts else None


def _shifts(road: MapRoad, before: LaneSection, after: LaneSection) -> list[int]:
    """For each of ``before``'s driving lanes that is there where the two sections meet (wider
    than ``NARROW``) and that a lane of ``after`` continues (centres within half a lane), the
    index of that lane in ``after`` less its own, in ``before``'s order."""

    def centres(section: LaneSection, at: float) -> list[tuple[float, float]]:
        inner, driving = driving_lanes(section)
        ds = np.array([at - section.s])
        edge = float(road.offset(np.array([at]))[0]) - sum(float(lane.width(ds)[0]) for lane in inner)
        found = []
        for lane in driving:
            width = float(lane.width(ds)[0])
            found.append((edge - width / 2, width))
            edge -= width
        return found

    at = after.s
    old, new = centres(before, at), centres(after, at)
    shifts = []
    for k, (centre, width) in enumerate(old):
        if width < NARROW:
            continue
        for j, (other, other_width) in enumerate(new):
            if other_width >= NARROW and abs(other - centre) < min(width, other_width) / 2:
                shifts.append(j - k)
                break
    return shifts


def lane_opens_between(road: MapRoad) -> bool:
    """Whether a driving lane begins or ends between two lanes that run on where two of ``road``'s
    lane sections meet (a turn pocket opening between a road's lane and its oncoming one): the
    lanes that run on then move apart by a lane, and no one numbering of the route's lanes holds
    all along (``Route._numbering`` numbers each section's lanes side by side)."""
    return any(len(set(_shifts(road, before, after))) > 1 for before, after in zip(road.sections, road.sections[1:]))


def through_lanes(road: MapRoad) -> tuple[int, int]:
    """(driving lanes side by side that run the road's whole length, the most driving lanes
    anywhere on it)."""
    counts = [len(driving_lanes(section)[1]) for section in road.sections]
    return min(counts), max(counts)
