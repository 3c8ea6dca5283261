"""The automaton as facts and the guards as rules: what every encoding's instance shares.

An encoding's instance writer (``encodings/<name>/instance.py``) writes its own facts and constants
and passes its guard rules to ``with_automaton``, which adds the automaton (for ``asp/automaton.lp``:
locations, transitions, their guard nodes, invariants, timed phases) and the guard program, one
``g(N,t)`` rule set per guard node. A bound the diagnosis may relax gets a ``relaxed(K)`` external.
Lane bounds are whole numbers in every encoding, so their rules are written here.
"""

from __future__ import annotations

import math
from typing import Any

from ..logic.automaton import SymbolicAutomaton, Timing
from ..logic.guards import LANE, POSITION, SPEED, And, Bound, Guard, Not, Or


def guard_nodes(automaton: SymbolicAutomaton) -> tuple[dict[int, int], dict[Guard, int]]:
    """Number every distinct guard node, children first: (transition id -> node, guard -> node).

    Location invariants are numbered too (after the transitions' guards); ``invariant_nodes``
    looks them up.
    """
    numbering: dict[Guard, int] = {}

    def visit(guard: Guard) -> int:
        if guard in numbering:
            return numbering[guard]
        for part in _children(guard):
            visit(part)
        numbering[guard] = len(numbering)
        return numbering[guard]

    transitions = {t.id: visit(negation_normal(t.guard)) for t in automaton.transitions}
    for location in automaton.locations:
        if not location.invariant.is_true:
            visit(negation_normal(location.invariant))
    return transitions, numbering


def invariant_nodes(automaton: SymbolicAutomaton, numbering: dict[Guard, int]) -> dict[int, int]:
    """location id -> guard node of its invariant, for locations that have one."""
    return {
        loc.id: numbering[negation_normal(loc.invariant)] for loc in automaton.locations if not loc.invariant.is_true
    }


def negation_normal(guard: Guard) -> Guard:
    """The guard with every ``not`` pushed down onto a bound.

    A bound is planned with a margin inside its range; its negation must be planned with the
    margin outside, which only a negation that sits directly on the bound can know.
    """
    if isinstance(guard, Not):
        part = guard.part
        if isinstance(part, Not):
            return negation_normal(part.part)
        if isinstance(part, And):
            return Or(tuple(negation_normal(Not(p)) for p in part.parts))
        if isinstance(part, Or):
            return And(tuple(negation_normal(Not(p)) for p in part.parts))
        return guard
    if isinstance(guard, (And, Or)):
        return type(guard)(tuple(negation_normal(p) for p in guard.parts))
    return guard


def _children(guard: Guard) -> tuple[Guard, ...]:
    if isinstance(guard, (And, Or)):
        return guard.parts
    if isinstance(guard, Not):
        return (guard.part,)
    return ()


def _bound_of(guard: Guard) -> Bound | None:
    """The bound a guard node stands for: itself, or the one its negation sits on (negation normal form)."""
    bound = guard.part if isinstance(guard, Not) else guard
    return bound if isinstance(bound, Bound) else None


def relaxable_constraints(automaton: SymbolicAutomaton) -> list:
    """The scenario's constraints that a diagnosis may relax, each once: every bound and duration
    with a source location (one modifier's bounds share it and are relaxed together)."""
    found: dict = {}
    _, numbering = guard_nodes(automaton)
    for guard in numbering:
        bound = _bound_of(guard)
        if bound is not None and bound.source is not None:
            found.setdefault(bound.source, bound)
    for timing in automaton.timings.values():
        if timing.source is not None:
            found.setdefault(timing.source, timing)
        for rate in timing.rates:
            if rate.source is not None:
                found.setdefault(rate.source, rate)
    return list(found.values())


def with_automaton(
    base: list[str], automaton: SymbolicAutomaton, dt: float, relaxable: bool, rules, more_state=None
) -> tuple[str, str]:
    """(base program, state(t) program): an encoding's own base facts ``base`` followed by the
    automaton's facts, and the guard program from the encoding's ``rules`` (see guard_program)
    followed by ``more_state(relax)``'s rules when given; with ``relaxable``, every bound and
    duration can be relaxed for a diagnosis (``relax``: constraint source -> its external's number)."""
    relax = {c.source: k for k, c in enumerate(relaxable_constraints(automaton))} if relaxable else {}
    state = guard_program(automaton, relax, rules) + (more_state(relax) if more_state is not None else [])
    return "\n".join([*base, *automaton_facts(automaton, dt, relax)]) + "\n", "\n".join(state) + "\n"


