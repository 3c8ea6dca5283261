"""From the leaves of a behavior tree to guards: invocations, durations and wait conditions.

An invocation's action and modifiers are translated by their specifications in the registry the
scenario was checked with (``pytest_roadlogic.constructs``): ``position([10..20]m, behind: v2,
at: start)`` becomes ``10 <= p(v2) - p(v1) <= 20`` on the phase's start transition, ``lane(1)``
(no ``at:``, so ``at: all``) an invariant of the phase's location. What is left here belongs to no
single construct: the invocation's own shape (its actor, ``until``, ``keep()``), durations, and
``wait`` conditions.

The front-end checker has already validated names, argument kinds and lane numbers; the errors
raised here are for what the automaton cannot express.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ..frontend import model
from ..frontend.errors import SourceLocation, error_at
from ..frontend.tolerances import DURATION_TOLERANCE, SPEED_TOLERANCE
from ..frontend.units import SPEED, TIME
from ..frontend.values import argument_interval, argument_range
from .guards import SPEED as SPEED_Q, Bound, Guard, Term, conjunction
from .phase import Phase

if TYPE_CHECKING:
    from ..constructs import Registry


def phase_guards(invocation: model.Invocation, registry: "Registry", lanes: int, env: dict) -> Phase:
    """The guards of one atomic phase; ``env`` gives the parameters' values or ranges."""
    actor = _actor(invocation)
    action = registry.action(invocation.action)
    if action is None or not action.translated:
        translated = registry.translated("action")
        raise error_at(
            invocation.location,
            f"not supported yet by the automaton: action {invocation.action!r}",
            hint=f"this version translates {', '.join(a + '()' for a in translated)}",
        )
    if invocation.until is not None:
        raise error_at(invocation.location, "not supported yet by the automaton: until")
    if invocation.constraints:
        raise error_at(invocation.constraints[0].location, "not supported yet by the automaton: keep() on an invocation")
    phase = Phase(actor, drives=action.moves)
    action.apply(invocation, actor, lanes, env, phase)
    for modifier in invocation.modifiers:
        construct = registry.modifier(modifier.name)
        if construct is None or not construct.translated:
            raise error_at(
                modifier.location, f"not supported yet by the automaton: modifier {modifier.name!r}",
                hint=f"supported: {', '.join(registry.translated('modifier'))}",
            )
        construct.apply(modifier, actor, lanes, env, phase)
    return phase


def _actor(invocation: model.Invocation) -> str:
    if invocation.actor is None:  # the checker reports this; a scenario with errors is no input here
        raise ValueError(f"{invocation.location}: build_automaton needs a scenario the checker accepted (an invocation without an actor)")
    return invocation.actor


def duration_interval(argument: model.Argument, env: dict) -> tuple[float, float]:
    """A ``duration:`` or ``elapsed(...)`` value in seconds; a single value gets the tolerance."""
    low, high = argument_range(argument, TIME, "a time such as 5s or [2..4]s", env)
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
            value = argument_interval(model.Argument(None, right, right.location), env)
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
