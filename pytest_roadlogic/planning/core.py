"""What every planner encoding shares: one clingo control grown step by step (multi-shot).

``IncrementalPlanner`` is the core an encoding's planner (``encodings/<name>/planner.py``) builds on:
the control with the encoding's theory, grounding one step's ``dynamics(t)``, ``state(t)`` and
``check(t)`` parts at a time and moving the ``query(t)`` external that asks for acceptance at the
last step (so nothing is re-grounded), grounding in chunks that keep to the time limit and the
memory limit, the deadline of each plan, the next model within a count of conflicts, the exclusion
of a plan found, the random start's horizon, and the window of horizons the phases' durations
allow (``window.py``). What an encoding adds: its instance (``instance.py``), its background
``.lp`` files, its search for plans (``plans``), and its plan decoder. Why a scenario has no plan is
``diagnosis.py``'s.

One ``seed`` fixes the result: it seeds clingo's random decisions (random signs, so that different
seeds give different plans) and a random start's draws.
"""

from __future__ import annotations

import math
import os
import random
import time
import weakref
from collections.abc import Iterator
from pathlib import Path

import clingo
from clingo.ast import ProgramBuilder, parse_string

from ..asp_dir import ASP_DIR
from ..logic.automaton import SymbolicAutomaton
from . import diagnosis
from .errors import HorizonTooShort, NoPlanError, PlanningTimeout, PlanningTooLarge
from .plan import Plan
from .window import DurationWindow, shortest_run

# the run of the automaton, shared by every encoding (the window's solver reads it alone)
AUTOMATON = ASP_DIR / "automaton.lp"
# a random start's vehicle keeps its lane unless the scenario needs a change (both encodings)
KEEP_LANE = ASP_DIR / "keep_lane.lp"
# a vehicle changes lane and speed only where its own constructs ask (both encodings), while the
# external least_action holds (IncrementalPlanner.least_action)
LEAST_ACTION = ASP_DIR / "least_action.lp"
# steps grounded in one call before the time limit is looked at again (a call cannot be stopped,
# and one call per step is several times slower: docs/decisions.md)
GROUND_CHUNK = 50  # steps grounded in one call (the chunks decide the ground program's order, hence the plans)
# A solve cannot be stopped while clasp prepares the ground program (equivalence preprocessing),
# which takes up to 1.6 times as long as grounding it did. A solve that would start with less
# time left than this many times its control's grounding time is not started: the time limit then
# holds within a tenth instead of being overrun by the preparation.
PREPARATION_PER_GROUNDING = 1.6
# what the process may hold while grounding (docs/decisions.md: what long horizons take)
MAX_PLANNING_BYTES = 8 * 2**30


def read_programs(*paths: Path) -> str:
    """The text of ``.lp`` files, one after the other."""
    return "\n".join(path.read_text(encoding="utf-8") for path in paths)


def resident_bytes() -> int:
    """The process's resident memory now (Linux's /proc; 0 where it cannot be read)."""
    try:
        with open("/proc/self/statm") as statm:
            return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


