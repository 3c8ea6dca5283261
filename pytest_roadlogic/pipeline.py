"""The stages chained for one scenario: build the automaton, plan, simulate, monitor; retry on rejection.

As in the paper, a simulation that the monitor rejects is discarded and the planner is asked for
its next plan, up to ``max_tries`` times. Every stage is timed. The strategies (which cases to
run, how they end, what is reported) are ``runner``'s; this module is usable alone from Python:

    outcome = run_scenario(load_scenario("scenarios/overtake.osc"), seed=1)
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

from .automaton import SymbolicAutomaton, build_automaton
from .dut import UnderTest
from .frontend import CheckedScenario, load_file
from .monitor import Verdict, monitor
from .oracles import DutReport, judge
from .planning import Plan, PlannerSettings, settings_for
from .planning.fallbacks import Guide, planned, tool_limit
from .sampling import guided, on_ways, sample_seed
from .settings import DEFAULT_SIM_TIMEOUT, RunSettings
from .simulation import DriverFactory, Simulation, SimulationLimits, Simulator

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
    # the oracles' verdict on the vehicle under test, when one drove itself (dut.UnderTest)
    dut: DutReport | None = None


def load_scenario(
    path: str | Path,
    name: str | None = None,
    lanes: int | None = None,
    dialect: str | None = None,
    roots=None,
    road_map: str | Path | None = None,
) -> CheckedScenario:
    """A checked scenario of ``path`` (the first one with a behavior unless ``name`` is given).

    ``lanes`` overrides the road's lane count, which otherwise comes from the scenario; ``dialect``
    (``settings.DIALECTS``) says how the file is read; ``roots`` (``confinement.ReadRoots``) where
    its imports may be read from (default: the project's root and the file's folder); ``road_map``
    an OpenDRIVE file to run on instead of the one the scenario's ``set_map`` names.
    """
    return load_file(path, lanes, dialect=dialect, roots=roots, road_map=road_map).scenario_to_run(name)


def run_scenario(
    scenario: CheckedScenario,
    seed: int = 1,
    settings: PlannerSettings | None = None,
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
    settings: PlannerSettings | None = None,
    max_tries: int = MAX_TRIES,
    drivers: DriverFactory | None = None,
    values: dict[str, object] | None = None,
    simulation_time_limit: float | None = DEFAULT_SIM_TIMEOUT,
    simulator: Simulator | None = None,
    fallbacks: bool = True,
    under_test: UnderTest | None = None,
) -> Iterator[SimulatedInstance]:
    """Up to ``count`` instances from one planner, each plan different from all before it (the base strategy).

    Each instance takes plans until the monitor accepts one or ``max_tries`` were rejected; it ends
    early when the planner has no further plan. Planning errors (no plan, a timeout) and
    ``SimulationTimeout`` propagate. ``fallbacks``: when the planner has no plan, try thinner
    margins, a finer step and relaxed limits (``planning.fallbacks``) before saying so.
    ``under_test``: the scenario's vehicle under test (``dut.UnderTest.vehicle``; none: every
    vehicle follows its plan) drives itself, and the oracles judge it (``SimulatedInstance.dut``);
    a try whose vehicle under test failed is the last.
    """
    from .simulation.backends import simulator as default_simulator

    settings = settings or settings_for(RunSettings())  # the default encoding's
    simulator = simulator or default_simulator()
    limits = SimulationLimits(time_limit=simulation_time_limit)
    start = time.perf_counter()
    scenario = on_ways(scenario, values or {})  # its instances report the ways they take
    specification = build_automaton(scenario)
    dut = under_test.vehicle(specification.actors) if under_test is not None else None
    if dut is not None:
        drivers = under_test.drivers(dut, drivers)
        settings = settings.with_self_driven(dut)
    guide, settings, seed = guided_planning(scenario, specification, values, settings, seed)
    automaton_seconds = time.perf_counter() - start
    plans = planned(guide, settings, seed, count * max_tries, fallbacks)
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
            react = _reactive(plan, guide, settings, seed, dut, under_test)
            simulation = simulator.simulate(plan, limits, drivers, **({"react": react} if react else {}))
            seconds["simulation"] += time.perf_counter() - start
            start = time.perf_counter()
            verdict = monitor(specification, simulation.trace, begins_by=plan.begins_by)
            if missed := simulation.turns_not_taken(frozenset({dut}) if dut is not None else frozenset()):
                # along(path) on a route that turns: the car drives through the junction
                verdict = dataclasses.replace(verdict, accepted=False, incidents=verdict.incidents + missed)
            report = (
                judge(simulation.trace, dut, under_test.thresholds, _apart(simulation, dut))
                if dut is not None
                else None
            )
            seconds["monitoring"] += time.perf_counter() - start
            outcome = SimulatedInstance(
                scenario, specification, plan, simulation, verdict, tries, seconds, instance, report
            )
            if verdict.accepted or (report is not None and report.failed):
                break
        if outcome is None:
            return  # the planner has no plan left; the first call raises NoPlanError instead
        if not outcome.verdict.accepted:
            limit = tool_limit(outcome.plan, outcome.verdict.explain(), guide, settings, seed)
            if limit is not None:
                raise limit
        yield outcome


def _apart(simulation, vehicle: str) -> frozenset[str]:
    """The vehicles of ``simulation`` on another route of the map than ``vehicle``'s."""
    own = simulation.road_of(vehicle)
    return frozenset(v for v in simulation.trace.actors if simulation.road_of(v) is not own)


