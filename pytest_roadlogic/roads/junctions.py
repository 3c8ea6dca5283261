"""A map's junctions as a scenario names them: the turns each junction offers (``turns``), told
apart by direction as the standard's ``map.roads_follow_in_junction`` does, and the route of one
turn (``turn_route``).

A turn is one of a junction's connections: a road driven into the junction (its end at the junction
if the junction is its successor, else driven against its reference line), the connecting road
inside the junction entered at the connection's contact, and the road it leads out into. Its
direction is how far the heading turns from the road in to the road out (left positive):
straight on within ``STRAIGHT``, a U-turn from ``UTURN`` on, else left or right. A junction's
``number_of_roads`` is the roads that meet it outside it (a four-way crossing's four). The geometry
decides, as it does for routes that go straight on (``chains``): a turn is offered only where the
connecting road's driving lane continues the road in and the road out, lane centres within
``chains.JOINT_TOLERANCE`` in the world.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from functools import cached_property

from .chains import chained, continues, heading_change, next_ways, previous_ways, way
from .directions import against
from .opendrive_in import MapRoad, RoadMap
from .route import SLOW_CURVE, through_lanes

STRAIGHT = math.radians(30.0)  # a turn of less is straight on
UTURN = math.radians(150.0)  # a turn of this or more is a U-turn


@dataclass(frozen=True)
class Turn:
    """One way through junction ``junction``: ``into`` (the road driven into it), ``inside`` (its
    connecting road, as driven) and ``out_of`` (the road driven out), each as a route drives it;
    ``angle`` the heading's change in radians (left positive), ``direction`` its name."""

    junction: str
    into: MapRoad
    inside: MapRoad
    out_of: MapRoad
    angle: float
    direction: str
    # the roads its route drives straight on before the road in and after the road out, where those
    # are short (``with_room``): the turn is the same, its route longer
    before: tuple[MapRoad, ...] = ()
    after: tuple[MapRoad, ...] = ()

    @property
    def roads(self) -> tuple[MapRoad, MapRoad, MapRoad]:
        return (self.into, self.inside, self.out_of)

    @property
    def route_roads(self) -> tuple[MapRoad, ...]:
        """The roads of its route, in the order driven."""
        return (*self.before, *self.roads, *self.after)

    @property
    def approach(self) -> float:
        """Metres of its route before the junction."""
        return sum(road.length for road in (*self.before, self.into))

    @property
    def leave(self) -> float:
        """Metres of its route past the junction."""
        return sum(road.length for road in (self.out_of, *self.after))

    @cached_property
    def clear_before(self) -> float:
        """Metres of its route before the junction that bend nowhere more sharply than
        ``SLOW_CURVE``: back to the last such bend (a town's corner), else all of ``approach``."""
        return _clear_back((*self.before, self.into))

    @cached_property
    def clear_after(self) -> float:
        """Metres of its route past the junction up to the first bend sharper than ``SLOW_CURVE``,
        else all of ``leave``."""
        return _clear((self.out_of, *self.after))

    @property
    def room(self) -> float:
        """Metres of its route around the junction, between the corners before and after it: where
        a scenario's cars drive (``Route.within``)."""
        return self.clear_before + self.inside.length + self.clear_after

    @property
    def within(self) -> tuple[float, float]:
        """Where ``room`` lies along its route (``turn_route``): first and last metre."""
        return (self.approach - self.clear_before, self.approach + self.inside.length + self.clear_after)

    @property
    def lanes(self) -> int:
        """The driving lanes it has all along on the road in and the road out, the fewer."""
        return min(through_lanes(self.into)[0], through_lanes(self.out_of)[0])

    @property
    def length(self) -> float:
        """Metres of its route: the road in, the connecting road and the road out, and the roads
        before and after them."""
        return sum(road.length for road in self.route_roads)

    def describe(self) -> str:
        return f"{self.direction} from road {self.into.id} into road {self.out_of.id}"