class IncrementalPlanner:
    """Plans for one automaton with one encoding; ``plans()`` yields them lazily (``planning.protocol.Planner``).

    A subclass gives ``instance_for`` (its instance writer), ``_start_preferences`` (a random start's
    draws as rules), ``control_for`` (a control with its background and theory), ``widened`` (wider
    settings for a second try, or None) and ``plans``."""

    # whether the search under way keeps every vehicle to what its own constructs ask
    # (asp/least_action.lp): an encoding's plans() searches so first (the grid's never does); a
    # diagnosis never assumes it
    least_action = True
    # whether, with least_action, a vehicle may make changes nothing asks, the fewest there are
    # (asp/least_action.lp): a second search when the first has no plan (the plan's stats then
    # say least_action 0); its solves optimise
    least_change = False
    # the fewest steps a plan may have, besides what the durations allow (a replan: past the
    # observed step, reactive/replanner.py)
    shortest = 0

    def __init__(self, automaton: SymbolicAutomaton, settings, seed: int = 0) -> None:
        self.automaton = automaton
        self.settings = settings
        self.seed = seed
        self.instance = self.instance_for(self.settings)
        self.stats: dict[str, float] = {"ground_s": 0.0, "solve_s": 0.0}
        # each control's theory propagator (weak: explaining a failure makes many controls)
        self._theories: weakref.WeakKeyDictionary[clingo.Control, object] = weakref.WeakKeyDictionary()
        self._grounding: weakref.WeakKeyDictionary[clingo.Control, float] = weakref.WeakKeyDictionary()
        # a random start: the first plan follows choices drawn from the seed, not the solver's habits
        # (how long it lasts is as free as where it starts: the scenario rarely says, and a plan at
        # the shortest horizon is only the incremental search's habit)
        self.preferences, self.stretch = "", 0.0
        if self.settings.random_start:
            draw = random.Random(seed)
            self.preferences = self._start_preferences(draw)
            self.stretch = draw.random()  # the fraction of the steps left up to max_horizon

    def instance_for(self, settings, relaxable: bool = False) -> str:
        """This encoding's instance of the scenario (facts and constants, ``#program base``); with ``relaxable``, every
        bound and duration switched off by a ``relaxed(K)`` external (``facts.relaxable_constraints``)."""
        raise NotImplementedError

    def _start_preferences(self, draw: random.Random) -> str:
        """A random start's draws from ``draw``, as this encoding's rules."""
        raise NotImplementedError

    def base_parts(self) -> list[tuple[str, list]]:
        """The program parts grounded once, before step 0: the instance's; an encoding adds its
        own (a replan's past, for the continuous one)."""
        return [("base", [])]

    def control_for(self, instance: str) -> clingo.Control:
        """A control with this encoding's background, theory and the instance, nothing grounded."""
        raise NotImplementedError

    def widened(self):
        """Settings for a second try when the first finds no plan (a wider start), or None."""
        return None

    def plans(self, limit: int | None = None) -> Iterator[Plan]:
        """Plans, at most ``limit``; ``NoPlanError`` (or a subclass saying why) when there is none."""
        raise NotImplementedError

    def explain(self, deadline: float | None = None) -> tuple | None:
        """A smallest group of the scenario's constraints that no plan meets (``diagnosis``)."""
        return diagnosis.smallest_conflict(self, deadline)

    def explain_failure(self, error: NoPlanError, deadline: float) -> None:
        """Raise the reason no plan exists, natural or not (``diagnosis.raise_reason``): the
        diagnosis never holds vehicles to what they are asked."""
        self.least_action = False
        diagnosis.raise_reason(self, error, deadline)

    def instance_program(self) -> str:
        return "#program base.\n" + self.instance

    def _new_control(self) -> clingo.Control:
        """A control searching as every encoding's does: seeded random signs, domain heuristics,
        one model at a time, no warnings on the console."""
        return clingo.Control(
            [
                f"--seed={self.seed}",
                "--sign-def=rnd",
                "--rand-freq=0.02",
                "--heuristic=Domain",
                "--warn=none",
                "--models=1",
            ],
            logger=lambda code, message: None,
        )

    def _add(self, control: clingo.Control, program: str) -> None:
        """Add a program, its ``&diff`` constraints rewritten for the difference-logic theory."""
        with ProgramBuilder(control) as builder:
            parse_string(program, lambda statement: self._theories[control].rewrite_ast(statement, builder.add))

    def needed_horizon(self, deadline: float, window: DurationWindow | None = None) -> int | None:
        """The shortest horizon the phases' durations allow (``earliest_horizon``);
        ``HorizonTooShort`` when that is past the horizon limit, a setting that then binds. None
        when no horizon at all lets a run end: the durations clash (a run can no longer be under
        way at four times the limit either), which is the scenario's matter, not the limit's."""
        window = window or self.window(deadline)
        reach = 4 * self.settings.max_horizon
        needed = window.earliest(reach)
        if needed is None and not window.open_at(reach):
            return None
        if needed is None or needed > self.settings.max_horizon:
            raise HorizonTooShort(self.settings.max_horizon, self.settings.dt, needed)
        return needed

    def earliest_horizon(self, deadline: float, limit: int | None = None) -> int | None:
        """The first horizon (up to ``limit``, default the horizon limit) at which the automaton
        alone, every guard holding, reaches its final location within its phases' durations: no
        plan can be shorter (planning/window.py). None when there is none up to ``limit``."""
        return self.window(deadline).earliest(self.settings.max_horizon if limit is None else limit)

    def window(self, deadline: float, instance: str | None = None, assumptions: list | None = None) -> DurationWindow:
        """The horizons the durations allow, for this scenario's instance or the diagnosis's
        relaxable one (``instance`` with the ``assumptions`` it keeps). Only the scenario's own
        instance has every duration in force, so only its window starts at the automaton's floor.
        The scenario's own window is kept for the planner's later searches (the one that allows
        unasked changes asks it the same questions), its deadline renewed."""
        if instance is None and self._own_window is not None:
            self._own_window.wait, self._own_window.deadline = self._waiter(deadline), deadline
            return self._own_window
        floor = shortest_run(self.automaton, self.settings.dt) if instance is None else 0
        automaton = self.automaton
        untimed = (
            instance is None
            and not automaton.timings
            and not any(t.source == automaton.initial and t.target == automaton.final for t in automaton.transitions)
        )
        window = DurationWindow(
            AUTOMATON,
            instance or self.instance,
            self._waiter(deadline),
            assumptions,
            floor,
            deadline,
            untimed,
        )
        if instance is None:
            self._own_window = window
        return window

    _own_window: DurationWindow | None = None

    def _waiter(self, deadline: float):
        """A window's wait: for a solve, until ``deadline``."""
        return lambda handle, message: self.wait(handle, deadline, f"{message} ({self.settings.time_limit:g} s)")

    def advance(self, control: clingo.Control, horizon: int) -> None:
        """Ground step ``horizon`` (with the base program at 0) and ask for acceptance there only."""
        t = clingo.Number(horizon)
        if horizon == 0:
            self._ground(control, [*self.base_parts(), ("state", [t]), ("check", [t])])
            self._assign_action(control)
        else:
            self._ground(control, [("dynamics", [t]), ("state", [t]), ("check", [t])])
            control.assign_external(clingo.Function("query", [clingo.Number(horizon - 1)]), False)
        control.assign_external(clingo.Function("query", [t]), True)

    def advance_to(self, control: clingo.Control, horizon: int, grounded: int = -1) -> None:
        """Ground the steps after ``grounded`` (-1: none yet, the base program too) up to
        ``horizon`` in one call and ask for acceptance at ``horizon`` only."""
        parts = (
            [*self.base_parts(), ("state", [clingo.Number(0)]), ("check", [clingo.Number(0)])] if grounded < 0 else []
        )
        for step in range(max(1, grounded + 1), horizon + 1):
            t = clingo.Number(step)
            parts += [("dynamics", [t]), ("state", [t]), ("check", [t])]
            if step % GROUND_CHUNK == 0 and step < horizon:
                # a grounding call cannot be interrupted: ground in chunks and keep to the time limit
                # between them
                self._ground(control, parts)
                parts = []
                if time.monotonic() > self._deadline:
                    raise PlanningTimeout(
                        f"planning ran out of its time limit ({self.settings.time_limit:g} s) while grounding step {step} of {horizon}"
                    )
                if (resident := resident_bytes()) > MAX_PLANNING_BYTES:
                    raise PlanningTooLarge(
                        f"planning stopped at {resident / 2**30:.1f} GiB while grounding step {step} of {horizon} (the planner's "
                        f"limit is {MAX_PLANNING_BYTES / 2**30:g} GiB): lower the horizon with --horizon, or split the scenario"
                    )
        self._ground(control, parts)
        if grounded < 0:
            self._assign_action(control)
        for step in range(max(0, grounded), horizon):
            control.assign_external(clingo.Function("query", [clingo.Number(step)]), False)
        control.assign_external(clingo.Function("query", [clingo.Number(horizon)]), True)

    def _assign_action(self, control: clingo.Control) -> None:
        """Set the externals of asp/least_action.lp as this search holds vehicles to what they are asked."""
        control.assign_external(clingo.Function("least_action"), self.least_action)
        control.assign_external(clingo.Function("least_change"), self.least_action and self.least_change)
        # an optimising search goes past the first model to the best (--models=1 stops at the
        # first); the two searches may take turns on one control
        control.configuration.solve.models = "0" if self.least_action and self.least_change else "1"

    _deadline = math.inf  # of the planning under way (_renewed): what grounding keeps to

    def _renewed(self, deadline: float | None = None) -> float:
        """The deadline of the next plan: ``deadline`` when the caller set one for the first plan
        (``plans(deadline=...)``), else the whole time limit from now. The time a caller spends
        with a plan before asking for the next (simulating it) is not planning time."""
        self._deadline = deadline if deadline is not None else time.monotonic() + self.settings.time_limit
        return self._deadline

    @staticmethod
    def wait(handle: clingo.SolveHandle, deadline: float, message: str) -> None:
        """Wait for a solve until the deadline; past it, cancel and raise ``PlanningTimeout``."""
        remaining = deadline - time.monotonic()
        if remaining <= 0 or not handle.wait(remaining):
            handle.cancel()
            raise PlanningTimeout(message)

    def _stretch_target(self, shortest: int, longest: int | None = None) -> int:
        """A random start's horizon: uniform from ``shortest`` up to ``longest`` (default the
        horizon limit); the shortest for any other planning, or when it is the longest already."""
        longest = self.settings.max_horizon if longest is None else longest
        if not self.settings.random_start or longest <= shortest:
            return shortest
        return shortest + math.floor(self.stretch * (longest - shortest + 1))

    def first(self) -> Plan:
        for plan in self.plans(limit=1):
            return plan
        raise NoPlanError("no plan")

    def _ground(self, control: clingo.Control, parts) -> None:
        start = time.perf_counter()
        control.ground(parts)
        self._theories[control].prepare(control)
        spent = time.perf_counter() - start
        self.stats["ground_s"] += spent
        self._grounding[control] = self._grounding.get(control, 0.0) + spent

    def _time_to_prepare(self, control: clingo.Control, deadline: float, message: str) -> None:
        """``PlanningTimeout`` when a solve of ``control`` begun now would not be prepared by the
        deadline (``PREPARATION_PER_GROUNDING``)."""
        if deadline - time.monotonic() < PREPARATION_PER_GROUNDING * self._grounding.get(control, 0.0):
            raise PlanningTimeout(message)

    def _next_model(
        self,
        control: clingo.Control,
        deadline: float,
        where: str,
        read,
        conflicts: int | None = None,
        assumptions: list[tuple[clingo.Symbol, bool]] = (),
    ):
        """What ``read(model, theory)`` makes of the next model (with ``assumptions`` held); None
        when there is none, or none within ``conflicts``. ``where`` ends the time limit's message."""
        start = time.perf_counter()
        answer = None
        theory = self._theories[control]
        if conflicts is not None:  # set only here: touching the configuration changes later searches
            control.configuration.solve.solve_limit = f"{conflicts},umax"
        message = f"planning ran out of its time limit ({self.settings.time_limit:g} s){where}"
        self._time_to_prepare(control, deadline, message)
        unproven = False  # a model found whose cost a better one may still beat
        with control.solve(assumptions=list(assumptions), yield_=True, async_=True) as handle:
            self.wait(handle, deadline, message)
            model = handle.model()
            while model is not None:
                theory.on_model(model)
                answer = read(model, theory)
                if not any(model.cost):
                    break  # nothing to optimise, or nothing left to: no better model exists
                # the least unasked changes (least_change): each next model is better, the last
                # one found is proved best once the search is exhausted
                handle.resume()
                self.wait(handle, deadline, message)
                model = handle.model()
            else:
                unproven = answer is not None and not handle.get().exhausted
        if conflicts is not None:
            control.configuration.solve.solve_limit = "umax,umax"
        self.stats["solve_s"] += time.perf_counter() - start
        if unproven:
            # the count of conflicts ran out while optimising: the search that found a model goes
            # on to the best one without it (a count, so every machine stops at the same model)
            return self._next_model(control, deadline, where, read, assumptions=assumptions)
        return answer

    def _forbid(
        self, control: clingo.Control, literals: list[clingo.Symbol], count: int, rules: list[str] = (), parts=()
    ) -> None:
        """Add and ground, as program part ``exclude_<count>``, a constraint against ``literals``
        (the symbols of a model) holding together and ``rules`` beside it, and the encoding's own
        program ``parts`` (name, parameters) with it."""
        name = f"exclude_{count}"
        control.add(name, [], ":- " + ", ".join(map(str, literals)) + ".\n" + "\n".join(rules))
        self._ground(control, [(name, []), *parts])
