"""The grid encoding's instance writer: a scenario's facts and guard rules for ``asp/grid/``.

The background theory (``asp/grid/dynamics.lp``, ``domain.lp``, ``initial.lp``, and the shared
``asp/automaton.lp``) is fixed; what is scenario-specific is written here, as facts and constants:
the vehicles, the grid (speeds and accelerations in cells per step, start zones and speeds: the
rules that read them are in ``asp/grid/initial.lp``), the run-up, the automaton (``facts``), and a
random start's preferences (``asp/grid/preferences.lp``), and the guard nodes
(``asp/guards.lp``, ``asp/grid/guards.lp``). No rule is written here: the rules are the ``.lp`` files'. Position and speed bounds are planned
with a margin inside their range so that a simulation that tracks the plan with some error still
meets them (the monitor checks the ranges as written).
"""

from __future__ import annotations

import math
import random

from ....frontend.errors import OscError, error_at
from ....logic.automaton import HeldSpeed, SymbolicAutomaton
from ....logic.guards import HEADWAY, POSITION, TRAVELED, Bound, Guard, Not
from ...facts import actors_of, atom, bounds_text, inset, whole_outside, whole_range, with_automaton
from .settings import GridSettings


def build_instance(automaton: SymbolicAutomaton, settings: GridSettings, relaxable: bool = False) -> tuple[str, str]:
    """The scenario's instance for the grid encoding.

    With ``relaxable``, each constraint of ``relaxable_constraints`` (numbered in that order) is
    switched off by an external ``relaxed(K)``: a diagnosis asks which of them cannot hold together.
    """
    rate = next(
        (rate for timing in automaton.timings.values() for rate in timing.rates if not isinstance(rate, HeldSpeed)),
        None,
    )
    if rate is not None:
        why = (
            "the grid encoding's accelerations are -2, 0 and +2 cells per step^2"
            if rate.column == "speed"
            else "the grid encoding has no rows over a phase's two ends"
        )
        raise _needs_continuous(rate.source, rate.construct, why)
    speeds = settings.speeds()
    if not speeds or speeds[0] < 1:
        raise ValueError("the speed bounds leave no positive speed on the grid")
    accels = settings.acceleration_cells()
    starts = settings.initial_speeds()
    if not starts:
        raise ValueError("the initial speed range leaves no allowed speed on the grid")
    width, zones = start_zones(automaton, settings)
    gap = math.ceil(settings.min_gap / settings.grid)
    vehicles = automaton.actors
    base = [
        "% scenario instance (generated)",
        *(f"vehicle({atom(v)})." for v in vehicles),
        *(f"stationary({atom(v)})." for v in vehicles if v in automaton.stationary),
        f"lane_id(0..{automaton.lanes - 1}).",
        f"speed({speeds[0]}..{speeds[-1]}).",
        *(f"accel({a})." for a in accels),
        "lateral(-1;0;1).",
        f"lane_change_gap({settings.lane_change_gap}).",
        f"min_gap({gap}).",
        "",
        "% initial state (asp/grid/initial.lp): the first vehicle at cell 0, the others in start zones",
        f"#const first_vehicle = {atom(vehicles[0])}.",
        f"#const zones = {zones}.",
        f"#const start_low = {starts[0]}.",
        f"#const start_high = {starts[-1]}.",
        f"zone_width({width}).",
        "% the run-up from standstill: runup_steps(X,S), the steps to reach speed X; runup(X,T,Lo,Hi),",
        "% the cells covered when the run-up lasts T steps (bounds of the exact distance)",
        *(f"runup_steps({x},{settings.runup_steps(x)})." for x in starts),
        *(
            _runup_fact(x, duration, settings)
            for x in starts
            for duration in range(settings.runup_steps(x), settings.runup_steps(starts[-1]) + 1)
        ),
        "runup_steps(0,0).",
        f"runup(0,0..{settings.runup_steps(starts[-1])},0,0).  % a stationary object has no run-up",
        "",
    ]
    return with_automaton(
        base,
        automaton,
        settings.dt,
        relaxable,
        lambda node, guard: node_facts(node, guard, settings, automaton),
        lambda relax: held_facts(automaton, relax),
    )


def held_facts(automaton: SymbolicAutomaton, relax: dict) -> list[str]:
    """Each kept speed (``HeldSpeed``, keep_speed()) as ``held_speed(R,P,V)`` (``asp/grid/rates.lp``:
    no acceleration on any step of phase P, the speed exactly held, as the grid's speeds are whole
    cells), with ``relaxable(rate(R),K)`` when the diagnosis may relax it."""
    facts = ["% kept speeds (asp/grid/rates.lp)"]
    held = (
        (phase, rate)
        for phase, timing in sorted(automaton.timings.items())
        for rate in timing.rates
        if isinstance(rate, HeldSpeed)
    )
    for r, (phase, rate) in enumerate(held):
        facts.append(f"held_speed({r},{phase},{atom(rate.actor)}).  % {rate}")
        if rate.source in relax:
            facts.append(f"relaxable(rate({r}),{relax[rate.source]}).")
    return facts


def _runup_fact(cells_per_step: int, steps: int, settings: GridSettings) -> str:
    metres = settings.runup_distance(cells_per_step * settings.grid / settings.dt, steps * settings.dt)
    return f"runup({cells_per_step},{steps},{math.floor(metres / settings.grid + 1e-9)},{math.ceil(metres / settings.grid - 1e-9)})."


