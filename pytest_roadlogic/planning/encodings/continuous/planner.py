"""The continuous encoding's planner (``asp/continuous/``), the default.

Positions, speeds and accelerations are real numbers in linear constraints that ``linear.py``
checks lazily with HiGHS (or clingo-lpx, ``theory="lpx"``, kept to compare); ASP decides the
automaton's run (``asp/automaton.lp``, shared with the grid encoding), lanes, and the order of
vehicles that share a lane.

Plans come shortest first, within the window of horizons the durations allow (``window.py``);
each further plan excludes the transition times and lanes of those before it and steers the start
speeds elsewhere; a random start draws start lanes and speeds as preferences (``preferences.py``).
A plan has no run-up: the simulation starts in its first state. A scenario without a plan is
explained by the shared diagnosis over the window's horizons.
"""

from __future__ import annotations

import functools
import math
import random
from collections.abc import Iterator
from dataclasses import dataclass, field

import clingo
from clingo.ast import ASTType, ProgramBuilder, parse_string

from ....logic.automaton import SymbolicAutomaton
from ... import diagnosis
from ...core import ASP_DIR, AUTOMATON, KEEP_LANE, LEAST_ACTION, IncrementalPlanner, read_programs
from ...diagnosis import check_satisfiable
from ...errors import HorizonTooShort, NoPlanError, PlanningTimeout
from ...live_rules import Annotated, live_statements, names_in, program_gives
from ...plan import Plan
from ...protocol import Past
from .decode import decode_plan
from .idle import GuardTree, idle_guards
from .instance import build_continuous_instance, decimal
from .linear import LazyLinearTheory, theory_program
from .preferences import farthest, start_preferences
from .replan import past_facts
from .settings import ContinuousSettings

ASP_CONTINUOUS = ASP_DIR / "continuous"
BACKGROUND = (
    AUTOMATON,
    ASP_DIR / "guards.lp",
    ASP_CONTINUOUS / "dynamics.lp",
    ASP_CONTINUOUS / "guards.lp",
    ASP_CONTINUOUS / "steer.lp",
    LEAST_ACTION,
)
# read only by the scenarios that use them (each is inert without its facts, and every file
# grounded costs each ground call its statements)
RATES = ASP_CONTINUOUS / "rates.lp"  # a bound over a timed phase (an acceleration, a distance, a kept speed)
TOWARD = ASP_CONTINUOUS / "toward.lp"  # a target speed (CARLA's speed(v))
REPLAN = ASP_CONTINUOUS / "replan.lp"  # a replan's facts (reactive/replanner.py)
ROUTE = ASP_CONTINUOUS / "route.lp"  # a map's route (roads/route.py)
RANDOM_START = (KEEP_LANE, ASP_CONTINUOUS / "start.lp")  # loaded for a random start only, in this order
# the soft rows clingo-lpx, which checks every row exactly, cannot weigh: a preference binds as a
# row, a random start's nudges and drifts are left out
SOFT = {"prefer": "sum", "nudge": None, "drift": None, "steady": None}
# conflicts a random start's search at its drawn horizon may spend before the shortest horizon's
# plans are taken instead: a count, not a time, so that every machine stops at the same point (the
# grid's 50 000 are about 2 s there; each conflict here may cost a linear program)
STRETCH_CONFLICTS = 2_000
# what the shortest-first search in which every vehicle does only what it is asked may spend
# proving horizons empty, all of them together, before the search that allows the fewest unasked
# changes takes over: conflicts (read after each horizon's solve, so the last may overrun them) and
# horizons. A scenario with no such plan at any horizon (a car behind a lead braking harder than it
# can brake, asked nothing) would otherwise prove every horizon up to the limit empty, each with
# few conflicts. Counts, not times, so that every machine gives up at the same point; the searches
# that find such a plan spend a few hundred conflicts and half a dozen horizons.
LEAST_ACTION_CONFLICTS = 2_000
LEAST_ACTION_HORIZONS = 12
# how near a target (m/s) a speed entering its phase is taken to lie on neither side of it
SIDE = 1e-4
# how many times a model's idle guards are set aside (a new model may hold others idle)
IDLE_ROUNDS = 3


@dataclass
class _Beside:
    """What the search that holds every vehicle to what it is asked learns, beside itself, of the
    search that allows unasked changes (``plans``): the horizons at which that one has no plan,
    whether it has one at the last horizon asked (nothing more to ask), and the first horizon
    the durations allow."""

    empty: set[int] = field(default_factory=set)
    has_plan: bool = False
    earliest: int | None = None