def guard_program(automaton: SymbolicAutomaton, relax: dict, rules) -> list[str]:
    """The state(t) program of the guards: ``rules(node, guard, numbering, switch)`` gives one node's
    rules in an encoding; a bound the diagnosis may relax gets the switch ``, not relaxed(K)`` on its
    constraints and holds whenever it is relaxed."""
    _, numbering = guard_nodes(automaton)
    state = ["% guards: g(N,t) holds when guard node N holds at step t (generated)"]
    for guard, node in numbering.items():
        state.append(f"% node {node}: {guard}")
        bound = _bound_of(guard)
        if bound is not None and bound.source in relax:
            # relaxed: the guard holds, and the constraints it imposes stand down
            k = relax[bound.source]
            state.extend(rules(node, guard, numbering, f", not relaxed({k})"))
            state.append(f"g({node},t) :- relaxed({k}).")
        else:
            state.extend(rules(node, guard, numbering, ""))
    return state


def automaton_facts(automaton: SymbolicAutomaton, dt: float, relax: dict | None = None) -> list[str]:
    """The automaton as facts for asp/automaton.lp (locations, transitions and their guard nodes,
    invariants, timed phases in steps of ``dt``); a timing whose source is in ``relax`` holds only
    while its ``relaxed(K)`` external does not."""
    relax = relax or {}
    facts = [
        "% the automaton",
        *(f"location({loc.id}).  % {loc.name}" for loc in automaton.locations),
        f"initial({automaton.initial}).",
        f"final({automaton.final}).",
    ]
    transition_node, numbering = guard_nodes(automaton)
    for t in automaton.transitions:
        facts.append(f"transition({t.id},{t.source},{t.target}).  % {t.guard}")
        facts.append(f"guard_of({t.id},{transition_node[t.id]}).")
    for location, node in invariant_nodes(automaton, numbering).items():
        facts.append(f"invariant_of({location},{node}).  % {automaton.location(location).invariant}")
    for t in automaton.transitions:
        facts.extend(f"starts({t.id},{p})." for p in sorted(t.starts) if p in automaton.timings)
        facts.extend(f"ends({t.id},{p})." for p in sorted(t.ends) if p in automaton.timings)
    facts.extend(f"#external relaxed({k})." for k in relax.values())
    for phase, timing in automaton.timings.items():
        low, high = timing_steps(timing, dt)
        high = "#sup" if high is None else high
        condition = f" :- not relaxed({relax[timing.source]})" if timing.source in relax else ""
        facts.append(f"timing({phase},{low},{high}){condition}.  % {timing}")
    return facts


def timing_steps(timing: Timing, dt: float) -> tuple[int, int | None]:
    """A timed phase's shortest and longest length in whole steps of ``dt`` (None: no longest)."""
    low = math.ceil(timing.low / dt - 1e-9)
    return low, math.floor(timing.high / dt + 1e-9) if math.isfinite(timing.high) else None


def atom(name: str) -> str:
    """An actor name as an ASP constant (quoted when it is not a lower-case identifier)."""
    return name if name[:1].islower() and name.replace("_", "").isalnum() else f'"{name}"'


def junction_rules(node: int, guard: And | Or, numbering: dict[Guard, int]) -> list[str]:
    """A conjunction's or disjunction's rules, over its parts' nodes (the same in every encoding)."""
    head = f"g({node},t)"
    if isinstance(guard, And):
        if not guard.parts:
            return [f"{head}."]
        return [f"{head} :- " + ", ".join(f"g({numbering[p]},t)" for p in guard.parts) + "."]
    return [f"{head} :- g({numbering[p]},t)." for p in guard.parts]


def _margin_and_scale(bound: Bound, settings: Any) -> tuple[float, float, str]:
    """(margin, metres or m/s per grid unit, fluent) of a bound's quantity. A lane bound needs no
    settings (lanes are whole numbers in every encoding): the continuous encoding passes None."""
    quantity = bound.term.quantity
    if quantity == LANE:
        return 0.0, 1.0, "lane"
    assert settings is not None, "a position or speed bound is planned with the grid's settings"
    if quantity == POSITION:
        return settings.position_margin, settings.grid, "pos"
    if quantity == SPEED:
        return settings.speed_margin, settings.grid / settings.dt, "vel"
    return 0.0, 1.0, "lane"


