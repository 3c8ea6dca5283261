"""Position: the ``position()`` modifier, a longitudinal gap to another actor, between centres,
as a distance or as a time headway."""

from __future__ import annotations

from dataclasses import dataclass

from ..frontend.errors import error_at
from ..frontend.semantics.library import AT, Parameter, Signature
from ..frontend.semantics.tolerances import HEADWAY_TOLERANCE, POSITION_TOLERANCE, widened
from ..frontend.syntax.units import LENGTH, TIME
from ..logic.guards import HEADWAY, POSITION, Bound, Guard, Term
from .base import ASKS_SPEED, AnchoredModifier, Use


class Position(AnchoredModifier):
    """``position(d, behind: x)``: x is ahead by d; ``position(d, ahead_of: x)``: this actor is.
    A single distance is read as d +- the tolerance (not across 0); a negative one is the other side. ``position(time: t, behind:
    x)``: a time headway, the gap over the speed of the actor behind (this one; x with
    ``ahead_of``): it reaches where x is now in t seconds; a single t is read as t +- 0.2 s."""

    asks = ASKS_SPEED
    signature = Signature(
        "position",
        (
            Parameter("distance", "length", positional=True, ranged=True),
            Parameter("time", "time", ranged=True),
            Parameter("ahead_of", "actor"),
            Parameter("behind", "actor"),
            AT,
        ),
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
        keyword, other = relation
        ahead, behind = (other, use.actor) if keyword == "behind" else (use.actor, other)
        return gap_bound(
            use, argument, GAPS[argument], ahead, behind, "use behind: instead of ahead_of: (or the reverse)"
        )


@dataclass(frozen=True)
class Gap:
    """One way to give a longitudinal gap: the quantity it bounds, its dimension, an example for
    errors, what it is called in them, and the tolerance of a single value."""

    quantity: str
    dimension: str
    example: str
    what: str
    tolerance: float


# by position()'s argument; the gap actions (constructs.gaps) read the same two
GAPS = {
    "distance": Gap(POSITION, LENGTH, "a length such as 10m or [10..20]m", "a distance", POSITION_TOLERANCE),
    "time": Gap(HEADWAY, TIME, "a time such as 2s or [1.5s..2.5s]", "a time headway", HEADWAY_TOLERANCE),
}


def gap_bound(use: Use, argument: str, gap: Gap, ahead: str, behind: str, hint: str, what: str | None = None) -> Bound:
    """``ahead`` is ahead of ``behind`` by the value of ``argument`` (+- the gap's tolerance for a
    single value, not across 0). A negative distance is the other side, as the standard reads it:
    ``position(-5m, ahead_of: x)`` is 5 m behind x, and ``position([-1m..1m], ahead_of: x)``
    beside it. A negative time headway is an error at its place, with ``hint``: a headway is the
    time the one behind needs to reach the other."""
    low, high = use.range(argument, gap.dimension, gap.example)
    if low < 0 and gap.quantity != POSITION:
        raise error_at(use.argument(argument).location, f"{what or gap.what} must not be negative", hint=hint)
    widened_low, widened_high = widened(low, high, gap.tolerance)
    # a single value is widened by the tolerance on its own side of 0 only
    if low >= 0:
        widened_low = max(0.0, widened_low)
    elif high <= 0:
        widened_high = min(0.0, widened_high)
    return Bound(Term(gap.quantity, ahead, behind), widened_low, widened_high, use.location)


CONSTRUCTS = (Position(),)
