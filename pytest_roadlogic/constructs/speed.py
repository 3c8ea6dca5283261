"""Speed: the ``speed()``, ``keep_speed()`` and ``acceleration()`` modifiers, the ``change_speed()``, ``assign_speed()`` and ``keep_speed()`` actions.

``keep_speed`` refers to the speed the phase started with, which a guard cannot see: it becomes a
bound over the phase (``HeldSpeed``), the speed within ``KEEP_SPEED_BAND`` of its first value at
every instant.
"""

from __future__ import annotations

import math

from ..frontend import model
from ..frontend.errors import error_at
from ..frontend.semantics.library import AT, DURATION, Binding, Parameter, Signature
from ..frontend.semantics.tolerances import ACCELERATION_TOLERANCE, SPEED_TOLERANCE, widened
from ..frontend.semantics.values import EvaluationError, evaluate
from ..frontend.syntax.units import ACCELERATION, SPEED
from ..logic.automaton import HeldSpeed, MeanAcceleration, ShapedSpeedChange
from ..logic.guards import SPEED as SPEED_Q
from ..logic.guards import Bound, Guard, Term
from ..logic.phase import Phase
from .base import ASKS_SPEED, Action, AnchoredModifier, CheckContext, Modifier, Use

# m/s: how far a kept speed may stray from the phase's first speed, either way (a tracking
# controller's wobble through a lane change)
KEEP_SPEED_BAND = 1.5
RELATIONS = ("faster_than", "slower_than", "same_as")


def held_speed(use: Use) -> HeldSpeed:
    """keep_speed()'s bound over its phase: the actor's speed within ``KEEP_SPEED_BAND`` of the phase's first."""
    return HeldSpeed(use.actor, -math.inf, KEEP_SPEED_BAND, source=use.location)


def refuse_negative_speed(binding: Binding, argument: str, context: CheckContext, relative: bool = False) -> None:
    """A speed below 0 is an error at its place: vehicles drive forward, and the planner would read
    speed(-20kph) as 0 kph and only ``run`` say "no plan"."""
    given = binding[argument]
    value = context.evaluate(given) if given is not None else None
    # an unbounded parameter (-inf) is reported as such where it is declared
    if value is not None and value.low < 0 and math.isfinite(value.low):
        hint = (
            "a relative speed is by how much: swap faster_than and slower_than"
            if relative
            else "vehicles drive forward; give a speed from 0 up, e.g. [20..40]kph"
        )
        context.error(given.value.location, "a speed must not be negative", hint)


