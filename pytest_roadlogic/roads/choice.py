"""The choice of a route in a map (``pick_route``), and a map's roads as a refusal lists them.

The route is one that has the lanes, the length and the curve a scenario asks for: one road driven
either way, or roads that continue one another (``chains``), the longest of those whose sharpest
curve lets a car drive ``BRISK`` (else the gentlest); a road of one lane each way with its
oncoming lane joined only when none has enough lanes one way.
"""

from __future__ import annotations

import numpy as np

from .asks import TurnAsk
from .chains import chained, chains
from .directions import against, left_hand, with_oncoming
from .junctions import (
    Turn,
    describe_junctions,
    junction_roads,
    junction_span,
    number_of_roads,
    turn_route,
    turns,
    with_room,
)
from .opendrive_in import MapError, MapRoad, RoadMap
from .route import ROUTE_MARGIN, SLOW_CURVE, Route, driving_lanes, holding_speed, lane_opens_between, through_lanes

# m/s a route's sharpest curve should let a car hold (90 kph): a longer route with a town's bend
# (26 m, 26 kph) lost to a shorter one without
BRISK = 25.0


def describe(road: MapRoad) -> str:
    """A road as a refusal lists it: its lanes each way, length and curves, or why it is no route."""
    if road.junction not in ("", "-1"):
        return f"{road.label}: inside junction {road.junction} (a route goes through a junction straight on, never begins in one)"
    one_way, other_way = ways_of(road)
    through, most = through_lanes(one_way)
    extra = f", {most} in parts" if most > through else ""
    back, back_most = through_lanes(other_way)
    if back_most:
        extra += f", {back}{f' ({back_most} in parts)' if back_most > back else ''} the other way"
    _, _, _, _, curvature = road.reference_line.sampled()
    curves = []
    for side, sign in (("left", 1.0), ("right", -1.0)):
        sharpest = float((sign * curvature).max())
        if sharpest > 1e-6:
            curves.append(f"{side} {1 / sharpest:.0f} m")
    bends = f", curves of radius down to {' and '.join(curves)}" if curves else ", straight"
    plural = "" if through == 1 else "s"
    traffic = " (left-hand traffic)" if road.rule == "LHT" else ""
    return f"{road.label}{traffic}: {through} driving lane{plural} over {road.length:g} m{extra}{bends}"


def ways_of(road: MapRoad) -> tuple[MapRoad, MapRoad]:
    """A road outside junctions driven each way, as a route reads it: along its reference line and
    against it, on the lanes that carry each direction (its right lanes along it in right-hand
    traffic, its left lanes in left-hand traffic, ``directions.left_hand``)."""
    if road.rule == "LHT":
        return left_hand(road), left_hand(against(road))
    return road, against(road)


def curve_stretch(road: MapRoad, curve: tuple[float | None, float | None, str | None]) -> tuple[float, float] | None:
    """The longest stretch of the road (first, last metre along it) that bends with a radius
    between ``curve``'s (metres; None: no bound) to its side (left, right; None: either); None
    when it has none."""
    low, high, side = curve
    s, _, _, _, curvature = road.reference_line.sampled()
    best = None
    for name, sign in (("left", 1.0), ("right", -1.0)):
        if side not in (None, name):
            continue
        bending = sign * curvature
        radius = np.where(bending > 1e-9, 1.0 / np.maximum(bending, 1e-12), np.inf)
        inside = np.isfinite(radius) & (radius >= (low or 0.0) - 1e-6) & (radius <= (high or np.inf) + 1e-6)
        # runs of consecutive samples inside: (start index, end index)
        edges = np.flatnonzero(np.diff(np.concatenate([[0], inside.astype(int), [0]])))
        for start, end in zip(edges[::2], edges[1::2]):
            stretch = (float(s[start]), float(s[end - 1]))
            if best is None or stretch[1] - stretch[0] > best[1] - best[0]:
                best = stretch
    return best


class NoFittingTurn(MapError):
    """The map has turns of the kind a path asks for, none with the lanes or the room the scenario
    needs; ``asked_by``: the scenario's path that asks."""

    def __init__(self, path, message: str, hint: str = "", asked_by: str = "") -> None:
        super().__init__(path, message, hint)
        self.asked_by = asked_by


MIN_ROUTE_LENGTH = 200.0  # m of route a scenario that names no path_length is given at least
# m of road a turn's road in and road out need each: the planner keeps every car ROUTE_MARGIN from
# a route's ends, and a car driving through the junction approaches it and leaves it on them
MIN_APPROACH = ROUTE_MARGIN + 20.0
# m of a route along which the lanes a scenario needs are there side by side, at least: lanes
# together for less are a row of parking bays drawn as a driving lane (esmini's parking_demo: 48 m),
# not a road of that many lanes (a 2+1 road's passing stretch: 130-170 m)
MIN_SIDE_BY_SIDE = 100.0
# m before and past the junction a turn's route is given when its own roads give less than
# MIN_APPROACH (``roomy``): a town's roads between two junctions
ROOM = ROUTE_MARGIN + 120.0


