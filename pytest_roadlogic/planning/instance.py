"""The ASP instance of one scenario: the automaton and the settings as facts, guards as rules.

The background theory in ``asp/*.lp`` is fixed; what is scenario-specific is generated here, as
facts and constants: the vehicles, the grid (speeds and accelerations in cells per step, start
zones and speeds: the rules that read them are in ``asp/initial.lp``), the run-up, the automaton's
locations and transitions, and a random start's preferences (``asp/preferences.lp``). The one
exception is the guards, one ``g(N,t)`` rule set per guard node, whose shapes ``asp/automaton.lp``
lists (and says why they are rules). Position and speed bounds are planned
with a margin inside their range so that a simulation that tracks the plan with some error still
meets them (the monitor checks the ranges as written).
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

from ..frontend.errors import OscError, error_at
from ..logic.automaton import SymbolicAutomaton, Timing
from ..logic.guards import HEADWAY, LANE, POSITION, SPEED, TRAVELED, And, Bound, Guard, Not, Or
from ..settings import DEFAULT_HORIZON, DEFAULT_PLAN_TIMEOUT


@dataclass(frozen=True)
class PlanningSettings:
    dt: float = 1.0  # seconds per planning step
    grid: float = 1.0  # metres per cell (the road's lanes come with the automaton)
    min_speed: float = 2.0  # m/s; positive, so that no vehicle stops (domain rule 1)
    max_speed: float = 40.0  # m/s
    # m/s the plan starts with: a moderate start keeps the run-up short and the plan easy for a
    # motion planner to track; a scenario that cannot start so is planned with any allowed start
    # speed instead (widen_initial_speed)
    initial_speed: tuple[float, float] = (8.0, 14.0)
    widen_initial_speed: bool = True
    accelerations: tuple[float, ...] = (-2.0, 0.0, 2.0)  # m/s^2, applied for a whole step
    min_gap: float = 8.0  # m between the centres of two vehicles sharing a lane
    lane_change_gap: int = 3  # steps from one lane change of a vehicle to its next
    initial_spread: float = 60.0  # m; other vehicles start within this distance of the first
    # m; start positions are chosen as a zone of this width (an atom the search can vary and a
    # plan be excluded by), the cell within it by the difference-logic solver
    start_zone: float = 5.0
    position_margin: float = 1.5  # m planned inside each side of a position range, when it fits
    speed_margin: float = 0.5  # m/s likewise for speed ranges
    runup_acceleration: float = 2.0  # m/s^2 with which every vehicle leaves standstill
    max_horizon: int = DEFAULT_HORIZON  # steps
    time_limit: float = DEFAULT_PLAN_TIMEOUT  # seconds for one solve, all horizons together
    # when no plan exists, find the constraints that cannot hold together (UnsatisfiableScenario);
    # a search over many samples turns it off and asks only for the one it reports
    explain_unsatisfiable: bool = True
    # seconds the diagnosis may spend deciding whether one constraint can leave the group that
    # clashes (None: as long as the time limit allows); see ContinuousSettings
    removal_time_limit: float | None = None
    # the refined strategy's instances are independent samples: its first plan follows random
    # preferences drawn from the seed (start_preferences) and lasts a random number of steps from
    # the shortest horizon to max_horizon, instead of being the solver's first answer at the shortest
    random_start: bool = False

    def thinned(self) -> None:
        """None: the grid encoding has no fallback search (``planning.fallbacks``), so a sample it
        has no plan for is reported at once; the continuous settings answer with thinner margins."""
        return None

    def summary(self, lanes: int) -> str:
        """The domain rules' numbers on a road of ``lanes`` lanes, for messages that blame them."""
        return (
            f"speeds {self.min_speed:g}..{self.max_speed:g} m/s, accelerations {min(self.accelerations):g}..{max(self.accelerations):g} m/s^2, "
            f"{lanes} lanes, {self.min_gap:g} m gaps, at most {self.max_horizon} steps of {self.dt:g} s"
        )

    def resolution(self) -> dict[str | None, float]:
        """The smallest difference the plan can express, per physical dimension (for sampled values)."""
        return {
            "length": self.grid,
            "speed": self.grid / self.dt,
            "time": self.dt,
            "acceleration": self.grid / self.dt**2,
        }

    def margins(self) -> dict[str | None, float]:
        """How far inside a range's edges the plan keeps, per physical dimension."""
        return {"length": self.position_margin, "speed": self.speed_margin}

    def cells_per_step(self, speed: float) -> float:
        return speed * self.dt / self.grid

    def speeds(self) -> range:
        return range(
            math.ceil(self.cells_per_step(self.min_speed)), math.floor(self.cells_per_step(self.max_speed)) + 1
        )

    def initial_speeds(self) -> range:
        """The start speeds in cells per step."""
        low, high = self.initial_speed
        return range(
            max(math.ceil(self.cells_per_step(low) - 1e-9), self.speeds()[0]),
            min(math.floor(self.cells_per_step(high) + 1e-9), self.speeds()[-1]) + 1,
        )

    def runup_steps(self, cells_per_step: int) -> int:
        """Steps a vehicle needs from standstill to ``cells_per_step`` at the run-up rate."""
        return math.ceil(cells_per_step * self.grid / self.dt / self.runup_acceleration / self.dt - 1e-9)

    def runup_distance(self, speed: float, duration: float) -> float:
        """Metres a vehicle covers in a run-up of ``duration`` s: it accelerates to ``speed``, then cruises."""
        return speed * duration - speed**2 / (2 * self.runup_acceleration)

    def acceleration_cells(self) -> list[int]:
        cells = []
        for a in self.accelerations:
            value = a * self.dt * self.dt / self.grid
            if not float(value).is_integer() or int(value) % 2:
                raise ValueError(
                    f"acceleration {a} m/s^2 is not an even number of cells per step^2 (exact kinematics need it)"
                )
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


