"""A sample with no plan, proved in milliseconds: the planning problem's linear relaxation.

What goes in: the automaton a planner would solve for a sample (its bounds and durations) and the
fastest speed any planner may plan. What comes out: None, or the smallest group of the scenario's
constraints (``Bound``s and ``Timing``s, as ``diagnosis.smallest_conflict`` gives them) under
which no plan of any planner exists, because even the relaxation has no solution.

Why: without it a sample with no plan costs the planner over every horizon, the fallback planners
and the diagnosis, and Hypothesis's shrinking of a failing band lives on such samples. Most of
them are plain arithmetic: a gap no speed allowed can close in the time allowed.

The relaxation, per path of the automaton from its initial to its final location (at most
``MAX_PATHS``; more, and it proves nothing): one instant per transition of the path, with its time
and each actor's position and speed. It keeps only what every plan of every planner satisfies:
instants in order; each transition's guard at its instant, its conjunction of bounds on positions
and speeds (headways, distances travelled and disjunctions are dropped); each phase's duration;
between two instants each actor's travel within its speed envelope times the time between them (a
plan's position advances by the mean of its speeds at consecutive steps; the run is in a location
from the instant it enters it, so every speed there lies in the location's invariant band but the
last, at the next instant, which lies in that instant's guard's band and in the invariant of the
location entered then; all within 0..``max_speed``); a stationary object stays; and two vehicles
an invariant keeps in one lane (``l(a) - l(b) = 0`` throughout consecutive locations) keep their
order over those instants, for no plan passes one car through another in its lane: one linear
program per choice of who is ahead in each such stretch (at most ``MAX_ORDERS`` of them; past
that, the order is dropped).
On a map (``RouteExtent``), each vehicle on the scenario's route stays between the route's first
and last metres a car may be at, and at an instant whose guard (or the invariant of a location it
is in) keeps it in lanes that begin or end, within their stretch: a car that must be in an
acceleration lane 400 m ahead of another where that lane is 215 m long has no plan, said in
milliseconds rather than after the planner's time limit.
Dropping constraints only adds solutions, so a relaxation with none on every path proves there is
no plan. The group named is minimal on the paths (one constraint taken out at a time, kept out
when the rest still fail on every path).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

from ..logic.automaton import SymbolicAutomaton, Transition
from ..logic.guards import LANE, POSITION, SPEED, Bound, required_bounds

MAX_PATHS = 64  # an automaton with more paths to its end is left to the planner
MAX_ORDERS = 64  # the most choices of who is ahead tried on one path (2 per stretch shared in a lane)


@dataclass(frozen=True)
class RouteExtent:
    """Where along a map's route the scenario's vehicles may be, as the planner keeps them: each
    (but those driving other routes) between ``span``'s metres along it; one in a lane of
    ``lanes`` (lane -> first and last metre: a lane that begins or ends) within those; the plan's
    position 0 within ``origin`` (None: anywhere). Positions along the route are a plan's plus the
    origin. ``sides``: the other routes, each its vehicles and their span, its origin free (how the
    planner lays routes onto each other is left out: only the road each has is read)."""

    span: tuple[float, float]
    lanes: dict[int, tuple[float, float]] = field(default_factory=dict)
    origin: tuple[float, float] | None = None
    sides: tuple[tuple[frozenset[str], tuple[float, float]], ...] = ()


def provably_unplannable(
    automaton: SymbolicAutomaton, max_speed: float, route: RouteExtent | None = None
) -> tuple | None:
    """The constraints that no plan can meet together when the relaxation proves it, else None.
    ``route``: the map's route the plan lies on (None: the straight road, as long as a plan needs)."""
    paths = _paths(automaton)
    if not paths:
        return None
    relaxations = [_PathRelaxation(automaton, path, max_speed, route) for path in paths]
    named: dict = {}  # source -> the constraint that names it (the first, as the diagnosis names it)
    for relaxation in relaxations:
        for source, constraint in relaxation.constraints.items():
            named.setdefault(source, constraint)
    kept = sorted(named, key=lambda s: (str(s.path), s.line, s.column))
    if any(r.feasible(set(kept)) for r in relaxations):
        return None
    for source in list(kept):
        trial = [s for s in kept if s != source]
        if not any(r.feasible(set(trial)) for r in relaxations):
            kept = trial
    return tuple(named[s] for s in kept) if kept else None


