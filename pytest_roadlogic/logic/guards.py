"""Guards: predicates over the states of actors, closed under and / or / not.

A guard is evaluated on a *snapshot* (actor name -> ``ActorState``) in three ways, one per consumer:
``holds`` (the monitor's yes/no), ``robustness`` (a signed margin in the quantity's own units,
positive when the guard holds, as in signal temporal logic; the monitor uses it to say how close a
trace came) and, in ``pytest_roadlogic.planning``, as ASP rules. Keeping the three side by side on
one small algebra is what lets the planner and the monitor agree on what a scenario means.

Lanes are integers with 0 the leftmost lane (the paper's convention); the robustness of a lane
bound counts half a lane of slack, so that "in the adjacent lane" has margin +0.5, not 0.

A time headway ``h(a, b)`` is the gap ``p(a) - p(b)`` over the speed of ``b``, the actor behind:
the seconds ``b`` needs to reach where ``a`` is now (``position(time: t, behind: a)``). It is not
linear, but a bound on it is, for the follower's speed is never negative: ``lo <= h <= hi`` is
``p(a) - p(b) - lo v(b) >= 0`` and ``p(a) - p(b) - hi v(b) <= 0`` (how the planner writes it).

The distance an actor has travelled, ``d(a)``, is its position now minus its position at the
run's first instant: the plan's step 0, which is the simulation's first sample (OpenSCENARIO XML's
TraveledDistanceCondition). A snapshot carries it as ``traveled``, for it needs the first state,
which one instant does not have.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from ..frontend.errors import SourceLocation

POSITION = "position"
LANE = "lane"
SPEED = "speed"
HEADWAY = "headway"
TRAVELED = "traveled"
QUANTITIES = (POSITION, LANE, SPEED, HEADWAY, TRAVELED)
SYMBOL = {POSITION: "p", LANE: "l", SPEED: "v", HEADWAY: "h", TRAVELED: "d"}
UNIT = {POSITION: "m", LANE: "lanes", SPEED: "m/s", HEADWAY: "s", TRAVELED: "m"}
# the follower's speed a headway is divided by at least (m/s): standing still, the headway to a
# car ahead is very long, not infinite (a number the monitor can compare and report)
HEADWAY_SPEED_FLOOR = 0.1


def headway(ahead_position, behind_position, behind_speed):
    """``h``: the gap over the follower's speed, floored; numbers or arrays alike."""
    return (ahead_position - behind_position) / np.maximum(behind_speed, HEADWAY_SPEED_FLOOR)


class ActorState(Protocol):
    position: float
    lane: int
    speed: float
    traveled: float  # position minus the position at the run's first instant (plan step 0, first sample)


Snapshot = Mapping[str, ActorState]


@dataclass(frozen=True)
class Term:
    """``x(actor)`` or the difference ``x(actor) - x(reference)`` for one quantity x; for a
    headway, ``h(actor, reference)``: (p(actor) - p(reference) - offset) / v(reference), the
    ``offset`` (metres, 0 but for the standard's time_gap: a car's length, bumper to bumper)
    taken off the gap; for a distance travelled, ``d(actor)`` (no reference)."""

    quantity: str
    actor: str
    reference: str | None = None
    offset: float = 0.0

    def value(self, snapshot: Snapshot) -> float:
        if self.quantity == HEADWAY:
            ahead, behind = snapshot[self.actor], snapshot[self.reference]
            return float(headway(ahead.position - self.offset, behind.position, behind.speed))
        value = getattr(snapshot[self.actor], self.quantity)
        if self.reference is not None:
            value -= getattr(snapshot[self.reference], self.quantity)
        return value

    @property
    def actors(self) -> tuple[str, ...]:
        return (self.actor,) if self.reference is None else (self.actor, self.reference)

    def __str__(self) -> str:
        s = SYMBOL[self.quantity]
        if self.quantity == HEADWAY and self.offset:
            return f"h({self.actor}, {self.reference}) - {_num(self.offset)}/v({self.reference})"
        if self.quantity == HEADWAY:
            return f"h({self.actor}, {self.reference})"
        text = f"{s}({self.actor})"
        return text if self.reference is None else f"{text} - {s}({self.reference})"


# quantity -> trace column (a distance travelled is the x column minus its first value)
COLUMN = {POSITION: "x", LANE: "lane", SPEED: "speed", TRAVELED: "x"}


class Guard:
    """Base of the algebra; subclasses are immutable dataclasses."""

    def holds(self, snapshot: Snapshot) -> bool:
        raise NotImplementedError

    def robustness(self, snapshot: Snapshot) -> float:
        raise NotImplementedError

    def robustness_series(
        self, columns: Mapping[str, Mapping[str, np.ndarray]], memo: dict | None = None
    ) -> np.ndarray:
        """``robustness`` at every sample of a trace at once (``columns``: actor -> column -> array).
        ``memo``: each bound's series, kept across the guards of one trace (an automaton's guards
        share a few dozen bounds among thousands of uses)."""
        raise NotImplementedError

    def atoms(self) -> tuple[Bound, ...]:
        """The bounds this guard is built from, in order."""
        raise NotImplementedError

    @property
    def is_true(self) -> bool:
        return False

    def __and__(self, other: Guard) -> Guard:
        return conjunction([self, other])


