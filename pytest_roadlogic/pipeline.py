"""The stages chained for one scenario: build the automaton, plan, simulate, monitor; retry on rejection.

As in the paper, a simulation that the monitor rejects is discarded and the planner is asked for
its next plan, up to ``max_tries`` times. Every stage is timed. The strategies (which cases to
run, how they end, what is reported) are ``runner``'s; this module is usable alone from Python:

    outcome = run_scenario(load_scenario("scenarios/overtake.osc"), seed=1)
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from .automaton import SymbolicAutomaton, build_automaton
from .frontend import CheckedScenario, load_file
from .monitor import Verdict, monitor
from .planning import Plan, PlanningSettings, settings_for
from .sampling import guided, sample_seed
from .settings import DEFAULT_SIM_TIMEOUT, RunSettings
from .simulation import DriverFactory, Simulation, SimulationLimits, Simulator

if TYPE_CHECKING:
    from .planning.continuous import ContinuousSettings

MAX_TRIES = 5


@dataclass
class SimulatedInstance:
    """One simulated instance: its plan, simulation and verdict (the last of its tries)."""

    scenario: CheckedScenario
    automaton: SymbolicAutomaton
    plan: Plan
    simulation: Simulation
    verdict: Verdict
    tries: int
    seconds: dict[str, float] = field(default_factory=dict)  # stage -> seconds, summed over tries
    instance: int = 0  # its index among the instances of one planner (base strategy)


def load_scenario(
    path: str | Path, name: str | None = None, lanes: int | None = None, dialect: str | None = None, roots=None
) -> CheckedScenario:
    """A checked scenario of ``path`` (the first one with a behavior unless ``name`` is given).

    ``lanes`` overrides the road's lane count, which otherwise comes from the scenario; ``dialect``
    (``settings.DIALECTS``) says how the file is read; ``roots`` (``confinement.ReadRoots``) where
    its imports may be read from (default: the project's root and the file's folder).
    """
    return load_file(path, lanes, dialect=dialect, roots=roots).scenario_to_run(name)


def run_scenario(
    scenario: CheckedScenario,
    seed: int = 1,
    settings: PlanningSettings | ContinuousSettings | None = None,
    max_tries: int = MAX_TRIES,
    drivers: DriverFactory | None = None,
    values: dict[str, object] | None = None,
    simulation_time_limit: float | None = DEFAULT_SIM_TIMEOUT,
    simulator: Simulator | None = None,
) -> SimulatedInstance:
    """One concrete instance of ``scenario``: plan, simulate, monitor, and retry with the next plan on rejection.

    ``values`` (the refined strategy) is a sample of the scenario's logical parameters: the planner
    solves the scenario narrowed to those values, the monitor checks the scenario as written. The
    planner's own free choices (start speeds and lanes, accelerations, how long the scenario lasts)
    are then random too, drawn from a seed made of ``seed`` and the values (``sample_seed``): the
    same sample always gives the same plan, and different samples do not share the solver's habits.
    Without it (the base strategy) the planner chooses every open value itself. ``simulator`` is the
    backend (default: frenetix).
    """
    return next(
        run_instances(scenario, 1, seed, settings, max_tries, drivers, values, simulation_time_limit, simulator)
    )


def run_instances(
    scenario: CheckedScenario,
    count: int,
    seed: int = 1,
    settings: PlanningSettings | ContinuousSettings | None = None,
    max_tries: int = MAX_TRIES,
    drivers: DriverFactory | None = None,
    values: dict[str, object] | None = None,
    simulation_time_limit: float | None = DEFAULT_SIM_TIMEOUT,
    simulator: Simulator | None = None,
    fallbacks: bool = True,
) -> Iterator[SimulatedInstance]:
    """Up to ``count`` instances from one planner, each plan different from all before it (the base strategy).

    Each instance takes plans until the monitor accepts one or ``max_tries`` were rejected; it ends
    early when the planner has no further plan. Planning errors (no plan, a timeout) and
    ``SimulationTimeout`` propagate. ``fallbacks``: when the planner has no plan, try thinner
    margins, a finer step and relaxed limits (``_with_fallbacks``) before saying so.
    """
    from .planning import planner_for
    from .simulation.backends import simulator as default_simulator

    settings = settings or settings_for(RunSettings())  # the default encoding's
    simulator = simulator or default_simulator()
    limits = SimulationLimits(time_limit=simulation_time_limit)
    start = time.perf_counter()
    specification = build_automaton(scenario)
    guide, settings, seed = _guided(scenario, specification, values, settings, seed)
    automaton_seconds = time.perf_counter() - start
    planner = planner_for(guide(settings), settings, seed)
    plans = planner.plans(limit=count * max_tries)
    if fallbacks:
        plans = _with_fallbacks(plans, guide, settings, seed, count * max_tries)
    for instance in range(count):
        seconds = {"automaton": automaton_seconds, "planning": 0.0, "simulation": 0.0, "monitoring": 0.0}
        automaton_seconds = 0.0
        outcome = None
        for tries in range(1, max_tries + 1):
            start = time.perf_counter()
            plan = next(plans, None)
            seconds["planning"] += time.perf_counter() - start
            if plan is None:
                break
            start = time.perf_counter()
            simulation = simulator.simulate(plan, limits, drivers)
            seconds["simulation"] += time.perf_counter() - start
            start = time.perf_counter()
            verdict = monitor(specification, simulation.trace)
            seconds["monitoring"] += time.perf_counter() - start
            outcome = SimulatedInstance(scenario, specification, plan, simulation, verdict, tries, seconds, instance)
            if verdict.accepted:
                break
        if outcome is None:
            return  # the planner has no plan left; the first call raises NoPlanError instead
        if not outcome.verdict.accepted:
            limit = _tool_limit(outcome, guide, settings, seed)
            if limit is not None:
                raise limit
        yield outcome


Guide = Callable[[object], SymbolicAutomaton]  # planner settings -> the automaton they solve


def _guided(
    scenario: CheckedScenario, specification: SymbolicAutomaton, values, settings, seed: int
) -> tuple[Guide, object, int]:
    """The automaton a planner solves for a sample, as a function of that planner's settings
    (``specification`` without a sample), and the settings and seed it solves with: each sample is
    its own random concrete scenario, fixed by the run's seed and the values.

    Why a function: a sample is narrowed to a band that keeps the planner's margins inside its
    parameter's range, which moves a value near an edge inward by the margin. A fallback planner
    with thinner margins must solve for the value itself, not for the first planner's moved one:
    emit_wait_brake's change_speed of 7.8 s (its range 4..8 s, but it must equal the 0.5-1.5 s wait
    plus the 3-5 s lane change) was moved to 6.5-7.5 s, where a plan at 6.5 s exists, and reported
    as a value the scenario meets (measured before this)."""
    if not values:
        return (lambda planner_settings: specification), settings, seed
    guides: dict[tuple, SymbolicAutomaton] = {}

    def guide(planner_settings) -> SymbolicAutomaton:
        resolution, margins = planner_settings.resolution(), planner_settings.margins()
        key = (tuple(sorted(resolution.items(), key=str)), tuple(sorted(margins.items(), key=str)))
        if key not in guides:
            narrowed, declared = guided(scenario, values, resolution, margins)
            guides[key] = build_automaton(narrowed, values=declared)
        return guides[key]

    return guide, dataclasses.replace(settings, random_start=True), sample_seed(seed, values)


def has_plan(
    scenario: CheckedScenario,
    values: dict[str, object],
    seed: int = 1,
    settings: PlanningSettings | ContinuousSettings | None = None,
    fallbacks: bool = True,
    beyond_limits: bool = True,
) -> bool:
    """Whether the scenario narrowed to ``values`` has a plan (planning alone: no simulation), with
    every fallback ``run_instances`` tries or, without ``fallbacks``, within the planner's margins
    and limits; without ``beyond_limits``, the fallbacks stay within a real car's limits
    (``CAR_LIMITS`` are never relaxed). A planning timeout or a horizon that binds is no proof that
    the values have none, and counts as a plan."""
    from .planning import HorizonTooShort, NoPlanError, PlanningTimeout, planner_for

    settings = dataclasses.replace(settings or settings_for(RunSettings()), explain_unsatisfiable=False)
    guide, settings, seed = _guided(scenario, build_automaton(scenario), values, settings, seed)
    try:
        plans = planner_for(guide(settings), settings, seed).plans(limit=1)
        return (
            next(_with_fallbacks(plans, guide, settings, seed, 1, beyond_limits) if fallbacks else plans, None)
            is not None
        )
    except (PlanningTimeout, HorizonTooShort):
        return True
    except NoPlanError:
        return False


# the vehicle limits a plan is tried without, when none exists within them: (field, relaxed value,
# unit). The relaxed values are beyond any car's, so a plan that needs them names the limit. The
# gap between two cars in one lane is the planner's too: 8 m between centres is 3.5 m between
# bumpers, and a scenario may ask for less (cut_out_obstacle stops the ego 5-15 m behind a wreck,
# which had been reported as a value no concrete scenario has); relaxed, 0.5 m between bumpers
RELAXED_LIMITS = (
    ("max_jerk", 50.0, "m/s^3"),
    ("min_acceleration", -20.0, "m/s^2"),
    ("max_acceleration", 12.0, "m/s^2"),
    ("max_speed", 100.0, "m/s"),
    ("closing_time", 0.0, "s"),
    ("min_gap", 5.0, "m"),
)
# of those, a real car's: a plan that needs one of them relaxed asks more than a car can do, so
# its values have no concrete scenario (the scenario's, not the tool's; follow_then_overtake's
# 19 s pass ending 15 m ahead after starting 39 m behind needs a 27 m drop back in 3 s). The others
# (the gap between cars) are how closely the tool dares to plan cars: settings of the tool
CAR_LIMITS = frozenset({"max_jerk", "min_acceleration", "max_acceleration", "max_speed"})
ALL_LIMITS = frozenset(name for name, _, _ in RELAXED_LIMITS)
SPACING = ALL_LIMITS - CAR_LIMITS


def _relaxed(settings, names=None):
    """``settings`` with the ``RELAXED_LIMITS`` named (all by default) relaxed."""
    return dataclasses.replace(
        settings, **{name: value for name, value, _ in RELAXED_LIMITS if names is None or name in names}
    )


def _relaxed_names(settings, names=None) -> list[str]:
    return [
        f"{name} {getattr(settings, name):g} {unit} relaxed to {value:g}"
        for name, value, unit in RELAXED_LIMITS
        if names is None or name in names
    ]


def _tool_limit(outcome: SimulatedInstance, guide: Guide, settings, seed: int):
    """The error that says which setting of the tool binds, when the rejected ``outcome`` was
    planned by one of ``_with_fallbacks``'s planners; None for a plan within every setting."""
    from .planning import LimitsBind, MarginsBind, StepBinds

    explanation = outcome.verdict.explain()
    if outcome.plan.stats.get("thinned_margins"):
        return MarginsBind(settings.describe_margins(), settings.thinned().describe_margins(), explanation)
    if outcome.plan.stats.get("finer_step"):
        return StepBinds(
            f"no plan in steps of {settings.dt:g} s; plans in steps of {settings.dt / 2:g} s exist, so the scenario itself "
            f"can be met at these values, but their simulation was not accepted (the planning step is a setting of the tool): "
            f"{explanation}"
        )
    if outcome.plan.stats.get("relaxed_limits"):
        names = _binding_limits(guide, settings, seed)
        return LimitsBind(
            _relaxed_names(settings, names), explanation=explanation, beyond_a_car=bool(names & CAR_LIMITS)
        )
    return None


