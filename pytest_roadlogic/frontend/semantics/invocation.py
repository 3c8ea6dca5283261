"""Scenario invocation: a user scenario called in ``do`` (``dut.cut_in_and_slow(gap: 20m)``).

The call is expanded in place before the caller is checked, so every later stage sees one
scenario: the callee's behavior with its parameters bound and its actors matched. Why expand
rather than plan sub-scenarios: the automaton, the planner and the monitor then need nothing new,
and every error inside the callee still points at the callee's own lines.

Binding, as the standard reads a call:
- an argument binds the callee's parameter of that name (positional ones in declaration order);
  an argument that names an actor of the caller binds the callee's actor field;
- an unbound actor field is the caller's actor of the same name (``dut``, or ``npc`` declared in
  both), or else becomes an actor of the caller;
- an unbound parameter keeps its declared type, default and constraints, as a parameter of the
  caller named ``<call>.<name>`` (``<call>`` is the call's label, or the callee's name);
- the actor the call is made on performs the callee's actions that name no actor;
- the callee's labels become ``<call>.<label>``, so that a scenario called twice has distinct phases;
- ``duration:`` on the call bounds the whole expanded behavior.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping

from .. import model
from ..errors import Diagnostic

# calls inside calls: deeper than this is a recursion the checker reports
MAX_DEPTH = 8


@dataclasses.dataclass
class Expansion:
    """A caller with its calls expanded: what it gained (fields, events, constraints) and what went wrong."""

    fields: list[model.Field] = dataclasses.field(default_factory=list)
    events: list[model.Event] = dataclasses.field(default_factory=list)
    constraints: list = dataclasses.field(default_factory=list)
    diagnostics: list[Diagnostic] = dataclasses.field(default_factory=list)

    def error(self, location, message: str, hint: str | None = None) -> None:
        self.diagnostics.append(Diagnostic(location, message, hint))


def _is_call(node, callable_: Mapping[str, model.Scenario], is_action: Callable[[str], bool]) -> bool:
    """Whether a behavior node invokes a user scenario (an action of the registry's name is not one)."""
    return isinstance(node, model.Invocation) and node.action in callable_ and not is_action(node.action)


RECURSION = "calls itself"  # the words of the error for a scenario that contains itself


def called_scenarios(
    scenario: model.Scenario, callable_: Mapping[str, model.Scenario], is_action: Callable[[str], bool]
) -> set[str]:
    """The names of the user scenarios ``scenario``'s behavior calls directly."""
    return {
        node.action
        for behavior in scenario.behaviors
        for node in model.walk(behavior)
        if _is_call(node, callable_, is_action)
    }


def expand_calls(
    scenario: model.Scenario,
    callable_: Mapping[str, model.Scenario],
    is_action: Callable[[str], bool],
    is_actor: Callable[[model.Field], bool],
) -> tuple[model.Scenario, list[Diagnostic]]:
    """``scenario`` with every call of a scenario in ``callable_`` expanded (``is_action``: a name
    the registry executes itself, which a user scenario does not shadow; ``is_actor``: whether a
    field declares an actor)."""
    if not called_scenarios(scenario, callable_, is_action):
        return scenario, []
    expansion = Expansion()
    names = {f.name for f in scenario.fields}
    behaviors = tuple(
        _expand(b, callable_, is_action, is_actor, expansion, names, (scenario.name,)) for b in scenario.behaviors
    )
    known_events = {e.name for e in scenario.events}
    events = [e for e in expansion.events if e.name not in known_events]
    expanded = dataclasses.replace(
        scenario,
        fields=scenario.fields + tuple(expansion.fields),
        events=scenario.events + tuple(dict((e.name, e) for e in events).values()),
        constraints=scenario.constraints + tuple(expansion.constraints),
        behaviors=behaviors,
        behavior=behaviors[0] if behaviors else None,
    )
    return expanded, expansion.diagnostics


def _expand(behavior, callable_, is_action, is_actor, expansion: Expansion, names: set[str], stack: tuple[str, ...]):
    if isinstance(behavior, model.Composition):
        children = tuple(_expand(c, callable_, is_action, is_actor, expansion, names, stack) for c in behavior.children)
        return dataclasses.replace(behavior, children=children)
    if not _is_call(behavior, callable_, is_action):
        return behavior
    callee = callable_[behavior.action]
    if behavior.action in stack or len(stack) > MAX_DEPTH:
        cycle = (*(stack[stack.index(behavior.action) :] if behavior.action in stack else stack), behavior.action)
        expansion.error(
            behavior.location,
            f"scenario {behavior.action!r} {RECURSION} ({' -> '.join(cycle)})",
            "a scenario cannot contain itself; remove the call",
        )
        return behavior
    if callee.behavior is None:
        expansion.error(
            behavior.location, f"scenario {behavior.action!r} has no do to call", "give it a do, or invoke an action"
        )
        return behavior
    if behavior.modifiers or behavior.constraints or behavior.until is not None:
        expansion.error(
            behavior.location,
            f"not supported: modifiers on a call of scenario {behavior.action!r}",
            "put the modifiers inside the called scenario, or pass values as arguments",
        )
    prefix = behavior.label or callee.name
    substitution = _bind(behavior, callee, is_actor, expansion, names, prefix)
    owner = behavior.actor
    body = _substitute(callee.behavior, substitution, owner)
    body = _relabel(body, prefix)
    body = _expand(body, callable_, is_action, is_actor, expansion, names, stack + (callee.name,))
    expansion.events.extend(callee.events)
    expansion.constraints.extend(_substitute(c, substitution, owner) for c in callee.constraints)
    duration = behavior.argument("duration") if not any(f.name == "duration" for f in callee.fields) else None
    if duration is not None:
        return model.Composition("serial", (duration,), (body,), behavior.label, behavior.location)
    if behavior.label is not None and getattr(body, "label", None) != behavior.label:
        return model.Composition("serial", (), (body,), behavior.label, behavior.location)
    return body


def _bind(
    call: model.Invocation, callee: model.Scenario, is_actor, expansion: Expansion, names: set[str], prefix: str
) -> dict[str, model.Expression]:
    """What each of the callee's field names stands for in the caller; adds the caller's new fields."""
    actors = [f for f in callee.fields if is_actor(f)]
    parameters = [f for f in callee.fields if not is_actor(f)]
    by_name = {f.name: f for f in callee.fields}
    given: dict[str, model.Argument] = {}
    positional = [p for p in parameters if p.name != "duration"]
    for argument in call.arguments:
        if argument.name is None:
            if not positional:
                expansion.error(
                    argument.location,
                    f"scenario {callee.name!r} takes no more positional arguments",
                    "name the argument: gap: 20m",
                )
                continue
            given[positional.pop(0).name] = argument
        elif argument.name in by_name:
            given[argument.name] = argument
            positional = [p for p in positional if p.name != argument.name]
        elif argument.name != "duration":
            known = ", ".join(f.name for f in callee.fields) or "none"
            expansion.error(
                argument.location, f"scenario {callee.name!r} has no field {argument.name!r}", f"its fields: {known}"
            )
    substitution: dict[str, model.Expression] = {}
    for field in actors:
        if field.name in given:
            value = given[field.name].value
            if not isinstance(value, model.Name):
                expansion.error(
                    given[field.name].location,
                    f"{field.name!r} is an actor: pass the name of one of the caller's actors",
                )
                continue
            substitution[field.name] = value
        elif field.name not in names:
            expansion.fields.append(field)
            names.add(field.name)
    for field in parameters:
        if field.name in given:
            substitution[field.name] = given[field.name].value
            continue
        renamed = f"{prefix}.{field.name}"
        substitution[field.name] = model.Name(renamed, field.location)
        if renamed not in names:
            constraints = tuple(
                dataclasses.replace(_substitute(c, substitution, None), subject=renamed)
                if isinstance(c, model.Keep) and c.subject == field.name
                else _substitute(c, substitution, None)
                for c in field.constraints
            )
            expansion.fields.append(dataclasses.replace(field, name=renamed, constraints=constraints))
            names.add(renamed)
    return substitution


def substitute_names(node, substitution: Mapping[str, model.Expression]):
    """``node`` (a model node or a tuple of them) with the bare names in ``substitution`` replaced."""
    return _substitute(node, substitution, None)


def _substitute(node, substitution: Mapping[str, model.Expression], owner: str | None):
    """``node`` with the callee's names replaced; an action without an actor goes to ``owner``."""
    if isinstance(node, model.Name):
        if node.enum is not None:
            return node
        head, dot, rest = node.name.partition(".")
        replacement = substitution.get(head)
        if replacement is None:
            return node
        if not dot:
            return replacement
        return (
            dataclasses.replace(node, name=f"{replacement.name}.{rest}")
            if isinstance(replacement, model.Name)
            else node
        )
    if isinstance(node, tuple):
        return tuple(_substitute(item, substitution, owner) for item in node)
    if not dataclasses.is_dataclass(node) or isinstance(node, type):
        return node
    changes = {}
    for field in dataclasses.fields(node):
        value = getattr(node, field.name)
        if field.name == "actor" and isinstance(node, (model.Invocation, model.Modifier)):
            if value is None:
                changes["actor"] = owner if isinstance(node, model.Invocation) else None
            elif isinstance(substitution.get(value), model.Name):
                changes["actor"] = substitution[value].name
            continue
        if isinstance(value, (tuple, model.Name)) or (dataclasses.is_dataclass(value) and not isinstance(value, type)):
            changes[field.name] = _substitute(value, substitution, owner)
    return dataclasses.replace(node, **changes) if changes else node


def owned_by(node, owner: str):
    """``node`` with every invocation that names no actor given to ``owner`` (a scenario's
    behaviors, invoked on the actor the scenario belongs to)."""
    return _substitute(node, {}, owner)


def substitute_calls(node, members: Mapping[str, str]):
    """``node`` with each call ``f()`` of no arguments whose ``f`` is in ``members`` replaced by
    the name ``members[f]`` at the call's place (``map.inner_side()`` -> ``left``)."""
    if isinstance(node, model.Call):
        if node.function in members and not node.arguments:
            return model.Name(members[node.function], node.location)
        return node
    if isinstance(node, tuple):
        return tuple(substitute_calls(item, members) for item in node)
    if not dataclasses.is_dataclass(node) or isinstance(node, type) or isinstance(node, model.Name):
        return node
    changes = {}
    for field in dataclasses.fields(node):
        value = getattr(node, field.name)
        if isinstance(value, tuple) or (dataclasses.is_dataclass(value) and not isinstance(value, type)):
            changed = substitute_calls(value, members)
            if changed is not value:
                changes[field.name] = changed
    return dataclasses.replace(node, **changes) if changes else node


def _relabel(behavior, prefix: str):
    """The callee's labels as ``prefix.label``: a scenario called twice keeps its phases apart."""
    label = f"{prefix}.{behavior.label}" if behavior.label else None
    if isinstance(behavior, model.Composition):
        return dataclasses.replace(
            behavior, label=label, children=tuple(_relabel(c, prefix) for c in behavior.children)
        )
    return dataclasses.replace(behavior, label=label)


def resolve_actor_aliases(scenario: model.Scenario, is_actor: Callable[[model.Field], bool]) -> model.Scenario:
    """``scenario`` with every actor field whose value names another of its actors declared
    before it (``other_car: Rubicon = npc``, as CARLA's emit example writes it) read as that actor: an
    actor-typed field holds a reference to an actor, so the name is one more name of the same
    vehicle, never a vehicle of its own. The field is dropped and its name replaced wherever the
    scenario uses it (actions, modifiers, events, constraints)."""
    aliases: dict[str, str] = {}  # alias -> the actor it names, declared before it
    actors: set[str] = set()
    for field in scenario.fields:
        if not is_actor(field):
            continue
        value = field.default
        if isinstance(value, model.Name) and value.enum is None and (value.name in actors or value.name in aliases):
            aliases[field.name] = aliases.get(value.name, value.name)
        else:
            actors.add(field.name)
    if not aliases:
        return scenario
    where = {field.name: field.location for field in scenario.fields}
    substitution = {alias: model.Name(actor, where[alias]) for alias, actor in aliases.items()}
    behaviors = tuple(substitute_names(b, substitution) for b in scenario.behaviors)
    return dataclasses.replace(
        scenario,
        fields=tuple(f for f in scenario.fields if f.name not in aliases),
        constraints=substitute_names(scenario.constraints, substitution),
        events=substitute_names(scenario.events, substitution),
        modifiers=substitute_names(scenario.modifiers, substitution),
        coverage=substitute_names(scenario.coverage, substitution),
        behaviors=behaviors,
        behavior=behaviors[0] if behaviors else None,
    )
