"""The continuous encoding's instance writer: a scenario's constants, facts and linear rows for ``asp/continuous/``.

Constants and facts (the vehicles, the limits, the start band) for ``asp/continuous/dynamics.lp``,
the automaton (``facts``), one rule set per guard node with ``&sum`` rows over positions and speeds
(inset by the settings' margins), and a phase's mean acceleration or distance travelled as rows
over its two ends.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ....logic.automaton import SymbolicAutomaton, Travelled
from ....logic.guards import HEADWAY, LANE, POSITION, SPEED, TRAVELED, And, Bound, Guard, Not, Or
from ...facts import atom, bound_rule, guard_nodes, inset, junction_rules, outside_rules, with_automaton
from .settings import ContinuousSettings


def number(value: float) -> str:
    """A rational constant for clingo-lpx: quoted, exact for the decimals we write."""
    fraction = Fraction(value).limit_denominator(10**6)
    text = f"{fraction.numerator}" if fraction.denominator == 1 else f"{float(fraction):.6f}".rstrip("0")
    return f'"{text}"'


def build_continuous_instance(
    automaton: SymbolicAutomaton, settings: ContinuousSettings, relaxable: bool = False
) -> tuple[str, str]:
    """(base program, state(t) program) of the scenario for the continuous encoding; with
    ``relaxable``, every bound and duration of the scenario can be switched off by an external
    ``relaxed(K)``, as in the grid encoding, for the diagnosis of a scenario without a plan."""
    s = settings
    vehicles = automaton.actors
    start_low, start_high = s.start_band()
    base = [
        "% scenario instance, continuous encoding (generated)",
        f"#const dt = {number(s.dt)}.",
        f"#const half_dt2 = {number(s.dt * s.dt / 2)}.",
        f"#const amin = {number(s.min_acceleration)}.",
        f"#const amax = {number(s.max_acceleration)}.",
        f"#const jerk = {number(s.max_jerk * s.dt)}.",
        f"#const vmin = {number(s.min_speed)}.",
        f"#const vmax = {number(s.max_speed)}.",
        f"#const v0min = {number(start_low)}.",
        f"#const v0max = {number(start_high)}.",
        f"#const gap = {number(s.min_gap)}.",
        f"#const closing_time = {number(s.closing_time)}.",
        f"#const lane_change_speed = {number(s.lane_change_speed)}.",
        f"#const spread = {number(s.spread)}.",
        f"#const first_vehicle = {atom(vehicles[0])}.",
        *(f"vehicle({atom(v)})." for v in vehicles),
        *(f"stationary({atom(v)})." for v in vehicles if v in automaton.stationary),
        *(f"may_stop({atom(v)})." for v in sorted(stopping(automaton, s))),
        f"lane_id(0..{automaton.lanes - 1}).",
        "lateral(-1;0;1).",
        f"lane_change_gap({s.lane_change_gap}).",
        "",
    ]
    return with_automaton(
        base,
        automaton,
        s.dt,
        relaxable,
        lambda node, guard, numbering, switch: _guard_rules(node, guard, numbering, s, switch),
        lambda relax: _rate_rules(automaton, s, relax),
    )


def _rate_rules(automaton: SymbolicAutomaton, settings: ContinuousSettings, relax: dict) -> list[str]:
    """The bounds over a timed phase P's two ends as linear rows. A mean acceleration: one row per
    length D the phase may have (a known length makes the mean linear):
      &sum{ v(V,t); -1*v(V,T) } >= lo*D*dt :- finish(P,t), begin(P,T), T = t-D.   (<= hi*D*dt likewise)
    with lo and hi inset by ``acceleration_margin``; the lengths run up to the phase's upper bound,
    or to the horizon limit for a phase with none. A distance travelled: one row,
      &sum{ p(V,t); -1*p(V,T) } >= lo :- finish(P,t), begin(P,T).
    inset by ``position_margin``."""
    rules = []
    for phase, timing in sorted(automaton.timings.items()):
        if not timing.rates:
            continue
        shortest = max(1, math.ceil(timing.low / settings.dt - 1e-9))
        longest = (
            min(settings.max_horizon, math.floor(timing.high / settings.dt + 1e-9))
            if math.isfinite(timing.high)
            else settings.max_horizon
        )
        for rate in timing.rates:
            rules.append(f"% {rate}")
            switch = f", not relaxed({relax[rate.source]})" if rate.source in relax else ""
            actor = atom(rate.actor)
            if isinstance(rate, Travelled):
                low, high = inset(rate.low, rate.high, settings.position_margin)
                body = f":- finish({phase},t), begin({phase},T){switch}."
                for value, operator in ((low, ">="), (high, "<=")):
                    if math.isfinite(value):
                        rules.append(f"&sum{{ p({actor},t); -1*p({actor},T) }} {operator} {number(value)} {body}")
                continue
            low, high = inset(rate.low, rate.high, settings.acceleration_margin)
            for length in range(shortest, longest + 1):
                seconds = length * settings.dt
                body = f":- finish({phase},t), begin({phase},T), T = t-{length}{switch}."
                for value, operator in ((low * seconds, ">="), (high * seconds, "<=")):
                    if math.isfinite(value):
                        rules.append(f"&sum{{ v({actor},t); -1*v({actor},T) }} {operator} {number(value)} {body}")
    return rules


def stopping(automaton: SymbolicAutomaton, settings: ContinuousSettings) -> set[str]:
    """The vehicles the scenario lets stop: a speed bound of theirs reaches below the speed every
    other driving vehicle keeps (``speed(0kph)``, ``change_speed(target: 0kph)``). The paper's
    no-stop rule, scoped: whoever the scenario does not ask to stop keeps moving."""
    _, numbering = guard_nodes(automaton)  # every guard and invariant, and every part of one
    return {
        node.term.actor
        for node in numbering
        if isinstance(node, Bound)
        and node.term.quantity == SPEED
        and node.term.reference is None
        and node.low < settings.min_speed
    }


def _terms(bound: Bound) -> tuple[str, str]:
    """The variable of a position or speed bound's quantity, and the &sum elements of its term."""
    variable = "p" if bound.term.quantity in (POSITION, TRAVELED) else "v"
    term = bound.term
    elements = f"{variable}({atom(term.actor)},t)"
    if term.quantity == TRAVELED:  # d(a) = p(a,t) - p(a,0)
        elements += f"; -1*p({atom(term.actor)},0)"
    if term.reference is not None:
        elements += f"; -1*{variable}({atom(term.reference)},t)"
    return variable, elements


