"""Built-in events: ``@L.start`` and ``@L.end`` happen when the phase labelled ``L`` starts and ends.

The standard gives every labelled phase these two events. They are read here as what a scenario
author would otherwise write by hand: the phase becomes ``serial: [emit L.start,] L [, emit L.end]``
with the events declared, so the automaton, the planner and the monitor handle them exactly as
declared events (an emit marks the instant between its serial neighbours; a waiting phase ends at
that instant). Only the events the scenario refers to are added: an unused ``emit`` would still
be an instant of the plan, and it would show in every report.
"""

from __future__ import annotations

import dataclasses

from .. import model

EDGES = ("start", "end")


def referenced_events(scenario: model.Scenario) -> set[str]:
    """The names of the events the scenario waits for: in ``wait``, ``until`` and event definitions."""
    specifications = [e.specification for e in scenario.events]
    for behavior in scenario.behaviors:
        for node in model.walk(behavior):
            if isinstance(node, model.Wait):
                specifications.append(node.condition)
            elif isinstance(node, model.Invocation) and node.until is not None:
                specifications.append(node.until)
    return {s.name for s in specifications if isinstance(s, model.EventReference)}


def with_builtin_events(scenario: model.Scenario) -> model.Scenario:
    """``scenario`` with an emit at each edge of a labelled phase that one of its events refers to."""
    declared = {e.name for e in scenario.events}
    labelled = {node.label: node for b in scenario.behaviors for node in model.walk(b) if getattr(node, "label", None)}
    wanted: dict[str, list[str]] = {}
    for name in sorted(referenced_events(scenario) - declared):
        label, _, edge = name.rpartition(".")
        if edge in EDGES and label in labelled:
            wanted.setdefault(label, []).append(edge)
    if not wanted:
        return scenario
    events = tuple(
        model.Event(f"{label}.{edge}", None, labelled[label].location)
        for label, edges in wanted.items()
        for edge in edges
    )
    behaviors = tuple(_marked(b, wanted) for b in scenario.behaviors)
    return dataclasses.replace(
        scenario,
        events=scenario.events + events,
        behaviors=behaviors,
        behavior=behaviors[0] if scenario.behavior is not None else None,
    )


def _marked(node: model.Behavior, wanted: dict[str, list[str]]) -> model.Behavior:
    if isinstance(node, model.Composition):
        node = dataclasses.replace(node, children=tuple(_marked(child, wanted) for child in node.children))
    label = getattr(node, "label", None)
    if label not in wanted:
        return node
    edges = wanted[label]
    emit = lambda edge: model.Emit(f"{label}.{edge}", (), None, node.location)  # noqa: E731
    members = ((emit("start"),) if "start" in edges else ()) + (node,) + ((emit("end"),) if "end" in edges else ())
    return model.Composition("serial", (), members, None, node.location)
