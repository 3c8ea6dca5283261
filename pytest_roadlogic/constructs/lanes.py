"""Lanes: ``lane()``, ``keep_lane()``, ``change_lane()`` (action and modifier), ``follow_lane()``.

The lane convention lives here: ``lane(k)`` counts 1-based from the right (the standard),
``lane(k, from: left)`` from the left, and internally 0 is the leftmost lane (the paper).
Constraints on the lane a phase started in (``keep_lane()``, ``change_lane(1, left)``) become one
variant per starting lane: guards see only the current state, and the road is finite.
"""

from __future__ import annotations

import math
from typing import ClassVar

from ..dimensions import LANE_WIDTH
from ..frontend.errors import SourceLocation, error_at
from ..frontend.semantics.library import AT, DURATION, RATE, Binding, Parameter, Signature
from ..logic.guards import LANE, Bound, Guard, Term
from ..logic.phase import Phase, Variant
from .base import ASKS_LANE, Action, AnchoredModifier, CheckContext, Modifier, Use

LANE_CONVENTION = (
    "lanes are numbered from 1 on the right (lane(1) is the rightmost); lane(k, from: left) counts from the left"
)
RELATIVE = ("same_as", "left_of", "right_of", "side_of")


def keep_lane_variants(actor: str, lanes: int, source: SourceLocation, written: str = "keep_lane()") -> list[Variant]:
    """The actor stays in whichever lane it starts the phase in (one variant per lane)."""
    text = f"{written}: l({actor}) held at its lane at the phase's start"
    return [Variant(invariant=Bound(Term(LANE, actor), lane, lane, source, text)) for lane in range(lanes)]


