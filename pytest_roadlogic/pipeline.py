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
from typing import TYPE_CHECKING

from .automaton import SymbolicAutomaton, build_automaton
from .frontend import CheckedScenario, load_file
from .monitor import Verdict, monitor
from .planning import Plan, PlanningSettings
from .sampling import guided, sample_seed
from .settings import DEFAULT_SIM_TIMEOUT, RunSettings
from .simulation import DriverFactory, Simulation, SimulationLimits, Simulator

if TYPE_CHECKING:
    from .planning.continuous import ContinuousSettings

MAX_TRIES = 5


@dataclass
class Outcome:
    """One simulated instance: its plan, simulation and verdict (the last of its tries)."""

    scenario: CheckedScenario
    automaton: SymbolicAutomaton
    plan: Plan
    simulation: Simulation
    verdict: Verdict
    tries: int
    seconds: dict[str, float] = field(default_factory=dict)  # stage -> seconds, summed over tries
    instance: int = 0  # its index among the instances of one planner (base strategy)


def load_scenario(path: str | Path, name: str | None = None, lanes: int | None = None, dialect: str | None = None) -> CheckedScenario:
    """A checked scenario of ``path`` (the first one with a behavior unless ``name`` is given).

    ``lanes`` overrides the road's lane count, which otherwise comes from the scenario; ``dialect``
    (``settings.DIALECTS``) says how the file is read.
    """
    return load_file(path, lanes, dialect=dialect).scenario_to_run(name)


def run_scenario(
    scenario: CheckedScenario,
    seed: int = 1,
    settings: PlanningSettings | ContinuousSettings | None = None,
    max_tries: int = MAX_TRIES,
    drivers: DriverFactory | None = None,
    values: dict[str, object] | None = None,
    simulation_time_limit: float | None = DEFAULT_SIM_TIMEOUT,
    simulator: Simulator | None = None,
) -> Outcome:
    """One concrete instance of ``scenario``: plan, simulate, monitor, and retry with the next plan on rejection.

    ``values`` (the refined strategy) is a sample of the scenario's logical parameters: the planner
    solves the scenario narrowed to those values, the monitor checks the scenario as written. The
    planner's own free choices (start speeds and lanes, accelerations, how long the scenario lasts)
    are then random too, drawn from a seed made of ``seed`` and the values (``sample_seed``): the
    same sample always gives the same plan, and different samples do not share the solver's habits.
    Without it (the base strategy) the planner chooses every open value itself. ``simulator`` is the
    backend (default: frenetix).
    """
    return next(run_instances(scenario, 1, seed, settings, max_tries, drivers, values, simulation_time_limit, simulator))


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
) -> Iterator[Outcome]:
    """Up to ``count`` instances from one planner, each plan different from all before it (the base strategy).

    Each instance takes plans until the monitor accepts one or ``max_tries`` were rejected; it ends
    early when the planner has no further plan. Planning errors (no plan, a timeout) and
    ``SimulationTimeout`` propagate.
    """
    from .planning import planner_for
    from .simulation.backends import simulator as default_simulator

    settings = settings or RunSettings().planning()  # the default encoding's
    simulator = simulator or default_simulator()
    limits = SimulationLimits(time_limit=simulation_time_limit)
    start = time.perf_counter()
    specification = build_automaton(scenario)
    guide = specification
    if values:
        narrowed, declared = guided(scenario, values, settings.resolution(), settings.margins())
        guide = build_automaton(narrowed, values=declared)
        # each sample is its own random concrete scenario, fixed by the run's seed and the values
        settings = dataclasses.replace(settings, random_start=True)
        seed = sample_seed(seed, values)
    automaton_seconds = time.perf_counter() - start
    planner = planner_for(guide, settings, seed)
    plans = planner.plans(limit=count * max_tries)
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
            outcome = Outcome(scenario, specification, plan, simulation, verdict, tries, seconds, instance)
            if verdict.accepted:
                break
        if outcome is None:
            return  # the planner has no plan left; the first call raises NoPlanError instead
        yield outcome
