"""From an invocation (action + modifiers) to the guards of its phase.

This is where OS2's spelling meets the guard algebra: ``position([10..20]m, behind: v2, at: start)``
becomes ``10 <= p(v2) - p(v1) <= 20`` on the phase's start transition, and ``lane(1)`` (no ``at:``,
so ``at: all``) becomes an invariant of the phase's location. The lane convention lives here too:
``lane(k)`` counts 1-based from the right (the standard), ``lane(k, from: left)`` from the left, and
internally 0 is the leftmost lane (the paper).

Some constraints refer to the value a quantity had when the phase started (``keep_lane()``,
``change_lane(1, left)``, ``keep_speed()``). Guards only see the current state, so such a phase
becomes a choice: one variant per starting lane (the road is finite), or per 1 m/s speed band
from 0 to 40 m/s for ``keep_speed`` (the speed starts within 0.5 m/s of the band's value and stays
within 1 m/s of it), each with plain guards.

The front-end checker has already validated names, argument kinds and lane numbers; the errors
raised here are for what the automaton cannot express.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..frontend import library, model
from ..frontend.checker import LANE_CONVENTION
from ..frontend.errors import SourceLocation, error_at
from ..frontend.units import LENGTH, SPEED, TIME
from ..frontend.values import EvaluationError, Interval, evaluate
from .guards import LANE, POSITION, SPEED as SPEED_Q, TRUE, Bound, Guard, Term, conjunction

SUPPORTED_ACTIONS = ("drive", "change_lane", "change_speed", "follow_lane", "keep_speed", "remain_stationary")
SUPPORTED_MODIFIERS = ("lane", "position", "speed", "keep_lane", "keep_speed", "change_lane")
# A single value cannot be met exactly by a continuous trace; speeds are read as value +- 0.5 m/s
# and distances as value +- 1 m (one planning cell).
SPEED_TOLERANCE = 0.5
POSITION_TOLERANCE = 1.0
# and a single duration as value +- 0.5 s (the planner's time step is 1 s)
DURATION_TOLERANCE = 0.5
# What "standing still" means for a trace's speed, in m/s.
STANDSTILL = 0.1
# keep_speed(): the speed at the phase's start lies within half a band of one of these values,
# and stays within a band of it throughout (so it varies by 1.5 m/s at most).
KEEP_SPEED_CENTRES = tuple(float(v) for v in range(0, 41))
KEEP_SPEED_BAND = 1.0


@dataclass(frozen=True)
class Variant:
    """One way the phase can go: the guard at its start, at its end, and throughout."""

    start: Guard = TRUE
    end: Guard = TRUE
    invariant: Guard = TRUE


@dataclass
class Phase:
    """The guards of one atomic phase; several variants when it depends on a starting lane."""

    actor: str
    variants: list[Variant] = field(default_factory=lambda: [Variant()])
    drives: bool = True  # whether the actor must make forward progress in this phase

    def add(self, start: Guard = TRUE, end: Guard = TRUE, invariant: Guard = TRUE) -> None:
        self.variants = [
            Variant(conjunction([v.start, start]), conjunction([v.end, end]), conjunction([v.invariant, invariant]))
            for v in self.variants
        ]

    def branch(self, options: list[Variant]) -> None:
        """Multiply the variants by ``options`` (each existing variant combined with each option)."""
        self.variants = [
            Variant(conjunction([v.start, o.start]), conjunction([v.end, o.end]), conjunction([v.invariant, o.invariant]))
            for v in self.variants
            for o in options
        ]


def phase_guards(invocation: model.Invocation, scenario: model.Scenario, lanes: int, env: dict | None = None) -> Phase:
    """The guards of one atomic phase; ``env`` gives the parameters' values or ranges."""
    env = env or {}
    actor = _actor(invocation, scenario)
    if invocation.action not in SUPPORTED_ACTIONS:
        raise error_at(
            invocation.location,
            f"not supported yet by the automaton: action {invocation.action!r}",
            hint=f"this version translates {', '.join(a + '()' for a in SUPPORTED_ACTIONS)}",
        )
    if invocation.until is not None:
        raise error_at(invocation.location, "not supported yet by the automaton: until")
    if invocation.constraints:
        raise error_at(invocation.constraints[0].location, "not supported yet by the automaton: keep() on an invocation")
    phase = Phase(actor)
    _action(invocation, phase, scenario, lanes, env)
    for modifier in invocation.modifiers:
        _modifier(modifier, phase, scenario, lanes, env)
    return phase


