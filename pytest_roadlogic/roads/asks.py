"""What a scenario asks of its map's junctions (``TurnAsk``), as the front end reads it: a small
value with no geometry, so that reading a scenario needs no map library (``choice`` answers it)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class TurnAsk:
    """One ``roads_follow_in_junction`` of a scenario: the turn's ``direction`` and the junction's
    ``number_of_roads`` (None: any), and the names of the scenario's ``junction`` and ``road``
    fields it binds (``junction:``, ``in_road:``, ``out_road:``; None: unbound): two turns that name
    one field take the same junction or road. ``path``: the scenario's path it is asked of."""

    direction: str | None = None
    roads: int | None = None
    junction: str | None = None
    in_road: str | None = None
    out_road: str | None = None
    path: str = "path"

    def describe(self) -> str:
        kind = {"uturn": "a U-turn", "straight": "a way straight on", None: "a turn"}.get(
            self.direction, f"a {self.direction} turn"
        )
        bound = [f"{name} {value}" for name, value in (("in from", self.in_road), ("out into", self.out_road)) if value]
        at = f" at junction {self.junction}" if self.junction else ""
        return f"{self.path}: {kind}{at}" + (f" ({', '.join(bound)})" if bound else "")


# the standard's map relations between the routes of two paths, by the name the tool gives each
ROUTE_RELATIONS = ("overlap", "opposite", "sequence")


@dataclass(frozen=True)
class RouteRelation:
    """One of the standard's map relations between the routes of two turning paths (``first`` and
    ``second``: indices of their ``TurnAsk``s, in the scenario's order):

    - ``overlap`` (``map.routes_overlap``): they share the road in (``kind`` ``start``), the road
      out (``end``), either (``any``), or are one way (``equal``);
    - ``opposite`` (``map.routes_are_opposite``): some road both drive, in opposite directions;
    - ``sequence`` (``map.routes_are_in_sequence``): the second comes in on the road the first
      leaves on, at the junction at that road's other end.

    ``road``: the scenario's road field that road is (``containing_road:``, ``road:``), or None."""

    relation: str
    first: int
    second: int
    kind: str | None = None
    road: str | None = None
