"""Which horizons a scenario's phase durations allow, before any vehicle moves.

The automaton alone, with every guard holding, says how long a run can last: no plan ends before
the first horizon at which it can reach its final location (``earliest``), and none needs a
horizon past the last step at which a run can still be under way (``last_open``): the final
location is absorbing, so a plan that ends earlier is a shorter plan the planner met first.
Planning and the diagnosis solve only between the two. Measured: follow_then_overtake's
durations rule out horizons 0-23, which the continuous encoding spent 60 s refuting with the
dynamics; infeasible_order (every phase 5-10 s) was refuted at all 120 horizons of the limit
(21 s) where its durations allow 5 to 11 steps.

Both questions are monotone in the horizon (reaching the final location by h, being under way at
h), so each is answered by doubling and then bisecting, on steps grounded in as few calls as
possible: measured on five_vehicle_minute (481 transitions), 45 steps grounded one call per step
took 2.5 s and in one call 0.36 s.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import clingo

# every guard holds: the durations alone decide (as free choices, measured 7.5 s for
# five_vehicle_minute's window, against well under a second this way)
GUARDS_HOLD = "g(N,t) :- guard_of(_,N).\ng(N,t) :- invariant_of(_,N)."
OPEN = "#program open(t).\n#external open(t).\n:- open(t), accepted(t)."


class DurationWindow:
    """The horizons a run of the automaton can end at, given its phases' durations.

    ``base_program`` holds the automaton's facts (and, for the diagnosis, ``relaxed(K)``
    externals: ``assumptions`` are those kept, and a relaxed duration leaves its phase open).
    ``wait(handle, message)`` waits for a solve and raises when time is up.
    """

    def __init__(self, automaton_lp: Path, base_program: str, wait: Callable[[clingo.SolveHandle, str], None], assumptions: list | None = None) -> None:
        self.control = clingo.Control(["--warn=none"], logger=lambda c, m: None)
        self.control.add("base", [], automaton_lp.read_text(encoding="utf-8") + "\n#program base.\n" + base_program
                         + "\n#program state(t).\n" + GUARDS_HOLD + "\n" + OPEN)
        self.wait = wait
        self.assumptions = assumptions or []
        self.grounded = -1
        self.answers: dict[tuple[str, int], bool] = {}

    def _ground_to(self, horizon: int) -> None:
        if horizon <= self.grounded:
            return
        parts = [("base", [])] if self.grounded < 0 else []
        for step in range(self.grounded + 1, horizon + 1):
            t = clingo.Number(step)
            parts += [("state", [t]), ("check", [t]), ("open", [t])]
        self.control.ground(parts)
        if self.grounded < 0:
            for atom in self.control.symbolic_atoms.by_signature("relaxed", 1):
                self.control.assign_external(atom.symbol, None)  # free unless assumed kept
        self.grounded = horizon

    def _holds(self, external: str, horizon: int) -> bool:
        if (external, horizon) not in self.answers:
            self.answers[(external, horizon)] = self._solve(external, horizon)
        return self.answers[(external, horizon)]

    def _solve(self, external: str, horizon: int) -> bool:
        self._ground_to(horizon)
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
        return _first(self.ends_by, limit)

    def last_open(self, limit: int) -> int | None:
        """The last step up to ``limit`` at which a run can be under way (-1: none, not even at
        step 0); None when one still can be at ``limit`` (a phase without an upper bound)."""
        first_closed = _first(lambda h: not self.open_at(h), limit)
        return None if first_closed is None else first_closed - 1


def _first(holds: Callable[[int], bool], limit: int) -> int | None:
    """The first h in 0..limit with ``holds(h)`` for a monotone ``holds``, or None."""
    low, high = 0, 8  # holds(low - 1) is false; doubling finds a true high
    while True:
        high = min(high, limit)
        if holds(high):
            break
        if high == limit:
            return None
        low, high = high + 1, 2 * high
    while low < high:
        middle = (low + high) // 2
        if holds(middle):
            high = middle
        else:
            low = middle + 1
    return high