def exact_rows(statement, add) -> None:
    """``add`` the statement as clingo-lpx reads it: a soft row of the linear program (``SOFT``)
    becomes a hard one, or is left out (a rewrite of the parsed program, not of its text)."""
    head = getattr(statement, "head", None)
    if head is not None and head.ast_type == ASTType.TheoryAtom and head.term.name in SOFT:
        name = SOFT[head.term.name]
        if name is None:
            return
        statement = statement.update(head=head.update(term=head.term.update(name=name)))
    add(statement)


@functools.cache
def parsed_encoding(paths: tuple, with_theory: bool = False) -> tuple:
    """The statements of the encoding files ``paths`` (after the linear theory's ``#theory`` with
    ``with_theory``), parsed once per process: every sample's controls add the same ones. Why:
    parsing the encoding was a twentieth of a small scenario's planning per sample."""
    text = (theory_program() if with_theory else "") + read_programs(*paths)
    statements: list = []
    parse_string(text, statements.append)
    return tuple(statements)


@functools.cache
def annotated_encoding(paths: tuple, with_theory: bool = False) -> Annotated:
    """``parsed_encoding`` with what each statement needs and gives (``live_rules``), read once."""
    return Annotated.of(parsed_encoding(paths, with_theory))


class ContinuousPlanner(IncrementalPlanner):
    """Plans for one automaton with the continuous encoding; ``plans()`` yields them lazily,
    shortest first (a random start's first at a drawn horizon)."""

    def __init__(self, automaton: SymbolicAutomaton, settings: ContinuousSettings | None = None, seed: int = 0) -> None:
        super().__init__(automaton, settings or ContinuousSettings(), seed)  # type: ignore[arg-type]
        # a replan's past as facts (replan.py), the program part ``past`` that asp/continuous/replan.lp
        # reads; empty for a plan from the start
        self.past = ""

    def base_parts(self) -> list[tuple[str, list]]:
        return [("base", []), *([("past", [])] if self.past else [])]

    def instance_for(self, settings, relaxable: bool = False) -> str:
        return build_continuous_instance(self.automaton, settings, relaxable)

    def _start_preferences(self, draw: random.Random) -> str:
        return start_preferences(self.automaton, self.settings, draw)

    def widened(self):
        return None  # every start speed the settings allow is tried at once

    def encoding_files(self) -> tuple:
        """The encoding's files this planner grounds: ``BACKGROUND`` and those of the extensions
        its scenario, settings and replan use, in one order for every control."""
        toward = any(location.targets() for location in self.automaton.locations)
        rates = any(timing.rates for timing in self.automaton.timings.values())
        return (
            *BACKGROUND,
            *((RATES,) if rates else ()),
            *((TOWARD,) if toward else ()),
            *((REPLAN,) if self.past else ()),
            *((ROUTE,) if self.settings.route_span is not None else ()),
        )

    def control_for(self, instance: str):
        control = self._new_control()
        own = "\n#program base.\n" + instance + "\n" + self.preferences
        if self.past:
            own += "\n#program past.\n" + self.past
        if self.settings.theory != "lpx":
            theory = LazyLinearTheory()
            theory.register(control)
            self._theories[control] = theory
            # the encoding is the same for every control: parsed once per process; its rules
            # that cannot fire for this instance are left out (live_rules)
            start = annotated_encoding(RANDOM_START) if self.settings.random_start else Annotated.of(())
            own_names = names_in(own)
            encoding = live_statements(
                annotated_encoding(self.encoding_files(), with_theory=True), own_names.union(*start.given)
            )
            with ProgramBuilder(control) as builder:
                for statement in encoding:
                    builder.add(statement)
                parse_string(own, builder.add)
                for statement in live_statements(start, own_names | program_gives(encoding)):
                    builder.add(statement)
            return control
        from clingolpx import ClingoLPXTheory

        program = read_programs(*self.encoding_files()) + own
        if self.settings.random_start:
            program += "\n" + read_programs(*RANDOM_START)
        theory = ClingoLPXTheory()
        for key, value in self.settings.lpx_options:
            theory.configure(key, value)

        def add(statement):
            exact_rows(statement, lambda kept: theory.rewrite_ast(kept, builder.add))

        theory.register(control)
        self._theories[control] = theory
        with ProgramBuilder(control) as builder:
            parse_string(program, add)
        return control

    def plans(self, limit: int | None = None, deadline: float | None = None) -> Iterator[Plan]:
        """Plans, shortest horizon first; each next one differs from all before it in when a
        transition fires or in a lane (the linear program then gives its smoothest motion).
        Every vehicle does only what its own constructs ask (``least_action``) unless no plan
        does: then plans with the fewest and smallest changes nothing asks (``least_change``),
        which say so in their stats. Past its first horizon, the first search asks at each
        horizon, on its own control, whether the second has a plan there, until one has: where
        the second has none, neither has the first, and the second, if it runs, steps over those
        horizons in one ground call instead of one call and one solve each (docs/decisions.md).
        The first plan is due by ``deadline`` (default: the time limit from now), both searches
        together."""
        check_satisfiable(self.automaton)
        self.least_action, self.least_change = True, False
        beside = _Beside()
        try:
            yield from self._search(limit, deadline, beside)
        except (PlanningTimeout, HorizonTooShort):
            raise  # the time is spent, or a setting binds: a search allowing unasked changes fares no better
        except NoPlanError:
            self.least_change = True
            yield from self._search(limit, self._deadline, beside)  # no plan yet: the first one's deadline holds

    def _search(
        self, limit: int | None, deadline: float | None = None, beside: _Beside | None = None
    ) -> Iterator[Plan]:
        """The plans of one search (``plans``), with ``least_action`` and ``least_change`` as they
        are set. The first search fills ``beside`` (what it learnt of the second); the second
        reads it."""
        beside = _Beside() if beside is None else beside
        deadline = self._renewed(deadline)
        strict = self.least_action and not self.least_change
        self.stats["least_action"] = float(strict)
        found = 0
        places: list[float] = []  # where in the start band each plan after the first was steered
        try:
            window = self.window(deadline)
            # the search starts at the automaton's floor, where most scenarios can end
            # (planning/window.py); the window's own solver is asked only when no plan ends there,
            # or when the floor is past the horizon limit: one solve less for the common case
            checked = window.floor > self.settings.max_horizon
            earliest = self._earliest(deadline, window) if checked else window.floor
            earliest = max(earliest, self.shortest)
            if not strict and beside.earliest is not None:
                checked, earliest = True, beside.earliest  # as the first search found it
            control = None  # the shortest-first search's, grounded when first asked
            horizon = earliest
            skipped = beside.empty if not strict else set()  # horizons known to have no plan
            # a random start's plans come from a search of their own at a drawn, longer horizon as
            # long as it answers within STRETCH_CONFLICTS (as the grid planner's do: _plans). The
            # first is drawn from the durations' floor and tried before any shorter horizon is
            # solved: where it answers, the shortest-first search is never grounded
            stretched = None  # (control, horizon)
            # the conflicts left to the shortest-first search (LEAST_ACTION_CONFLICTS): for the
            # search that holds every vehicle to what it is asked, when another search follows it
            budget = LEAST_ACTION_CONFLICTS if strict else None
            empty = 0  # horizons the shortest-first search proved empty
            target = self._stretch_target(earliest)
            if target > earliest and target not in skipped and window.open_at(target):
                stretched = (self.control_for(self.instance), target)
                self.advance_to(stretched[0], target)
            while limit is None or found < limit:
                if stretched is not None:
                    answer = self._model(stretched[0], deadline, f"at horizon {stretched[1]}", STRETCH_CONFLICTS)
                    if answer is None:
                        stretched = None
                        continue
                    source, plan_horizon = stretched
                else:
                    if control is None and horizon in skipped:
                        horizon = _first_not_in(skipped, horizon)
                        if horizon > self.settings.max_horizon or window.past_end(horizon):
                            break
                    if control is None:
                        control = self.control_for(self.instance)
                        self.advance_to(control, horizon)
                    # each solve unlimited (a solve limit set on the control changes its later
                    # searches, hence the plans): the budget is read between them. Past its first
                    # horizon, the search with only asked changes first asks whether the one that
                    # allows unasked changes has a plan at this one: where it has none, neither
                    # has this one
                    if strict and found == 0 and empty and not beside.has_plan:
                        asked_empty = not self._ask_beside(control, deadline, horizon, beside)
                    else:
                        asked_empty = False
                    answer = None if asked_empty else self._model(control, deadline, f"at horizon {horizon}")
                    if answer is None and budget is not None:
                        budget -= int(control.statistics["solving"]["solvers"]["conflicts"])
                        empty += 1
                        if budget <= 0 or empty >= LEAST_ACTION_HORIZONS:
                            if checked:  # else the second search asks the durations itself
                                beside.earliest = earliest
                            raise NoPlanError(
                                f"no plan in which every vehicle does only what it is asked within "
                                f"{LEAST_ACTION_CONFLICTS} conflicts and {LEAST_ACTION_HORIZONS} horizons, "
                                f"at horizons up to {horizon}"
                            )
                    if answer is None and not checked:
                        checked, grounded = True, horizon
                        earliest = horizon = max(horizon, self._earliest(deadline, window))
                        if horizon > grounded:
                            self.advance_to(control, horizon, grounded)
                            continue
                    if answer is None:
                        if strict and found == 0:
                            beside.earliest = earliest
                        # one question, not the whole window's bisection (5 solves, a fifth of
                        # change_lane's first plan): open_at is monotone, so a run not under way at
                        # this horizon is under way at no later one
                        later = _first_not_in(skipped, horizon + 1)
                        if later > self.settings.max_horizon or window.past_end(later):
                            break  # no run of the automaton lasts longer: no longer plan either
                        if later == horizon + 1:
                            self.advance(control, later)
                        else:
                            self.advance_to(control, later, horizon)  # in one call past those known empty
                        horizon = later
                        continue
                    source, plan_horizon = control, horizon
                    target = self._stretch_target(horizon)
                    if found == 0 and target > horizon and window.open_at(target):
                        longer = self.control_for(self.instance)
                        self.advance_to(longer, target)
                        longer_answer = self._model(longer, deadline, f"at horizon {target}", STRETCH_CONFLICTS)
                        if longer_answer is not None:
                            answer, source, plan_horizon = longer_answer, longer, target
                            stretched = (longer, target)
                symbols, values = answer
                self.stats["horizon"] = plan_horizon
                yield decode_plan(
                    symbols, values, plan_horizon, found, self.automaton, self.settings, self.seed, self.stats
                )
                deadline = self._renewed()
                window.wait = self._waiter(deadline)
                found += 1
                self._exclude(source, symbols, found, self._steering(places))
            if found:
                return
            last_open = window.last_open(self.settings.max_horizon)
            if last_open is None:
                raise NoPlanError(
                    f"no plan satisfies the scenario within {self.settings.max_horizon} steps ({self.settings.max_horizon * self.settings.dt:g} s)"
                )
            dt, longest = self.settings.dt, last_open + 1
            lengths = f"{earliest * dt:g} s" if longest <= earliest else f"{earliest * dt:g}..{longest * dt:g} s"
            raise NoPlanError(f"no plan satisfies the scenario in any length its durations allow ({lengths})")
        except (PlanningTimeout, HorizonTooShort):
            raise
        except NoPlanError as error:
            if strict or not self.settings.explain_unsatisfiable:
                raise
            diagnosis.raise_reason(self, error, deadline, window)

    def _ask_beside(self, control, deadline: float, horizon: int, beside: _Beside) -> bool:
        """Whether the search that allows unasked changes has a plan at ``horizon``, asked on the
        control of the one that does not (``plans``); recorded in ``beside``. Its first model
        answers: the best one is the second search's to find, if it runs."""
        message = f"planning ran out of its time limit ({self.settings.time_limit:g} s) at horizon {horizon}"
        self._time_to_prepare(control, deadline, message)
        self.least_change = True
        self._assign_action(control)
        control.configuration.solve.models = "1"
        try:
            with control.solve(yield_=True, async_=True) as handle:
                self.wait(handle, deadline, message)
                beside.has_plan = handle.model() is not None
        finally:
            self.least_change = False
            self._assign_action(control)
        if not beside.has_plan:
            beside.empty.add(horizon)
        return beside.has_plan

    def replan(self, past: Past, shortest: int) -> Plan | None:
        """The first plan from ``past`` on (``asp/continuous/replan.lp`` reads its facts, the
        program part ``past``), at least ``shortest`` steps long. A planner replans once."""
        self.past = past_facts(past)
        self.shortest = shortest
        return next(self.plans(limit=1), None)

    def _earliest(self, deadline: float, window) -> int:
        """The first horizon the durations allow (``needed_horizon``); ``NoPlanError`` when none does."""
        earliest = self.needed_horizon(deadline, window)
        if earliest is None:
            raise NoPlanError(
                f"the phases' durations cannot all hold at any length, in steps of {self.settings.dt:g} s"
            )
        return earliest

    def _stretch_target(self, shortest: int, longest: int | None = None) -> int:
        """As the grid planner's, but never past ``stretch_limit``."""
        cap = min(self.settings.max_horizon, math.floor(self.settings.stretch_limit / self.settings.dt + 1e-9))
        return super()._stretch_target(shortest, cap if longest is None else min(longest, cap))

    def _model(
        self, control, deadline: float, where: str, conflicts: int | None = None
    ) -> tuple[list, dict[str, object]] | None:
        """(shown symbols, the linear program's values) of the next model; None when there is none,
        or none within ``conflicts``. The model's run and lanes as found, its values as the scenario
        asks them (``_refined``)."""

        lazy = self.settings.theory != "lpx"

        def answer(model, theory) -> tuple[list, dict[str, object], tuple]:
            values = {str(key): value for key, value in theory.assignment(model.thread_id)}
            cost = (*model.cost, theory.cost(model.thread_id) if lazy else 0.0)
            return list(model.symbols(shown=True)), values, cost

        found = self._next_model(control, deadline, f" {where}", answer, conflicts)
        if found is not None and lazy:
            found = self._refined(
                control,
                found,
                lambda assumed: self._next_model(control, deadline, f" {where}", answer, conflicts, assumed),
            )
        return None if found is None else found[:2]

    @functools.cached_property
    def _guard_tree(self) -> GuardTree:
        """The automaton's guard nodes as the instance numbers them (built once per planner)."""
        return GuardTree(self.automaton)

    def _refined(self, control, found: tuple, solve) -> tuple:
        """``found`` (a model's symbols, values and costs), or the model of the same run and lanes
        (its ``fire`` and ``lane`` atoms assumed; ``solve(assumptions)`` gives it) whose values
        hold only what the scenario asks of them: without idle guards (in a plan from the start),
        then with each target speed approached from the side it lies on."""
        kept: list[tuple[clingo.Symbol, bool]] = [(s, True) for s in found[0] if s.name in ("fire", "lane")]
        # a replan keeps the guards its model holds: it starts past the start's guards, and a
        # second solve at every replan period of a reactive case costs more than it mends
        if not self.past:
            found, kept = self._without_idle_guards(found, kept, solve)
        found, kept = self._sides_weighed(found, kept, solve)
        return self._directions_weighed(found, kept, solve)

    def _sides_weighed(self, found: tuple, kept: list, solve) -> tuple[tuple, list]:
        """``found`` and its assumptions ``kept``, each phase held at one speed before a later
        target (``asp/continuous/toward.lp``'s ``held_phase/2``) driven on the side of that target
        that costs less. Which side (above or below the later target) is the solver's choice, made
        before any speed is known; a wrong guess holds the phase's speed on the far side of the
        target, and the vehicles around it pay for that (a car asked to start at 20 kph starting at
        11 kph so that the held one need not be faster)."""
        kept = list(kept)
        chosen = {(s.arguments[0], s.arguments[1]) for s in found[0] if s.name == "above_later"}
        for phase in sorted((s for s in found[0] if s.name == "held_phase"), key=str):
            side = clingo.Function("above_later", list(phase.arguments))
            above = tuple(phase.arguments) in chosen
            found, kept = _cheaper(found, kept, (side, above), (side, not above), solve)
        return found, kept

    def _without_idle_guards(self, found: tuple, kept: list, solve) -> tuple[tuple, list]:
        """``found`` and its assumptions ``kept``, or the model with its idle guards (``idle.py``:
        a bound the solver set where no transition or invariant needs it) assumed false and the
        assumptions that give it, when it costs no more. Their rows held the vehicles to a place
        or speed nothing asks there: a car placed 15 m behind another at the start held there a
        step longer, then jumping to its speed. A new model may hold others idle: a few rounds."""
        for _ in range(IDLE_ROUNDS):
            idle = [(guard, False) for guard in idle_guards(self._guard_tree, found[0])]
            if not idle:
                break
            tried = solve(kept + idle)
            if tried is None or tried[2] > found[2]:
                break
            found, kept = tried, kept + idle
        return found, kept

    def _directions_weighed(self, found: tuple, kept: list, solve) -> tuple:
        """``found``, or a cheaper model (``kept`` assumed) in which a target speed's phase starts
        toward its band from the other side.

        Which way a target speed (CARLA's ``speed(v)``, ``asp/continuous/toward.lp``) is approached
        is the solver's choice at the phase's first step, made before the speeds are known: rising
        needs the speed entering the phase at most the band's top, falling at least its bottom. A
        wrong guess is met by the linear program bringing the entering speed to the target before
        the phase begins: the phase before changes the vehicle's speed for this one, which nothing
        there asks. Where the entering speed does not lie below the target for a rising phase
        (above it for a falling one), the other way is tried and kept when its model costs less:
        the solver's own costs first (the least unasked changes), then the smoothing's."""
        kept = list(kept)
        entries = sorted((s for s in found[0] if s.name == "toward_entry"), key=lambda s: s.arguments[3].number)
        for entry in entries:
            vehicle, way, target, step = entry.arguments
            entering = found[1].get(f"v({vehicle},{step.number - 1})")
            if entering is None:
                continue
            rising = way.name == "up"
            below = float(entering) < float(target.string) - SIDE
            above = float(entering) > float(target.string) + SIDE
            if (rising and below) or (not rising and above):
                continue
            way = clingo.Function("rising" if rising else "falling", [vehicle, step])
            other = clingo.Function("falling" if rising else "rising", [vehicle, step])
            found, kept = _cheaper(found, kept, (way, True), (other, True), solve)
        return found

    def _exclude(self, control, symbols, count: int, place: float | None = None) -> None:
        """Never these transition times and lanes together again; the next plan's driving vehicles
        are nudged to start at ``place`` (m/s, ``_steering``; ``asp/continuous/steer.lp``)
        instead of where the plan before was steered."""
        steer = [] if place is None else [("steer", [clingo.Number(count), clingo.String(decimal(place))])]
        self._forbid(control, [s for s in symbols if s.name in ("fire", "lane")], count, parts=steer)
        if steer:
            control.assign_external(clingo.Function("steer", [clingo.Number(count)]), True)
            if count > 1:
                control.assign_external(clingo.Function("steer", [clingo.Number(count - 1)]), False)

    def _steering(self, places: list[float]) -> float | None:
        """The start speed (m/s) that steers the next plan's start speeds away from those of the plans before it,
        as the grid planner's base strategy steered its choices away from every earlier plan's:
        every driving vehicle is nudged to one place of its start band (``road_speed``), the
        place farthest from those of the plans before (``farthest``: the first plan's is the
        band's low end, then the high end, the middle, the quarters...). A nudge of the linear
        program, so a scenario's own speeds decide where they bind; switched on by
        ``steer(count)`` for this plan only. ``places`` is the places so far, and grows.

        Why: exclusion alone changes a plan's transition times and lanes, and the linear program
        then gives every plan the same smoothest values: the base strategy's ten plans of
        overtake all started at 8 m/s, alike but for their lanes (mean similarity 0.507 against
        the grid's 0.391). One place for all vehicles, not one each: the scenario often ties their
        speeds together (an overtaker faster than the one it passes), which places drawn apart
        would pull against each other. Places are not moved by what a plan reached: a speed the
        scenario caps in one plan (dodge_obstacle's ego, at most 20 m/s at 4 steps) may be free in
        the next, and bands shrunk to the speeds reached ended overtake's plans at 8 m/s."""
        if self.settings.theory != "lazy":
            return None  # clingo-lpx has no preferences
        low, high = self.settings.start_band()
        place = farthest([0.0, *places], 0.0, 1.0)  # the first plan, unsteered, starts low
        places.append(place)
        return round(low + place * (high - low), 1)


def _cheaper(found: tuple, kept: list, chosen: tuple, other: tuple, solve) -> tuple[tuple, list]:
    """``found`` (a model's symbols, values and costs) or the model ``solve`` gives with ``other``
    assumed beside ``kept`` instead of ``chosen`` (each ``(atom, truth)``: one choice of the
    solver, either way), whichever costs less; and ``kept`` with the choice taken."""
    tried = solve([*kept, other])
    if tried is not None and tried[2] < found[2]:
        return tried, [*kept, other]
    return found, [*kept, chosen]


def _first_not_in(skipped: set[int], horizon: int) -> int:
    """The first horizon from ``horizon`` on that is not in ``skipped``."""
    while horizon in skipped:
        horizon += 1
    return horizon
