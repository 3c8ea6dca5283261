"""The ASP instance of one scenario: the automaton and the settings as facts, guards as rules.

The background theory in ``asp/*.lp`` is fixed; everything scenario-specific is generated here:
the vehicles, the grid (speeds and accelerations in cells per step), the automaton's locations and
transitions, and one ``g(N,t)`` rule set per guard node. Position and speed bounds are planned
with a margin inside their range so that a simulation that tracks the plan with some error still
meets them (the monitor checks the ranges as written).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..automaton.guards import POSITION, SPEED, And, Bound, Guard, Not, Or
from ..automaton.model import SymbolicAutomaton


@dataclass(frozen=True)
class PlanningSettings:
    dt: float = 1.0  # seconds per planning step
    grid: float = 1.0  # metres per cell
    lanes: int = 3
    min_speed: float = 2.0  # m/s; positive, so that no vehicle stops (domain rule 1)
    max_speed: float = 20.0  # m/s
    initial_speed: tuple[float, float] = (8.0, 14.0)  # m/s, the speeds the plan may start with
    accelerations: tuple[float, ...] = (-2.0, 0.0, 2.0)  # m/s^2, applied for a whole step
    min_gap: float = 8.0  # m between the centres of two vehicles sharing a lane
    lane_change_gap: int = 3  # steps from one lane change of a vehicle to its next
    initial_spread: float = 60.0  # m; other vehicles start within this distance of the first
    position_margin: float = 1.5  # m planned inside each side of a position range, when it fits
    speed_margin: float = 0.5  # m/s likewise for speed ranges
    runup_acceleration: float = 2.0  # m/s^2 with which every vehicle leaves standstill
    max_horizon: int = 25  # steps
    time_limit: float = 60.0  # seconds for one solve, all horizons together

    def cells_per_step(self, speed: float) -> float:
        return speed * self.dt / self.grid

    def speeds(self) -> range:
        return range(math.ceil(self.cells_per_step(self.min_speed)), math.floor(self.cells_per_step(self.max_speed)) + 1)

    @property
    def runup(self) -> float:
        """Seconds from standstill to the scenario's start: the fastest start speed at the run-up rate."""
        return self.initial_speed[1] / self.runup_acceleration

    def runup_distance(self, speed: float) -> float:
        """Metres a vehicle covers in the run-up: it accelerates to ``speed``, then cruises."""
        return speed * self.runup - speed**2 / (2 * self.runup_acceleration)

    def acceleration_cells(self) -> list[int]:
        cells = []
        for a in self.accelerations:
            value = a * self.dt * self.dt / self.grid
            if not float(value).is_integer() or int(value) % 2:
                raise ValueError(f"acceleration {a} m/s^2 is not an even number of cells per step^2 (exact kinematics need it)")
            cells.append(int(value))
        return cells


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

    transitions = {t.id: visit(t.guard) for t in automaton.transitions}
    for location in automaton.locations:
        if not location.invariant.is_true:
            visit(location.invariant)
    return transitions, numbering


def invariant_nodes(automaton: SymbolicAutomaton, numbering: dict[Guard, int]) -> dict[int, int]:
    """location id -> guard node of its invariant, for locations that have one."""
    return {loc.id: numbering[loc.invariant] for loc in automaton.locations if not loc.invariant.is_true}


def _children(guard: Guard) -> tuple[Guard, ...]:
    if isinstance(guard, (And, Or)):
        return guard.parts
    if isinstance(guard, Not):
        return (guard.part,)
    return ()