def pick_route(
    road_map: RoadMap,
    lanes: int,
    length: float = 0.0,
    curve: tuple[float | None, float | None, str | None] | None = None,
) -> Route:
    """The route of ``road_map`` a scenario of ``lanes`` lanes and ``length`` metres fits on: the
    longest road outside junctions with at least that many driving lanes (those beyond the lanes
    that run its whole length begin or end on it: the planner keeps a car in such a lane only
    where it is), at least that long, and with a ``curve`` (min radius, max radius, side; the
    standard's ``path_curve``) when one is asked for (a route that turns at a junction is one of
    ``ways.choose_ways``). ``MapError`` saying why no road fits, road by road."""
    # a scenario that names no path_length still needs room to drive: a route too short for it
    # would be reported as a scenario without a plan, blaming the scenario for the map
    length = length or MIN_ROUTE_LENGTH
    ways = [way for road in road_map.roads.values() if road.junction in ("", "-1") for way in ways_of(road)]

    split: list[MapRoad] = []  # routes that would fit but for a lane opening between two others

    def fits(way: MapRoad) -> bool:
        _, most = through_lanes(way)
        if not (most >= lanes and way.length >= length and (curve is None or curve_stretch(way, curve) is not None)):
            return False
        if lane_opens_between(way):
            split.append(way)
            return False
        # the lanes are there together too briefly (parking bays drawn as a lane)
        return _side_by_side(road_map, way, lanes) >= MIN_SIDE_BY_SIDE

    # the lanes of one direction first, on one road or on roads that continue one another; a road
    # of too few, with its oncoming lanes joined, only when no route has enough (an overtake on a
    # road of one lane each way passes in the oncoming one)
    fitting = [way for way in ways + [chained(c) for c in chains(road_map, ways, lanes)] if fits(way)]
    if not fitting:
        one_way = ways + [chained(c) for c in chains(road_map, ways, 1)]
        fitting = [joined for way in one_way if (joined := with_oncoming(way)) is not None and fits(joined)]
    if not fitting:
        # a route through a sharper bend than a highway's: the planner holds the cars to its
        # speed, and a scenario that needs more is told so by name (the curve's speed limit)
        fitting = [chained(c) for c in chains(road_map, ways, lanes, gentle=False)]
        fitting = [way for way in fitting if fits(way)]
    if not fitting:
        lines = "; ".join(describe(road) for road in road_map.roads.values())
        need = f"{lanes} driving lane{'' if lanes == 1 else 's'}" + (f" over {length:g} m" if length else "")
        if curve is not None:
            low, high, side = curve
            radius = f"{low or 0:g}..{high:g} m" if high else f"at least {low:g} m"
            need += f" and a curve{' to the ' + side if side else ''} of radius {radius}"
        if split:
            lines += (
                f"; {len(split)} route{'s' if len(split) > 1 else ''} with the lanes ({split[0].label}, ...) "
                "not supported: a lane there opens between two that run on (a turn pocket between a road's "
                "lane and its oncoming one), and a lane keeps no one number along it"
            )
        raise MapError(
            road_map.path,
            f"no road of the map has {need}: {lines}",
            "ask for less (the lanes it names, path_min_driving_lanes, path_length, path_curve) or give a map with a road that has it",
        )

    # the planner holds every car to the speed of the route's sharpest curve: of the routes that let
    # cars drive ``BRISK`` the longest, else the gentlest; of two alike, the one along its
    # reference line, then the least id
    def rank(way: MapRoad) -> tuple:
        speed = holding_speed(way.reference_line.sharpest())
        return (min(speed, BRISK), way.length, not way.against, -int(way.id) if way.id.isdigit() else 0)

    road = max(fitting, key=rank)
    stretch = curve_stretch(road, curve) if curve is not None else None
    return Route(road_map.path, road, through_lanes(road)[1], _lane_width(road), road_map.data, stretch)


def _side_by_side(road_map: RoadMap, road: MapRoad, lanes: int) -> float:
    """Metres of the longest stretch of ``road`` along which ``lanes`` of its driving lanes are
    there side by side, a car's width wide (``Route.spans``): all of it where they run its whole
    length."""
    route = Route(road_map.path, road, through_lanes(road)[1], _lane_width(road))
    spans = route.spans()
    if not spans:
        return road.length
    s = np.arange(0.0, road.length + 1.0, 1.0)
    present = np.full(len(s), route.lanes - len(spans))
    for first, last in spans.values():
        present += (s >= first) & (s <= last)
    enough = np.concatenate([[0], (present >= lanes).astype(int), [0]])
    edges = np.flatnonzero(np.diff(enough))
    return max((float(s[end - 1] - s[begin]) for begin, end in zip(edges[::2], edges[1::2])), default=0.0)


