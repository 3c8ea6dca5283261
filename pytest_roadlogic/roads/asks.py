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