class Speed(AnchoredModifier):
    """``speed(v)``, ``speed([a..b])``; relative: ``faster_than: x`` / ``slower_than: x`` (by the
    value), ``same_as: x`` (within the value, default 0 +- the tolerance)."""

    asks = ASKS_SPEED
    signature = Signature(
        "speed",
        (Parameter("speed", "speed", positional=True, ranged=True), *(Parameter(r, "actor") for r in RELATIONS), AT),
        exclusive=(RELATIONS,),
        required=(("speed", "same_as"),),
        description="absolute speed, or relative to another actor's",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        super().check(binding, context)
        refuse_negative_speed(binding, "speed", context, relative=any(binding[r] is not None for r in RELATIONS))

    def translate(self, use: Use, phase: Phase) -> None:
        guard, anchor = self.guard(use), self.anchor(use.binding)
        phase.anchor(guard, anchor)
        if anchor == "all" and guard.term.reference is None and guard.high <= SPEED_TOLERANCE:
            # a car asked to stand (``speed(0kph)`` throughout) makes no progress to require: it
            # stands, as one that braked to a standstill does (``change_speed`` to 0)
            phase.drives = False

    def guard(self, use: Use) -> Guard:
        relation = use.relation(RELATIONS)
        if use.argument("speed") is None:
            if relation is None or relation[0] != "same_as":
                raise error_at(use.location, "speed() needs a speed, e.g. speed([20..30]kph)")
            low = high = 0.0
        else:
            low, high = use.range("speed", SPEED, "a speed such as 20mps or [50..80]kph")
        low, high = widened(low, high, SPEED_TOLERANCE)
        if relation is None:
            return Bound(Term(SPEED_Q, use.actor), max(0.0, low), high, use.location)
        keyword, other = relation
        if keyword == "slower_than":
            return Bound(Term(SPEED_Q, other, use.actor), low, high, use.location)
        return Bound(Term(SPEED_Q, use.actor, other), low, high, use.location)  # faster_than; same_as: within the value


class KeepSpeedModifier(Modifier):
    signature = Signature("keep_speed", (), description="hold the speed from the phase's start")

    def translate(self, use: Use, phase: Phase) -> None:
        phase.rates.append(held_speed(use))


class KeepSpeedAction(Action):
    signature = Signature("keep_speed", (DURATION,), description="hold the speed from the phase's start")

    def translate(self, use: Use, phase: Phase) -> None:
        phase.rates.append(held_speed(use))


# a speed change's rate_profile (the standard's dynamics_shape since 2.0, rate_profile in 1.0) -> the
# shape this tool plans: 1.0's constant rate is linear, its asap a step; smooth, the motion planner's
# own (rate_peak then bounds the acceleration)
SHAPES = {
    "linear": "linear",
    "constant": "linear",
    "cubic": "cubic",
    "sinusoidal": "sinusoidal",
    "step": "step",
    "asap": "step",
    "smooth": None,
}
# m/s^2: the mean a change asked at once (step) is judged to reach at least: no car changes its
# speed at once, so it is planned at the car's limit (4 m/s^2 up, 8 down) and judged brisk
STEP_LEAST = 3.0


def profile_of(binding: Binding, env: dict) -> tuple[str | None, model.Argument | None]:
    """The rate_profile given (a member, or a parameter whose value is one) and its argument."""
    given = binding["rate_profile"]
    if given is None:
        return None, None
    try:
        value = evaluate(given.value, env)
    except EvaluationError:
        value = given.value
    return (value.name.rpartition(".")[2] if isinstance(value, model.Name) else None), given


class ChangeSpeed(Action):
    """``change_speed(target)``: the target speed (+- the tolerance for a single value) at the phase's
    end. ``rate_profile`` (the standard's ``dynamics_shape``) with ``rate_peak: p``: the speed moves
    to the target in that shape, its acceleration peaking at p (``ShapedSpeedChange``): ``linear``
    (1.0's ``constant``) at p throughout, ``cubic`` and ``sinusoidal`` from none to p and back to
    none; ``step`` (1.0's ``asap``) asks the target at once, which no car can: planned at the
    car's limit. Without a shape (or ``smooth``, what the motion planner does), ``rate_peak: p``
    bounds the acceleration within -p..p on every step (the monitor judges the mean)."""

    asks = ASKS_SPEED
    signature = Signature(
        "change_speed",
        (
            Parameter("target", "speed", positional=True),
            DURATION,
            Parameter("rate_profile", "enum:dynamics_shape"),
            Parameter("rate_peak", "acceleration"),
        ),
        required=(("target",),),
        description="reach the target speed",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        refuse_negative_speed(binding, "target", context)
        peak = binding["rate_peak"]
        value = context.evaluate(peak) if peak is not None else None
        if value is not None and value.low <= 0:
            context.error(peak.value.location, "rate_peak must be a positive acceleration", "e.g. rate_peak: 3mpss")
        shape, given = profile_of(binding, {})
        if given is None or shape not in SHAPES or SHAPES[shape] is None:
            return
        if SHAPES[shape] == "step":
            if peak is not None:
                context.warning(
                    peak.location,
                    f"rate_peak has no effect with rate_profile: {shape}: the target is asked at once, "
                    "which a car meets at its limit",
                    "drop rate_peak, or give rate_profile: linear to change at that rate",
                )
        elif peak is None:
            context.error(
                given.location,
                f"rate_profile: {shape} needs rate_peak: the peak acceleration of the change",
                "e.g. rate_profile: linear, rate_peak: 3mpss",
            )

    def translate(self, use: Use, phase: Phase) -> None:
        if use.argument("target") is None:
            raise error_at(use.location, "change_speed() needs a target speed, e.g. change_speed(target: 20mps)")
        low, high = widened(*use.range("target", SPEED, "a speed such as 20mps"), SPEED_TOLERANCE)
        phase.add(end=Bound(Term(SPEED_Q, use.actor), max(0.0, low), high, use.location))
        if low <= 0:
            # a car braking to a standstill stands there: it makes no progress to require, and its
            # speed at the end (and an asked rate) say what it does
            phase.drives = False
        name, given = profile_of(use.binding, use.env)
        shape = SHAPES.get(name) if name is not None else None
        if shape == "step":
            phase.rates.append(
                ShapedSpeedChange(
                    use.actor, STEP_LEAST, math.inf, source=given.location, shape=shape, target=(max(0.0, low), high)
                )
            )
            return
        if use.argument("rate_peak") is None:
            return
        peak_low, peak = use.range("rate_peak", ACCELERATION, "an acceleration such as 3mpss")
        source = use.argument("rate_peak").location
        if shape is None:
            phase.rates.append(MeanAcceleration(use.actor, -peak, peak, source=source, standstill=SPEED_TOLERANCE))
            return
        peak_low, peak = widened(peak_low, peak, ACCELERATION_TOLERANCE)
        phase.rates.append(
            ShapedSpeedChange(
                use.actor, max(0.0, peak_low), peak, source=source, shape=shape, target=(max(0.0, low), high)
            )
        )


class AssignSpeed(Action):
    """``assign_speed(target)``: the speed is the target (+- the tolerance) at the phase's start.
    The standard's assignment is instantaneous; a simulated car cannot jump to a speed, so the plan
    reaches it by the phase's start, and the monitor checks it there."""

    asks = ASKS_SPEED
    signature = Signature(
        "assign_speed",
        (Parameter("target", "speed", positional=True), DURATION),
        required=(("target",),),
        description="the speed at the phase's start",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        refuse_negative_speed(binding, "target", context)

    def translate(self, use: Use, phase: Phase) -> None:
        low, high = widened(*use.range("target", SPEED, "a speed such as 20mps"), SPEED_TOLERANCE)
        phase.add(start=Bound(Term(SPEED_Q, use.actor), max(0.0, low), high, use.location))


class Acceleration(Modifier):
    """``acceleration([a..b])``: the actor's mean acceleration over the phase,
    (v(end) - v(start)) / duration, lies in the range (``MeanAcceleration`` says why the mean).
    A range held over the phase is a bound, not a sampled parameter."""

    asks = ASKS_SPEED
    signature = Signature(
        "acceleration",
        (Parameter("acceleration", "acceleration", positional=True, ranged=True), AT),
        required=(("acceleration",),),
        description="the mean acceleration over the phase",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        at = binding["at"]
        if at is not None and isinstance(at.value, model.Name) and at.value.name in ("start", "end"):
            context.error(
                at.location,
                f"not supported: acceleration at: {at.value.name} (the acceleration of one instant)",
                "drop at: the phase's mean acceleration is what this tool plans and checks",
            )

    def held_throughout(self, binding: Binding) -> bool:
        return True

    def translate(self, use: Use, phase: Phase) -> None:
        low, high = widened(
            *use.range("acceleration", ACCELERATION, "an acceleration such as -3mpsps or [-6..-3]mpsps"),
            ACCELERATION_TOLERANCE,
        )
        phase.rates.append(MeanAcceleration(use.actor, low, high, source=use.location, standstill=SPEED_TOLERANCE))


CONSTRUCTS = (Speed(), KeepSpeedModifier(), KeepSpeedAction(), ChangeSpeed(), AssignSpeed(), Acceleration())
