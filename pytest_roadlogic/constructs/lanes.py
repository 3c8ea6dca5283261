"""Lanes: ``lane()``, ``keep_lane()``, ``change_lane()`` (action and modifier), ``follow_lane()``.

The lane convention lives here: ``lane(k)`` counts 1-based from the right (the standard),
``lane(k, from: left)`` from the left, and internally 0 is the leftmost lane (the paper).
Constraints on the lane a phase started in (``keep_lane()``, ``change_lane(1, left)``) become one
variant per starting lane: guards see only the current state, and the road is finite.
"""

from __future__ import annotations

import math
from typing import ClassVar

from ..dimensions import CAR_WIDTH, LANE_WIDTH
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
    ``lane(side_of: x, side: left)``; ``lane()`` is ``lane(1)``. ``left_of: x`` is the lane next to x's on the left, and
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
        description="lane occupancy, absolute or relative (lane() is lane(1), the standard's default)",
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
        # lane() is lane(1): the standard's default lane (its domain model calls lane(), lane(1)
        # and lane(lane: 1) the same)
        low, high = (1, 1) if use.argument("lane") is None else self._whole(use)  # within the road: check() saw to it
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


# where on a vehicle (or a lane) a lateral() distance is measured from (its ``measure_by``): the
# offset of the named side from the centre, positive to the left, in widths
_SIDE_OFFSET = {"left": 0.5, "center": 0.0, "right": -0.5}


