"""Translating a scenario's behavior into a ``SymbolicAutomaton`` (the paper, section 3.2).

- atomic ``drive`` with start guard g1 and end guard g2:  i --g1--> s --g2--> f
- serial A . B: A's final and B's initial location are one instant, so every transition into
  f_A is fused with every transition out of i_B into one transition guarded by both (the end of A
  and the start of B happen at the same split point, as the semantics demands).
- parallel A || B: the product, built only over reachable locations. All components leave their
  initial locations together and reach their final locations together (``parallel`` without
  ``overlap:`` starts and ends its members together); in between they move alone or jointly.
- one_of A | B: the union, with a fresh initial and final location.
Locations that cannot reach the final location are pruned.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import Hashable

from ..frontend import model
from ..frontend.checked import CheckedScenario
from ..frontend.errors import error_at
from .guards import TRUE, Guard, conjunction
from .model import Location, SymbolicAutomaton, Timing, Transition
from .phase import Variant
from .translation import check_behavior_arguments, condition_guard, duration_interval, phase_guards

Key = Hashable


@dataclass
class _Edge:
    source: Key
    guard: Guard
    events: tuple[str, ...]
    target: Key
    starts: frozenset[int] = frozenset()
    ends: frozenset[int] = frozenset()


@dataclass
class _Fragment:
    """An automaton under construction, with hashable location keys."""

    initial: Key
    final: Key
    edges: list[_Edge]
    names: dict[Key, tuple[str, bool]] = field(default_factory=dict)  # key -> (name, labelled)
    drivers: dict[Key, frozenset[str]] = field(default_factory=dict)
    invariants: dict[Key, Guard] = field(default_factory=dict)

    def outgoing(self, key: Key) -> list[_Edge]:
        return [e for e in self.edges if e.source == key]


def build_automaton(checked: CheckedScenario, values: dict[str, object] | None = None) -> SymbolicAutomaton:
    """The automaton of a checked scenario, on its road.

    ``values`` fixes logical parameters (the refined strategy samples them); a parameter left out
    keeps its range, which the planner then chooses within (the base strategy).
    """
    if not isinstance(checked, CheckedScenario):
        raise TypeError("build_automaton takes a CheckedScenario: load it with frontend.check_file, load_file or pipeline.load_scenario")
    scenario = checked.scenario
    if scenario.behavior is None:
        raise error_at(scenario.location, f"scenario {scenario.name!r} has no `do` behavior", hint="add do: with what the actors must do")
    env = checked.space.environment(values)
    builder = _Builder(checked, env)
    fragment = builder.translate(scenario.behavior)
    return _finish(fragment, tuple(a.name for a in scenario.actors), scenario, builder.timings, checked.lanes)


class _Builder:
    """Walks the behavior tree; numbers fragments and collects the timed phases on the way."""

    def __init__(self, checked: CheckedScenario, env: dict) -> None:
        self.checked = checked
        self.env = env
        self.counter = itertools.count()
        self.timings: dict[int, Timing] = {}

    def translate(self, behavior: model.Behavior) -> _Fragment:
        if isinstance(behavior, model.Invocation):
            fragment = _atomic(behavior, self.checked, self.counter, self.env)
            duration = behavior.argument("duration")
        elif isinstance(behavior, model.Wait):
            return self.wait(behavior)
        elif isinstance(behavior, model.Composition):
            fragment = self.composition(behavior)
            duration = behavior.argument("duration")
        else:
            kind = type(behavior).__name__.lower()
            raise error_at(behavior.location, f"not supported yet by the automaton: {kind}", hint="events (emit, wait @e, until) and call are not translated")
        if duration is not None:
            low, high = duration_interval(duration, self.env)
            name = getattr(behavior, "label", None) or _phase_name(behavior)
            fragment = self.timed(fragment, name, low, high, duration.location)
        return fragment

    def composition(self, behavior: model.Composition) -> _Fragment:
        check_behavior_arguments(behavior)
        children = [self.translate(child) for child in behavior.children]
        if not children:
            raise error_at(behavior.location, f"{behavior.operator} has no members")
        if behavior.operator == "serial":
            result = children[0]
            for child in children[1:]:
                result = _serial(result, child)
            return result
        if behavior.operator == "parallel":
            return _parallel(children) if len(children) > 1 else children[0]
        return _one_of(children, next(self.counter))

    def wait(self, wait: model.Wait) -> _Fragment:
        """A phase in which nothing is asked of anyone: it lasts the given time, or until the condition."""
        name = wait.label or "wait"
        condition = wait.condition
        end: Guard = TRUE
        timed = None
        if isinstance(condition, model.Call) and condition.function == "elapsed":
            timed = duration_interval(condition.arguments[0], self.env)
        elif isinstance(condition, model.EventReference):
            raise error_at(wait.location, "not supported yet by the automaton: wait @event", hint="wait elapsed(t) or wait on a condition")
        else:
            end = condition_guard(condition, self.env)
        fragment = _phase(next(self.counter), name, wait.label is not None, Variant(end=end), frozenset())
        if timed is not None:
            fragment = self.timed(fragment, name, timed[0], timed[1], wait.location)
        return fragment

    def timed(self, fragment: _Fragment, name: str, low: float, high: float, source) -> _Fragment:
        """Mark the fragment's first and last instants as one timed phase lasting low..high seconds."""
        phase = next(self.counter)
        self.timings[phase] = Timing(phase, name, low, high, source)
        for edge in fragment.edges:
            if edge.source == fragment.initial:
                edge.starts = edge.starts | {phase}
            if edge.target == fragment.final:
                edge.ends = edge.ends | {phase}
        return fragment