@dataclass(frozen=True)
class Bound(Guard):
    """``low <= term <= high`` (either side may be infinite); the atomic predicate."""

    term: Term
    low: float = -math.inf
    high: float = math.inf
    source: SourceLocation | None = None
    # the file's constraint as written, when this bound is one of the variants that stand for it
    # (keep_lane(): one lane each): a message names the constraint, not the variant
    written: str | None = field(default=None, compare=False, repr=False)

    def holds(self, snapshot: Snapshot) -> bool:
        value = self.term.value(snapshot)
        return self.low <= value <= self.high

    @property
    def as_written(self) -> str:
        """How a message names this bound: the file's constraint for a variant, else the bound."""
        return self.written or str(self)

    def robustness_series(self, columns, memo: dict | None = None) -> np.ndarray:
        if memo is not None:
            if self not in memo:
                memo[self] = self.robustness_series(columns)
            return memo[self]
        if self.term.quantity == HEADWAY:
            ahead, behind = columns[self.term.actor], columns[self.term.reference]
            ahead_x, behind_x, behind_speed = (
                np.asarray(column, dtype=float) for column in (ahead["x"], behind["x"], behind["speed"])
            )
            value = headway(ahead_x - self.term.offset, behind_x, behind_speed)
        else:
            column = COLUMN[self.term.quantity]
            value = np.asarray(columns[self.term.actor][column], dtype=float)
            if self.term.quantity == TRAVELED:
                value = value - value[0]
            if self.term.reference is not None:
                value = value - np.asarray(columns[self.term.reference][column], dtype=float)
        slack = 0.5 if self.term.quantity == LANE else 0.0
        return np.minimum(value - (self.low - slack), (self.high + slack) - value)

    def robustness(self, snapshot: Snapshot) -> float:
        value = self.term.value(snapshot)
        slack = 0.5 if self.term.quantity == LANE else 0.0
        return min(value - (self.low - slack), (self.high + slack) - value)

    def atoms(self) -> tuple[Bound, ...]:
        return (self,)

    def __str__(self) -> str:
        term = str(self.term)
        if self.term.quantity == LANE and self.term.reference is not None and self.low == self.high == 0:
            return f"{SYMBOL[LANE]}({self.term.actor}) = {SYMBOL[LANE]}({self.term.reference})"
        if self.low == self.high:
            return f"{term} = {_num(self.low)}"
        if self.term.quantity == LANE and self.term.reference is not None:
            # Paper style for lane relations: l(v1) < l(v2) rather than l(v1) - l(v2) <= -1.
            a, b = f"{SYMBOL[LANE]}({self.term.actor})", f"{SYMBOL[LANE]}({self.term.reference})"
            if self.low == -math.inf and self.high == -1:
                return f"{a} < {b}"
            if self.low == 1 and self.high == math.inf:
                return f"{a} > {b}"
        if self.low == -math.inf:
            return f"{term} <= {_num(self.high)}"
        if self.high == math.inf:
            return f"{term} >= {_num(self.low)}"
        return f"{_num(self.low)} <= {term} <= {_num(self.high)}"


@dataclass(frozen=True)
class And(Guard):
    parts: tuple[Guard, ...]

    def holds(self, snapshot: Snapshot) -> bool:
        return all(p.holds(snapshot) for p in self.parts)

    def robustness(self, snapshot: Snapshot) -> float:
        return min((p.robustness(snapshot) for p in self.parts), default=math.inf)

    def robustness_series(self, columns, memo: dict | None = None) -> np.ndarray:
        if not self.parts:
            length = len(next(iter(next(iter(columns.values())).values())))
            return np.full(length, math.inf)
        return np.minimum.reduce([p.robustness_series(columns, memo) for p in self.parts])

    def atoms(self) -> tuple[Bound, ...]:
        return tuple(a for p in self.parts for a in p.atoms())

    @property
    def is_true(self) -> bool:
        return not self.parts

    def __str__(self) -> str:
        return " and ".join(_wrap(p) for p in self.parts) if self.parts else "true"


@dataclass(frozen=True)
class Or(Guard):
    parts: tuple[Guard, ...]

    def holds(self, snapshot: Snapshot) -> bool:
        return any(p.holds(snapshot) for p in self.parts)

    def robustness(self, snapshot: Snapshot) -> float:
        return max((p.robustness(snapshot) for p in self.parts), default=-math.inf)

    def robustness_series(self, columns, memo: dict | None = None) -> np.ndarray:
        if not self.parts:
            length = len(next(iter(next(iter(columns.values())).values())))
            return np.full(length, -math.inf)
        return np.maximum.reduce([p.robustness_series(columns, memo) for p in self.parts])

    def atoms(self) -> tuple[Bound, ...]:
        return tuple(a for p in self.parts for a in p.atoms())

    def __str__(self) -> str:
        return " or ".join(_wrap(p) for p in self.parts) if self.parts else "false"


