"""Position: the ``position()`` modifier, a longitudinal gap to another actor, between centres,
as a distance or as a time headway."""

from __future__ import annotations

from ..automaton.guards import HEADWAY, POSITION, Bound, Guard, Term
from ..frontend.errors import error_at
from ..frontend.library import AT, Parameter, Signature
from ..frontend.tolerances import HEADWAY_TOLERANCE, POSITION_TOLERANCE, widened
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
        argument = "time" if use.argument("time") is not None else "distance"
        if use.argument(argument) is None:
            raise error_at(use.location, "position() needs a distance, e.g. position([10..20]m, behind: v2)")
        quantity, dimension, example, what, tolerance = _GAPS[argument]
        low, high = use.range(argument, dimension, example)
        if low < 0:
            raise error_at(use.argument(argument).location, f"{what} must not be negative", hint="use behind: instead of ahead_of: (or the reverse)")
        low, high = widened(low, high, tolerance)
        keyword, other = relation
        term = Term(quantity, other, use.actor) if keyword == "behind" else Term(quantity, use.actor, other)
        return Bound(term, max(0.0, low), high, use.location)


# the two ways to give the gap, by argument: (quantity, dimension, an example for errors, what it
# is, the tolerance of a single value)
_GAPS = {
    "distance": (POSITION, LENGTH, "a length such as 10m or [10..20]m", "a distance", POSITION_TOLERANCE),
    "time": (HEADWAY, TIME, "a time such as 2s or [1.5s..2.5s]", "a time headway", HEADWAY_TOLERANCE),
}

CONSTRUCTS = (Position(),)