class Lane(AnchoredModifier):
    """``lane(k)``, ``lane([1..2])``, ``lane(k, from: left)``, ``lane(same_as:|left_of:|right_of: x)``,
    ``lane(side_of: x, side: left)``. ``left_of: x`` is the lane next to x's on the left, and
    ``lane(k, left_of: x)`` the k-th lane left of it: the standard's ``lane:`` argument counts the
    lanes to the side and defaults to 1 (CARLA's runner, too, takes the adjacent lane), not any lane on that side."""

    counted_from: ClassVar[str] = "right"  # where lane(1) is when from: is not given
    convention: ClassVar[str] = LANE_CONVENTION

    asks = ASKS_LANE
    signature = Signature(
        "lane",
        (
            Parameter("lane", "uint", positional=True),
            Parameter("right_of", "actor"),
            Parameter("left_of", "actor"),
            Parameter("same_as", "actor"),
            Parameter("side_of", "actor"),
            Parameter("side", "enum:side"),
            Parameter("from", "enum:side"),
            AT,
        ),
        exclusive=(("lane", "same_as"), RELATIVE),
        required=(("lane", *RELATIVE),),
        description="lane occupancy, absolute or relative",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        relative = [binding[name] for name in RELATIVE if binding[name] is not None]
        side = binding["from"]
        if relative and side is not None:
            context.error(side.location, "from: goes with a lane number, not with a relative lane", self.convention)
        number = binding["lane"]
        if number is None:
            return
        value = context.evaluate(number)
        # a lane number is one of the road's lanes; beside another car, a count of lanes to its side
        most = context.lanes - 1 if relative else context.lanes
        if value is None or value.dimension is not None or (1 <= value.low and value.high <= most):
            return
        shown = f"{value.low:g}" if value.is_point else str(value)
        if relative:
            context.error(
                number.value.location,
                f"{shown} lanes to the side of another car do not fit on the road's {context.lanes} lanes{context.lanes_origin}",
                "lane: counts the lanes to the side (1: the next lane)",
            )
        else:
            context.error(
                number.value.location,
                f"lane {shown} is outside the road's {context.lanes} lanes{context.lanes_origin}",
                self.convention,
            )

    def lanes_needed(self, binding, highest) -> int:
        if any(binding[name] is not None for name in ("left_of", "right_of", "side_of")):
            return highest(binding["lane"]) + 1  # the reference's lane and k more to the side
        return highest(binding["lane"])

    def guard(self, use: Use) -> Guard:
        relation = use.relation(RELATIVE)
        if relation is not None:
            keyword, other = relation
            if keyword == "same_as":
                return Bound(Term(LANE, use.actor, other), 0, 0, use.location, f"{use.actor} in {other}'s lane")
            low, high = (1, 1) if use.argument("lane") is None else self._whole(use)
            side = side_named(use, keyword)
            count = "the lane" if high == 1 else (f"{low} lanes" if low == high else f"{low}..{high} lanes")
            return lanes_to_the_side(use, other, side, low, high, f"{use.actor} in {count} {side} of {other}'s")
        if use.argument("lane") is None:
            raise error_at(
                use.location, "lane() needs a lane number or same_as:/left_of:/right_of:", hint=self.convention
            )
        low, high = self._whole(use)  # within the road: the checker's check() saw to it
        from_left = (use.name("from") or self.counted_from) == "left"
        first, last = (low - 1, high - 1) if from_left else (use.lanes - high, use.lanes - low)
        # named in the file's numbering, not the planner's (lane 0 the leftmost)
        written = f"{use.actor} in lane {low}" if low == high else f"{use.actor} in lanes {low}..{high}"
        if use.name("from") is not None:
            written += f" from the {use.name('from')}"
        return Bound(Term(LANE, use.actor), first, last, use.location, written)

    def _whole(self, use: Use) -> tuple[int, int]:
        """The ``lane:`` argument's whole numbers (a lane, or lanes to the side of a reference)."""
        value = use.interval("lane")
        if value.dimension is not None or not float(value.low).is_integer() or not float(value.high).is_integer():
            raise error_at(use.argument("lane").location, "a lane number must be a whole number", hint=self.convention)
        return int(value.low), int(value.high)


class Lateral(AnchoredModifier):
    """``lateral(distance, side_of: x, side: left|right)`` (or ``left_of: x`` / ``right_of: x``): the
    vehicle ``distance`` to the side of x, centre to centre. The planner places vehicles in lanes,
    so a distance is read as the whole lanes it spans (``LANE_WIDTH`` each, within a quarter lane:
    3.5 m is the next lane, 7 m the one beyond, 0 m x's own); one that is no whole number of lanes
    is refused at its place. ``side`` defaults to left, as for ``lane(side_of: x)``."""

    asks = ASKS_LANE
    signature = Signature(
        "lateral",
        (
            Parameter("distance", "length", positional=True),
            Parameter("side_of", "actor"),
            Parameter("side", "enum:side"),
            Parameter("left_of", "actor"),
            Parameter("right_of", "actor"),
            AT,
        ),
        exclusive=(("side_of", "left_of", "right_of"),),
        required=(("distance",), ("side_of", "left_of", "right_of")),
        description="lateral distance to another vehicle, in whole lanes",
    )

    def guard(self, use: Use) -> Guard:
        keyword, other = use.relation(("side_of", "left_of", "right_of"))
        distance = use.interval("distance")
        tolerance = LANE_WIDTH / 4  # a car off its lane's centre by up to a quarter lane is in it
        low = max(0, math.ceil((distance.low - tolerance) / LANE_WIDTH))
        high = math.floor((distance.high + tolerance) / LANE_WIDTH)
        if low > high or high >= use.lanes:
            raise error_at(
                use.argument("distance").location,
                f"a lateral distance of {shown_metres(distance)} is no whole number of lanes ({LANE_WIDTH:g} m) on the road's {use.lanes} lanes",
                "this tool places vehicles in lanes: give a multiple of the lane width, or use lane(k, side_of: x)",
            )
        side = side_named(use, keyword)
        return lanes_to_the_side(use, other, side, low, high, f"{use.actor} {shown_metres(distance)} {side} of {other}")


def side_named(use: Use, keyword: str) -> str:
    """``left`` or ``right``: the side ``left_of:``/``right_of:`` names, or ``side:`` of
    ``side_of:`` (default left)."""
    if keyword == "side_of":
        return "left" if use.name("side") in (None, "left") else "right"
    return "left" if keyword == "left_of" else "right"


def lanes_to_the_side(use: Use, other: str, side: str, low: int, high: int, written: str) -> Bound:
    """The use's actor ``low..high`` lanes to ``side`` of ``other``'s lane. Internally lane 0 is
    the leftmost: a lane left of x's has the smaller number."""
    first, last = (-high, -low) if side == "left" else (low, high)
    return Bound(Term(LANE, use.actor, other), first, last, use.location, written)


def shown_metres(distance) -> str:
    """A lateral distance as a message names it: ``3.5 m`` or ``3..4 m``."""
    return f"{distance.low:g} m" if distance.is_point else f"{distance.low:g}..{distance.high:g} m"


class KeepLane(Modifier):
    """``keep_lane()``: the lane held at the phase's start, throughout."""

    signature = Signature("keep_lane", (), description="stay in the lane held at the phase's start")

    def translate(self, use: Use, phase: Phase) -> None:
        phase.branch(keep_lane_variants(use.actor, use.lanes, use.location))


class FollowLane(Action):
    """``follow_lane()``: drive on in the lane the phase starts in."""

    signature = Signature(
        "follow_lane", (DURATION, Parameter("offset", "length", supported=False)), description="stay in the lane"
    )

    def translate(self, use: Use, phase: Phase) -> None:
        phase.branch(keep_lane_variants(use.actor, use.lanes, use.location, "follow_lane()"))


class _LaneChange:
    """What the action and the modifier ``change_lane`` share: ``num_of_lanes`` lanes (default 1;
    a range such as [1..2] is one variant per count, and a sample picks one) to ``side`` (either side when not given), relative to the lane the phase started in or, for the
    action with ``reference:``, ending that many lanes beside another actor."""

    count: ClassVar[str] = "num_of_lanes"  # the argument that says how many lanes

    def asked_at_start(self, binding: Binding) -> bool:
        """A change of lanes is asked within its phase, from whichever lane the phase starts in:
        the modifier asks no lane at the phase's first instant (no move in the phase before)."""
        return False

    def check(self, binding: Binding, context: CheckContext) -> None:
        count = binding[self.count]
        if count is None:
            return
        value = context.evaluate(count)
        if (
            value is not None
            and value.dimension is None
            and value.low >= 0
            and (value.low < 1 or value.high > context.lanes - 1)
        ):
            context.error(
                count.value.location,
                f"a change of {value} lanes is impossible on a road of {context.lanes} lanes{context.lanes_origin}",
                f"{self.count} must be between 1 and {context.lanes - 1}",
            )

    def lanes_needed(self, binding, highest) -> int:
        return highest(binding[self.count]) + 1

    def translate(self, use: Use, phase: Phase) -> None:
        counts = range(1, 2)
        if use.argument(self.count) is not None:
            value = use.interval(self.count)
            if not float(value.low).is_integer() or not float(value.high).is_integer():
                raise error_at(
                    use.argument(self.count).location,
                    "the number of lanes to change must be a whole number or a range of them, e.g. [1..2]",
                )
            counts = range(max(1, int(value.low)), int(value.high) + 1)
        side = use.name("side")
        reference = use.name("reference")
        variants = []
        shown = f"{counts[0]}" if len(counts) == 1 else f"{counts[0]} to {counts[-1]}"
        for count in counts:
            for direction in ("left", "right") if side is None else (side,):
                step = -count if direction == "left" else count  # internal lanes grow to the right
                if reference is not None and reference != use.actor:
                    variants.append(Variant(end=Bound(Term(LANE, use.actor, reference), step, step, use.location)))
                    continue
                written = (
                    f"change_lane(): l({use.actor}) ends {shown} lane{'s' if shown != '1' else ''} "
                    f"{side or 'left or right'} of its lane at the phase's start"
                )
                for lane in range(use.lanes):
                    if 0 <= lane + step < use.lanes:
                        variants.append(
                            Variant(
                                start=Bound(Term(LANE, use.actor), lane, lane, use.location, written),
                                end=Bound(Term(LANE, use.actor), lane + step, lane + step, use.location, written),
                            )
                        )
        if not variants:
            raise error_at(use.location, f"a change of {shown} lanes is impossible on a road of {use.lanes} lanes")
        phase.branch(variants)


class ChangeLaneAction(_LaneChange, Action):
    asks = ASKS_LANE
    signature = Signature(
        "change_lane",
        (
            Parameter("num_of_lanes", "uint", positional=True),
            Parameter("side", "enum:side", positional=True),
            Parameter("reference", "actor"),
            DURATION,
            *RATE,
        ),
        description="move num_of_lanes lanes (default 1) to the side",
    )


class ChangeLaneModifier(_LaneChange, Modifier):
    asks = ASKS_LANE
    signature = Signature(
        "change_lane",
        (Parameter("num_of_lanes", "uint", positional=True), Parameter("side", "enum:side", positional=True)),
        description="change lanes during the phase",
    )


CONSTRUCTS = (Lane(), Lateral(), KeepLane(), FollowLane(), ChangeLaneAction(), ChangeLaneModifier())
__all__ = ["CONSTRUCTS", "LANE_CONVENTION", "keep_lane_variants"]
