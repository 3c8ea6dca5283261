"""The grid encoding's instance writer: a scenario's facts and guard rules for ``asp/grid/``.

The background theory (``asp/grid/dynamics.lp``, ``domain.lp``, ``initial.lp``, and the shared
``asp/automaton.lp``) is fixed; what is scenario-specific is written here, as facts and constants:
the vehicles, the grid (speeds and accelerations in cells per step, start zones and speeds: the
rules that read them are in ``asp/grid/initial.lp``), the run-up, the automaton (``facts``), and a
random start's preferences (``asp/grid/preferences.lp``). Position and speed bounds are planned
with a margin inside their range so that a simulation that tracks the plan with some error still
meets them (the monitor checks the ranges as written).
"""

from __future__ import annotations

import math
import random

from ....frontend.errors import OscError, error_at
from ....logic.automaton import SymbolicAutomaton
from ....logic.guards import HEADWAY, POSITION, TRAVELED, And, Bound, Guard, Not, Or
from ...facts import (
    atom,
    bound_rule,
    junction_rules,
    outside_rules,
    planned_range,
    position_terms,
    with_automaton,
)
from .settings import GridSettings


def build_instance(automaton: SymbolicAutomaton, settings: GridSettings, relaxable: bool = False) -> tuple[str, str]:
    """Returns (base program, state(t) program) of the scenario instance.

    With ``relaxable``, each constraint of ``relaxable_constraints`` (numbered in that order) is
    switched off by an external ``relaxed(K)``: a diagnosis asks which of them cannot hold together.
    """
    rate = next((rate for timing in automaton.timings.values() for rate in timing.rates), None)
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
        "% initial state (asp/initial.lp): the first vehicle at cell 0, the others in start zones",
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
        lambda node, guard, numbering, switch: _guard_rules(node, guard, numbering, settings, switch),
    )


def _runup_fact(cells_per_step: int, steps: int, settings: GridSettings) -> str:
    metres = settings.runup_distance(cells_per_step * settings.grid / settings.dt, steps * settings.dt)
    return f"runup({cells_per_step},{steps},{math.floor(metres / settings.grid + 1e-9)},{math.ceil(metres / settings.grid - 1e-9)})."


def _guard_rules(
    node: int, guard: Guard, numbering: dict[Guard, int], settings: GridSettings, switch: str = ""
) -> list[str]:
    """The rules of one guard node; ``switch`` is a body condition (``, not relaxed(K)``) under
    which the difference constraints of a position bound apply."""
    head = f"g({node},t)"
    if isinstance(guard, (And, Or)):
        return junction_rules(node, guard, numbering)
    if isinstance(guard, Not):  # on a bound (negation normal form): outside the range, with a margin
        assert isinstance(guard.part, Bound)
        if guard.part.term.quantity in _CONTINUOUS_ONLY:
            raise _needs_continuous(
                guard.part.source, _CONTINUOUS_ONLY[guard.part.term.quantity], "the grid encoding cannot express it"
            )
        return outside_rules(node, guard.part, settings, switch)
    assert isinstance(guard, Bound)
    if guard.term.quantity in _CONTINUOUS_ONLY:
        raise _needs_continuous(
            guard.source, _CONTINUOUS_ONLY[guard.term.quantity], "the grid encoding cannot express it"
        )
    if guard.term.quantity == POSITION:
        return _position_rules(node, guard, settings, switch)
    return bound_rule(head, guard, settings)


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


def _position_rules(node: int, bound: Bound, settings: GridSettings, switch: str = "") -> list[str]:
    """A position bound as difference constraints on the position variables.

    Positions are not atoms, so the guard cannot be derived from them: the solver chooses
    ``g(N,t)`` and its truth imposes the bound. Guards are only used positively (negations sit on
    bounds, ``outside_rules``), so a false ``g`` needs no meaning.
    """
    lo, hi = planned_range(bound.low, bound.high, settings.position_margin, settings.grid)
    head = f"g({node},t)"
    if lo > hi:
        return [f"% {head} cannot hold on this grid"]
    a, b = position_terms(bound)
    rules = [f"{{ {head} }}."]
    if hi != math.inf:
        rules.append(f"&diff{{ {a} - {b} }} <= {hi} :- {head}{switch}.")
    if lo != -math.inf:
        rules.append(f"&diff{{ {b} - {a} }} <= {-lo} :- {head}{switch}.")
    return rules


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
    """A random start's draws (asp/preferences.lp says what the solver does with them): per vehicle
    a preferred start lane, zone and speed, as ground heuristics of step 0's atoms, and one
    acceleration, as a fact the per-step heuristics read; drawn from ``draw`` in a fixed order so
    that one seed gives one set of preferences."""
    starts = list(settings.initial_speeds())
    _, zones = start_zones(automaton, settings)
    accelerations = settings.acceleration_cells()
    rules = []
    for index, vehicle in enumerate(automaton.actors):
        name = atom(vehicle)
        rules.append(f"#heuristic lane({name},{draw.randrange(automaton.lanes)},0). [1,true]")
        if index:
            rules.append(f"#heuristic zone({name},{draw.randint(-zones, zones)}). [1,true]")
        if vehicle in automaton.stationary:
            continue
        rules.append(f"#heuristic vel({name},{draw.choice(starts)},0). [1,true]")
        rules.append(f"preferred_acc({name},{draw.choice(accelerations)}).")
    return "\n".join(rules) + "\n"