def build_instance(
    automaton: SymbolicAutomaton, settings: PlanningSettings, relaxable: bool = False
) -> tuple[str, str]:
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


def _runup_fact(cells_per_step: int, steps: int, settings: PlanningSettings) -> str:
    metres = settings.runup_distance(cells_per_step * settings.grid / settings.dt, steps * settings.dt)
    return f"runup({cells_per_step},{steps},{math.floor(metres / settings.grid + 1e-9)},{math.ceil(metres / settings.grid - 1e-9)})."


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


def _guard_rules(
    node: int, guard: Guard, numbering: dict[Guard, int], settings: PlanningSettings, switch: str = ""
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


def _margin_and_scale(bound: Bound, settings: PlanningSettings | None) -> tuple[float, float, str]:
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


def _position_rules(node: int, bound: Bound, settings: PlanningSettings, switch: str = "") -> list[str]:
    """A position bound as difference constraints on the position variables.

    Positions are not atoms, so the guard cannot be derived from them: the solver chooses
    ``g(N,t)`` and its truth imposes the bound. Guards are only used positively (negations sit on
    bounds, ``outside_rules``), so a false ``g`` needs no meaning.
    """
    lo, hi = _planned_range(bound.low, bound.high, settings.position_margin, settings.grid)
    head = f"g({node},t)"
    if lo > hi:
        return [f"% {head} cannot hold on this grid"]
    a, b = _position_terms(bound)
    rules = [f"{{ {head} }}."]
    if hi != math.inf:
        rules.append(f"&diff{{ {a} - {b} }} <= {hi} :- {head}{switch}.")
    if lo != -math.inf:
        rules.append(f"&diff{{ {b} - {a} }} <= {-lo} :- {head}{switch}.")
    return rules


def _position_terms(bound: Bound) -> tuple[str, str]:
    term = bound.term
    return f"p({atom(term.actor)},t)", "0" if term.reference is None else f"p({atom(term.reference)},t)"


def _fluent_terms(bound: Bound, fluent: str) -> tuple[list[str], str]:
    """The body atoms reading a speed or lane bound's term, and the term's value in them."""
    term = bound.term
    if term.reference is None:
        return [f"{fluent}({atom(term.actor)},X,t)"], "X"
    return [f"{fluent}({atom(term.actor)},X,t)", f"{fluent}({atom(term.reference)},Y,t)"], "X-Y"


def outside_rules(node: int, bound: Bound, settings: PlanningSettings | None, switch: str = "") -> list[str]:
    """``not bound``: the value below or above the range, planned with the margin outside it."""
    margin, scale, fluent = _margin_and_scale(bound, settings)
    head = f"g({node},t)"
    # the largest grid value below low - margin and the smallest above high + margin
    below = None if bound.low == -math.inf else math.ceil((bound.low - margin) / scale - 1e-9) - 1
    above = None if bound.high == math.inf else math.floor((bound.high + margin) / scale + 1e-9) + 1
    if below is None and above is None:
        return [f"% {head} never holds"]
    if fluent == "pos":
        a, b = _position_terms(bound)
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


def bound_rule(head: str, bound: Bound, settings: PlanningSettings | None) -> list[str]:
    """A speed or lane bound, derived from the vel/lane atoms (speeds with a margin inside)."""
    margin, scale, fluent = _margin_and_scale(bound, settings)
    lo, hi = _planned_range(bound.low, bound.high, margin, scale)
    if lo > hi:
        return [f"% {head} cannot hold on this grid"]
    conditions, value = _fluent_terms(bound, fluent)
    conditions += [f"{value} >= {lo}"] if lo != -math.inf else []
    conditions += [f"{value} <= {hi}"] if hi != math.inf else []
    return [f"{head} :- " + ", ".join(conditions) + "."]


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


def _planned_range(low: float, high: float, margin: float, scale: float) -> tuple[float, float]:
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


def start_zones(automaton: SymbolicAutomaton, settings: PlanningSettings) -> tuple[int, int]:
    """(cells per start zone, zones on either side of the first vehicle): enough zones to cover the
    spread, or the farthest start the scenario's position bounds ask for when that is farther."""
    width = max(1, round(settings.start_zone / settings.grid))
    return width, math.ceil(max(settings.initial_spread, _farthest_position(automaton)) / settings.grid / width)


def start_preferences(automaton: SymbolicAutomaton, settings: PlanningSettings, draw: random.Random) -> str:
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
