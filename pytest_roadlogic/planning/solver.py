"""Multi-shot (incremental) solving of a scenario's planning problem with clingo.

The horizon grows one step at a time: each step grounds only the new ``dynamics(t)`` and
``state(t)`` parts and moves the ``query(t)`` external that asks for acceptance at the last step,
so nothing is re-grounded. The first horizon with an answer set gives the shortest plans. Further
plans come from the same control: each plan found is excluded (projected on positions and lanes),
a domain heuristic makes the search prefer cells no earlier plan occupied (so plans spread out
instead of being near neighbours), and the solver is asked again, at the same horizon first and
then at longer ones.

One ``seed`` fixes the result: it seeds clingo's random decisions, which use random signs so that
different seeds give different plans.
"""

from __future__ import annotations

import dataclasses
import math
import os
import random
import time
import weakref
from collections.abc import Iterator
from pathlib import Path

import clingo
from clingo.ast import ProgramBuilder, parse_string
from clingodl import ClingoDLTheory

from ..logic.automaton import SymbolicAutomaton, Timing
from ..logic.guards import contradiction
from .errors import (
    HorizonTooShort,
    NoPlanError,
    PlanningTimeout,
    PlanningTooLarge,
    UnsatisfiableScenario,
    conflict_message,
)
from .instance import PlanningSettings, build_instance, relaxable_constraints, start_preferences
from .plan import Plan, PlanState
from .window import DurationWindow, shortest_run

ASP_DIR = Path(__file__).resolve().parent.parent / "asp"
if not ASP_DIR.is_dir():  # running from a source checkout: asp/ sits at the top level
    ASP_DIR = Path(__file__).resolve().parents[2] / "asp"
BACKGROUND = ("dynamics.lp", "domain.lp", "automaton.lp")
INITIAL = "initial.lp"  # the rules of the initial state, after the instance's facts (see _control)
PREFERENCES = ("preferences.lp", "keep_lane.lp")  # loaded for a random start only, in this order


def check_satisfiable(automaton: SymbolicAutomaton) -> None:
    """Raise ``UnsatisfiableScenario`` when every path to the end crosses a self-contradicting guard."""
    blocked = {}
    for transition in automaton.transitions:
        pair = contradiction(transition.guard)
        if pair is not None:
            blocked[transition.id] = pair
    if not blocked:
        return
    reachable = {automaton.initial}
    frontier = [automaton.initial]
    while frontier:
        location = frontier.pop()
        for transition in automaton.outgoing(location):
            if transition.id not in blocked and transition.target not in reachable:
                reachable.add(transition.target)
                frontier.append(transition.target)
    if automaton.final in reachable:
        return
    conflicts = list(dict.fromkeys(blocked.values()))
    raise UnsatisfiableScenario(conflict_message(conflicts), conflicts)


def background_theory() -> str:
    return "\n".join((ASP_DIR / name).read_text(encoding="utf-8") for name in BACKGROUND)


# conflicts a random start may spend stretching its plan past the shortest horizon: random
# preferences now and then lead the search into a long detour (measured: up to 36 s), and a count
# of conflicts, unlike a time limit, ends it at the same point on every machine (50 000: about 2 s
# here; past it the plan keeps the shortest horizon)
STRETCH_CONFLICTS = 50_000
# steps grounded in one call before the time limit is looked at again (a call cannot be stopped;
# one per step had cost 2.5 s over 45 steps against 0.36 s in one call)
GROUND_CHUNK = 50
# what the process may hold while grounding: measured, 3,500 steps of five vehicles held 1.7 GB
MAX_PLANNING_BYTES = 8 * 2**30


def resident_bytes() -> int:
    """The process's resident memory now (Linux's /proc; 0 where it cannot be read)."""
    try:
        with open("/proc/self/statm") as statm:
            return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


