"""Idle guards: bounds a model holds where its run does not need them.

A bound's atom ``g(N,t)`` is a free choice of the solver (``asp/continuous/guards.lp``): positions
and speeds are not atoms, so a bound cannot be derived. The domain heuristic tries it false, but
the solver's random decisions set some true where no transition is taken on it and no invariant
holds it, and the linear program then enforces its rows there: a car placed 15 m behind another
``at: start`` held there a step longer, then jumping to its own speed. Such a bound is idle: the
run is the same without it, and the planner solves the model's run and lanes again with it
assumed false.

Why in Python and not as a rule reading the rows from where the run needs them: rows read that
way made the solver's proofs that no plan exists slower, and any new rule changes the solver's
search, so every scenario's first plan (docs/decisions.md). The shown atoms (``fire/2``,
``g/2``) do not.
"""

from __future__ import annotations

from collections.abc import Iterable

import clingo

from ....logic.automaton import SymbolicAutomaton
from ....logic.guards import LANE, And, Or
from ...facts import bound_of, guard_nodes, invariant_nodes


class GuardTree:
    """The automaton's guard nodes as ``asp/guards.lp`` numbers them (``planning/facts.py``):
    which node each transition takes and each location holds, the parts of each junction, and
    which nodes are bounds the solver chooses (not lanes, which are derived)."""

    def __init__(self, automaton: SymbolicAutomaton) -> None:
        self.transition_node, numbering = guard_nodes(automaton)
        self.invariant_node = invariant_nodes(automaton, numbering)
        self.parts: dict[int, tuple[bool, tuple[int, ...]]] = {}  # node -> (a conjunction?, parts)
        self.chosen: set[int] = set()
        for guard, node in numbering.items():
            if isinstance(guard, (And, Or)):
                self.parts[node] = (isinstance(guard, And), tuple(numbering[p] for p in guard.parts))
            elif (bound := bound_of(guard)) is not None and bound.term.quantity != LANE:
                self.chosen.add(node)
        self.automaton = automaton

    def needed(
        self, fired: Iterable[tuple[int, int]], holding: set[tuple[int, int]], horizon: int
    ) -> set[tuple[int, int]]:
        """(node, step) pairs the run needs: the guard of each transition taken (``fired``:
        (transition, step)), the invariant of the location held at each step up to ``horizon``,
        and the parts that make them hold (of a disjunction, those ``holding``)."""
        by_step = {step: transition for transition, step in fired}
        needed = {(self.transition_node[transition], step) for step, transition in by_step.items()}
        for step, location in enumerate(self.automaton.run_locations(by_step, horizon)):
            if location in self.invariant_node:
                needed.add((self.invariant_node[location], step))
        pending = list(needed)
        while pending:
            node, step = pending.pop()
            conjunction, parts = self.parts.get(node, (True, ()))
            for part in parts:
                if (conjunction or (part, step) in holding) and (part, step) not in needed:
                    needed.add((part, step))
                    pending.append((part, step))
        return needed


def idle_guards(tree: GuardTree, symbols: list[clingo.Symbol]) -> list[clingo.Symbol]:
    """The ``g(N,t)`` atoms of a model (its shown ``symbols``) that hold a chosen bound where the
    run does not need it."""
    fired = [(s.arguments[0].number, s.arguments[1].number) for s in symbols if s.name == "fire"]
    holding = {
        (s.arguments[0].number, s.arguments[1].number) for s in symbols if s.name == "g" and len(s.arguments) == 2
    }
    if not fired or not holding:
        return []
    needed = tree.needed(fired, holding, max(step for _, step in holding))
    return [
        clingo.Function("g", [clingo.Number(node), clingo.Number(step)])
        for node, step in sorted(holding - needed)
        if node in tree.chosen
    ]