def node_facts(node: int, guard: Guard, settings: GridSettings, automaton: SymbolicAutomaton) -> list[str]:
    """One guard node's facts (``asp/grid/guards.lp``): a position bound, ``position_within`` in
    cells, or its negation, ``position_outside``; a speed bound, ``speed_within`` in cells per
    step, or ``speed_outside``. Within: the range inset by the margin (``planned_range``); outside:
    the largest grid value below ``low - margin`` and the smallest above ``high + margin``.
    ``#inf`` / ``#sup`` for a side with no end; a range with no grid value has no fact (its guard
    never holds)."""
    outside = isinstance(guard, Not)
    bound = guard.part if outside else guard
    assert isinstance(bound, Bound)
    if bound.term.quantity in _CONTINUOUS_ONLY:
        raise _needs_continuous(
            bound.source, _CONTINUOUS_ONLY[bound.term.quantity], "the grid encoding cannot express it"
        )
    if bound.term.quantity == POSITION:
        margin, scale, kind = settings.position_margin, settings.grid, "position"
    else:
        margin, scale, kind = settings.speed_margin, settings.grid / settings.dt, "speed"
    actor, reference = actors_of(bound)
    if outside:
        below, above = whole_outside(bound.low, bound.high, margin, scale)
        if below == -math.inf and above == math.inf:
            return ["% never holds"]
        low, high = bounds_text(below, above)
        return [f"{kind}_outside({node},{actor},{reference},{low},{high})."]
    lo, hi = planned_range(bound.low, bound.high, automaton.planned_margin(bound, margin), scale)
    if lo > hi:
        return ["% cannot hold on this grid"]
    low, high = bounds_text(lo, hi)
    return [f"{kind}_within({node},{actor},{reference},{low},{high})."]


def planned_range(low: float, high: float, margin: float, scale: float) -> tuple[float, float]:
    """The grid values a plan may use for [low, high]: inset by the margin, unless that leaves none.

    A narrow range (a sampled value's one-cell band, say) can hold a grid value that every inset
    misses: [23, 24] inset to [23.25, 23.75] has no whole metre, so the plan uses the range itself.
    """
    lo, hi = whole_range(*inset(low, high, margin), scale)
    return (lo, hi) if lo <= hi else whole_range(low, high, scale)


# the grid's positions and speeds are separate integer fluents: a time headway (a gap over a
# speed) has no rule there
HEADWAY_CONSTRUCT = "a time headway (position(time: ...))"


# nor the metres travelled since the start, which the grid's position differences do not carry
_CONTINUOUS_ONLY = {HEADWAY: HEADWAY_CONSTRUCT, TRAVELED: "a distance travelled (traveled_distance())"}


def _needs_continuous(source, construct: str, why: str) -> OscError:
    """A construct only the continuous encoding plans, refused by the grid at its place."""
    return error_at(
        source,
        f"{construct} needs the continuous planner; {why}",
        hint="drop --roadlogic-encoding grid / --encoding grid (continuous is the default)",
    )


def _farthest_position(automaton: SymbolicAutomaton) -> float:
    """How far apart the scenario's position bounds may need vehicles to start: per pair of
    vehicles the largest finite distance bounding them, summed over the pairs (a chain of them
    can put the last vehicle that far from the first)."""
    guards = [t.guard for t in automaton.transitions] + [loc.invariant for loc in automaton.locations]
    farthest: dict[frozenset[str], float] = {}
    for guard in guards:
        for bound in guard.atoms():
            if bound.term.quantity != POSITION:
                continue
            pair = frozenset((bound.term.actor, bound.term.reference or ""))
            ends = [abs(end) for end in (bound.low, bound.high) if math.isfinite(end)]
            farthest[pair] = max([farthest.get(pair, 0.0), *ends])
    return sum(farthest.values())


def start_zones(automaton: SymbolicAutomaton, settings: GridSettings) -> tuple[int, int]:
    """(cells per start zone, zones on either side of the first vehicle): enough zones to cover the
    spread, or the farthest start the scenario's position bounds ask for when that is farther."""
    width = max(1, round(settings.start_zone / settings.grid))
    return width, math.ceil(max(settings.initial_spread, _farthest_position(automaton)) / settings.grid / width)


def start_preferences(automaton: SymbolicAutomaton, settings: GridSettings, draw: random.Random) -> str:
    """A random start's draws as facts (``asp/grid/preferences.lp`` says what the solver does with
    them): per vehicle a preferred start lane, zone and speed, and one acceleration; drawn from
    ``draw`` in a fixed order so that one seed gives one set of preferences."""
    starts = list(settings.initial_speeds())
    _, zones = start_zones(automaton, settings)
    accelerations = settings.acceleration_cells()
    facts = ["% a random start's draws (asp/grid/preferences.lp)"]
    for index, vehicle in enumerate(automaton.actors):
        name = atom(vehicle)
        facts.append(f"preferred_lane({name},{draw.randrange(automaton.lanes)}).")
        if index:
            facts.append(f"preferred_zone({name},{draw.randint(-zones, zones)}).")
        if vehicle in automaton.stationary:
            continue
        facts.append(f"preferred_speed({name},{draw.choice(starts)}).")
        facts.append(f"preferred_acc({name},{draw.choice(accelerations)}).")
    return "\n".join(facts) + "\n"
