"""Which horizons a scenario's phase durations allow, before any vehicle moves.

The automaton alone, with every guard holding, says how long a run can last: no plan ends before
the first horizon at which it can reach its final location (``earliest``), and none needs a
horizon more than one step past the last step at which a run can still be under way
(``last_open``; ``last_horizon``): the final location is absorbing, so a longer plan only idles
longer. The one step is the plan's own: the checks of its last state (asp/continuous/dynamics.lp, nobody
closes in at the end) may need a step after the scenario's last transition. Planning and the
diagnosis solve only between ``earliest`` and ``last_horizon``: refuting the horizons the
durations rule out with the dynamics costs far more (docs/decisions.md).

Both questions are monotone in the horizon (reaching the final location by h, being under way at
h), so each is answered by doubling and then bisecting, on steps grounded in as few calls as
possible.

The search for ``earliest`` starts at a floor read off the automaton's graph (``shortest_run``), a
step no run can end before: a scenario of serial phases ends exactly there, and one solve says so.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from pathlib import Path

import clingo

from ..logic.automaton import SymbolicAutomaton
from .errors import PlanningTimeout
from .facts import timing_steps

GROUND_CHUNK = 25  # steps grounded in one call, between two looks at the deadline
PREPARATION_PER_GROUNDING = 1.0  # without equivalence preprocessing (see core's): 2.4 s after 3.7 s

# every guard holds: the durations alone decide (guards as free choices are far slower)
GUARDS_HOLD = "g(N,t) :- guard_of(_,N).\ng(N,t) :- invariant_of(_,N)."
OPEN = "#program open(t).\n#external open(t).\n:- open(t), accepted(t)."


class DurationWindow:
    """The horizons a run of the automaton can end at, given its phases' durations.

    ``base_program`` holds the automaton's facts (and, for the diagnosis, ``relaxed(K)``
    externals: ``assumptions`` are those kept, and a relaxed duration leaves its phase open).
    ``wait(handle, message)`` waits for a solve and raises when time is up. ``untimed``: the
    automaton has no timed phase and no transition from its initial location straight into its
    final one, so a run can end at any step from ``floor`` on and still be under way at any step:
    the window answers so without a solver, and a plain scenario's every sample saves one.
    """

    def __init__(
        self,
        automaton_lp: Path,
        base_program: str,
        wait: Callable[[clingo.SolveHandle, str], None],
        assumptions: list | None = None,
        floor: int = 0,
        deadline: float = math.inf,
        untimed: bool = False,
    ) -> None:
        self.deadline = deadline
        self.untimed = untimed
        self.wait = wait
        self.assumptions = assumptions or []
        self.grounded = -1
        self.floor = floor  # no run ends before this step (the caller's proof: shortest_run)
        self.answers: dict[tuple[str, int], bool] = {}
        self.grounding = 0.0  # seconds spent grounding
        if untimed:
            return
        # --eq=0: no equivalence preprocessing, which cannot be interrupted and answers no
        # question the window asks (whether a run ends by, or is open at, a step): 200 one-second
        # phases spent 6.7 s in it before a solve could be cancelled, 2.4 s without
        self.control = clingo.Control(["--warn=none", "--eq=0"], logger=lambda c, m: None)
        self.control.add(
            "base",
            [],
            automaton_lp.read_text(encoding="utf-8")
            + "\n#program base.\n"
            + base_program
            + "\n#program state(t).\n"
            + GUARDS_HOLD
            + "\n"
            + OPEN,
        )

    def _ground_to(self, horizon: int) -> None:
        if horizon <= self.grounded:
            return
        parts = [("base", [])] if self.grounded < 0 else []
        for step in range(self.grounded + 1, horizon + 1):
            t = clingo.Number(step)
            parts += [("state", [t]), ("check", [t]), ("open", [t])]
            # the time limit covers grounding too (a call cannot be stopped): ground in chunks
            if step % GROUND_CHUNK == 0 and step < horizon:
                self._ground(parts)
                parts = []
                if time.monotonic() > self.deadline:
                    raise PlanningTimeout(
                        f"planning ran out of its time limit while grounding step {step} of {horizon}"
                    )
        self._ground(parts)
        if (
            time.monotonic() + PREPARATION_PER_GROUNDING * self.grounding > self.deadline
        ):  # a solve begun past it would not stop before its preparation ends
            raise PlanningTimeout(f"planning ran out of its time limit while grounding step {horizon}")
        if self.grounded < 0:
            for atom in self.control.symbolic_atoms.by_signature("relaxed", 1):
                self.control.assign_external(atom.symbol, None)  # free unless assumed kept
        self.grounded = horizon

    def _ground(self, parts) -> None:
        start = time.perf_counter()
        self.control.ground(parts)
        self.grounding += time.perf_counter() - start

    def _holds(self, external: str, horizon: int) -> bool:
        if self.untimed:
            return horizon >= self.floor if external == "query" else True
        if (external, horizon) not in self.answers:
            self.answers[(external, horizon)] = self._solve(external, horizon)
        return self.answers[(external, horizon)]

    def _solve(self, external: str, horizon: int) -> bool:
        # a phase past its longest is cut off at the step after it: without that step grounded, a
        # run seems still under way at a step where its phase must have ended
        self._ground_to(horizon + 1 if external == "open" else horizon)
        atom = clingo.Function(external, [clingo.Number(horizon)])
        self.control.assign_external(atom, True)
        try:
            with self.control.solve(assumptions=self.assumptions, async_=True) as handle:
                self.wait(handle, "planning ran out of its time limit")
                return handle.get().satisfiable
        finally:
            self.control.assign_external(atom, False)

    def ends_by(self, horizon: int) -> bool:
        """A run can reach the final location within ``horizon`` steps."""
        return self._holds("query", horizon)

    def open_at(self, horizon: int) -> bool:
        """A run can still be under way (not yet final) at step ``horizon``."""
        return self._holds("open", horizon)

    def earliest(self, limit: int) -> int | None:
        """The first horizon up to ``limit`` by which a run can end; None when there is none."""
        return _first(self.ends_by, limit, self.floor)

    def past_end(self, horizon: int) -> bool:
        """No plan needs this horizon or a longer one: every run has ended more than a step
        before it (``horizon > last_horizon``, in one question where ``last_horizon`` bisects)."""
        return horizon >= 2 and not self.open_at(horizon - 2)

    def last_horizon(self, limit: int) -> int:
        """The longest horizon up to ``limit`` that a plan may need (see the module's docstring)."""
        last_open = self.last_open(limit)
        return limit if last_open is None else min(limit, last_open + 2)

    def last_open(self, limit: int) -> int | None:
        """The last step up to ``limit`` at which a run can be under way (-1: none, not even at
        step 0); None when one still can be at ``limit`` (a phase without an upper bound)."""
        first_closed = _first(lambda h: not self.open_at(h), limit)
        return None if first_closed is None else first_closed - 1


def _first(holds: Callable[[int], bool], limit: int, floor: int = 0) -> int | None:
    """The first h in 0..limit with ``holds(h)`` for a monotone ``holds`` that is false below
    ``floor``, or None."""
    if floor > limit:
        return None
    # holds(low - 1) is false; a stride doubling from 8 finds a true high
    low, high, stride = floor, floor if floor else 8, 8
    while True:
        high = min(high, limit)
        if holds(high):
            break
        if high == limit:
            return None
        low, high, stride = high + 1, high + stride, 2 * stride
    while low < high:
        middle = (low + high) // 2
        if holds(middle):
            high = middle
        else:
            low = middle + 1
    return high


def shortest_run(automaton: SymbolicAutomaton, dt: float) -> int:
    """A step before which no run of ``automaton`` reaches its final location (asp/automaton.lp,
    every guard holding): a transition fires at least one step after the one before it, and one
    that ends a timed phase at least the phase's shortest length after the earliest step any
    transition can begin it, when every path to it has begun the phase.

    These are inequalities that the earliest firing steps of every run meet; their least solution,
    found by raising all from 0 until they hold, is below each run's steps (a least fixpoint lies
    below every point the inequalities allow). Whether a run ends there is the solver's to say.
    """
    reachable = automaton.depth()  # the locations a run can reach
    # only reachable ones: a cycle no run enters would raise its steps without end
    transitions = [t for t in automaton.transitions if t.source in reachable]
    incoming: dict[int, list] = {}
    for t in transitions:
        incoming.setdefault(t.target, []).append(t)
    phases = frozenset(automaton.timings)
    # the timed phases that every path to a location has begun (a must-analysis, from above)
    begun: dict[int, frozenset[int]] = {loc.id: phases for loc in automaton.locations}
    begun[automaton.initial] = frozenset()
    changed = True
    while changed:
        changed = False
        for location, into in incoming.items():
            if location == automaton.initial:
                continue
            meet = frozenset.intersection(*(begun[t.source] | (t.starts & phases) for t in into))
            if meet != begun[location]:
                begun[location], changed = meet, True
    shortest = {p: timing_steps(timing, dt)[0] for p, timing in automaton.timings.items()}
    fires = {t.id: 0 for t in transitions}
    changed = True
    while changed:
        changed = False
        beginning = {p: min((fires[t.id] for t in transitions if p in t.starts), default=0) for p in phases}
        for t in transitions:
            step = (
                0
                if t.source == automaton.initial
                else 1 + min((fires[e.id] for e in incoming.get(t.source, ())), default=0)
            )
            for p in t.ends & begun[t.source]:
                step = max(step, beginning[p] + shortest[p])
            if step > fires[t.id]:
                fires[t.id], changed = step, True
    return min((fires[t.id] for t in incoming.get(automaton.final, ())), default=0)
