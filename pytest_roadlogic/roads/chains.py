"""Routes over several roads: roads that continue one another, found by the map's links
(``chains``), joined into one road (``chained``).

A road's successor is a road (entered at its start or its end) or a junction, whose connections
lead from the road into a connecting road and out of it into the next road. A route goes on into
the next road when that road has the lanes the scenario needs all along and its driving lanes
continue the route's where the two meet (their centres within ``JOINT_TOLERANCE`` in the world:
the map's lane links are not trusted to say it, the geometry is checked); through a junction only
straight on (a connecting road that turns by less than ``STRAIGHT_ON``): a turn is a scenario's
business, not a default route's. A route goes on only into roads whose curves are no sharper than
its own so far or a highway's (``GENTLE``): the planner holds every car to the speed of the route's
sharpest curve, and a town's 26 m bend at the end of a long road made a follow at 100 kph
impossible. A road is driven at most once on a route.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterator

import numpy as np

from .cubic_records import summed
from .directions import against, left_hand
from .opendrive_in import LaneSection, MapRoad, RoadMap
from .reference_line import JoinedLine
from .route import driving_lanes, inner_edge, through_lanes

JOINT_TOLERANCE = 0.3  # m between a lane's centre at one road's end and at the next one's start
STRAIGHT_ON = math.radians(20.0)  # the most a connecting road may turn for a route to go through it
GENTLE = 1 / 500.0  # 1/m: a highway's curve (114 kph at the planner's 2 m/s^2 of lateral acceleration)
MAX_ROADS = 20  # roads on one route
MAX_CHAINS = 2_000  # routes followed from all roads together: a map of many junctions stays quick
# continuations looked at, all routes together (each road's are worked out once): routes through
# two crafted junctions of 12,000 connections each would be looked at by the hundred million
MAX_STEPS = 50_000


def way(road_map: RoadMap, road_id: str, contact: str) -> MapRoad | None:
    """The road ``road_id`` entered at its ``contact`` end, as a route drives it: along its
    reference line from its start, against it from its end, on the lanes of that direction (of
    left-hand traffic: ``directions.left_hand``); None for a road the map lacks."""
    road = road_map.roads.get(road_id)
    if road is None:
        return None
    driven = against(road) if contact == "end" else road
    return left_hand(driven) if road.rule == "LHT" else driven


def _lane_centres(road: MapRoad, s: float) -> np.ndarray:
    """World points (n x 2) of the centres of the driving lanes of ``road`` at ``s`` metres along
    it, from the reference line outward (a lane narrower than 1 m there is left out)."""
    section = next((x for x in road.sections if x.s - 1e-9 <= s <= x.end + 1e-9), road.sections[-1])
    _, driving = driving_lanes(section)
    ds = min(max(s - section.s, 0.0), section.end - section.s)
    edge = float(inner_edge(road, s))
    centres = []
    for lane in driving:
        width = float(lane.width(ds))
        if width >= 1.0:
            centres.append(edge - width / 2)
        edge -= width
    x, y, _ = road.reference_line.pose(np.full(len(centres), s), np.array(centres))
    return np.stack([x, y], axis=1)


def continues(first: MapRoad, then: MapRoad) -> bool:
    """Whether ``then``'s driving lanes begin where ``first``'s end: the same heading and, lane by
    lane from the inner edge, centres within ``JOINT_TOLERANCE`` (lanes beyond the fewer of
    them begin or end at the joint)."""
    end, start = _lane_centres(first, first.length), _lane_centres(then, 0.0)
    n = min(len(end), len(start))
    if n == 0:
        return False
    return abs(heading_change(first, then)) < 0.1 and bool(np.all(np.hypot(*(end[:n] - start[:n]).T) < JOINT_TOLERANCE))


def heading_change(first: MapRoad, then: MapRoad) -> float:
    """How far the heading turns from ``first``'s end to ``then``'s start (radians, -pi..pi, left
    positive)."""
    _, _, heading_end = first.reference_line.pose(np.array([first.length]))
    _, _, heading_start = then.reference_line.pose(np.array([0.0]))
    return (float(heading_start[0] - heading_end[0]) + math.pi) % (2 * math.pi) - math.pi


def _turn(road: MapRoad) -> float:
    """How far a road turns from its start to its end (radians, either way)."""
    _, _, _, heading, _ = road.reference_line.sampled()
    return abs(float(heading[-1] - heading[0]))


def next_ways(road_map: RoadMap, current: MapRoad) -> Iterator[tuple[MapRoad, ...]]:
    """The roads a route may drive after ``current``'s end: the next road (one), or through a
    junction a connecting road that goes straight on and the road after it (two)."""
    link = current.successor
    if link is None:
        return
    if link.type == "road":
        after = way(road_map, link.id, link.contact or "start")
        if after is not None and after.junction in ("", "-1"):
            yield (after,)
        return
    if link.type != "junction":
        return
    for connection in road_map.connections.get(link.id, ()):
        if connection.incoming != current.id:
            continue
        inside = way(road_map, connection.connecting, connection.contact)
        if inside is None or _turn(inside) >= STRAIGHT_ON or inside.successor is None:
            continue
        out = inside.successor
        after = way(road_map, out.id, out.contact or "start") if out.type == "road" else None
        if after is not None and after.junction in ("", "-1"):
            yield (inside, after)


def turned(road_map: RoadMap, road: MapRoad) -> MapRoad | None:
    """``road`` (a road of the map as a route drives it) driven the other way."""
    return way(road_map, road.id, "start" if road.against else "end")


def previous_ways(road_map: RoadMap, current: MapRoad) -> Iterator[tuple[MapRoad, ...]]:
    """The roads a route may drive before ``current``'s start, in its direction: the road before
    (one), or the road before a junction and the connecting road from it straight on into
    ``current`` (two). They are the ways after ``current`` driven the other way, turned round;
    through a junction the connecting road is this direction's own, found from the road before:
    a town's connecting roads are one way each (CARLA's are), and the other direction's, driven
    against its reference line, has no lane."""
    back_from = turned(road_map, current)
    if back_from is None:
        return
    for step in next_ways(road_map, back_from):
        before = turned(road_map, step[-1])
        if before is None:
            continue
        if len(step) == 1:
            yield (before,)
            continue
        for onward in next_ways(road_map, before):
            if len(onward) == 2 and onward[1].id == current.id and onward[1].against == current.against:
                yield (before, onward[0])


def chains(road_map: RoadMap, starts: list[MapRoad], lanes: int, gentle: bool = True) -> list[tuple[MapRoad, ...]]:
    """Every route of two or more roads from one of ``starts`` on which each road has ``lanes``
    driving lanes all along (a connecting road inside a junction: at least one) and continues the
    last: the longest ones, each as far as it goes (as far as ``MAX_CHAINS`` routes and ``MAX_STEPS``
    continuations looked at find them). Without ``gentle``, a route also goes on into roads whose
    curves are sharper than its own so far and a highway's (for a map that has no other route)."""
    found: list[tuple[MapRoad, ...]] = []
    onward: dict[tuple[str, bool], list[tuple[tuple[MapRoad, ...], float]]] = {}

    def steps_after(current: MapRoad) -> list[tuple[tuple[MapRoad, ...], float]]:
        """The continuations of ``current`` that have the lanes and meet its lanes, each with its
        sharpest curve: worked out once per road and direction, whatever route reaches it."""
        key = (current.id, current.against)
        if key not in onward:
            onward[key] = [
                (step, max(road.reference_line.sharpest() for road in step))
                for step in next_ways(road_map, current)
                if all(through_lanes(road)[0] >= (lanes if road is step[-1] else 1) for road in step)
                and all(continues(a, b) for a, b in zip((current, *step), step))
            ]
        return onward[key]

    stack = [((start,), start.reference_line.sharpest()) for start in starts if through_lanes(start)[0] >= lanes]
    followed = looked = 0
    while stack and followed < MAX_CHAINS and looked < MAX_STEPS:
        route, sharpest = stack.pop()
        followed += 1
        grown = False
        if len(route) < MAX_ROADS:
            taken = {road.id for road in route}
            for step, bends in steps_after(route[-1]):
                looked += 1
                if looked > MAX_STEPS:
                    break
                if (not gentle or bends <= max(sharpest, GENTLE)) and not any(road.id in taken for road in step):
                    stack.append((route + step, max(sharpest, bends)))
                    grown = True
        if not grown and len(route) > 1:
            found.append(route)
    return found


def chained(roads: tuple[MapRoad, ...]) -> MapRoad:
    """Roads one after another as one road: its reference line runs on over theirs, its lane
    sections and lane offset are theirs, s counting on; its speed limit their least; its id theirs
    joined by '+' and ``chain`` their labels."""
    sections: list[LaneSection] = []
    offsets = []
    start = 0.0
    for road in roads:
        sections += [
            dataclasses.replace(section, s=section.s + start, end=section.end + start) for section in road.sections
        ]
        offsets.append((start, start + road.length, road.lane_offset))
        start += road.length
    limits = [road.speed_limit for road in roads if road.speed_limit is not None]
    first = roads[0]
    return dataclasses.replace(
        first,
        id="+".join(road.id for road in roads),
        name="",
        length=start,
        reference_line=JoinedLine((), first.reference_line.step, {}, False, tuple(r.reference_line for r in roads)),
        sections=tuple(sections),
        successor=roads[-1].successor,
        speed_limit=min(limits) if limits else None,
        lane_offset=summed(offsets, start),
        chain=tuple(road.label for road in roads),
    )