def _phase_name(behavior: model.Behavior) -> str:
    if isinstance(behavior, model.Invocation):
        return f"{behavior.actor}.{behavior.action}"
    return getattr(behavior, "operator", "phase")


def _atomic(invocation: model.Invocation, checked: CheckedScenario, counter, env: dict) -> _Fragment:
    phase = phase_guards(invocation, checked.registry, checked.lanes, env)
    labelled = invocation.label is not None
    name = invocation.label if labelled else _phase_name(invocation)
    drivers = frozenset([invocation.actor]) if phase.drives else frozenset()
    fragments = [_phase(next(counter), name, labelled, variant, drivers) for variant in phase.variants]
    return fragments[0] if len(fragments) == 1 else _one_of(fragments, next(counter))


def _phase(uid: int, name: str, labelled: bool, variant: Variant, drivers: frozenset[str]) -> _Fragment:
    """``init --start--> phase --end--> fin`` for one phase (of an action, or a wait)."""
    i, s, f = ("i", uid), ("s", uid), ("f", uid)
    # An invariant holds throughout the phase, its first and last instants included.
    start = conjunction([variant.start, variant.invariant])
    end = conjunction([variant.end, variant.invariant])
    return _Fragment(
        initial=i,
        final=f,
        edges=[_Edge(i, start, (f"{name} start",), s), _Edge(s, end, (f"{name} end",), f)],
        names={s: (name, labelled)},
        drivers={s: drivers},
        invariants={s: variant.invariant} if not variant.invariant.is_true else {},
    )


def _serial(first: _Fragment, second: _Fragment) -> _Fragment:
    edges = [e for e in first.edges if e.target != first.final]
    edges += [e for e in second.edges if e.source != second.initial]
    for into in (e for e in first.edges if e.target == first.final):
        for out in second.outgoing(second.initial):
            edges.append(
                _Edge(into.source, conjunction([into.guard, out.guard]), into.events + out.events, out.target,
                      into.starts | out.starts, into.ends | out.ends)
            )
    return _Fragment(
        initial=first.initial,
        final=second.final,
        edges=edges,
        names={**first.names, **second.names},
        drivers={**first.drivers, **second.drivers},
        invariants={**first.invariants, **second.invariants},
    )


