"""From an invocation's modifiers to its start and end guards.

This is where OS2's spelling meets the guard algebra: ``position([10..20]m, behind: v2, at: start)``
becomes ``10 <= p(v2) - p(v1) <= 20`` on the phase's start transition. The lane convention lives
here too: ``lane(k)`` counts 1-based from the right (the standard), ``lane(k, from: left)`` from the
left, and internally 0 is the leftmost lane (the paper).
"""

from __future__ import annotations

import math

from ..frontend import model
from ..frontend.checker import LANE_CONVENTION
from ..frontend.errors import OscError, error_at
from ..frontend.units import LENGTH, SPEED
from ..frontend.values import EvaluationError, Interval, evaluate
from .guards import LANE, POSITION, SPEED as SPEED_Q, TRUE, Bound, Guard, Term, conjunction

SUPPORTED_ACTIONS = ("drive",)
SUPPORTED_MODIFIERS = ("lane", "position", "speed")
# A single speed value cannot be met exactly by a continuous trace; it is read as value +- this.
SPEED_TOLERANCE = 0.5


def phase_guards(invocation: model.Invocation, scenario: model.Scenario, lanes: int, env: dict | None = None) -> tuple[Guard, Guard]:
    """The (start, end) guards of one atomic phase; ``env`` gives the parameters' values or ranges."""
    env = env or {}
    actor = _actor(invocation, scenario)
    if invocation.action not in SUPPORTED_ACTIONS:
        raise error_at(
            invocation.location,
            f"not supported: action {invocation.action!r}",
            hint=f"this version supports {', '.join(SUPPORTED_ACTIONS)}() with modifiers {', '.join(SUPPORTED_MODIFIERS)}",
        )
    if invocation.arguments:
        raise error_at(invocation.arguments[0].location, f"not supported: arguments to {invocation.action}()")
    start: list[Guard] = []
    end: list[Guard] = []
    for modifier in invocation.modifiers:
        anchor, guard = _modifier_guard(modifier, actor, scenario, lanes, env)
        (start if anchor == "start" else end).append(guard)
    return conjunction(start) if start else TRUE, conjunction(end) if end else TRUE


def _actor(invocation: model.Invocation, scenario: model.Scenario) -> str:
    if invocation.actor is None:
        raise error_at(invocation.location, f"{invocation.action}() needs an actor", hint="write it as v1.drive()")
    _check_actor(invocation.actor, invocation.location, scenario)
    return invocation.actor


def _check_actor(name: str, location, scenario: model.Scenario) -> None:
    if scenario.actor(name) is None:
        known = ", ".join(a.name for a in scenario.actors) or "none"
        raise error_at(location, f"unknown actor {name!r}", hint=f"the scenario declares: {known}")


def _modifier_guard(modifier: model.Modifier, actor: str, scenario: model.Scenario, lanes: int, env: dict) -> tuple[str, Guard]:
    if modifier.name not in SUPPORTED_MODIFIERS:
        raise error_at(modifier.location, f"not supported: modifier {modifier.name!r}", hint=f"supported: {', '.join(SUPPORTED_MODIFIERS)}")
    anchor = _anchor(modifier)
    if modifier.name == "lane":
        guard = _lane(modifier, actor, scenario, lanes, env)
    elif modifier.name == "position":
        guard = _position(modifier, actor, scenario, env)
    else:
        guard = _speed(modifier, actor, scenario, env)
    return anchor, guard


def _anchor(modifier: model.Modifier) -> str:
    argument = modifier.argument("at")
    if argument is None:
        raise error_at(
            modifier.location,
            f"not supported: {modifier.name}() without `at:` (it means `at: all`, an invariant)",
            hint="write at: start or at: end",
        )
    value = argument.value
    if not isinstance(value, model.Name) or value.name not in ("start", "end", "all"):
        raise error_at(argument.location, "`at:` takes start, end or all")
    if value.name == "all":
        raise error_at(argument.location, "not supported: at: all", hint="write at: start or at: end")
    return value.name


def _reference(modifier: model.Modifier, names: tuple[str, ...], scenario: model.Scenario) -> tuple[str, str] | None:
    """The relation keyword used (e.g. ``same_as``) and the actor it names, if any."""
    found = [a for a in modifier.arguments if a.name in names]
    if len(found) > 1:
        raise error_at(found[1].location, f"{modifier.name}() takes only one of {', '.join(names)}")
    if not found:
        return None
    argument = found[0]
    if not isinstance(argument.value, model.Name):
        raise error_at(argument.location, f"`{argument.name}:` takes an actor")
    _check_actor(argument.value.name, argument.value.location, scenario)
    return argument.name, argument.value.name


