"""From the leaves of a behavior tree to guards: invocations and durations.

An invocation's action and modifiers are translated by their specifications in the registry the
scenario was checked with (``pytest_roadlogic.constructs``): ``position([10..20]m, behind: v2,
at: start)`` becomes ``10 <= p(v2) - p(v1) <= 20`` on the phase's start transition, ``lane(1)``
(no ``at:``, so ``at: all``) an invariant of the phase's location. What is left here belongs to no
single construct: the invocation's own shape (its actor, ``keep()``) and durations. Conditions
(``wait``, ``until``) are specified in ``constructs.conditions``.

The front-end checker has already validated names, argument kinds and lane numbers; the errors
raised here are for what the automaton cannot express.
"""

from __future__ import annotations

from ..frontend import model
from ..frontend.errors import error_at
from ..frontend.semantics.checked import Registry
from ..frontend.semantics.tolerances import DURATION_TOLERANCE, widened
from ..frontend.semantics.values import argument_range
from ..frontend.syntax.units import TIME
from ..logic.phase import Phase


def phase_guards(
    invocation: model.Invocation, registry: Registry, lanes: int, env: dict, actors: tuple[str, ...]
) -> Phase:
    """The guards of one atomic phase; ``env`` gives the parameters' values or ranges, ``actors``
    the scenario's actors."""
    actor = _actor(invocation)
    action = registry.action(invocation.action)
    if action is None or not action.translated:
        translated = registry.translated("action")
        raise error_at(
            invocation.location,
            f"not supported yet by the automaton: action {invocation.action!r}",
            hint=f"this version translates {', '.join(a + '()' for a in translated)}",
        )
    if invocation.constraints:
        raise error_at(
            invocation.constraints[0].location, "not supported yet by the automaton: keep() on an invocation"
        )
    phase = Phase(actor, drives=action.moves)
    action.apply(invocation, actor, lanes, env, phase, actors)
    for modifier in invocation.modifiers:
        construct = registry.modifier(modifier.name)
        if construct is None or not construct.translated:
            raise error_at(
                modifier.location,
                f"not supported yet by the automaton: modifier {modifier.name!r}",
                hint=f"supported: {', '.join(registry.translated('modifier'))}",
            )
        construct.apply(modifier, actor, lanes, env, phase, actors)
    return phase


def _actor(invocation: model.Invocation) -> str:
    if invocation.actor is None:  # the checker reports this; a scenario with errors is no input here
        raise ValueError(
            f"{invocation.location}: build_automaton needs a scenario the checker accepted (an invocation without an actor)"
        )
    return invocation.actor


def duration_interval(argument: model.Argument, env: dict) -> tuple[float, float]:
    """A ``duration:`` or ``elapsed(...)`` value in seconds; a single value gets the tolerance."""
    low, high = argument_range(argument, TIME, "a time such as 5s or [2..4]s", env)
    if low < 0:
        raise error_at(argument.location, "a duration must not be negative")
    low, high = widened(low, high, DURATION_TOLERANCE)
    return max(0.0, low), high


def offset_interval(argument: model.Argument, env: dict) -> tuple[float, float]:
    """A parallel's ``start_to_start:`` or ``end_to_end:`` in seconds, from the primary member's
    start (end) to each other member's (negative: before it); a single value gets the tolerance."""
    low, high = argument_range(argument, TIME, "a time such as 2s, -1s or [-1..3]s", env)
    return widened(low, high, DURATION_TOLERANCE)


def check_behavior_arguments(composition: model.Composition) -> None:
    for argument in composition.arguments:
        if argument.name == "overlap" and isinstance(argument.value, model.Name):
            continue  # how the members sit in time: what the product builds
        if argument.name == "duration":
            continue  # a timed phase, handled by the construction
        if argument.name in ("start_to_start", "end_to_end") and composition.operator == "parallel":
            continue  # offsets between the members, timed phases the product marks
        raise error_at(
            argument.location,
            f"not supported yet by the automaton: {argument.name or 'arguments'} on {composition.operator}",
        )
