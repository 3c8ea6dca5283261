"""The whole pipeline: parse, build the automaton, plan, simulate, monitor; retry on rejection.

As in the paper, a simulation that the monitor rejects is discarded and the planner is asked for
its next plan, up to ``max_tries`` times. Every stage is timed.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

from .automaton import SymbolicAutomaton, build_automaton
from .frontend import Scenario, load_file
from .frontend.errors import Diagnostic, OscError, SourceLocation
from .monitor import Verdict, monitor
from .planning import Plan, Planner, PlanningSettings
from .simulation import Simulation, simulate
from .simulation.simulator import DriverFactory

MAX_TRIES = 5


@dataclass
class Outcome:
    scenario: Scenario
    automaton: SymbolicAutomaton
    plan: Plan
    simulation: Simulation
    verdict: Verdict
    tries: int
    seconds: dict[str, float] = field(default_factory=dict)  # stage -> seconds, summed over tries


def load_scenario(path: str | Path, name: str | None = None, lanes: int | None = None) -> Scenario:
    """A checked scenario of ``path`` (the first one with a behavior unless ``name`` is given).

    ``lanes`` overrides the road's lane count, which otherwise comes from the scenario.
    """
    checked = load_file(path, lanes)
    runnable = [s for s in checked.scenarios if s.behavior is not None]
    if not runnable:
        raise OscError([Diagnostic(SourceLocation(str(path), 1, 1), "the file declares no scenario with a `do` behavior")])
    return checked.file.scenario(name) if name else runnable[0]


def run_scenario(
    scenario: Scenario,
    seed: int = 1,
    settings: PlanningSettings | None = None,
    max_tries: int = MAX_TRIES,
    drivers: DriverFactory | None = None,
) -> Outcome:
    settings = settings or PlanningSettings()
    seconds = {"automaton": 0.0, "planning": 0.0, "simulation": 0.0, "monitoring": 0.0}
    start = time.perf_counter()
    automaton = build_automaton(scenario)
    seconds["automaton"] += time.perf_counter() - start
    planner = Planner(automaton, settings, seed)
    plans = planner.plans(limit=max_tries)
    outcome = None
    for tries in range(1, max_tries + 1):
        start = time.perf_counter()
        plan = next(plans, None)
        seconds["planning"] += time.perf_counter() - start
        if plan is None:
            break
        start = time.perf_counter()
        simulation = simulate(plan, drivers=drivers)
        seconds["simulation"] += time.perf_counter() - start
        start = time.perf_counter()
        verdict = monitor(automaton, simulation.trace)
        seconds["monitoring"] += time.perf_counter() - start
        outcome = Outcome(scenario, automaton, plan, simulation, verdict, tries, seconds)
        if verdict.accepted:
            break
    assert outcome is not None, "the planner yields at least one plan or raises NoPlanError"
    return outcome
