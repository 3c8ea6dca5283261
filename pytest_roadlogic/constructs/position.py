"""Position: the ``position()`` modifier, a longitudinal gap to another actor, between centres,
as a distance or as a time headway."""

from __future__ import annotations

from ..automaton.guards import HEADWAY, POSITION, Bound, Guard, Term
from ..frontend.errors import error_at
from ..frontend.library import AT, Parameter, Signature
from ..frontend.tolerances import HEADWAY_TOLERANCE, POSITION_TOLERANCE
from ..frontend.units import LENGTH, TIME
from .base import AnchoredModifier, Use


class Position(AnchoredModifier):
    """``position(d, behind: x)``: x is ahead by d; ``position(d, ahead_of: x)``: this actor is.
    A single distance is read as d +- the tolerance (never below 0). ``position(time: t, behind:
    x)``: a time headway, the gap over the speed of the actor behind (this one; x with
    ``ahead_of``): it reaches where x is now in t seconds; a single t is read as t +- 0.2 s."""

    signature = Signature(
        "position",
        (Parameter("distance", "length", positional=True), Parameter("time", "time"), Parameter("ahead_of", "actor"), Parameter("behind", "actor"), AT),
        exclusive=(("ahead_of", "behind"), ("distance", "time")),
        required=(("ahead_of", "behind"), ("distance", "time")),
        description="longitudinal gap to another actor",
    )

    def sampled_as(self, argument: str) -> str | None:
        return "headway" if argument == "time" else None

    def guard(self, use: Use) -> Guard:
        relation = use.relation(("behind", "ahead_of"))
        if relation is None:
            raise error_at(use.location, "position() needs behind: or ahead_of: another actor")
        keyword, other = relation
        if use.argument("time") is not None:
            low, high = use.range("time", TIME, "a time such as 2s or [1.5s..2.5s]")
            if low < 0:
                raise error_at(use.argument("time").location, "a time headway must not be negative", hint="use behind: instead of ahead_of: (or the reverse)")
            if low == high:
                low, high = max(0.0, low - HEADWAY_TOLERANCE), high + HEADWAY_TOLERANCE
            term = Term(HEADWAY, other, use.actor) if keyword == "behind" else Term(HEADWAY, use.actor, other)
            return Bound(term, low, high, use.location)
        if use.argument("distance") is None:
            raise error_at(use.location, "position() needs a distance, e.g. position([10..20]m, behind: v2)")
        low, high = use.range("distance", LENGTH, "a length such as 10m or [10..20]m")
        if low < 0:
            raise error_at(use.argument("distance").location, "a distance must not be negative", hint="use behind: instead of ahead_of: (or the reverse)")
        if low == high:
            low, high = max(0.0, low - POSITION_TOLERANCE), high + POSITION_TOLERANCE
        term = Term(POSITION, other, use.actor) if keyword == "behind" else Term(POSITION, use.actor, other)
        return Bound(term, low, high, use.location)


CONSTRUCTS = (Position(),)
