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

from .automaton import SymbolicAutomaton
from .dut import UnderTest
from .frontend import CheckedScenario, load_file
from .monitor import Verdict, monitor
from .oracles import DutReport, judge
from .planning import Plan, PlannerSettings, settings_for
from .planning.fallbacks import planned, tool_limit
from .problem import problem_for
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
    problem = problem_for(scenario, values, settings, seed, under_test.vehicle if under_test is not None else None)
    dut = problem.self_driven
    if dut is not None:
        from .reactive import execution_for  # replanning loads with a vehicle under test only

        drivers = under_test.drivers(dut, drivers)
    automaton_seconds = time.perf_counter() - start
    plans = planned(problem.guide, problem.settings, problem.seed, count * max_tries, fallbacks)
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
            react = (
                execution_for(plan, problem.guide, problem.settings, problem.seed, dut, under_test.replan_period)
                if dut is not None
                else None
            )
            simulation = simulator.simulate(plan, limits, drivers, **({"react": react} if react else {}))
            seconds["simulation"] += time.perf_counter() - start
            start = time.perf_counter()
            verdict = monitor(problem.specification, simulation.trace, begins_by=plan.begins_by)
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
                problem.scenario, problem.specification, plan, simulation, verdict, tries, seconds, instance, report
            )
            if verdict.accepted or (report is not None and report.failed):
                break
        if outcome is None:
            return  # the planner has no plan left; the first call raises NoPlanError instead
        if not outcome.verdict.accepted:
            limit = tool_limit(outcome.plan, outcome.verdict.explain(), problem.guide, problem.settings, problem.seed)
            if limit is not None:
                raise limit
        yield outcome


def _apart(simulation, vehicle: str) -> frozenset[str]:
    """The vehicles of ``simulation`` on another route of the map than ``vehicle``'s."""
    own = simulation.road_of(vehicle)
    return frozenset(v for v in simulation.trace.actors if simulation.road_of(v) is not own)
