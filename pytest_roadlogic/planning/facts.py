"""The automaton as facts and the guards as rules: what every encoding's instance shares.

An encoding's instance writer (``encodings/<name>/instance.py``) writes its own facts and constants
and passes its guard rules to ``with_automaton``, which adds the automaton (for ``asp/automaton.lp``:
locations, transitions, their guard nodes, invariants, timed phases) and the guard program, one
``g(N,t)`` rule set per guard node. A bound the diagnosis may relax gets a ``relaxed(K)`` external.
Lane bounds are whole numbers in every encoding, so their rules are written here.
"""

from __future__ import annotations

import math

from ..logic.automaton import SymbolicAutomaton, Timing
from ..logic.guards import LANE, And, Bound, Guard, Not, Or


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


def bound_of(guard: Guard) -> Bound | None:
    """The bound a guard node stands for: itself, or the one its negation sits on (negation normal form)."""
    bound = guard.part if isinstance(guard, Not) else guard
    return bound if isinstance(bound, Bound) else None


def relaxable_constraints(automaton: SymbolicAutomaton) -> list:
    """The scenario's constraints that a diagnosis may relax, each once: every bound and duration
    with a source location (one modifier's bounds share it and are relaxed together)."""
    found: dict = {}
    _, numbering = guard_nodes(automaton)
    for guard in numbering:
        bound = bound_of(guard)
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
    base: list[str], automaton: SymbolicAutomaton, dt: float, relaxable: bool, node_facts, more_facts=None
) -> str:
    """An instance (facts and constants only: every rule is in ``asp/``): the encoding's own facts ``base``, the
    automaton's facts, the guard nodes' facts (``guard_facts`` with the encoding's ``node_facts``)
    and ``more_facts(relax)`` when given; with ``relaxable``, every bound and duration can be
    relaxed for a diagnosis (``relax``: constraint source -> its external's number)."""
    relax = {c.source: k for k, c in enumerate(relaxable_constraints(automaton))} if relaxable else {}
    facts = [
        *base,
        *automaton_facts(automaton, dt, relax),
        *guard_facts(automaton, relax, node_facts),
        *(more_facts(relax) if more_facts is not None else []),
    ]
    return "\n".join(facts) + "\n"


def guard_facts(automaton: SymbolicAutomaton, relax: dict, node_facts) -> list[str]:
    """The guard nodes as facts for ``asp/guards.lp`` and the encoding's ``guards.lp``: junctions
    and lane bounds here, the encoding's own bounds from ``node_facts(node, guard)``. A bound the
    diagnosis may relax gets ``relaxable(node(N),K)``. Each node is headed by a comment with the
    guard it stands for and the constraint it comes from (its place in the file)."""
    _, numbering = guard_nodes(automaton)
    facts = ["% guard nodes (asp/guards.lp)"]
    for guard, node in numbering.items():
        bound = bound_of(guard)
        facts.append(f"% node {node}: {guard}{origin(automaton, bound)}")
        if isinstance(guard, (And, Or)):
            facts.append(f"{'conjunction' if isinstance(guard, And) else 'disjunction'}({node}).")
            facts.extend(f"part({node},{numbering[part]})." for part in guard.parts)
        elif bound.term.quantity == LANE:
            facts.extend(lane_facts(node, bound, outside=isinstance(guard, Not)))
        else:
            facts.extend(node_facts(node, guard))
        if bound is not None and bound.source in relax:
            facts.append(f"relaxable(node({node}),{relax[bound.source]}).")
    return facts


def origin(automaton: SymbolicAutomaton, constraint) -> str:
    """`` (line L, column C: name, ...)``: where a constraint is written and the logical parameters
    behind it, for the comments of the instance; empty for a constraint of no place."""
    source = getattr(constraint, "source", None)
    if source is None:
        return ""
    names = automaton.parameters_of(constraint)
    return f" (line {source.line}, column {source.column}{': ' + ', '.join(names) if names else ''})"


def lane_facts(node: int, bound: Bound, outside: bool) -> list[str]:
    """A lane bound (whole lanes in every encoding): ``lane_within`` its range, or ``lane_outside``
    it, below the largest lane under the range or above the smallest over it."""
    actor, reference = actors_of(bound)
    if outside:
        below, above = whole_outside(bound.low, bound.high)
        if below == -math.inf and above == math.inf:
            return ["% never holds"]
        return [f"lane_outside({node},{actor},{reference},{','.join(bounds_text(below, above))})."]
    low, high = whole_range(bound.low, bound.high)
    if low > high:
        return ["% cannot hold: no whole lane in the range"]
    return [f"lane_within({node},{actor},{reference},{','.join(bounds_text(low, high))})."]


def actors_of(bound: Bound) -> tuple[str, str]:
    """A bound's actor and reference as ASP terms (``none`` for an absolute bound)."""
    return atom(bound.term.actor), atom(bound.term.reference) if bound.term.reference else "none"


def whole_range(low: float, high: float, scale: float = 1.0) -> tuple[float, float]:
    """The whole units of ``scale`` within [low, high] (infinite sides stay infinite)."""
    lo = -math.inf if low == -math.inf else math.ceil(low / scale - 1e-9)
    hi = math.inf if high == math.inf else math.floor(high / scale + 1e-9)
    return lo, hi


def whole_outside(low: float, high: float, margin: float = 0.0, scale: float = 1.0) -> tuple[float, float]:
    """The largest whole unit below ``low - margin`` and the smallest above ``high + margin``
    (-inf / inf for a side with no end): the values a negated bound may take."""
    below = -math.inf if low == -math.inf else math.ceil((low - margin) / scale - 1e-9) - 1
    above = math.inf if high == math.inf else math.floor((high + margin) / scale + 1e-9) + 1
    return below, above


def bounds_text(low, high) -> tuple[str, str]:
    """A range's two ends as ASP terms: the values as given, ``#inf`` / ``#sup`` for no end."""
    return ("#inf" if low == -math.inf else str(low)), ("#sup" if high == math.inf else str(high))


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
    for location in automaton.locations:
        facts.extend(
            f"asks({location.id},{atom(actor)},{what})."
            for actor, what in sorted((a, w) for a, w in location.asks if isinstance(w, str))
        )
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
        facts.append(f"timing({phase},{low},{high}){condition}.  % {timing}{origin(automaton, timing)}")
    return facts


def timing_steps(timing: Timing, dt: float) -> tuple[int, int | None]:
    """A timed phase's shortest and longest length in whole steps of ``dt`` (None: no longest)."""
    low = math.ceil(timing.low / dt - 1e-9)
    return low, math.floor(timing.high / dt + 1e-9) if math.isfinite(timing.high) else None


def atom(name: str) -> str:
    """An actor name as an ASP constant (quoted when it is not a lower-case identifier)."""
    return name if name[:1].islower() and name.replace("_", "").isalnum() else f'"{name}"'


def inset(low: float, high: float, margin: float) -> tuple[float, float]:
    """Shrink a finite range by up to ``margin`` per side, keeping at least a quarter of it."""
    if low == -math.inf or high == math.inf:
        return (low if low == -math.inf else low + margin, high if high == math.inf else high - margin)
    kept = min(margin, (high - low) / 4)
    return low + kept, high - kept