def _margin(bound: Bound, settings: ContinuousSettings) -> float:
    if bound.term.quantity == HEADWAY:
        return settings.headway_margin
    return settings.position_margin if bound.term.quantity in (POSITION, TRAVELED) else settings.speed_margin


def _compared(bound: Bound, value: float) -> tuple[str, str]:
    """(&sum elements, right-hand side) that compare a bound's term with ``value`` in a linear
    row: the row's ``<=`` (``>=``) holds exactly when the term is at most (at least) ``value``.
    A headway ``h(a, b)`` is compared as ``gap - value * v(b)`` with 0 (the follower never
    reverses); a position or speed as the term itself with ``value``."""
    if bound.term.quantity == HEADWAY:
        ahead, behind = atom(bound.term.actor), atom(bound.term.reference)
        return f"p({ahead},t); -1*p({behind},t); {number(-value)}*v({behind},t)", "0"
    return _terms(bound)[1], number(value)


def _guard_rules(
    node: int, guard: Guard, numbering: dict[Guard, int], settings: ContinuousSettings, switch: str = ""
) -> list[str]:
    """The rules of one guard node; ``switch`` is a body condition (``, not relaxed(K)``) under
    which a bound's linear constraints apply."""
    head = f"g({node},t)"
    if isinstance(guard, (And, Or)):
        return junction_rules(node, guard, numbering)
    if isinstance(guard, Not):
        bound = guard.part
        assert isinstance(bound, Bound)
        if bound.term.quantity == LANE:
            return outside_rules(node, bound, None)  # lanes: the grid's rules, which need no settings
        return _outside(node, bound, settings, switch)
    assert isinstance(guard, Bound)
    if guard.term.quantity == LANE:
        return bound_rule(head, guard, None)
    low, high = inset(guard.low, guard.high, _margin(guard, settings))
    if guard.term.quantity == SPEED and guard.term.reference is None and guard.low <= 0:
        low = 0.0  # no margin below a standstill: no vehicle undershoots it (none reverses)
    # a free guard is tried false first: set at random, it would add linear constraints at steps
    # where no transition or invariant needs it
    rules = [f"{{ {head} }}.", f"#heuristic {head}. [1,false]"]
    for value, operator in ((high, "<="), (low, ">=")):
        if math.isfinite(value):
            elements, right = _compared(guard, value)
            rules.append(f"&sum{{ {elements} }} {operator} {right} :- {head}{switch}.")
    if guard.term.quantity == SPEED:
        rules += _speed_lead(node, _terms(guard)[1], low, high)
    return rules


def _speed_lead(node: int, elements: str, low: float, high: float) -> list[str]:
    """A speed bound that holds at a step is preferred to hold at the steps next to it too.

    Why: the motion planner rounds off the plan's changes of speed, starting them late and ending
    them early (measured on follow_then_overtake's refined samples: a relative speed the plan
    reached at a phase's first step, the trace reached 1.2 s later, past the 0.5 s a sampled
    duration allows). Holding the bound a step either side is a preference of the smoothing
    program, never a reason for no plan.
    """
    before, after = elements.replace(",t)", ",S)"), elements
    rules = []
    for bound, operator in ((high, "<="), (low, ">=")):
        if math.isfinite(bound):
            rules.append(f"&prefer{{ {before} }} {operator} {number(bound)} :- g({node},t), S = t-1, t > 0.")
            rules.append(f"&prefer{{ {after} }} {operator} {number(bound)} :- g({node},S), S = t-1.")
    return rules


def _outside(node: int, bound: Bound, settings: ContinuousSettings, switch: str = "") -> list[str]:
    """``not bound``: below the range or above it, with the margin outside."""
    margin = _margin(bound, settings)
    head = f"g({node},t)"
    sides = []
    rules = []
    if bound.low != -math.inf:
        sides.append(f"below({node},t)")
        elements, right = _compared(bound, bound.low - margin)
        rules.append(f"&sum{{ {elements} }} <= {right} :- below({node},t).")
    if bound.high != math.inf:
        sides.append(f"above({node},t)")
        elements, right = _compared(bound, bound.high + margin)
        rules.append(f"&sum{{ {elements} }} >= {right} :- above({node},t).")
    if not sides:
        return [f"% {head} never holds"]
    return [
        f"{{ {head} }}.",
        f"#heuristic {head}. [1,false]",
        f"{{ {'; '.join(sides)} }} = 1 :- {head}{switch}.",
        *rules,
    ]