def _clear_back(roads: tuple[MapRoad, ...]) -> float:
    """``_clear`` from the end of ``roads`` back: each driven the other way, the last first."""
    return _clear(tuple(against(road) for road in reversed(roads)))


def _clear(roads: tuple[MapRoad, ...]) -> float:
    """Metres along ``roads``, driven one after another, up to the first point whose reference line
    bends more sharply than ``SLOW_CURVE``; all their metres where none does."""
    metres = 0.0
    for road in roads:
        s, _, _, _, curvature = road.reference_line.sampled()
        sharp = s[abs(curvature) > SLOW_CURVE]
        if sharp.size:
            return metres + float(sharp.min())
        metres += road.length
    return metres


def direction(angle: float) -> str:
    """The standard's junction direction of a turn by ``angle`` radians (left positive)."""
    if abs(angle) < STRAIGHT:
        return "straight"
    if abs(angle) >= UTURN:
        return "uturn"
    return "left" if angle > 0 else "right"


def _into(road_map: RoadMap, road_id: str, junction: str) -> MapRoad | None:
    """Road ``road_id`` as driven into ``junction``: along its reference line when the junction is
    its successor, against it when its predecessor; None when neither (or no such road)."""
    road = road_map.roads.get(road_id)
    if road is None:
        return None
    if road.successor is not None and road.successor.type == "junction" and road.successor.id == junction:
        return way(road_map, road_id, "start")
    if road.predecessor is not None and road.predecessor.type == "junction" and road.predecessor.id == junction:
        return way(road_map, road_id, "end")
    return None


def turns(road_map: RoadMap) -> list[Turn]:
    """Every turn of every junction of ``road_map`` whose connecting road's driving lane continues
    the road in and the road out, in the map's order of connections."""
    found = []
    for junction, connections in road_map.connections.items():
        for connection in connections:
            into = _into(road_map, connection.incoming, junction)
            inside = way(road_map, connection.connecting, connection.contact)
            if into is None or inside is None or inside.successor is None or inside.successor.type != "road":
                continue
            out_of = way(road_map, inside.successor.id, inside.successor.contact or "start")
            if out_of is None or out_of.junction not in ("", "-1"):
                continue
            if min(through_lanes(road)[0] for road in (into, inside, out_of)) < 1:
                continue
            if not (continues(into, inside) and continues(inside, out_of)):
                continue
            angle = heading_change(into, out_of)
            found.append(Turn(junction, into, inside, out_of, angle, direction(angle)))
    return found


def number_of_roads(road_map: RoadMap, junction: str) -> int:
    """How many roads outside ``junction`` meet it (lead into it or out of it)."""
    meeting = set()
    for connection in road_map.connections.get(junction, ()):
        meeting.add(connection.incoming)
        inside = road_map.roads.get(connection.connecting)
        if inside is not None:
            for link in (inside.predecessor, inside.successor):
                if link is not None and link.type == "road":
                    meeting.add(link.id)
    return len(meeting)


def describe_junctions(road_map: RoadMap) -> str:
    """The map's junctions and the turns each offers, as a refusal lists them (or that it has none)."""
    by_junction: dict[str, list[Turn]] = {}
    for turn in turns(road_map):
        by_junction.setdefault(turn.junction, []).append(turn)
    if not by_junction:
        return "the map has no junction with a turn a route can drive"
    parts = []
    for junction, offered in by_junction.items():
        name = road_map.junctions.get(junction, "")
        label = f"junction {junction}" + (f" ({name!r})" if name else "")
        parts.append(
            f"{label}, {number_of_roads(road_map, junction)} roads: " + ", ".join(t.describe() for t in offered)
        )
    return "; ".join(parts)


def turn_route(turn: Turn) -> MapRoad:
    """The route of ``turn``: the roads before, the road in, the connecting road, the road out and
    the roads after as one road (``chains.chained``), s from the first one's start."""
    return chained(turn.route_roads)