def _grid_range(low: float, high: float, scale: float) -> tuple[float, float]:
    """The whole grid units within [low, high] (infinite sides stay infinite)."""
    lo = -math.inf if low == -math.inf else math.ceil(low / scale - 1e-9)
    hi = math.inf if high == math.inf else math.floor(high / scale + 1e-9)
    return lo, hi


def position_terms(bound: Bound) -> tuple[str, str]:
    term = bound.term
    return f"p({atom(term.actor)},t)", "0" if term.reference is None else f"p({atom(term.reference)},t)"


def _fluent_terms(bound: Bound, fluent: str) -> tuple[list[str], str]:
    """The body atoms reading a speed or lane bound's term, and the term's value in them."""
    term = bound.term
    if term.reference is None:
        return [f"{fluent}({atom(term.actor)},X,t)"], "X"
    return [f"{fluent}({atom(term.actor)},X,t)", f"{fluent}({atom(term.reference)},Y,t)"], "X-Y"


def outside_rules(node: int, bound: Bound, settings: Any, switch: str = "") -> list[str]:
    """``not bound``: the value below or above the range, planned with the margin outside it."""
    margin, scale, fluent = _margin_and_scale(bound, settings)
    head = f"g({node},t)"
    # the largest grid value below low - margin and the smallest above high + margin
    below = None if bound.low == -math.inf else math.ceil((bound.low - margin) / scale - 1e-9) - 1
    above = None if bound.high == math.inf else math.floor((bound.high + margin) / scale + 1e-9) + 1
    if below is None and above is None:
        return [f"% {head} never holds"]
    if fluent == "pos":
        a, b = position_terms(bound)
        sides = [f"below({node},t)"] * (below is not None) + [f"above({node},t)"] * (above is not None)
        rules = [f"{{ {'; '.join(sides)} }} = 1 :- {head}{switch}.", f"{{ {head} }}."]
        if below is not None:
            rules.append(f"&diff{{ {a} - {b} }} <= {below} :- below({node},t).")
        if above is not None:
            rules.append(f"&diff{{ {b} - {a} }} <= {-above} :- above({node},t).")
        return rules
    values, value = _fluent_terms(bound, fluent)
    rules = []
    if below is not None:
        rules.append(f"{head} :- " + ", ".join(values + [f"{value} <= {below}"]) + ".")
    if above is not None:
        rules.append(f"{head} :- " + ", ".join(values + [f"{value} >= {above}"]) + ".")
    return rules


def bound_rule(head: str, bound: Bound, settings: Any) -> list[str]:
    """A speed or lane bound, derived from the vel/lane atoms (speeds with a margin inside)."""
    margin, scale, fluent = _margin_and_scale(bound, settings)
    lo, hi = planned_range(bound.low, bound.high, margin, scale)
    if lo > hi:
        return [f"% {head} cannot hold on this grid"]
    conditions, value = _fluent_terms(bound, fluent)
    conditions += [f"{value} >= {lo}"] if lo != -math.inf else []
    conditions += [f"{value} <= {hi}"] if hi != math.inf else []
    return [f"{head} :- " + ", ".join(conditions) + "."]


def planned_range(low: float, high: float, margin: float, scale: float) -> tuple[float, float]:
    """The grid values a plan may use for [low, high]: inset by the margin, unless that leaves none.

    A narrow range (a sampled value's one-cell band, say) can hold a grid value that every inset
    misses: [23, 24] inset to [23.25, 23.75] has no whole metre, so the plan uses the range itself.
    """
    lo, hi = _grid_range(*inset(low, high, margin), scale)
    return (lo, hi) if lo <= hi else _grid_range(low, high, scale)


def inset(low: float, high: float, margin: float) -> tuple[float, float]:
    """Shrink a finite range by up to ``margin`` per side, keeping at least a quarter of it."""
    if low == -math.inf or high == math.inf:
        return (low if low == -math.inf else low + margin, high if high == math.inf else high - margin)
    kept = min(margin, (high - low) / 4)
    return low + kept, high - kept
