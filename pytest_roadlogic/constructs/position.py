"""Position: the ``position()`` modifier, a longitudinal gap to another actor, between centres."""

from __future__ import annotations

from ..automaton.guards import POSITION, Bound, Guard, Term
from ..frontend.errors import error_at
from ..frontend.library import AT, Parameter, Signature
from ..frontend.tolerances import POSITION_TOLERANCE
from ..frontend.units import LENGTH
from .base import AnchoredModifier, Use


class Position(AnchoredModifier):
    """``position(d, behind: x)``: x is ahead by d; ``position(d, ahead_of: x)``: this actor is.
    A single distance is read as d +- the tolerance (never below 0)."""

    signature = Signature(
        "position",
        (Parameter("distance", "length", positional=True), Parameter("time", "time"), Parameter("ahead_of", "actor"), Parameter("behind", "actor"), AT),
        exclusive=(("ahead_of", "behind"), ("distance", "time")),
        required=(("ahead_of", "behind"), ("distance", "time")),
        description="longitudinal gap to another actor",
    )

    def guard(self, use: Use) -> Guard:
        if use.argument("time") is not None:
            raise error_at(use.argument("time").location, "not supported yet by the automaton: position(time: ...)", hint="give the gap as a distance")
        relation = use.relation(("behind", "ahead_of"))
        if relation is None:
            raise error_at(use.location, "position() needs behind: or ahead_of: another actor")
        if use.argument("distance") is None:
            raise error_at(use.location, "position() needs a distance, e.g. position([10..20]m, behind: v2)")
        low, high = use.range("distance", LENGTH, "a length such as 10m or [10..20]m")
        if low < 0:
            raise error_at(use.argument("distance").location, "a distance must not be negative", hint="use behind: instead of ahead_of: (or the reverse)")
        if low == high:
            low, high = max(0.0, low - POSITION_TOLERANCE), high + POSITION_TOLERANCE
        keyword, other = relation
        term = Term(POSITION, other, use.actor) if keyword == "behind" else Term(POSITION, use.actor, other)
        return Bound(term, low, high, use.location)


CONSTRUCTS = (Position(),)
