"""The standard's gap actions: the actor follows a reference at a space gap or a time gap.

- ``keep_space_gap(gap, reference: r)``: throughout the phase, r is ahead by the gap, p(r) - p(a)
  (centres, as ``position`` measures); ``keep_time_gap(gap, reference: r)``: the same as a time
  headway, the gap over the actor's speed (``position(time:)``'s quantity).
- ``change_space_gap(target, reference: r)``, ``change_time_gap(target, reference: r)``: the gap
  is the target at the phase's end.

A gap is the follower's: the reference is ahead (a vehicle that must lead its reference writes
``position(d, ahead_of: r)``). ``direction: lateral`` is refused: a lateral gap needs lateral
positions, which the plan does not have. A single value is read +- the tolerance of ``position``.
A kept range holds throughout the phase, so it is a bound the plan stays within, not a sampled
parameter; a change's target is one instant's, so it is one.
"""

from __future__ import annotations

from typing import ClassVar

from ..frontend import model
from ..frontend.semantics.library import DURATION, Binding, Parameter, Signature
from ..logic.guards import HEADWAY
from ..logic.phase import Phase
from .base import ASKS_SPEED, Action, CheckContext, Use
from .position import GAPS, Gap, gap_bound


class GapAction(Action):
    """One of the four: which argument holds the gap, what it measures, and where it holds."""

    argument: ClassVar[str]  # "gap" (keep) or "target" (change)
    gap: ClassVar[Gap]  # position()'s distance or time headway
    what: ClassVar[str]  # "a space gap" or "a time gap", in messages
    anchor: ClassVar[str]  # "all" (keep) or "end" (change)
    asks = ASKS_SPEED  # a gap is kept or changed by the actor's own speed

    def check(self, binding: Binding, context: CheckContext) -> None:
        direction = binding["direction"]
        if (
            direction is not None
            and isinstance(direction.value, model.Name)
            and direction.value.name.rpartition(".")[2] == "lateral"
        ):
            context.error(
                direction.location,
                f"not supported: {self.name}(direction: lateral)",
                "a lateral gap needs lateral positions, which the plan does not have: use lane(side_of: ...)",
            )

    def held_throughout(self, binding: Binding) -> bool:
        return self.anchor == "all"

    def sampled_as(self, argument: str) -> str | None:
        return "headway" if self.gap.quantity == HEADWAY and argument == self.argument else None

    def translate(self, use: Use, phase: Phase) -> None:
        reference = use.name("reference")  # required: the checker saw to it
        hint = "a gap is to a reference ahead; for one behind, use position(d, ahead_of: ...)"
        phase.anchor(gap_bound(use, self.argument, self.gap, reference, use.actor, hint, self.what), self.anchor)


def _gap_action(name: str, argument: str, gap: Gap, what: str, anchor: str, description: str) -> GapAction:
    signature = Signature(
        name,
        (
            Parameter(argument, gap.dimension, positional=True),
            Parameter("direction", "enum:direction"),
            Parameter("reference", "actor"),
            DURATION,
        ),
        required=((argument,), ("reference",)),
        description=description,
    )
    attributes = {
        "signature": signature,
        "argument": argument,
        "gap": gap,
        "what": what,
        "anchor": anchor,
        "__doc__": f"``{name}()``: {description}",
    }
    return type(name, (GapAction,), attributes)()


SPACE, TIME_GAP = GAPS["distance"], GAPS["time"]
CONSTRUCTS = (
    _gap_action("keep_space_gap", "gap", SPACE, "a space gap", "all", "follow the reference at a space gap throughout"),
    _gap_action("keep_time_gap", "gap", TIME_GAP, "a time gap", "all", "follow the reference at a time gap throughout"),
    _gap_action(
        "change_space_gap",
        "target",
        SPACE,
        "a space gap",
        "end",
        "reach a space gap to the reference by the phase's end",
    ),
    _gap_action(
        "change_time_gap",
        "target",
        TIME_GAP,
        "a time gap",
        "end",
        "reach a time gap to the reference by the phase's end",
    ),
)