def _actor(invocation: model.Invocation, scenario: model.Scenario) -> str:
    if invocation.actor is None:
        raise error_at(invocation.location, f"{invocation.action}() needs an actor", hint="write it as v1.drive()")
    if scenario.actor(invocation.actor) is None:
        known = ", ".join(a.name for a in scenario.actors) or "none"
        raise error_at(invocation.location, f"unknown actor {invocation.actor!r}", hint=f"the scenario declares: {known}")
    return invocation.actor


# ---------------------------------------------------------------- actions


def _action(invocation: model.Invocation, phase: Phase, scenario: model.Scenario, lanes: int, env: dict) -> None:
    actor = phase.actor
    action = invocation.action
    args = library.bind(library.ACTIONS[action], invocation.arguments)
    if action == "remain_stationary":
        phase.drives = False
        phase.add(invariant=Bound(Term(SPEED_Q, actor), -STANDSTILL, STANDSTILL, invocation.location))
    elif action == "follow_lane":
        phase.branch(_keep_lane_variants(actor, lanes, invocation.location))
    elif action == "keep_speed":
        phase.branch(_keep_speed_variants(actor, invocation.location))
    elif action == "change_speed":
        target = args["target"]
        if target is None:
            raise error_at(invocation.location, "change_speed() needs a target speed, e.g. change_speed(target: 20mps)")
        low, high = _interval(target, SPEED, "a speed such as 20mps", env)
        if low == high:
            low, high = low - SPEED_TOLERANCE, high + SPEED_TOLERANCE
        phase.add(end=Bound(Term(SPEED_Q, actor), max(0.0, low), high, invocation.location))
    elif action == "change_lane":
        phase.branch(_lane_change_variants(actor, args["num_of_lanes"], args["side"], args["reference"], lanes, invocation.location, env))


def _keep_lane_variants(actor: str, lanes: int, source) -> list[Variant]:
    return [Variant(invariant=Bound(Term(LANE, actor), lane, lane, source)) for lane in range(lanes)]


def _keep_speed_variants(actor: str, source) -> list[Variant]:
    return [
        Variant(
            start=Bound(Term(SPEED_Q, actor), max(0.0, c - KEEP_SPEED_BAND / 2), c + KEEP_SPEED_BAND / 2, source),
            invariant=Bound(Term(SPEED_Q, actor), max(0.0, c - KEEP_SPEED_BAND), c + KEEP_SPEED_BAND, source),
        )
        for c in KEEP_SPEED_CENTRES
    ]


def _lane_change_variants(actor, count_arg, side_arg, reference_arg, lanes, source, env) -> list[Variant]:
    count = 1
    if count_arg is not None:
        value = _evaluate(count_arg, env)
        if not value.is_point or not float(value.low).is_integer():
            raise error_at(count_arg.location, "the number of lanes to change must be one whole number")
        count = int(value.low)
    sides = ("left", "right") if side_arg is None else (_name(side_arg),)
    variants = []
    for side in sides:
        step = -count if side == "left" else count  # internal lanes grow to the right
        if reference_arg is not None and _name(reference_arg) != actor:
            other = _name(reference_arg)
            variants.append(Variant(end=Bound(Term(LANE, actor, other), step, step, source)))
            continue
        for lane in range(lanes):
            if 0 <= lane + step < lanes:
                variants.append(
                    Variant(start=Bound(Term(LANE, actor), lane, lane, source), end=Bound(Term(LANE, actor), lane + step, lane + step, source))
                )
    if not variants:
        raise error_at(source, f"a change of {count} lanes is impossible on a road of {lanes} lanes")
    return variants


def _name(argument: model.Argument) -> str:
    value = argument.value
    if not isinstance(value, model.Name):
        raise error_at(argument.location, f"`{argument.name or 'this argument'}` takes a name")
    return value.name


# ---------------------------------------------------------------- modifiers