def _reactive(plan: Plan, guide: Guide, settings, seed: int, dut: str | None, under_test: UnderTest | None):
    """The reactive execution of ``plan`` around the vehicle under test ``dut`` (None: the plan is
    driven as it is: no vehicle under test, a replanning period of 0, or an encoding that cannot
    replan from a state, the grid's)."""
    if dut is None or not under_test.replan_period or not settings.replanning:
        return None
    if plan.side_routes and not _laid_together(plan):
        # a replan keeps the routes where the simulation has them through route 0's origin and the
        # routes laid onto it; a route laid onto none has an origin of its own, which a replan
        # would move under its cars: its vehicles are driven as planned (docs/junctions.md)
        return None
    from .planning.fallbacks import settings_of
    from .reactive import ReactiveExecution, Replanner

    planned_with = settings_of(plan, settings)
    if plan.origin is not None:
        # on a map the scenario stays where the simulation has it: a replan's positions are the
        # plan's, from the same place on the route
        planned_with = planned_with.at_origin(plan.origin)
    replanner = Replanner(guide(planned_with), planned_with, seed, dut)
    # vehicles on other ways through a junction meet the vehicle under test only where the ways do
    return ReactiveExecution(replanner, plan, under_test.replan_period, on_course_only=bool(plan.side_routes))


def _laid_together(plan: Plan) -> bool:
    """Whether every route of ``plan`` is laid onto the first where they meet (``roads.conflicts.alignments``)."""
    from .roads.conflicts import alignments

    routes = (plan.route, *dict.fromkeys(route for route, _ in plan.side_routes.values()))
    return {a.route for a in alignments(routes)} == set(range(1, len(routes)))


def guided_planning(
    scenario: CheckedScenario, specification: SymbolicAutomaton, values, settings, seed: int
) -> tuple[Guide, object, int]:
    """The automaton a planner solves for a sample, as a function of that planner's settings
    (``specification`` without a sample), and the settings and seed it solves with: each sample is
    its own random concrete scenario, fixed by the run's seed and the values. ``scenario`` is on
    the ways through the map the sample takes (``sampling.on_ways``).

    Why a function: a sample is narrowed to a band that keeps the planner's margins inside its
    parameter's range, which moves a value near an edge inward by the margin. A fallback planner
    with thinner margins must solve for the value itself, not for the first planner's moved one,
    or a value the scenario cannot meet is reported as one it meets.

    On a map, the settings are the encoding's for the scenario's route (``on_route``); an
    encoding that cannot plan on a map (the grid's) says so (``CannotPlanOnMap``) rather than plan
    a straight road the simulation would then drive on the map."""
    if scenario.route is not None:
        # CannotPlanOnMap from an encoding that cannot
        settings = settings.on_route(scenario.route, scenario.routes[1:])
    if not values:
        return (lambda planner_settings: specification), settings, seed
    guides: dict[tuple, SymbolicAutomaton] = {}

    def guide(planner_settings) -> SymbolicAutomaton:
        resolution, margins = planner_settings.resolution(), planner_settings.margins()
        key = (tuple(sorted(resolution.items(), key=str)), tuple(sorted(margins.items(), key=str)))
        if key not in guides:
            narrowed, declared = guided(scenario, values, resolution, margins)
            automaton = build_automaton(narrowed, values=declared)
            automaton.sampled = frozenset(
                p for parameter in scenario.parameters if parameter.name in values for p in parameter.places
            )
            guides[key] = automaton
        return guides[key]

    return guide, dataclasses.replace(settings, random_start=True), sample_seed(seed, values)