def build_instance(automaton: SymbolicAutomaton, settings: PlanningSettings) -> tuple[str, str]:
    """Returns (base program, state(t) program) of the scenario instance."""
    speeds = settings.speeds()
    if not speeds or speeds[0] < 1:
        raise ValueError("the speed bounds leave no positive speed on the grid")
    accels = settings.acceleration_cells()
    v_lo = math.ceil(settings.cells_per_step(settings.initial_speed[0]))
    v_hi = math.floor(settings.cells_per_step(settings.initial_speed[1]))
    spread = math.ceil(settings.initial_spread / settings.grid)
    gap = math.ceil(settings.min_gap / settings.grid)
    runup_spread = math.ceil(
        (settings.runup_distance(v_hi * settings.grid / settings.dt) - settings.runup_distance(v_lo * settings.grid / settings.dt)) / settings.grid
    )
    # how far apart two vehicles can be and still collide or swap within one step; at step 0 also
    # within the run-up from standstill, whose spread grows with the square of the start speed
    reach = (speeds[-1] - speeds[0]) + max(abs(a) for a in accels) + gap
    reach0 = max(reach, runup_spread + gap)
    vehicles = automaton.actors
    base = [
        "% scenario instance (generated)",
        *(f"vehicle({_atom(v)})." for v in vehicles),
        *(f"stationary({_atom(v)})." for v in vehicles if v in automaton.stationary),
        f"lane_id(0..{settings.lanes - 1}).",
        f"speed({speeds[0]}..{speeds[-1]}).",
        *(f"accel({a})." for a in accels),
        "lateral(-1;0;1).",
        f"lane_change_gap({settings.lane_change_gap}).",
        f"min_gap({gap}).",
        f"reach({reach}).",
        f"reach0({reach0}).",
        "",
        "% initial state: the first vehicle at cell 0, the others within the spread",
        f"pos({_atom(vehicles[0])},0,0).",
        *(f"{{ pos({_atom(v)},S,0) : S = -{spread}..{spread} }} = 1." for v in vehicles[1:]),
        "{ lane(V,L,0) : lane_id(L) } = 1 :- vehicle(V).",
        f"{{ vel(V,X,0) : X = {v_lo}..{v_hi}, speed(X) }} = 1 :- vehicle(V), not stationary(V).",
        "vel(V,0,0) :- stationary(V).",
        "% cells covered in the run-up from standstill by a vehicle starting the scenario at speed X",
        *(_runup_fact(x, settings) for x in range(v_lo, v_hi + 1)),
        "runup(0,0,0).  % a stationary object has no run-up",
        "",
        "% the automaton",
        *(f"location({loc.id}).  % {loc.name}" for loc in automaton.locations),
        f"initial({automaton.initial}).",
        f"final({automaton.final}).",
    ]
    transition_node, numbering = guard_nodes(automaton)
    for t in automaton.transitions:
        base.append(f"transition({t.id},{t.source},{t.target}).  % {t.guard}")
        base.append(f"guard_of({t.id},{transition_node[t.id]}).")
    for location, node in invariant_nodes(automaton, numbering).items():
        base.append(f"invariant_of({location},{node}).  % {automaton.location(location).invariant}")
    for t in automaton.transitions:
        base.extend(f"starts({t.id},{p})." for p in sorted(t.starts) if p in automaton.timings)
        base.extend(f"ends({t.id},{p})." for p in sorted(t.ends) if p in automaton.timings)
    for phase, timing in automaton.timings.items():
        low = math.ceil(timing.low / settings.dt - 1e-9)
        high = math.floor(timing.high / settings.dt + 1e-9)
        base.append(f"timing({phase},{low},{high}).  % {timing}")
    state = ["% guards: g(N,t) holds when guard node N holds at step t (generated)"]
    for guard, node in numbering.items():
        state.append(f"% node {node}: {guard}")
        state.extend(_guard_rules(node, guard, numbering, settings))
    return "\n".join(base) + "\n", "\n".join(state) + "\n"


def _runup_fact(cells_per_step: int, settings: PlanningSettings) -> str:
    metres = settings.runup_distance(cells_per_step * settings.grid / settings.dt)
    return f"runup({cells_per_step},{math.floor(metres / settings.grid)},{math.ceil(metres / settings.grid)})."


def _atom(name: str) -> str:
    """An actor name as an ASP constant (quoted when it is not a lower-case identifier)."""
    return name if name[:1].islower() and name.replace("_", "").isalnum() else f'"{name}"'


def _guard_rules(node: int, guard: Guard, numbering: dict[Guard, int], settings: PlanningSettings) -> list[str]:
    head = f"g({node},t)"
    if isinstance(guard, And):
        if not guard.parts:
            return [f"{head}."]
        return [f"{head} :- " + ", ".join(f"g({numbering[p]},t)" for p in guard.parts) + "."]
    if isinstance(guard, Or):
        return [f"{head} :- g({numbering[p]},t)." for p in guard.parts]
    if isinstance(guard, Not):
        return [f"{head} :- not g({numbering[guard.part]},t)."]
    assert isinstance(guard, Bound)
    return _bound_rule(head, guard, settings)


def _bound_rule(head: str, bound: Bound, settings: PlanningSettings) -> list[str]:
    term = bound.term
    low, high = bound.low, bound.high
    if term.quantity == POSITION:
        low, high = _inset(low, high, settings.position_margin)
        scale = settings.grid
        fluent = "pos"
    elif term.quantity == SPEED:
        low, high = _inset(low, high, settings.speed_margin)
        scale = settings.grid / settings.dt
        fluent = "vel"
    else:
        scale = 1.0
        fluent = "lane"
    lo = -math.inf if low == -math.inf else math.ceil(low / scale - 1e-9)
    hi = math.inf if high == math.inf else math.floor(high / scale + 1e-9)
    if lo > hi:
        return [f"% {head} cannot hold on this grid"]
    a = _atom(term.actor)
    if term.reference is None:
        conditions = [f"{fluent}({a},X,t)"]
        conditions += [f"X >= {lo}"] if lo != -math.inf else []
        conditions += [f"X <= {hi}"] if hi != math.inf else []
        return [f"{head} :- " + ", ".join(conditions) + "."]
    b = _atom(term.reference)
    if term.quantity == POSITION and lo != -math.inf and hi != math.inf:
        # direct look-up of the other vehicle's cell: no join over all position pairs
        return [f"{head} :- pos({a},S,t), pos({b},S-D,t), D = {lo}..{hi}."]
    conditions = [f"{fluent}({a},X,t)", f"{fluent}({b},Y,t)"]
    conditions += [f"X-Y >= {lo}"] if lo != -math.inf else []
    conditions += [f"X-Y <= {hi}"] if hi != math.inf else []
    return [f"{head} :- " + ", ".join(conditions) + "."]


def _inset(low: float, high: float, margin: float) -> tuple[float, float]:
    """Shrink a finite range by up to ``margin`` per side, keeping at least a quarter of it."""
    if low == -math.inf or high == math.inf:
        return (low if low == -math.inf else low + margin, high if high == math.inf else high - margin)
    inset = min(margin, (high - low) / 4)
    return low + inset, high - inset