def _modifier(modifier: model.Modifier, phase: Phase, scenario: model.Scenario, lanes: int, env: dict) -> None:
    actor = phase.actor
    if modifier.name not in SUPPORTED_MODIFIERS:
        raise error_at(modifier.location, f"not supported yet by the automaton: modifier {modifier.name!r}", hint=f"supported: {', '.join(SUPPORTED_MODIFIERS)}")
    if modifier.name == "keep_lane":
        phase.branch(_keep_lane_variants(actor, lanes, modifier.location))
        return
    if modifier.name == "keep_speed":
        phase.branch(_keep_speed_variants(actor, modifier.location))
        return
    args = library.bind(library.MODIFIERS[modifier.name], modifier.arguments)
    if modifier.name == "change_lane":
        phase.branch(_lane_change_variants(actor, args["num_of_lanes"], args["side"], None, lanes, modifier.location, env))
        return
    if modifier.name == "lane":
        guard = _lane(args, modifier.location, actor, lanes, env)
    elif modifier.name == "position":
        guard = _position(args, modifier.location, actor, env)
    else:
        guard = _speed(args, modifier.location, actor, env)
    anchor = _anchor(args)
    if anchor == "start":
        phase.add(start=guard)
    elif anchor == "end":
        phase.add(end=guard)
    else:
        phase.add(invariant=guard)


def _anchor(args: library.Binding) -> str:
    argument = args["at"]
    if argument is None:
        return "all"  # the standard's default: the modifier holds throughout the phase
    value = argument.value
    if not isinstance(value, model.Name) or value.name not in ("start", "end", "all"):
        raise error_at(argument.location, "`at:` takes start, end or all")
    return value.name


def _reference(args: library.Binding, names: tuple[str, ...]) -> tuple[str, str] | None:
    """The relation keyword used (e.g. ``same_as``) and the actor it names, if any."""
    for name in names:
        if args[name] is not None:
            return name, _name(args[name])
    return None


def _lane(args: library.Binding, source, actor: str, lanes: int, env: dict) -> Guard:
    relation = _reference(args, ("same_as", "left_of", "right_of", "side_of"))
    if relation is not None:
        keyword, other = relation
        if keyword == "side_of":
            side = args["side"]
            keyword = "left_of" if side is None or _name(side) == "left" else "right_of"
        low, high = {"same_as": (0, 0), "left_of": (-math.inf, -1), "right_of": (1, math.inf)}[keyword]
        return Bound(Term(LANE, actor, other), low, high, source)
    number_arg = args["lane"]
    if number_arg is None:
        raise error_at(source, "lane() needs a lane number or same_as:/left_of:/right_of:", hint=LANE_CONVENTION)
    value = _evaluate(number_arg, env)
    if value.dimension is not None or not float(value.low).is_integer() or not float(value.high).is_integer():
        raise error_at(number_arg.location, "a lane number must be a whole number", hint=LANE_CONVENTION)
    low, high = int(value.low), int(value.high)
    if low < 1 or high > lanes:
        raise error_at(number_arg.location, f"lane {value} is outside the road's {lanes} lanes", hint=LANE_CONVENTION)
    side = args["from"]
    from_left = side is not None and _name(side) == "left"
    first, last = (low - 1, high - 1) if from_left else (lanes - high, lanes - low)
    return Bound(Term(LANE, actor), first, last, source)


def _position(args: library.Binding, source, actor: str, env: dict) -> Guard:
    if args["time"] is not None:
        raise error_at(args["time"].location, "not supported yet by the automaton: position(time: ...)", hint="give the gap as a distance")
    relation = _reference(args, ("behind", "ahead_of"))
    if relation is None:
        raise error_at(source, "position() needs behind: or ahead_of: another actor")
    distance = args["distance"]
    if distance is None:
        raise error_at(source, "position() needs a distance, e.g. position([10..20]m, behind: v2)")
    low, high = _interval(distance, LENGTH, "a length such as 10m or [10..20]m", env)
    if low < 0:
        raise error_at(distance.location, "a distance must not be negative", hint="use behind: instead of ahead_of: (or the reverse)")
    if low == high:
        low, high = max(0.0, low - POSITION_TOLERANCE), high + POSITION_TOLERANCE
    keyword, other = relation
    # behind: the other actor is ahead by the distance; ahead_of: this actor is.
    term = Term(POSITION, other, actor) if keyword == "behind" else Term(POSITION, actor, other)
    return Bound(term, low, high, source)


