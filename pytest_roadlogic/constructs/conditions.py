"""Conditions: what ``wait c``, ``until c`` and ``wait @e if c`` may read, and what each means as a guard.

A condition is a comparison of an *observable* with a value, or several joined by ``and``, ``or``,
``not``. The observables are the standard's methods on a vehicle, each one quantity of the shared
guard algebra (so the planner and the monitor read it alike):

- ``a.speed``: the actor's speed, ``v(a)``.
- ``a.space_headway(reference: b)``: the distance from a's front to b's front along the road,
  ``p(b) - p(a)``; negative when ``a`` leads (the standard's sign).
- ``a.time_headway(reference: b)``: that distance over a's speed, ``h(b, a)``: the seconds ``a``
  needs to reach where ``b`` is now.
- ``a.relative_speed(reference: b)``: ``v(a) - v(b)``, positive when ``a`` is faster.
- ``a.relative_lane(reference: b)``: how many lanes ``a`` is to the left of ``b`` (0: the same
  lane, -1: one lane to its right), ``l(b) - l(a)`` with lanes counted from the left. Left and
  right mean the same in both dialects, so the condition does not depend on how lanes are numbered.
- ``a.space_gap(reference: b, direction: longitudinal | lateral)`` (the standard's
  traffic-participant method): the free distance between the two cars' boxes, along the road or
  across it, positive when ``a`` is ahead of ``b`` (longitudinal) or left of it (lateral), 0 while
  the boxes overlap in that direction. A monotone function of ``p(a) - p(b)`` (or of the lanes
  between them, a lane being LANE_WIDTH wide), so a bound on it is a bound on that term.
- ``a.time_gap(reference: b, direction: longitudinal)`` (the standard's): that space gap over
  the speed of the car behind, positive when ``a`` is ahead; a bound on it is a bound on a time
  headway with a car's length taken off the gap, ``h(a, b) - L/v(b)`` or ``h(b, a) - L/v(a)``
  (``_time_gap`` says which).
- ``a.traveled_distance()``: the metres ``a`` has covered since the run's first instant (the
  plan's step 0, the simulation's first sample), ``d(a) = p(a) - p(a at start)`` (OpenSCENARIO XML's TraveledDistanceCondition; the standard's
  DSL library has no method for it, so the name follows the XML's condition).

A strict comparison is read as its closed form (``<`` as ``<=``): the boundary instant has measure
zero, and a planner cannot keep a strict margin of nothing. A comparison with a range that is
still a logical parameter (the base strategy) is read at the range's most permissive end, as
``wait`` has always done for speeds. ``elapsed(t)`` is a timed phase, not a guard: it is the whole
condition of a ``wait`` (``automaton.construction``), never part of one.

The checker calls ``condition_guard`` on every condition, so a condition that checks is one the
automaton translates: the two cannot disagree about what is supported.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Collection
from dataclasses import dataclass

from ..dimensions import CAR_LENGTH, CAR_WIDTH, LANE_WIDTH
from ..frontend import model
from ..frontend.errors import error_at
from ..frontend.semantics.library import refused_call
from ..frontend.semantics.tolerances import SPEED_TOLERANCE, widened
from ..frontend.semantics.values import EvaluationError, argument_interval, describe
from ..frontend.syntax.units import LENGTH, SPEED, TIME
from ..logic.guards import (
    HEADWAY,
    LANE,
    POSITION,
    TRAVELED,
    Bound,
    Guard,
    Not,
    Or,
    Term,
    conjunction,
)
from ..logic.guards import (
    SPEED as SPEED_Q,
)


def _between_bumpers(extent: float, scale: float = 1.0) -> Callable[[float, float], tuple[float, float]]:
    """The range of a centre-to-centre difference d whose gap between the boxes is in [lo, hi]: the
    gap is d - extent ahead of the reference, d + extent behind it, 0 while the boxes overlap (the
    standard's space_gap), a monotone function of d, so its inverse is exact; ``scale`` is metres
    per unit of d (a lane's width when d counts lanes)."""

    def bounds(low: float, high: float) -> tuple[float, float]:
        low = (low + extent if low > 0 else low - extent) / scale
        high = (high + extent if high >= 0 else high - extent) / scale
        return low, high

    return bounds


def _same(low: float, high: float) -> tuple[float, float]:
    return low, high


def _time_gap(a: str, b: str, low: float, high: float, source) -> Guard:
    """The standard's ``a.time_gap(b, longitudinal)``: the space gap over the speed of the car
    behind, positive when a is ahead. Ahead, it is ``h_L(a, b) = (p(a) - p(b) - L) / v(b)`` (L a
    car's length: bumper to bumper); behind, ``-h_L(b, a)``; 0 while the boxes overlap. A bound on
    it is a bound on one of the two (speeds are never negative): at most hi >= 0 holds wherever a
    is not ahead, so it is ``h_L(a, b) <= hi``; at most hi < 0 puts a behind, ``h_L(b, a) >= -hi``;
    and at least lo alike."""
    ahead, behind = Term(HEADWAY, a, b, CAR_LENGTH), Term(HEADWAY, b, a, CAR_LENGTH)
    parts = []
    if math.isfinite(high):
        parts.append(Bound(ahead, -math.inf, high, source) if high >= 0 else Bound(behind, -high, math.inf, source))
    if math.isfinite(low):
        parts.append(Bound(ahead, low, math.inf, source) if low > 0 else Bound(behind, -math.inf, -low, source))
    return conjunction(parts)


@dataclass(frozen=True)
class Observable:
    """A method a condition may call on an actor, as a term of the guard algebra.

    ``parameters`` are its arguments after the actor (``reference``, and ``direction`` for the
    standard's gap methods, whose ``lateral`` form has its own term); ``bounds`` maps a range of the
    observable to the range of its term."""

    name: str
    dimension: str | None  # None: a plain number (a count of lanes)
    term: Callable[[str, str | None], Term]  # (actor, reference) -> term
    needs_reference: bool
    bounds: Callable[[float, float], tuple[float, float]] = _same
    lateral: Observable | None = None  # the form with direction: lateral
    # for an observable that is no one term: (actor, reference, low, high, place) -> its guard
    guard: Callable | None = None

    @property
    def parameters(self) -> tuple[str, ...]:
        return ("reference", "direction") if self.lateral is not None or self.guard is not None else ("reference",)


OBSERVABLES = {
    o.name: o
    for o in (
        Observable("speed", SPEED, lambda a, _: Term(SPEED_Q, a), False),
        Observable("space_headway", LENGTH, lambda a, b: Term(POSITION, b, a), True),
        Observable("time_headway", TIME, lambda a, b: Term(HEADWAY, b, a), True),
        Observable("relative_speed", SPEED, lambda a, b: Term(SPEED_Q, a, b), True),
        Observable("traveled_distance", LENGTH, lambda a, _: Term(TRAVELED, a), False),
        Observable("relative_lane", None, lambda a, b: Term(LANE, b, a), True),
        # the standard's traffic_participant.space_gap: between the boxes, positive when the actor
        # is ahead of (longitudinal) or left of (lateral) the reference
        Observable(
            "space_gap",
            LENGTH,
            lambda a, b: Term(POSITION, a, b),
            True,
            _between_bumpers(CAR_LENGTH),
            lateral=Observable(
                "space_gap", LENGTH, lambda a, b: Term(LANE, b, a), True, _between_bumpers(CAR_WIDTH, LANE_WIDTH)
            ),
        ),
        # the standard's traffic_participant.time_gap (longitudinal; the lateral one divides by a
        # lateral speed the plan does not have): the space gap over the speed of the car behind
        Observable(
            "time_gap",
            TIME,
            lambda a, b: Term(HEADWAY, a, b, CAR_LENGTH),
            True,
            lateral=None,
            guard=_time_gap,
        ),
    )
}
# the standard's methods a condition cannot read yet, with what to write instead
NOT_YET = {
    "time_to_collision": "a.time_gap(b, longitudinal) or a.space_gap(b, longitudinal) with a.relative_speed(reference: b)",
}
_MIRROR = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "==": "=="}
_EXAMPLE = "e.g. v1.speed >= 20mps or ego.space_headway(reference: lead) < 10m"


def usage() -> str:
    return ", ".join(
        f"a.{o.name}"
        + (
            "(reference: b, direction: longitudinal)"
            if "direction" in o.parameters
            else "(reference: b)"
            if o.needs_reference
            else ""
        )
        for o in OBSERVABLES.values()
    )


def condition_guard(condition: model.Expression, env: dict, actors: Collection[str]) -> Guard:
    """A condition as a guard. Raises a located ``OscError`` for what is not a supported condition."""
    if isinstance(condition, model.Binary) and condition.operator in ("and", "or"):
        parts = [condition_guard(condition.left, env, actors), condition_guard(condition.right, env, actors)]
        return conjunction(parts) if condition.operator == "and" else Or(tuple(parts))
    if isinstance(condition, model.Unary) and condition.operator == "not":
        return Not(condition_guard(condition.operand, env, actors))
    if isinstance(condition, model.Binary) and condition.operator in _MIRROR:
        left, right, operator = condition.left, condition.right, condition.operator
        found = _observable(left, actors)
        if found is None:
            left, right, operator = right, left, _MIRROR[operator]
            found = _observable(left, actors)
        if found is None:
            raise error_at(
                condition.location,
                "a condition compares an actor's observable with a value",
                f"observables: {usage()}; {_EXAMPLE}",
            )
        observable, term = found
        try:
            value = argument_interval(model.Argument(None, right, right.location), env)
        except EvaluationError as error:
            raise error_at(error.location, error.message, error.hint) from None
        if value.dimension != observable.dimension:
            raise error_at(
                right.location,
                f"{observable.name} is {describe(observable.dimension)}, compared here with {describe(value.dimension)}",
                "write the value with a unit of the same kind",
            )
        low = value.low if operator in (">", ">=", "==") else -math.inf
        high = value.high if operator in ("<", "<=", "==") else math.inf
        if operator == "==" and observable.dimension == SPEED:
            low, high = widened(low, high, SPEED_TOLERANCE)
        if observable.guard is not None:
            return observable.guard(*term.actors, low, high, condition.location)
        low, high = observable.bounds(low, high)
        return Bound(term, low, high, condition.location)
    refused = refused_call(condition)
    if refused is not None:
        raise error_at(
            condition.location, f"not supported: {refused}", "compare an observable with a value, or wait for an event"
        )
    if isinstance(condition, model.Call) and condition.function == "elapsed":
        raise error_at(
            condition.location,
            "elapsed() is the whole condition of a wait",
            "write wait elapsed(3s) as its own member of a serial",
        )
    location = getattr(condition, "location", None)
    if isinstance(condition, model.Call) and "." not in condition.function:
        raise error_at(
            location,
            f"unknown function {condition.function!r}",
            f"a wait takes elapsed(t), an event (@e) or a comparison: {_EXAMPLE}",
        )
    raise error_at(location, "not a condition this tool can read", f"observables: {usage()}; {_EXAMPLE}")


def _observable(expression: model.Expression, actors: Collection[str]) -> tuple[Observable, Term] | None:
    """The observable and term ``expression`` reads, or None when it reads none. Raises for a
    method call on an actor that is not an observable or lacks its reference."""
    if isinstance(expression, model.Name) and "." in expression.name:
        actor, _, method = expression.name.rpartition(".")
        observable = OBSERVABLES.get(method)
        if actor in actors and observable is not None and not observable.needs_reference:
            return observable, observable.term(actor, None)
        return None
    if not isinstance(expression, model.Call) or "." not in expression.function:
        return None
    actor, _, method = expression.function.rpartition(".")
    if actor not in actors:
        raise error_at(expression.location, f"unknown actor {actor!r}", f"actors: {', '.join(sorted(actors))}")
    observable = OBSERVABLES.get(method)
    if observable is None:
        hint = f"write {NOT_YET[method]}" if method in NOT_YET else f"observables: {usage()}"
        raise error_at(expression.location, f"not supported in a condition: {method}()", hint)
    reference = None
    positional = list(observable.parameters)
    for argument in expression.arguments:
        name = argument.name
        if name is None and positional:
            name = positional[0]
        if name in positional:
            positional.remove(name)
        if name == "direction" and "direction" in observable.parameters:
            direction = argument.value.name if isinstance(argument.value, model.Name) else None
            if direction not in ("longitudinal", "lateral"):
                raise error_at(argument.location, f"{method}() takes direction: longitudinal or lateral")
            if direction == "lateral" and observable.lateral is None:
                raise error_at(
                    argument.location,
                    f"not supported: {method}(direction: lateral)",
                    "a lateral time gap divides by a lateral speed the plan does not have; use space_gap(b, lateral)",
                )
            if direction == "lateral":
                observable = observable.lateral
            continue
        if name != "reference" or not isinstance(argument.value, model.Name):
            raise error_at(
                argument.location,
                f"{method}() takes {', '.join(f'{p}:' for p in observable.parameters)}",
                f"e.g. {actor}.{method}(reference: lead)",
            )
        reference = argument.value.name
        if reference not in actors:
            raise error_at(argument.location, f"unknown actor {reference!r}", f"actors: {', '.join(sorted(actors))}")
    if observable.needs_reference and reference is None:
        raise error_at(
            expression.location, f"{method}() needs reference: <actor>", f"e.g. {actor}.{method}(reference: lead)"
        )
    return observable, observable.term(actor, reference)