def _parallel(children: list[_Fragment]) -> _Fragment:
    initial = tuple(c.initial for c in children)
    final = tuple(c.final for c in children)
    edges: list[_Edge] = []
    seen = {initial}
    frontier = [initial]
    while frontier:
        current = frontier.pop()
        options = []
        for child, key in zip(children, current):
            moves: list[_Edge | None] = list(child.outgoing(key))
            if current != initial:
                moves.append(None)  # this component stays
            options.append(moves)
        for combination in itertools.product(*options):
            if all(m is None for m in combination):
                continue
            target = tuple(m.target if m is not None else key for m, key in zip(combination, current))
            finished = [t == c.final for t, c in zip(target, children)]
            if any(finished) and not all(finished):
                continue  # members of a parallel end together
            moving = [m for m in combination if m is not None]
            edges.append(
                _Edge(current, conjunction([m.guard for m in moving]), tuple(ev for m in moving for ev in m.events), target,
                      frozenset().union(*(m.starts for m in moving)), frozenset().union(*(m.ends for m in moving)))
            )
            if target not in seen:
                seen.add(target)
                frontier.append(target)
    names: dict[Key, tuple[str, bool]] = {}
    drivers: dict[Key, frozenset[str]] = {}
    invariants: dict[Key, Guard] = {}
    for key in seen:
        parts = [c.names[k] for c, k in zip(children, key) if k in c.names]
        labelled = [n for n, is_labelled in parts if is_labelled]
        chosen = labelled or [n for n, _ in parts]
        if chosen:
            names[key] = (" | ".join(chosen), bool(labelled))
        drivers[key] = frozenset().union(*(c.drivers.get(k, frozenset()) for c, k in zip(children, key)))
        parts = [c.invariants[k] for c, k in zip(children, key) if k in c.invariants]
        if parts:
            invariants[key] = conjunction(parts)
    return _Fragment(initial, final, edges, names, drivers, invariants)


def _one_of(children: list[_Fragment], uid: int) -> _Fragment:
    initial, final = ("oi", uid), ("of", uid)
    edges: list[_Edge] = []
    names: dict[Key, tuple[str, bool]] = {}
    drivers: dict[Key, frozenset[str]] = {}
    invariants: dict[Key, Guard] = {}
    for child in children:
        rename = {child.initial: initial, child.final: final}
        for e in child.edges:
            edges.append(_Edge(rename.get(e.source, e.source), e.guard, e.events, rename.get(e.target, e.target), e.starts, e.ends))
        names.update(child.names)
        drivers.update(child.drivers)
        invariants.update(child.invariants)
    return _Fragment(initial, final, edges, names, drivers, invariants)


def _finish(fragment: _Fragment, actors: tuple[str, ...], scenario: model.Scenario, timings: dict[int, Timing], lanes: int) -> SymbolicAutomaton:
    # Keep locations that are reachable from the initial one and can still reach the final one.
    forward = _closure(fragment.initial, lambda k: [e.target for e in fragment.edges if e.source == k])
    backward = _closure(fragment.final, lambda k: [e.source for e in fragment.edges if e.target == k])
    useful = forward & backward
    if fragment.initial not in useful:
        raise error_at(scenario.location, f"scenario {scenario.name!r} can never finish: its phases cannot all end", hint="check that the members of each parallel can end together")
    order = _bfs_order(fragment, useful)
    ids = {key: index for index, key in enumerate(order)}
    used: dict[str, int] = {}
    locations = []
    for key in order:
        if key == fragment.initial:
            name = "init"
        elif key == fragment.final:
            name = "fin"
        else:
            name = fragment.names.get(key, ("phase", False))[0]
        used[name] = used.get(name, 0) + 1
        if used[name] > 1:
            name = f"{name}#{used[name]}"
        locations.append(Location(ids[key], name, fragment.drivers.get(key, frozenset()), fragment.invariants.get(key, TRUE)))
    transitions = []
    for edge in fragment.edges:
        if edge.source in useful and edge.target in useful:
            transitions.append(Transition(len(transitions), ids[edge.source], ids[edge.target], edge.guard, edge.events, edge.starts, edge.ends))
    transitions.sort(key=lambda t: (t.source, t.target))
    transitions = [Transition(i, t.source, t.target, t.guard, t.events, t.starts, t.ends) for i, t in enumerate(transitions)]
    stationary = frozenset(a.name for a in scenario.actors if a.stationary)
    return SymbolicAutomaton(locations, transitions, ids[fragment.initial], ids[fragment.final], actors, stationary, timings, lanes)


def _closure(start: Key, neighbours) -> set[Key]:
    seen = {start}
    stack = [start]
    while stack:
        for nxt in neighbours(stack.pop()):
            if nxt not in seen:
                seen.add(nxt)
                stack.append(nxt)
    return seen


def _bfs_order(fragment: _Fragment, useful: set[Key]) -> list[Key]:
    order = [fragment.initial]
    index = 0
    while index < len(order):
        for e in fragment.edges:
            if e.source == order[index] and e.target in useful and e.target not in order:
                order.append(e.target)
        index += 1
    return order
