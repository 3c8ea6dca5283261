"""Scenario inheritance: ``scenario dut.fast_cut_in inherits cut_in:`` is cut_in with more members.

The standard's unconditional inheritance: the child has every member of its parent (fields,
constraints, events, methods, scenario modifiers and the ``do``) and adds its own; a ``keep`` of
the child narrows a parameter of the parent, and a field the child declares again is a second
declaration of that name (reported by the checker at the child's line). A scenario has one
``do``: a child either inherits its parent's or, when the parent has none, declares it.

Why resolve it here, as members copied in, rather than as a type hierarchy the later stages walk:
the automaton, the planner and the monitor then read one flat scenario, and every error in an
inherited member still points at the parent's own line. Conditional inheritance
(``inherits cut_in(kind == fast)``) makes a parent's instance a child when a field has a value;
it is refused by the parser at its place.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

from .. import model
from ..errors import Diagnostic


def inherited(
    scenario: model.Scenario, scenarios: Mapping[str, model.Scenario]
) -> tuple[model.Scenario, list[Diagnostic]]:
    """``scenario`` with the members of its ancestors, and the problems of its ``inherits`` chain."""
    problems: list[Diagnostic] = []
    chain = [scenario]
    while chain[-1].parent is not None:
        child = chain[-1]
        parent = scenarios.get(child.parent)
        if parent is None:
            known = ", ".join(sorted(n for n in scenarios if n != scenario.name)) or "none"
            problems.append(
                Diagnostic(
                    child.location,
                    f"scenario {child.name!r} inherits an unknown scenario {child.parent!r}",
                    f"scenarios declared here or imported: {known}",
                )
            )
            break
        if any(parent is seen for seen in chain):
            names = " -> ".join(s.name for s in (*chain, parent))
            problems.append(
                Diagnostic(
                    scenario.location,
                    f"the inherits of scenario {scenario.name!r} form a cycle ({names})",
                    "remove one inherits from the cycle",
                )
            )
            break
        chain.append(parent)
    result = chain[-1]
    for child in reversed(chain[:-1]):
        result, problem = _merged(result, child)
        problems.extend(problem)
    return result, problems


def _merged(parent: model.Scenario, child: model.Scenario) -> tuple[model.Scenario, list[Diagnostic]]:
    problems = []
    behaviors = parent.behaviors + child.behaviors
    if parent.behaviors and child.behaviors:
        behaviors = parent.behaviors
        first = parent.behaviors[0]
        problems.append(
            Diagnostic(
                child.behaviors[0].location,
                f"scenario {child.name!r} declares a do and inherits one from {parent.name!r} (line {first.location.line}); a scenario has one do",
                f"remove this do to keep {parent.name}'s, or declare {child.name} without inherits and call {parent.name}() in its do",
            )
        )
    return dataclasses.replace(
        child,
        actor_type=child.actor_type if child.actor_type is not None else parent.actor_type,
        parent=None,
        fields=parent.fields + child.fields,
        constraints=parent.constraints + child.constraints,
        events=parent.events + child.events,
        methods=parent.methods + child.methods,
        behaviors=behaviors,
        behavior=behaviors[0] if behaviors else None,
        unsupported=parent.unsupported + child.unsupported,
        modifiers=parent.modifiers + child.modifiers,
        coverage=parent.coverage + child.coverage,
        samples=parent.samples + child.samples,
    ), problems
