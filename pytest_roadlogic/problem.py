"""The planning problem of one sample: what the planners solve for it and what the monitor checks.

In: a checked scenario, a sample of its logical parameters (none: the base strategy), the first
planner's settings and the run's seed. Out: a ``Problem``: the scenario on the ways through the
map the sample takes, its automaton as written (the monitor's), the automaton each planner solves
as a function of that planner's settings (``Guide``), and the settings and seed the first planner
solves with. The pipeline, the blame and the benches build it here, the one way.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from .automaton import SymbolicAutomaton, build_automaton
from .frontend import CheckedScenario
from .planning.fallbacks import Guide
from .sampling import guided, on_ways, sample_seed


@dataclass(frozen=True)
class Problem:
    """One sample's planning problem (``problem_for``)."""

    scenario: CheckedScenario  # on the ways through the map the sample takes (``sampling.on_ways``)
    specification: SymbolicAutomaton  # the scenario as written: what the monitor checks
    guide: Guide  # planner settings -> the automaton that planner solves
    settings: object  # the first planner's (``planning.PlannerSettings``)
    seed: int  # the seed the planners solve with
    self_driven: str | None = None  # the vehicle that drives itself (a vehicle under test)


def problem_for(scenario: CheckedScenario, values, settings, seed: int, self_driven=None) -> Problem:
    """The problem of ``scenario`` at the sample ``values`` (empty or None: the base strategy).

    Each sample is its own random concrete scenario, fixed by the run's seed and the values: its
    settings plan a random start and its seed is drawn from both (``sampling.sample_seed``).
    ``self_driven(actors)`` names the vehicle that drives itself among the automaton's actors
    (``dut.UnderTest.vehicle``), planned as one whose motion the planner does not choose.

    Why a guide (a function of the settings): a sample is narrowed to a band that keeps the
    planner's margins inside its parameter's range, which moves a value near an edge inward by the
    margin. A fallback planner with thinner margins must solve for the value itself, not for the
    first planner's moved one, or a value the scenario cannot meet is reported as one it meets.

    On a map, the settings are the encoding's for the sample's route (``on_route``); an encoding
    that cannot plan on a map (the grid's) says so (``CannotPlanOnMap``) rather than plan a
    straight road the simulation would then drive on the map. ``UnknownParameter`` for a value the
    scenario's parameters cannot take."""
    values = values or {}
    specification = build_automaton(scenario)
    dut = self_driven(specification.actors) if self_driven is not None else None
    if dut is not None:
        settings = settings.with_self_driven(dut)
        specification = specification.driving_itself(dut)
    guide = _guide(scenario, values) if values else (lambda planner_settings: specification)
    if values:
        settings, seed = dataclasses.replace(settings, random_start=True), sample_seed(seed, values)
    # the ways are the route's, not the automaton's: each planner's automaton is the same on any way
    scenario = on_ways(scenario, values)
    if scenario.route is not None:
        # CannotPlanOnMap from an encoding that cannot
        settings = settings.on_route(scenario.route, scenario.routes[1:])
    return Problem(scenario, specification, guide, settings, seed, dut)


def _guide(scenario: CheckedScenario, values) -> Guide:
    """The automaton a planner solves for the sample ``values``, one per planner resolution and margins."""
    guides: dict[tuple, SymbolicAutomaton] = {}
    sampled = frozenset(p for parameter in scenario.parameters if parameter.name in values for p in parameter.places)

    def guide(planner_settings) -> SymbolicAutomaton:
        resolution, margins = planner_settings.resolution(), planner_settings.margins()
        key = (tuple(sorted(resolution.items(), key=str)), tuple(sorted(margins.items(), key=str)))
        if key not in guides:
            narrowed, declared = guided(scenario, values, resolution, margins)
            automaton = build_automaton(narrowed, values=declared)
            automaton.sampled = sampled
            guides[key] = automaton
        return guides[key]

    return guide
