"""The grid encoding's planner: the paper's integer grid (``asp/grid/``) under clingo-dl.

Positions are difference-logic variables (``&diff``), speeds, accelerations and lanes atoms of
whole cells per step. The horizon grows one step at a time (``core``); the first horizon with an
answer set gives the shortest plans. Further plans come from the same control: each plan found is
excluded (projected on start cells, speeds, accelerations and lanes), a domain heuristic makes the
search prefer choices no earlier plan made (so plans spread out instead of being near neighbours),
and the solver is asked again, at the same horizon first and then at longer ones. A scenario that
cannot start within the preferred start speeds is planned again with any allowed start speed.
"""

from __future__ import annotations

import dataclasses
import random
from collections.abc import Iterator

import clingo
from clingodl import ClingoDLTheory

from ... import diagnosis
from ...core import ASP_DIR, AUTOMATON, KEEP_LANE, IncrementalPlanner, read_programs
from ...diagnosis import check_satisfiable
from ...errors import CannotReplan, NoPlanError, PlanningTimeout
from ...plan import Plan
from .decode import decode_plan
from .instance import build_instance, start_preferences
from .settings import GridSettings

ASP_GRID = ASP_DIR / "grid"
BACKGROUND = (
    ASP_GRID / "dynamics.lp",
    ASP_GRID / "domain.lp",
    AUTOMATON,
    ASP_DIR / "guards.lp",
    ASP_GRID / "guards.lp",
    ASP_GRID / "rates.lp",  # inert without keep_speed()
)
INITIAL = "initial.lp"  # the rules of the initial state, after the instance's facts (see control_for)
PREFERENCES = (ASP_GRID / "preferences.lp", KEEP_LANE)  # loaded for a random start only, in this order
# conflicts a random start may spend stretching its plan past the shortest horizon: random
# preferences now and then lead the search into a long detour, and a count of conflicts, unlike a
# time limit, ends it at the same point on every machine (past it the plan keeps the shortest horizon)
STRETCH_CONFLICTS = 50_000


def background_theory() -> str:
    """The grid encoding's background program: its dynamics and domain rules, the automaton's run and the guards."""
    return read_programs(*BACKGROUND)


class GridPlanner(IncrementalPlanner):
    """Plans for one automaton on the grid; ``plans()`` yields them lazily, shortest horizon first
    (but for a random start, whose first plans have a random horizon)."""

    def __init__(self, automaton, settings: GridSettings | None = None, seed: int = 0) -> None:
        super().__init__(automaton, settings or GridSettings(), seed)

    def instance_for(self, settings, relaxable: bool = False) -> str:
        return build_instance(self.automaton, settings, relaxable)

    def _start_preferences(self, draw: random.Random) -> str:
        """A random start's draws, as this encoding's rules."""
        return start_preferences(self.automaton, self.settings, draw)

    def control_for(self, instance: str) -> clingo.Control:
        control = self._new_control()
        self._theories[control] = theory = ClingoDLTheory()
        theory.register(control)
        initial = read_programs(ASP_GRID / INITIAL)
        self._add(
            control,
            background_theory() + "\n#program base.\n" + instance + "\n" + initial,
        )
        if self.preferences:
            self._add(
                control,
                "#program base.\n" + self.preferences + read_programs(*PREFERENCES),
            )
        return control

    def plans(self, limit: int | None = None, deadline: float | None = None) -> Iterator[Plan]:
        """Plans with start speeds in ``initial_speed`` first; when there is none up to the horizon
        limit, plans that start at any allowed speed (``widen_initial_speed``). The first plan is
        due by ``deadline`` (default: the time limit from now), both programs together."""
        check_satisfiable(self.automaton)
        deadline = self._renewed(deadline)
        programs = [lambda: self.instance]
        if (wide := self.widened()) is not None:
            programs.append(lambda: self.instance_for(wide))
        # the paper's encoding plans as the paper did: least action (asp/least_action.lp) is the
        # continuous encoding's: the grid has no rule against closing in at a plan's end, and least
        # action's plans can end in a collision after it (docs/decisions.md)
        self.least_action = False
        self.stats["least_action"] = 0.0
        for program in programs:
            try:
                # a program that yields any plan ends without NoPlanError, so this is the last try
                yield from self._plans(program(), limit, deadline)
                return
            except PlanningTimeout:
                raise
            except NoPlanError as error:
                last = error
        if not self.settings.explain_unsatisfiable:
            raise last
        diagnosis.raise_reason(self, last, deadline)

    def replan(self, past, shortest: int) -> Plan | None:
        """Cannot (``GridSettings.replanning`` is False): the grid plans from a run-up at the start."""
        raise CannotReplan("the grid encoding does not replan from an observed state: use the continuous encoding")

    def widened(self) -> GridSettings | None:
        """The settings with any allowed start speed, when that is wider than the first try."""
        wide = dataclasses.replace(self.settings, initial_speed=(self.settings.min_speed, self.settings.max_speed))
        if not self.settings.widen_initial_speed or wide.initial_speeds() == self.settings.initial_speeds():
            return None
        return wide

    def _plans(self, instance: str, limit: int | None, deadline: float) -> Iterator[Plan]:
        control = self.control_for(instance)
        horizon = 0
        found = 0
        self.advance(control, horizon)
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
                    self.advance(control, horizon)
                    continue
                source, plan_horizon = control, horizon
                target = self._stretch_target(horizon)
                if found == 0 and target > horizon:
                    longer = self._stretched(instance, target, deadline)
                    if longer is not None:
                        source, symbols = longer
                        stretched = (source, target)
                        plan_horizon = target
            self.stats["rules"] = float(source.statistics.get("problem", {}).get("lp", {}).get("rules", 0))
            plan = decode_plan(symbols, plan_horizon, found, self.automaton, self.settings, self.seed, self.stats)
            found += 1
            yield plan
            deadline = self._renewed()
            self._exclude(source, symbols, found)

    def _stretched(
        self, instance: str, horizon: int, deadline: float
    ) -> tuple[clingo.Control, list[clingo.Symbol]] | None:
        """A search for plans of exactly ``horizon`` steps and its first plan; None when none is
        found within STRETCH_CONFLICTS (a timed phase may forbid any)."""
        control = self.control_for(instance)
        for step in range(horizon + 1):
            self.advance(control, step)
        symbols = self._solve(control, deadline, STRETCH_CONFLICTS)
        return None if symbols is None else (control, symbols)

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