def _speed(args: library.Binding, source, actor: str, env: dict) -> Guard:
    value = args["speed"]
    relation = _reference(args, ("faster_than", "slower_than", "same_as"))
    if value is None:
        if relation is None or relation[0] != "same_as":
            raise error_at(source, "speed() needs a speed, e.g. speed([20..30]kph)")
        low = high = 0.0
    else:
        low, high = _interval(value, SPEED, "a speed such as 20mps or [50..80]kph", env)
    if low == high:
        low, high = low - SPEED_TOLERANCE, high + SPEED_TOLERANCE
    if relation is None:
        return Bound(Term(SPEED_Q, actor), max(0.0, low), high, source)
    keyword, other = relation
    if keyword == "slower_than":
        return Bound(Term(SPEED_Q, other, actor), low, high, source)
    if keyword == "faster_than":
        return Bound(Term(SPEED_Q, actor, other), low, high, source)
    return Bound(Term(SPEED_Q, actor, other), low, high, source)  # same_as: within the given difference


def _evaluate(argument: model.Argument, env: dict) -> Interval:
    try:
        value = evaluate(argument.value, env)
    except EvaluationError as error:
        raise error_at(error.location, error.message, error.hint) from None
    if not isinstance(value, Interval):
        raise error_at(argument.location, "expected a number or a quantity")
    return value


def _interval(argument: model.Argument, dimension: str, example: str, env: dict) -> tuple[float, float]:
    value = _evaluate(argument, env)
    if value.dimension != dimension:
        got = value.dimension or "a plain number"
        raise error_at(argument.location, f"expected {example}, got {got}", hint="add a unit of the right kind")
    if not (math.isfinite(value.low) and math.isfinite(value.high)):
        raise error_at(argument.location, f"expected {example}, got an unbounded value", hint="give the parameter a range")
    return value.low, value.high


def duration_interval(argument: model.Argument, env: dict) -> tuple[float, float]:
    """A ``duration:`` or ``elapsed(...)`` value in seconds; a single value gets the tolerance."""
    low, high = _interval(argument, TIME, "a time such as 5s or [2..4]s", env)
    if low < 0:
        raise error_at(argument.location, "a duration must not be negative")
    if low == high:
        low, high = max(0.0, low - DURATION_TOLERANCE), high + DURATION_TOLERANCE
    return low, high


_COMPARISONS = {"<": "<=", "<=": "<=", ">": ">=", ">=": ">=", "==": "=="}


def condition_guard(condition: model.Expression, env: dict) -> Guard:
    """A ``wait`` condition as a guard: comparisons of an actor's speed with a value, joined by and."""
    if isinstance(condition, model.Binary) and condition.operator == "and":
        return conjunction([condition_guard(condition.left, env), condition_guard(condition.right, env)])
    if isinstance(condition, model.Binary) and condition.operator in _COMPARISONS:
        left, right, operator = condition.left, condition.right, condition.operator
        if not (isinstance(left, model.Name) and left.name.endswith(".speed")):
            left, right = right, left
            operator = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "==": "=="}[operator]
        if isinstance(left, model.Name) and left.name.endswith(".speed"):
            actor = left.name[: -len(".speed")]
            value = _evaluate(model.Argument(None, right, right.location), env)
            if value.dimension == SPEED:
                operator = _COMPARISONS[operator]
                low = value.low if operator in (">=", "==") else -math.inf
                high = value.high if operator in ("<=", "==") else math.inf
                if operator == "==" and low == high:
                    low, high = low - SPEED_TOLERANCE, high + SPEED_TOLERANCE
                return Bound(Term(SPEED_Q, actor), low, high, condition.location)
    raise error_at(
        getattr(condition, "location", None) or SourceLocation("?", 1, 1),
        "not supported yet by the automaton: this wait condition",
        hint="wait elapsed(t), or compare an actor's speed: wait v1.speed >= 20mps",
    )


def check_behavior_arguments(composition: model.Composition) -> None:
    for argument in composition.arguments:
        if argument.name == "overlap" and isinstance(argument.value, model.Name) and argument.value.name in ("start", "equal"):
            continue  # members start (and here also end) together: what the product builds
        if argument.name == "duration":
            continue  # a timed phase, handled by the construction
        raise error_at(argument.location, f"not supported yet by the automaton: {argument.name or 'arguments'} on {composition.operator}")


__all__ = [
    "Phase", "Variant", "phase_guards", "check_behavior_arguments", "condition_guard", "duration_interval",
    "LANE_CONVENTION", "STANDSTILL",
]