class Planner:
    """Plans for one automaton; ``plans()`` yields them lazily, shortest horizon first (but for a
    random start, whose first plans have a random horizon)."""

    def __init__(self, automaton: SymbolicAutomaton, settings: PlanningSettings | None = None, seed: int = 0) -> None:
        self.automaton = automaton
        self.settings = settings or PlanningSettings()
        self.seed = seed
        self.base_program, self.state_program = self._instance(self.settings)
        self.stats: dict[str, float] = {"ground_s": 0.0, "solve_s": 0.0}
        # each control's difference-logic propagator (weak: explaining a failure makes many controls)
        self._theories: weakref.WeakKeyDictionary[clingo.Control, ClingoDLTheory] = weakref.WeakKeyDictionary()
        # a random start: the first plan follows choices drawn from the seed, not the solver's habits
        # (how long it lasts is as free as where it starts: the scenario rarely says, and a plan at
        # the shortest horizon is only the incremental search's habit)
        self.preferences, self.stretch = "", 0.0
        if self.settings.random_start:
            draw = random.Random(seed)
            self.preferences = self._start_preferences(draw)
            self.stretch = draw.random()  # the fraction of the steps left up to max_horizon

    def _instance(self, settings, relaxable: bool = False) -> tuple[str, str]:
        """(base program, state(t) program) of this encoding's instance."""
        return build_instance(self.automaton, settings, relaxable)

    def _start_preferences(self, draw: random.Random) -> str:
        """A random start's draws, as this encoding's rules."""
        return start_preferences(self.automaton, self.settings, draw)

    def instance_program(self) -> str:
        return "#program base.\n" + self.base_program + "\n#program state(t).\n" + self.state_program

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

    def _control(self, base_program: str, state_program: str) -> clingo.Control:
        control = self._new_control()
        self._theories[control] = theory = ClingoDLTheory()
        theory.register(control)
        initial = (ASP_DIR / INITIAL).read_text(encoding="utf-8")
        self._add(
            control,
            background_theory()
            + "\n#program base.\n"
            + base_program
            + "\n"
            + initial
            + "\n#program state(t).\n"
            + state_program,
        )
        if self.preferences:
            self._add(
                control,
                "#program base.\n"
                + self.preferences
                + "".join((ASP_DIR / name).read_text(encoding="utf-8") for name in PREFERENCES),
            )
        return control

    def _add(self, control: clingo.Control, program: str) -> None:
        """Add a program, its ``&diff`` constraints rewritten for the difference-logic theory."""
        with ProgramBuilder(control) as builder:
            parse_string(program, lambda statement: self._theories[control].rewrite_ast(statement, builder.add))

    def plans(self, limit: int | None = None) -> Iterator[Plan]:
        """Plans with start speeds in ``initial_speed`` first; when there is none up to the horizon
        limit, plans that start at any allowed speed (``widen_initial_speed``)."""
        check_satisfiable(self.automaton)
        deadline = self._renewed()
        programs = [lambda: (self.base_program, self.state_program)]
        if (wide := self._widened()) is not None:
            programs.append(lambda: self._instance(wide))
        for program in programs:
            try:
                # a program that yields any plan ends without NoPlanError, so this is the last try
                yield from self._plans(*program(), limit, deadline)
                return
            except PlanningTimeout:
                raise
            except NoPlanError as error:
                last = error
        if not self.settings.explain_unsatisfiable:
            raise last
        self._explain(last, deadline)

    def _widened(self) -> PlanningSettings | None:
        """The settings with any allowed start speed, when that is wider than the first try."""
        wide = dataclasses.replace(self.settings, initial_speed=(self.settings.min_speed, self.settings.max_speed))
        if not self.settings.widen_initial_speed or wide.initial_speeds() == self.settings.initial_speeds():
            return None
        return wide

    def _explain(self, error: NoPlanError, deadline: float, window: DurationWindow | None = None) -> None:
        """Raise the reason there is no plan: the horizon limit when the phases' durations alone
        need longer (a setting binds, not the scenario), else the constraints that cannot hold
        together, when a diagnosis finds them in time, else ``error`` as it is. ``window``: the
        planning's own, whose answers it reuses."""
        try:
            self.needed_horizon(deadline, window)
        except PlanningTimeout:
            pass  # no time to tell: go on to the diagnosis, which says what it finds
        conflict = self.explain(deadline)
        if conflict:
            raise UnsatisfiableScenario(
                f"{error}\n" + conflict_message([conflict]), [conflict], self.settings.summary(self.automaton.lanes)
            ) from None
        raise error

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

    def window(
        self, deadline: float, base_program: str | None = None, assumptions: list | None = None
    ) -> DurationWindow:
        """The horizons the durations allow, for this scenario's instance or the diagnosis's
        relaxable one (``base_program`` with the ``assumptions`` it keeps). Only the scenario's own
        instance has every duration in force, so only its window starts at the automaton's floor."""
        floor = shortest_run(self.automaton, self.settings.dt) if base_program is None else 0
        return DurationWindow(
            ASP_DIR / "automaton.lp",
            base_program or self.base_program,
            self._waiter(deadline),
            assumptions,
            floor,
            deadline,
        )

    def _waiter(self, deadline: float):
        """A window's wait: for a solve, until ``deadline``."""
        return lambda handle, message: self._wait(handle, deadline, f"{message} ({self.settings.time_limit:g} s)")

    def explain(self, deadline: float | None = None) -> tuple | None:
        """A smallest group of the scenario's constraints that no plan up to the horizon limit meets.

        Every bound and duration gets an external that relaxes it, and each horizon is solved as in
        planning, assuming none is relaxed: clingo's unsatisfiable cores name the assumptions that
        failed, and their union over the horizons is a group that cannot hold together. Removing
        one member at a time, and keeping it out whenever the rest still fail at every horizon,
        makes the group minimal; with a ``removal_time_limit`` setting, a member whose removal is not
        decided within it stays (the group still cannot hold together, it may name one constraint
        too many). None when relaxing everything still leaves no plan (the settings
        alone forbid one), or when time runs out.
        """
        constraints = relaxable_constraints(self.automaton)
        if not constraints:
            return None
        deadline = deadline if deadline is not None else time.monotonic() + self.settings.time_limit
        settings = self._widened() or self.settings
        program = self._instance(settings, relaxable=True)
        try:
            if self._failing(program, settings, [], len(constraints), deadline) is not None:
                return None  # no plan even with every constraint relaxed
            core = self._failing(program, settings, list(range(len(constraints))), len(constraints), deadline)
            if not core:
                return None
            budget = self.settings.removal_time_limit
            for k in list(core):
                if k in core:
                    step_deadline = deadline if budget is None else min(deadline, time.monotonic() + budget)
                    try:
                        smaller = self._failing(
                            program, settings, [c for c in core if c != k], len(constraints), step_deadline
                        )
                    except PlanningTimeout:
                        if time.monotonic() >= deadline:
                            raise
                        continue  # undecided in its budget: k stays, and the group is still one that fails
                    if smaller is not None:
                        core = smaller
        except PlanningTimeout:
            return None
        return tuple(constraints[k] for k in core)

    def _failing(
        self, program: tuple[str, str], settings: PlanningSettings, kept: list[int], count: int, deadline: float
    ) -> list[int] | None:
        """Grow the horizon as in planning with the constraints ``kept`` (the rest may be relaxed):
        None when some horizon has a plan, else the union of the unsatisfiable cores."""
        relaxed = [clingo.Function("relaxed", [clingo.Number(k)]) for k in range(count)]
        # only the horizons the kept durations allow (a relaxed one leaves its phase open)
        window = self.window(deadline, program[0], [(relaxed[k], False) for k in kept])
        earliest = window.earliest(settings.max_horizon)
        if earliest is None:
            # the kept durations let no run end within the horizon limit: they fail among themselves,
            # whatever the bounds (emit_wait_brake's brake of 6.3-7.3 s that must equal its 0.5-1 s
            # wait plus its 3-3.5 s lane change had been reported with no constraint named)
            timings = {
                k
                for k, constraint in enumerate(relaxable_constraints(self.automaton))
                if isinstance(constraint, Timing)
            }
            return sorted(k for k in kept if k in timings)
        last = window.last_horizon(settings.max_horizon)
        control = self._control(*program)
        union: set[int] = set()
        for horizon in range(earliest, last + 1):
            if horizon == earliest:
                self._advance_to(control, horizon)
                for atom in relaxed:
                    control.assign_external(atom, None)  # free: what is not kept may be relaxed
                literal = {control.symbolic_atoms[atom].literal: k for k, atom in enumerate(relaxed)}
            else:
                self._advance(control, horizon)
            with control.solve(assumptions=[(relaxed[k], False) for k in kept], async_=True) as handle:
                self._wait(handle, deadline, "no time left to explain why there is no plan")
                if handle.get().satisfiable:
                    return None
                union.update(literal[abs(lit)] for lit in handle.core() if abs(lit) in literal)
        return sorted(union)

    def _advance(self, control: clingo.Control, horizon: int) -> None:
        """Ground step ``horizon`` (with the base program at 0) and ask for acceptance there only."""
        t = clingo.Number(horizon)
        if horizon == 0:
            self._ground(control, [("base", []), ("state", [t]), ("check", [t])])
        else:
            self._ground(control, [("dynamics", [t]), ("state", [t]), ("check", [t])])
            control.assign_external(clingo.Function("query", [clingo.Number(horizon - 1)]), False)
        control.assign_external(clingo.Function("query", [t]), True)

    def _advance_to(self, control: clingo.Control, horizon: int, grounded: int = -1) -> None:
        """Ground the steps after ``grounded`` (-1: none yet, the base program too) up to
        ``horizon`` in one call and ask for acceptance at ``horizon`` only (measured on
        five_vehicle_minute: 45 steps in one call 0.36 s, one call per step 2.5 s)."""
        parts = [("base", []), ("state", [clingo.Number(0)]), ("check", [clingo.Number(0)])] if grounded < 0 else []
        for step in range(max(1, grounded + 1), horizon + 1):
            t = clingo.Number(step)
            parts += [("dynamics", [t]), ("state", [t]), ("check", [t])]
            if step % GROUND_CHUNK == 0 and step < horizon:
                # a grounding call cannot be interrupted: ground in chunks and keep to the time limit
                # between them (a 3,500 s scenario of five vehicles had grounded for 55 s under a 5 s limit)
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
        for step in range(max(0, grounded), horizon):
            control.assign_external(clingo.Function("query", [clingo.Number(step)]), False)
        control.assign_external(clingo.Function("query", [clingo.Number(horizon)]), True)

    _deadline = math.inf  # of the planning under way (_renewed): what grounding keeps to

    def _renewed(self) -> float:
        """The deadline of the next plan: the whole time limit from now. The time a caller spends
        with a plan before asking for the next (simulating it) is not planning time (measured:
        five_vehicle_minute's second plan takes 0.24 s, but after its first plan's 45 s simulation
        it ran out of the 60 s limit before it started)."""
        self._deadline = time.monotonic() + self.settings.time_limit
        return self._deadline

    @staticmethod
    def _wait(handle: clingo.SolveHandle, deadline: float, message: str) -> None:
        """Wait for a solve until the deadline; past it, cancel and raise ``PlanningTimeout``."""
        remaining = deadline - time.monotonic()
        if remaining <= 0 or not handle.wait(remaining):
            handle.cancel()
            raise PlanningTimeout(message)

    def _plans(self, base_program: str, state_program: str, limit: int | None, deadline: float) -> Iterator[Plan]:
        control = self._control(base_program, state_program)
        horizon = 0
        found = 0
        self._advance(control, horizon)
        # a random start's first plan comes from a search of its own at a longer horizon; the plans
        # after it too, as long as that search answers within STRETCH_CONFLICTS, then the shortest
        # horizon's search goes on (a stretched search that stalls must not cost the run its plans)
        stretched: tuple[clingo.Control, int] | None = None
        while limit is None or found < limit:
            if stretched is not None:
                symbols = self._solve(stretched[0], deadline, STRETCH_CONFLICTS)
                if symbols is None:
                    stretched = None
                    continue
                source, plan_horizon = stretched
            else:
                symbols = self._solve(control, deadline)
                if symbols is None:
                    if horizon >= self.settings.max_horizon:
                        if found:
                            return
                        raise NoPlanError(
                            f"no plan satisfies the scenario within {self.settings.max_horizon} steps "
                            f"({self.settings.max_horizon * self.settings.dt:g} s)"
                        )
                    horizon += 1
                    self._advance(control, horizon)
                    continue
                source, plan_horizon = control, horizon
                target = self._stretch_target(horizon)
                if found == 0 and target > horizon:
                    longer = self._stretched(base_program, state_program, target, deadline)
                    if longer is not None:
                        source, symbols = longer
                        stretched = (source, target)
                        plan_horizon = target
            self.stats["rules"] = float(source.statistics.get("problem", {}).get("lp", {}).get("rules", 0))
            plan = self._plan(symbols, plan_horizon, found)
            found += 1
            yield plan
            deadline = self._renewed()
            self._exclude(source, symbols, found)

    def _stretch_target(self, shortest: int, longest: int | None = None) -> int:
        """A random start's horizon: uniform from ``shortest`` up to ``longest`` (default the
        horizon limit); the shortest for any other planning, or when it is the longest already."""
        longest = self.settings.max_horizon if longest is None else longest
        if not self.settings.random_start or longest <= shortest:
            return shortest
        return shortest + math.floor(self.stretch * (longest - shortest + 1))

    def _stretched(
        self, base_program: str, state_program: str, horizon: int, deadline: float
    ) -> tuple[clingo.Control, list[clingo.Symbol]] | None:
        """A search for plans of exactly ``horizon`` steps and its first plan; None when none is
        found within STRETCH_CONFLICTS (a timed phase may forbid any)."""
        control = self._control(base_program, state_program)
        for step in range(horizon + 1):
            self._advance(control, step)
        symbols = self._solve(control, deadline, STRETCH_CONFLICTS)
        return None if symbols is None else (control, symbols)

    def first(self) -> Plan:
        for plan in self.plans(limit=1):
            return plan
        raise NoPlanError("no plan")

    def _ground(self, control: clingo.Control, parts) -> None:
        start = time.perf_counter()
        control.ground(parts)
        self._theories[control].prepare(control)
        self.stats["ground_s"] += time.perf_counter() - start

    def _solve(
        self, control: clingo.Control, deadline: float, conflicts: int | None = None
    ) -> list[clingo.Symbol] | None:
        """The shown atoms of the next model; None when there is none, or none within ``conflicts``."""

        def symbols(model: clingo.Model, theory) -> list[clingo.Symbol]:
            return list(model.symbols(shown=True)) + [
                clingo.Function("pos", [symbol.arguments[0], clingo.Number(int(value)), symbol.arguments[1]])
                for symbol, value in theory.assignment(model.thread_id)
                if symbol.name == "p"
            ]

        return self._next_model(control, deadline, "", symbols, conflicts)

    def _next_model(self, control: clingo.Control, deadline: float, where: str, read, conflicts: int | None = None):
        """What ``read(model, theory)`` makes of the next model; None when there is none, or none
        within ``conflicts``. ``where`` ends the time limit's message."""
        start = time.perf_counter()
        answer = None
        theory = self._theories[control]
        if conflicts is not None:  # set only here: touching the configuration changes later searches
            control.configuration.solve.solve_limit = f"{conflicts},umax"
        with control.solve(yield_=True, async_=True) as handle:
            self._wait(handle, deadline, f"planning ran out of its time limit ({self.settings.time_limit:g} s){where}")
            model = handle.model()
            if model is not None:
                theory.on_model(model)
                answer = read(model, theory)
        if conflicts is not None:
            control.configuration.solve.solve_limit = "umax,umax"
        self.stats["solve_s"] += time.perf_counter() - start
        return answer

    def _exclude(self, control: clingo.Control, symbols: list[clingo.Symbol], count: int) -> None:
        """Forbid this exact plan from being found again.

        A plan is a function of its start cells, start speeds, accelerations and lanes, so
        excluding that combination excludes the plan (and only it).
        """
        literals = [
            s for s in symbols if s.name in ("lane", "acc", "zone") or (s.name == "vel" and s.arguments[-1].number == 0)
        ]
        # never this plan again, and prefer choices no earlier plan made: spread plans out instead of
        # enumerating near neighbours (a domain heuristic steers the search, it adds no constraint)
        steer = [
            f"#heuristic {s}. [{count},false]" for s in literals if s.name != "lane" or s.arguments[-1].number == 0
        ]
        self._forbid(control, literals, count, steer)

    def _forbid(
        self, control: clingo.Control, literals: list[clingo.Symbol], count: int, rules: list[str] = ()
    ) -> None:
        """Add and ground, as program part ``exclude_<count>``, a constraint against ``literals``
        holding together, and ``rules`` beside it."""
        name = f"exclude_{count}"
        control.add(name, [], ":- " + ", ".join(map(str, literals)) + ".\n" + "\n".join(rules))
        self._ground(control, [(name, [])])

    def _plan(self, symbols: list[clingo.Symbol], horizon: int, index: int) -> Plan:
        s = self.settings
        cells: dict[tuple[str, int], dict[str, int]] = {}
        transitions: list[tuple[int, int]] = []
        runup_steps = 0
        for symbol in symbols:
            if symbol.name == "runup_time":
                runup_steps = symbol.arguments[0].number
            elif symbol.name in ("pos", "lane", "vel"):
                vehicle, value, step = symbol.arguments
                name = vehicle.string if vehicle.type == clingo.SymbolType.String else vehicle.name
                cells.setdefault((name, step.number), {})[symbol.name] = value.number
            elif symbol.name == "fire":
                transitions.append((symbol.arguments[1].number, symbol.arguments[0].number))
        states = {
            v: [
                PlanState(
                    position=cells[(v, k)]["pos"] * s.grid,
                    lane=cells[(v, k)]["lane"],
                    speed=cells[(v, k)]["vel"] * s.grid / s.dt,
                )
                for k in range(horizon + 1)
            ]
            for v in self.automaton.actors
        }
        transitions.sort()
        stats = dict(self.stats)
        stats["horizon"] = horizon
        return Plan(
            dt=s.dt,
            lanes=self.automaton.lanes,
            states=states,
            transitions=transitions,
            seed=self.seed,
            index=index,
            stats=stats,
            runup=runup_steps * s.dt,
            runup_acceleration=s.runup_acceleration,
            stationary=tuple(v for v in self.automaton.actors if v in self.automaton.stationary),
        )