def junction_span(turn: Turn) -> tuple[float, float]:
    """Where the junction lies along ``turn_route(turn)``: its connecting road's first and last metre."""
    return (turn.approach, turn.approach + turn.inside.length)


MAX_ROOM_STEPS = 4  # roads (or junctions crossed straight on) added before or after a turn, each way


def with_room(road_map: RoadMap, turn: Turn, side: float, length: float) -> Turn:
    """``turn`` with the roads straight on before its road in and after its road out
    (``chains.next_ways``: the next road, or through a junction straight on) added while the route
    has less than ``side`` metres of ``Turn.room`` before or past the junction, then, one side after
    the other, while it has less than ``length`` metres of room in all (a corner on the road in or
    out ends the room on its side: nothing is added beyond it). Each road added has the turn's
    lanes all along (a connecting road: one), continues the last and bends nowhere more sharply
    than ``SLOW_CURVE`` (a town's corner is a turn of its own); the first such in the map's order,
    at most ``MAX_ROOM_STEPS`` each way. Why: in a town the roads between two junctions are short
    (CARLA's Town04: 44 m), and a car approaching a turn comes from the road before, as a driver
    does; a corner on the way would be a second turn and a slowing down the scenario never asked
    for."""
    lanes = turn.lanes
    taken = {road.id for road in turn.roads}

    def first_fit(steps, joints) -> tuple[MapRoad, ...] | None:
        """The first of ``steps`` not yet driven whose roads have the lanes (a connecting road:
        one), bend gently and continue one another at ``joints(step)``."""
        for step in steps:
            if any(r.id in taken for r in step):
                continue
            if any(through_lanes(r)[0] < (1 if r.junction not in ("", "-1") else lanes) for r in step):
                continue
            if any(r.reference_line.sharpest() > SLOW_CURVE for r in step):
                continue
            if all(continues(a, b) for a, b in joints(step)):
                taken.update(r.id for r in step)
                return step
        return None

    before, after = list(turn.before), list(turn.after)
    # the roads added bend like no corner (first_fit): one on the road in or out is the only one
    # there, and the room on its side is found once
    into_clear, out_clear = _clear_back((*before, turn.into)), _clear((turn.out_of, *after))

    def clear_before() -> float:
        return into_clear + metres(before[: len(before) - len(turn.before)])

    def clear_after() -> float:
        return out_clear + metres(after[len(turn.after) :])

    def grow_before() -> bool:
        # a corner before the junction ends the room there: the roads before it would not be driven
        if len(before) >= 2 * MAX_ROOM_STEPS or into_clear < metres(turn.before) + turn.into.length:
            return False
        first = (before or [turn.into])[0]
        step = first_fit(previous_ways(road_map, first), lambda step: zip(step, (*step[1:], first)))
        if step is None:
            return False
        before[:0] = step
        return True

    def grow_after() -> bool:
        if len(after) >= 2 * MAX_ROOM_STEPS or out_clear < turn.out_of.length + metres(turn.after):
            return False
        last = (after or [turn.out_of])[-1]
        step = first_fit(next_ways(road_map, last), lambda step: zip((last, *step), step))
        if step is None:
            return False
        after.extend(step)
        return True

    def metres(roads) -> float:
        return sum(road.length for road in roads)

    while clear_before() < side and grow_before():
        pass
    while clear_after() < side and grow_after():
        pass
    growing = [grow_before, grow_after]
    while growing and clear_before() + turn.inside.length + clear_after() < length:
        if not growing[0]():
            growing.pop(0)
        else:
            growing.append(growing.pop(0))
    return dataclasses.replace(turn, before=tuple(before), after=tuple(after))


def junction_roads(road_map: RoadMap, junction: str) -> tuple[MapRoad, ...]:
    """The roads of ``junction`` (its connecting roads) and those that meet it, as the map has them:
    what a picture of the junction draws."""
    return tuple(
        road
        for road in road_map.roads.values()
        if road.junction == junction
        or any(
            link is not None and link.type == "junction" and link.id == junction
            for link in (road.predecessor, road.successor)
        )
    )