@dataclass(frozen=True)
class Not(Guard):
    part: Guard

    def holds(self, snapshot: Snapshot) -> bool:
        return not self.part.holds(snapshot)

    def robustness(self, snapshot: Snapshot) -> float:
        return -self.part.robustness(snapshot)

    def robustness_series(self, columns, memo: dict | None = None) -> np.ndarray:
        return -self.part.robustness_series(columns, memo)

    def atoms(self) -> tuple[Bound, ...]:
        return self.part.atoms()

    def __str__(self) -> str:
        return f"not {_wrap(self.part)}"


TRUE = And(())


def conjunction(guards: list[Guard] | tuple[Guard, ...]) -> Guard:
    """Flattened conjunction; ``true`` parts disappear, a single part stands alone."""
    parts: list[Guard] = []
    for guard in guards:
        if isinstance(guard, And):
            parts.extend(p for p in guard.parts if p not in parts)
        elif guard not in parts:
            parts.append(guard)
    return parts[0] if len(parts) == 1 else And(tuple(parts))


def required_bounds(guard: Guard) -> list[Bound]:
    """The bounds a guard requires whichever way it holds: those of its conjunctions, in order, not
    those under a disjunction or a negation (what a planner may take as plain rows)."""
    if isinstance(guard, Bound):
        return [guard]
    if isinstance(guard, And):
        return [b for part in guard.parts for b in required_bounds(part)]
    return []


def _wrap(guard: Guard) -> str:
    return f"({guard})" if isinstance(guard, (And, Or)) and len(getattr(guard, "parts", ())) > 1 else str(guard)


def _num(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else f"{value:g}"


def _normalised(bound: Bound) -> tuple[tuple[str, str, str | None], float, float]:
    """The bound over a canonical term: differences always as x(first) - x(second) by name."""
    term = bound.term
    if (
        term.reference is not None and term.reference < term.actor and term.quantity != HEADWAY
    ):  # h(a, b) is no -h(b, a)
        return (term.quantity, term.reference, term.actor), -bound.high, -bound.low
    if term.offset:
        return (term.quantity, term.actor, term.reference, term.offset), bound.low, bound.high
    return (term.quantity, term.actor, term.reference), bound.low, bound.high


def lanes_conflict(guard: Guard, lanes: int) -> tuple[Bound, ...] | None:
    """The fewest lane bounds of a conjunction that no placement on a road of ``lanes`` lanes meets
    together (a car in the rightmost lane and another right of it), or None. Only plain
    conjunctions of up to ``LANE_ACTORS`` vehicles are examined: every placement is tried."""
    parts = guard.parts if isinstance(guard, And) else (guard,)
    if not all(isinstance(p, Bound) for p in parts):
        return None
    bounds = [p for p in parts if p.term.quantity == LANE]
    actors = sorted({actor for bound in bounds for actor in bound.term.actors})
    if not bounds or len(actors) > LANE_ACTORS:
        return None

    def placed(group: tuple[Bound, ...]) -> bool:
        # lazily, stopping at the first placement that fits
        placements = (dict(zip(actors, at)) for at in itertools.product(range(lanes), repeat=len(actors)))
        return any(all(_lane_holds(bound, at) for bound in group) for at in placements)

    if placed(tuple(bounds)):
        return None
    for size in range(1, len(bounds) + 1):
        for group in itertools.combinations(bounds, size):
            if not placed(group):
                return group
    return None  # unreachable: the whole conjunction has no placement


# vehicles whose lanes lanes_conflict places by trying every placement (lanes ** vehicles of them)
LANE_ACTORS = 5


def _lane_holds(bound: Bound, lanes: Mapping[str, int]) -> bool:
    value = lanes[bound.term.actor] - (lanes[bound.term.reference] if bound.term.reference is not None else 0)
    return bound.low <= value <= bound.high


def contradiction(guard: Guard) -> tuple[Bound, Bound] | None:
    """Two bounds of a conjunction that no state can meet together (e.g. ahead by 30 m and behind
    by 10 m), or None. Only plain conjunctions are examined: enough to name the usual mistakes."""
    parts = guard.parts if isinstance(guard, And) else (guard,)
    if not all(isinstance(p, Bound) for p in parts):
        return None
    by_term: dict[tuple, list[tuple[Bound, float, float]]] = {}
    for bound in parts:
        key, low, high = _normalised(bound)
        by_term.setdefault(key, []).append((bound, low, high))
    for bounds in by_term.values():
        for i, (a, a_low, a_high) in enumerate(bounds):
            for b, b_low, b_high in bounds[i + 1 :]:
                if max(a_low, b_low) > min(a_high, b_high) + 1e-9:
                    return a, b
    return None