def _lane_width(road: MapRoad) -> float:
    """The width of a route's lanes: its innermost lane's (beside the centre line: the first of its
    lanes, the last on a road of left-hand traffic), where the road has the most lanes (a route's
    lanes are as wide as one another; the outer ones of a published map may be a parking bay 5 m
    wide here and there)."""
    widest = max(road.sections, key=lambda section: len(driving_lanes(section)[1]))
    within = np.linspace(0.0, widest.end - widest.s, 9)
    lanes = driving_lanes(widest)[1]
    return float(np.max(lanes[-1 if road.left_hand else 0].width(within)))


def fitting_turns(road_map: RoadMap, lanes: int, length: float, ask: TurnAsk) -> list[Turn]:
    """The turns of ``road_map`` of the kind ``ask`` names (direction, roads at the junction) with
    ``lanes`` driving lanes on the roads in and out and ``length`` metres in all, in the map's
    order. ``MapError`` naming the map's junctions and the turns they offer when none fits."""
    direction, roads = ask.direction, ask.roads
    asked_for = [
        t
        for t in turns(road_map)
        if direction in (None, t.direction) and roads in (None, number_of_roads(road_map, t.junction))
    ]
    asked_for = [roomy(road_map, t) for t in asked_for]
    offered = [
        t
        for t in asked_for
        if t.lanes >= lanes and t.room >= length and min(t.clear_before, t.clear_after) >= MIN_APPROACH
    ]
    if asked_for and not offered:
        # the map has the turn, but not with the lanes or the room the scenario needs: say which
        with_lanes = [t for t in asked_for if t.lanes >= lanes]
        long_enough = [t for t in with_lanes if t.room >= length]
        approach = max(min(t.clear_before, t.clear_after) for t in (long_enough or with_lanes or asked_for))
        count = len(asked_for)
        if not with_lanes:
            most = max(t.lanes for t in asked_for)
            short = f"none has {lanes} driving lanes in and out (at most {most})"
        elif not long_enough:
            short = f"{len(with_lanes)} have {lanes} driving lane{'' if lanes == 1 else 's'} in and out, none {length:g} m of road in all (at most {max(t.room for t in with_lanes):.0f} m)"
        else:
            short = f"{len(long_enough)} have the lanes and {length:g} m of road in all, none {MIN_APPROACH:g} m of road both in and out of the junction (at most {approach:.0f} m)"
        raise NoFittingTurn(
            road_map.path,
            f"of the map's {count} turn{'' if count == 1 else 's'} of the kind {ask.path} asks "
            f"({', '.join(t.describe() for t in asked_for[:6])}{', ...' if count > 6 else ''}), {short}; "
            f"a car approaches and leaves the junction on the roads in and out, and stays {ROUTE_MARGIN:g} m from a route's ends "
            f"and from a corner before or after the junction (a bend sharper than a {1 / SLOW_CURVE:g} m radius)",
            "ask for less (the lanes it names, path_length), or give a map whose junction has longer roads",
            asked_by=ask.path,
        )
    if not offered:
        where = f"a junction of {roads} roads" if roads else "a junction"
        asked = {
            "uturn": f"U-turn at {where}",
            "straight": f"way straight on through {where}",
            None: f"turn at {where}",
        }.get(direction, f"{direction} turn at {where}")
        need = f" with {lanes} driving lane{'' if lanes == 1 else 's'} in and out" if lanes > 1 else ""
        raise MapError(
            road_map.path,
            f"no {asked}{need} in the map: {describe_junctions(road_map)}",
            "ask for a turn the map has (roads_follow_in_junction's direction, number_of_roads), or give a map with one",
        )
    return offered


def roomy(road_map: RoadMap, turn: Turn) -> Turn:
    """``turn`` as it is when its roads give a car room to approach and leave the junction
    (``MIN_APPROACH`` each side) and a scenario room to drive (``MIN_ROUTE_LENGTH`` in all); else
    with the roads straight on before and after it (``junctions.with_room``) up to ``ROOM`` each
    side: two cars approaching one after the other need more than one car's room."""
    if min(turn.clear_before, turn.clear_after) >= MIN_APPROACH and turn.room >= MIN_ROUTE_LENGTH:
        return turn
    return with_room(road_map, turn, ROOM, MIN_ROUTE_LENGTH)


def turn_as_route(road_map: RoadMap, chosen: Turn, crossers: frozenset[str] = frozenset()) -> Route:
    """The route of the turn ``chosen``: its roads as one (``junctions.turn_route``, with the roads
    before and after it that ``roomy`` adds), as many lanes as the roads in and out both have all
    along, the junction where it lies along it."""
    chosen = roomy(road_map, chosen)
    return Route(
        road_map.path,
        turn_route(chosen),
        min(through_lanes(chosen.into)[1], through_lanes(chosen.out_of)[1]),
        _lane_width(chosen.into),
        road_map.data,
        junction_span=junction_span(chosen),
        within=chosen.within,
        turn=f"{chosen.describe()} at junction {chosen.junction}",
        crossers=crossers,
        junction_roads=junction_roads(road_map, chosen.junction),
    )