def _check_arguments(modifier: model.Modifier, allowed: tuple[str, ...], positional: int) -> None:
    for argument in modifier.arguments:
        if argument.name is None:
            continue
        if argument.name not in allowed:
            raise error_at(argument.location, f"unknown argument {argument.name!r} of {modifier.name}()", hint=f"it takes: {', '.join(allowed)}")
    if len(modifier.positional()) > positional:
        raise error_at(modifier.positional()[positional].location, f"too many positional arguments to {modifier.name}()")


def _lane(modifier: model.Modifier, actor: str, scenario: model.Scenario, lanes: int, env: dict) -> Guard:
    _check_arguments(modifier, ("same_as", "left_of", "right_of", "from", "at"), positional=1)
    relation = _reference(modifier, ("same_as", "left_of", "right_of"), scenario)
    positional = modifier.positional()
    if relation is not None:
        if positional:
            raise error_at(positional[0].location, "not supported: a lane count together with a relative lane", hint=LANE_CONVENTION)
        keyword, other = relation
        term = Term(LANE, actor, other)
        low, high = {"same_as": (0, 0), "left_of": (-math.inf, -1), "right_of": (1, math.inf)}[keyword]
        return Bound(term, low, high, modifier.location)
    if not positional:
        raise error_at(modifier.location, "lane() needs a lane number or same_as:/left_of:/right_of:", hint=LANE_CONVENTION)
    value = _evaluate(positional[0], env)
    if value.dimension is not None or not value.is_point or not float(value.low).is_integer():
        raise error_at(positional[0].location, "a lane number must be one whole number", hint=LANE_CONVENTION)
    number = int(value.low)
    side = modifier.argument("from")
    from_left = side is not None and isinstance(side.value, model.Name) and side.value.name == "left"
    if side is not None and not (isinstance(side.value, model.Name) and side.value.name in ("left", "right")):
        raise error_at(side.location, "`from:` takes left or right", hint=LANE_CONVENTION)
    if not 1 <= number <= lanes:
        raise error_at(positional[0].location, f"lane {number} is outside the road's {lanes} lanes", hint=LANE_CONVENTION)
    index = number - 1 if from_left else lanes - number
    return Bound(Term(LANE, actor), index, index, modifier.location)


def _position(modifier: model.Modifier, actor: str, scenario: model.Scenario, env: dict) -> Guard:
    _check_arguments(modifier, ("behind", "ahead_of", "at"), positional=1)
    relation = _reference(modifier, ("behind", "ahead_of"), scenario)
    if relation is None:
        raise error_at(modifier.location, "position() needs behind: or ahead_of: another actor")
    positional = modifier.positional()
    if not positional:
        raise error_at(modifier.location, "position() needs a distance, e.g. position([10..20]m, behind: v2)")
    low, high = _interval(positional[0], LENGTH, "a length such as 10m or [10..20]m", env)
    if low < 0:
        raise error_at(positional[0].location, "a distance must not be negative", hint="use behind: instead of ahead_of: (or the reverse)")
    keyword, other = relation
    # behind: the other actor is ahead by the distance; ahead_of: this actor is.
    term = Term(POSITION, other, actor) if keyword == "behind" else Term(POSITION, actor, other)
    return Bound(term, low, high, modifier.location)


def _speed(modifier: model.Modifier, actor: str, scenario: model.Scenario, env: dict) -> Guard:
    _check_arguments(modifier, ("at",), positional=1)
    positional = modifier.positional()
    if not positional:
        raise error_at(modifier.location, "speed() needs a speed, e.g. speed([20..30]kph)")
    low, high = _interval(positional[0], SPEED, "a speed such as 20mps or [50..80]kph", env)
    if low == high:
        low, high = low - SPEED_TOLERANCE, high + SPEED_TOLERANCE
    return Bound(Term(SPEED_Q, actor), max(0.0, low), high, modifier.location)


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


def check_behavior_arguments(composition: model.Composition) -> None:
    if composition.arguments:
        raise error_at(composition.arguments[0].location, f"not supported: arguments to {composition.operator}")


__all__ = ["phase_guards", "check_behavior_arguments", "LANE_CONVENTION", "OscError"]