def _binding_limits(guide: Guide, settings, seed: int) -> frozenset[str]:
    """The vehicle limits without which the sample has a plan (with the thinner margins): one at a
    time first, so that the report names the one that binds; then a car's limits alone, the
    spacing alone, all together; all of them when even that gives none."""
    from .planning import NoPlanError, planner_for

    settings = dataclasses.replace(settings.thinned() or settings, explain_unsatisfiable=False)

    def plannable(names) -> bool:
        try:
            relaxed = _relaxed(settings, names)
            return next(planner_for(guide(relaxed), relaxed, seed).plans(limit=1), None) is not None
        except NoPlanError:
            return False

    for names in (*(frozenset({name}) for name, _, _ in RELAXED_LIMITS), CAR_LIMITS, SPACING):
        if plannable(names):
            return names
    return ALL_LIMITS


def _with_fallbacks(
    plans: Iterator[Plan], guide: Guide, settings, seed: int, limit: int, beyond_limits: bool = True
) -> Iterator[Plan]:
    """``plans``, or, when the planner has none at all, those of a planner that keeps
    ``settings.fallback_margins`` of its margins (``stats["thinned_margins"]``), or else those of
    one that also plans in half the step (``stats["finer_step"]``), or else of one that drives
    beyond the vehicle limits (``RELAXED_LIMITS``, ``stats["relaxed_limits"]``; without
    ``beyond_limits`` only the spacing between cars is relaxed, never ``CAR_LIMITS``). Each
    planner solves the sample narrowed with its own margins (``guide``).

    Why: the margins and the limits are the planner's guesses at what the vehicles can track, not
    the scenario's constraints; a plan nearer the scenario's edges is simulated and monitored like
    any other, and an accepted simulation is an instance of the scenario. A scenario with no plan
    even then raises the first planner's error: its constraints clash."""
    from .planning import HorizonTooShort, NoPlanError, PlanningTimeout, planner_for

    try:
        first = next(plans, None)
    except NoPlanError as error:
        thinned = settings.thinned() if hasattr(settings, "thinned") else None
        if thinned is None or isinstance(error, (PlanningTimeout, HorizonTooShort)):
            raise
        quiet = dataclasses.replace(thinned, explain_unsatisfiable=False)
        # half the planning step: durations between whole seconds (a 0.5 s wait, a 3.6 s brake)
        finer = dataclasses.replace(
            quiet, dt=quiet.dt / 2, max_horizon=quiet.max_horizon * 2, lane_change_gap=quiet.lane_change_gap * 2
        )
        # the spacing first, then a car's limits too: a plan within a car's limits is one a car can
        # drive (cut_out_obstacle's stop 5 m behind its wreck, planned with every limit relaxed,
        # braked with a jerk of 4 m/s^3 and its simulated ego hit the wreck)
        relaxed = [(_relaxed(quiet, SPACING), "relaxed_limits")] + (
            [(_relaxed(quiet), "relaxed_limits")] if beyond_limits else []
        )
        for fallback_settings, mark in ((quiet, "thinned_margins"), (finer, "finer_step"), *relaxed):
            try:
                fallback = planner_for(guide(fallback_settings), fallback_settings, seed).plans(limit=limit)
                plan = next(fallback, None)
            except NoPlanError:
                continue
            while plan is not None:
                plan.stats[mark] = 1.0
                yield plan
                plan = next(fallback, None)
            return
        raise error from None
    if first is not None:
        yield first
        yield from plans