def _paths(automaton: SymbolicAutomaton) -> list[list[Transition]] | None:
    """Every path of transitions from the initial to the final location; None past ``MAX_PATHS``."""
    found: list[list[Transition]] = []

    def walk(location: int, prefix: list[Transition], seen: frozenset[int]) -> bool:
        if location == automaton.final:
            found.append(prefix)
            return len(found) <= MAX_PATHS
        for transition in automaton.outgoing(location):
            if transition.target in seen:
                continue
            if not walk(transition.target, [*prefix, transition], seen | {transition.target}):
                return False
        return True

    if not walk(automaton.initial, [], frozenset({automaton.initial})):
        return None
    return found


def _linear(bound: Bound) -> bool:
    return bound.term.quantity in (POSITION, SPEED)


def _in_lanes(bound: Bound) -> bool:
    """Whether ``bound`` keeps a vehicle in lanes by their numbers (``l(a)`` within a range)."""
    return bound.term.quantity == LANE and bound.term.reference is None


def _one_lane(bound: Bound) -> bool:
    """Whether ``bound`` keeps two vehicles in one lane (``l(a) - l(b) = 0``)."""
    return bound.term.quantity == LANE and bound.term.reference is not None and bound.low == bound.high == 0


class _PathRelaxation:
    """The linear program of one path, built for any subset of the scenario's constraints (``groups``:
    a bound or a duration with a source; bounds of one source go in or out together)."""

    def __init__(
        self, automaton: SymbolicAutomaton, path: list[Transition], max_speed: float, route: RouteExtent | None = None
    ) -> None:
        self.automaton, self.path, self.max_speed, self.route = automaton, path, max_speed, route
        self.actors = list(automaton.actors)
        # per instant, the bounds of its transition's guard; per interval, its location's invariant
        guards = [required_bounds(t.guard) for t in path]
        self.at = [[b for b in bounds if _linear(b)] for bounds in guards]
        invariants = [required_bounds(automaton.location(t.target).invariant) for t in path[:-1]]
        self.during = [[b for b in bounds if _linear(b)] for bounds in invariants]
        # per interval, the invariant's bounds that keep two vehicles in one lane
        self.one_lane = [[b for b in bounds if _one_lane(b)] for bounds in invariants]
        # per instant, the bounds that keep a vehicle in lanes by number: its guard's, and the
        # invariants of the intervals it begins and ends (only read on a map's route)
        self.lanes_at = [
            [
                b
                for b in (
                    *guards[i],
                    *(invariants[i] if i < len(invariants) else ()),
                    *(invariants[i - 1] if i else ()),
                )
                if _in_lanes(b)
            ]
            if route is not None and route.lanes
            else []
            for i in range(len(path))
        ]
        # the timed phases and the instants that start and end them on this path
        started: dict[int, int] = {}
        self.durations: list[tuple[int, int, object]] = []
        for i, transition in enumerate(path):
            for phase in transition.ends:
                if phase in automaton.timings and phase in started:
                    self.durations.append((started.pop(phase), i, automaton.timings[phase]))
            for phase in transition.starts:
                if phase in automaton.timings:
                    started[phase] = i
        # the scenario's constraints on this path by their place: one modifier's bounds go in or out together
        self.constraints: dict = {}
        for bound in (b for bounds in (*self.at, *self.during, *self.one_lane, *self.lanes_at) for b in bounds):
            if bound.source is not None:
                self.constraints.setdefault(bound.source, bound)
        for _, _, timing in self.durations:
            if timing.source is not None:
                self.constraints.setdefault(timing.source, timing)

    def feasible(self, sources: set) -> bool:
        """Whether the relaxation with only the constraints at ``sources`` (and those with no
        place, which are not the scenario's to take out) has a solution."""

        def on(constraint) -> bool:
            return constraint.source is None or constraint.source in sources

        n = len(self.path)
        columns: dict[tuple, int] = {}

        def var(*name) -> int:
            return columns.setdefault(name, len(columns))

        rows: list[tuple[dict[int, float], float, float]] = []
        lows: dict[int, float] = {}
        highs: dict[int, float] = {}
        for i in range(n):
            lows[var("t", i)] = 0.0
            if i:
                rows.append(({var("t", i): 1.0, var("t", i - 1): -1.0}, 0.0, math.inf))
            for actor in self.actors:
                lows[var("v", actor, i)] = 0.0
                highs[var("v", actor, i)] = 0.0 if actor in self.automaton.stationary else self.max_speed
                lows[var("p", actor, i)] = -math.inf
        # each actor's speed band at each instant: its transition's guard's and the invariant of
        # the location it enters (the run is there from that instant on)
        envelope_at = [self._speed_bands(self.at[i] + (self.during[i] if i < n - 1 else []), on) for i in range(n)]
        for i in range(n):
            for bound in self.at[i]:
                if on(bound):
                    rows.append(self._row(bound, i, var))
        for i in range(n - 1):
            invariant = [b for b in self.during[i] if on(b)]
            for bound in invariant:
                rows.append(self._row(bound, i, var))
                rows.append(self._row(bound, i + 1, var))
            bands = self._speed_bands(invariant, on)
            for actor in self.actors:
                travel = {var("p", actor, i + 1): 1.0, var("p", actor, i): -1.0}
                if actor in self.automaton.stationary:
                    rows.append((travel, 0.0, 0.0))
                    continue
                # the speeds of the interval's steps lie in its location's band but the last, at
                # the next instant, which lies in that instant's envelope
                band = bands.get(actor, (0.0, self.max_speed))
                then = envelope_at[i + 1].get(actor, (0.0, self.max_speed))
                low, high = min(band[0], then[0]), max(band[1], then[1])
                low, high = max(low, 0.0), min(high, self.max_speed)
                dt = {var("t", i + 1): 1.0, var("t", i): -1.0}
                # travel >= low * (t[i+1] - t[i]) and travel <= high * (t[i+1] - t[i])
                rows.append(({**travel, **{k: -low * c for k, c in dt.items()}}, 0.0, math.inf))
                rows.append(({**travel, **{k: -high * c for k, c in dt.items()}}, -math.inf, 0.0))
        for start, end, timing in self.durations:
            if on(timing):
                rows.append(({var("t", end): 1.0, var("t", start): -1.0}, timing.low, timing.high))
        if self.route is not None:
            rows += self._on_route(on, var, lows, highs)
        stretches = self._stretches(on)
        if not stretches or 2 ** len(stretches) > MAX_ORDERS:
            return _solvable(len(columns), lows, highs, rows)
        for ahead in itertools.product((1.0, -1.0), repeat=len(stretches)):
            ordered = [
                ({var("p", a, i): sign, var("p", b, i): -sign}, 0.0, math.inf)
                for sign, (a, b, first, last) in zip(ahead, stretches, strict=True)
                for i in range(first, last + 1)
            ]
            if _solvable(len(columns), lows, highs, rows + ordered):
                return True
        return False

    def _on_route(self, on, var, lows: dict[int, float], highs: dict[int, float]) -> list:
        """The rows that keep the routes' vehicles on them: each between its route's metres at every
        instant, and, on the scenario's route, within the stretch of the lanes an instant's bounds
        (those that are on) keep it in, where each of those lanes begins or ends (metres along the
        route: its position plus the route's origin)."""
        route, rows = self.route, []
        origin = var("origin")
        lows[origin], highs[origin] = route.origin if route.origin is not None else (-math.inf, math.inf)
        side_of = {actor: k for k, (vehicles, _) in enumerate(route.sides) for actor in vehicles}
        for i in range(len(self.path)):
            for actor in self.actors:
                if actor in side_of:
                    k = side_of[actor]
                    rows.append(({var("p", actor, i): 1.0, var("origin", k): 1.0}, *route.sides[k][1]))
                    continue
                along = {var("p", actor, i): 1.0, origin: 1.0}
                rows.append((along, *route.span))
                for bound in self.lanes_at[i]:
                    if bound.term.actor != actor or not on(bound) or not math.isfinite(bound.high - bound.low):
                        continue
                    low, high = math.ceil(bound.low - 1e-9), math.floor(bound.high + 1e-9)
                    if high - low > len(route.lanes) or not all(k in route.lanes for k in range(low, high + 1)):
                        continue  # a lane of the range runs all along the route
                    stretches = [route.lanes[k] for k in range(low, high + 1)]
                    rows.append((along, min(s[0] for s in stretches), max(s[1] for s in stretches)))
        return rows

    def _stretches(self, on) -> list[tuple[str, str, int, int]]:
        """Each pair of vehicles kept in one lane by the invariants (those that are on) of
        consecutive intervals, with the first and last instant of that stretch."""
        stretches: list[tuple[str, str, int, int]] = []
        open_: dict[tuple[str, str], int] = {}  # pair -> the instant its stretch began
        for i, bounds in enumerate([*self.one_lane, []]):
            pairs = {tuple(sorted(b.term.actors)) for b in bounds if on(b)}
            for pair in [p for p in open_ if p not in pairs]:
                stretches.append((*pair, open_.pop(pair), i))
            for pair in pairs:
                open_.setdefault(pair, i)
        return stretches

    def _speed_bands(self, bounds: list[Bound], on) -> dict[str, tuple[float, float]]:
        """Each actor's speed band from the absolute speed bounds among ``bounds`` that are on."""
        bands: dict[str, tuple[float, float]] = {}
        for bound in bounds:
            if on(bound) and bound.term.quantity == SPEED and bound.term.reference is None:
                low, high = bands.get(bound.term.actor, (0.0, self.max_speed))
                bands[bound.term.actor] = (max(low, bound.low), min(high, bound.high))
        return bands

    @staticmethod
    def _row(bound: Bound, i: int, var) -> tuple[dict[int, float], float, float]:
        symbol = "p" if bound.term.quantity == POSITION else "v"
        coefficients = {var(symbol, bound.term.actor, i): 1.0}
        if bound.term.reference is not None:
            coefficients[var(symbol, bound.term.reference, i)] = -1.0
        return coefficients, bound.low, bound.high


def _solvable(count: int, lows: dict[int, float], highs: dict[int, float], rows) -> bool:
    """Whether the linear rows ``(coefficients, low, high)`` over ``count`` columns have a solution."""
    import highspy
    import numpy as np

    from .highs import quiet_highs

    solver = quiet_highs()
    lower = np.array([lows.get(k, -math.inf) for k in range(count)], dtype=float)
    upper = np.array([highs.get(k, math.inf) for k in range(count)], dtype=float)
    inf = solver.getInfinity()
    solver.addVars(count, np.maximum(lower, -inf), np.minimum(upper, inf))
    for coefficients, low, high in rows:
        indices = np.array(list(coefficients), dtype=np.int32)
        values = np.array(list(coefficients.values()), dtype=float)
        solver.addRow(max(low, -inf), min(high, inf), len(indices), indices, values)
    solver.run()
    return solver.getModelStatus() != highspy.HighsModelStatus.kInfeasible