class Lateral(AnchoredModifier):
    """``lateral(distance, side_of: x, side: left|right, measure_by: m)`` (or ``left_of: x`` /
    ``right_of: x``): the vehicle ``distance`` to the side of x, measured between the sides
    ``measure_by`` names (``center_to_center``, the default; ``right_to_left``: this vehicle's
    right side to x's left side; ``closest``: the free space between the two). The planner places
    vehicles in lanes, so the distance between centres it makes (vehicles are ``CAR_WIDTH`` wide)
    is read as the whole lanes it spans (``LANE_WIDTH`` each, within a quarter lane: 3.5 m is the
    next lane, 7 m the one beyond, 0 m x's own); one that is no whole number of lanes is refused
    at its place. ``side`` defaults to left, as for ``lane(side_of: x)``.

    Without a reference (the standard's Euro NCAP example: ``lateral(1m, measure_by:
    left_to_left)``) the distance places the vehicle inside its own lane, from the lane's
    markings; vehicles drive on their lane's centre line, so that is read with a warning, and a
    distance that puts the vehicle across a marking is refused."""

    asks = ASKS_LANE
    signature = Signature(
        "lateral",
        (
            Parameter("distance", "length", positional=True, ranged=True),
            Parameter("side_of", "actor"),
            Parameter("side", "enum:side"),
            Parameter("left_of", "actor"),
            Parameter("right_of", "actor"),
            Parameter("measure_by", "enum:lat_measure_by"),
            AT,
        ),
        exclusive=(("side_of", "left_of", "right_of"),),
        required=(("distance",),),
        description="lateral distance to another vehicle (in whole lanes), or inside the own lane",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        if _referenced(binding):
            return
        distance = context.evaluate(binding["distance"])
        if distance is None or distance.dimension != "length":
            return
        measure = binding["measure_by"].value.name if binding["measure_by"] is not None else "center_to_center"
        offsets = [_offset_in_lane(measure, value) for value in (distance.low, distance.high)]
        place_in_lane(
            context,
            binding["distance"],
            offsets,
            f"lateral({shown_metres(distance)}, measure_by: {measure})",
            "without side_of:, the distance is measured from the vehicle's own lane; give one that keeps it "
            "in the lane, or name the vehicle it is measured from (side_of: x)",
            inward_only=measure == "closest",
        )

    def asked_within(self, binding: Binding) -> bool:
        """A place inside the own lane asks no lane (least action): only one beside another car does."""
        return _referenced(binding) and super().asked_within(binding)

    def asked_at_start(self, binding: Binding) -> bool:
        return _referenced(binding) and super().asked_at_start(binding)

    def translate(self, use: Use, phase: Phase) -> None:
        if not _referenced(use.binding):
            return None  # a place inside the own lane: warned at check
        super().translate(use, phase)

    def guard(self, use: Use) -> Guard:
        keyword, other = use.relation(("side_of", "left_of", "right_of"))
        side = side_named(use, keyword)
        distance = use.interval("distance")
        measure = use.name("measure_by") or "center_to_center"
        # the vehicle's centre off x's, positive to the left (a negative distance: the other side)
        offsets = sorted(_centre_offset(measure, side, value) for value in (distance.low, distance.high))
        tolerance = LANE_WIDTH / 4  # a car off its lane's centre by up to a quarter lane is in it
        left_low = math.ceil((offsets[0] - tolerance) / LANE_WIDTH)  # whole lanes to the left of x's
        left_high = math.floor((offsets[1] + tolerance) / LANE_WIDTH)
        if left_low > left_high or max(abs(left_low), abs(left_high)) >= use.lanes:
            measured = "" if measure == "center_to_center" else f", {offsets[0]:g}..{offsets[1]:g} m centre to centre"
            raise error_at(
                use.argument("distance").location,
                f"a lateral distance of {shown_metres(distance)}{measured} is no whole number of lanes "
                f"({LANE_WIDTH:g} m) on the road's {use.lanes} lanes",
                "this tool places vehicles in lanes: give a multiple of the lane width, or use lane(k, side_of: x)",
            )
        measured = "" if measure == "center_to_center" else f" ({measure})"
        written = f"{use.actor} {shown_metres(distance)}{measured} {side} of {other}"
        # internally lane 0 is the leftmost: a lane k to the left of x's is x's minus k
        return Bound(Term(LANE, use.actor, other), -left_high, -left_low, use.location, written)


def _referenced(binding: Binding) -> bool:
    """Whether a lateral() use names the vehicle it is measured from."""
    return any(binding[name] is not None for name in ("side_of", "left_of", "right_of"))


def place_in_lane(
    context: CheckContext, argument, offsets: list[float], written: str, hint: str, inward_only: bool = False
) -> None:
    """A use that places its vehicle inside its own lane, ``offsets`` (metres, positive to the
    left) off the lane's centre line: vehicles drive on that line, so a place that keeps the
    vehicle between its lane's markings is read with one warning, and one across a marking (or,
    ``inward_only``, a negative offset) is refused at ``argument``."""
    room = (LANE_WIDTH - CAR_WIDTH) / 2
    if any(abs(offset) > room + 1e-9 or (inward_only and offset < 0) for offset in offsets):
        context.error(
            argument.value.location,
            f"{written} puts the vehicle across its lane's marking ({CAR_WIDTH:g} m wide, in a lane of "
            f"{LANE_WIDTH:g} m: at most {room:g} m off its centre)",
            hint,
        )
        return
    context.warning(
        context.location,
        f"{written} is read but not simulated: vehicles drive on their lane's centre line",
        "the vehicle keeps its lane; remove it to silence this warning",
    )


def _sides(measure: str) -> tuple[float, float]:
    """The offsets from centre (positive to the left, in metres) of the two sides ``measure`` names:
    this vehicle's, then the reference's (``left_to_right``: this one's left, the other's right)."""
    mine, _, theirs = measure.partition("_to_")
    return _SIDE_OFFSET[mine] * CAR_WIDTH, _SIDE_OFFSET[theirs] * CAR_WIDTH


def _centre_offset(measure: str, side: str, distance: float) -> float:
    """Where the centre of a vehicle ``distance`` to ``side`` of another lies from the other's
    centre, positive to the left, measured by ``measure``. With its centre at ``o``, the measured
    sides lie ``o + mine - theirs`` apart, ``distance`` on ``side`` (sign +1 left, -1 right); a
    negative distance is the other side, as the standard reads it."""
    sign = 1 if side == "left" else -1
    if measure == "closest":
        return sign * (distance + CAR_WIDTH)  # the free space between two boxes side by side
    mine, theirs = _sides(measure)
    return sign * distance - (mine - theirs)


def _offset_in_lane(measure: str, distance: float) -> float:
    """The offset (positive to the left) from its lane's centre line of a vehicle whose side
    ``measure`` names lies ``distance`` inside the lane's marking it names (``left_to_left``:
    its left side that far right of the lane's left marking; ``closest``: its side nearer a
    marking that far from it, negative when no side can be that far)."""
    if measure == "closest":
        return (LANE_WIDTH - CAR_WIDTH) / 2 - distance
    mine, _, marking = measure.partition("_to_")
    edge = _SIDE_OFFSET[marking] * LANE_WIDTH  # the marking (or centre line) off the lane's centre
    inward = -1 if marking == "left" else 1  # from the marking into the lane
    return edge + inward * distance - _SIDE_OFFSET[mine] * CAR_WIDTH


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

    signature = Signature("follow_lane", (DURATION, Parameter("offset", "length")), description="stay in the lane")

    def check(self, binding: Binding, context: CheckContext) -> None:
        """``offset:`` (the standard's: off the lane's centre line, inside the lane) is read with a
        warning, as vehicles drive on the centre line (``place_in_lane``)."""
        if binding["offset"] is None:
            return
        offset = context.evaluate(binding["offset"])
        if offset is None or offset.dimension != "length":
            return
        place_in_lane(
            context,
            binding["offset"],
            [offset.low, offset.high],
            f"follow_lane(offset: {shown_metres(offset)})",
            "offset: is measured from the lane's centre line; give one that keeps the vehicle in its lane",
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
        (
            # the standard's 2.2 names it lane (change_lane(lane: 2, side: left)), 2.0 num_of_lanes
            Parameter("num_of_lanes", "uint", positional=True, aliases=("lane",)),
            Parameter("side", "enum:side", positional=True),
        ),
        description="change lanes during the phase",
    )


CONSTRUCTS = (Lane(), Lateral(), KeepLane(), FollowLane(), ChangeLaneAction(), ChangeLaneModifier())
__all__ = ["CONSTRUCTS", "LANE_CONVENTION", "keep_lane_variants"]
