"""What the planner tries when it finds no plan for a sample: thinner margins, a finer step, and
vehicle limits beyond its own (``planned``), and which of its settings binds when such a
plan's simulation is not accepted (``tool_limit``).

Why here: the margins, the step and the limits are the planner's guesses at what the vehicles can
track, not the scenario's constraints; the pipeline asks for plans and reports what binds, and
this module is the one policy for both.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable, Generator, Iterator

from ..logic.automaton import SymbolicAutomaton
from .errors import (
    HorizonTooShort,
    LimitsBind,
    MarginsBind,
    NoPlanError,
    PlanningTimeout,
    StepBinds,
    UnsatisfiableScenario,
)
from .plan import Plan

Guide = Callable[[object], SymbolicAutomaton]  # planner settings -> the automaton they solve


def _planner_for(automaton, settings, seed):
    from . import planner_for  # the planners (and clingo) load when a fallback is needed

    return planner_for(automaton, settings, seed)


def relaxed_names(settings, names: frozenset[str] | None = None) -> list[str]:
    """Each of the settings' relaxable limits named (all by default) with its value, what it was
    relaxed to, and why it had its value when the settings say (a map's curve bounding the top speed)."""
    return [limit.describe() for limit in settings.limits() if names is None or limit.name in names]


def car_limits(settings) -> frozenset[str]:
    """The relaxable limits that are a real car's (``Limit.of_a_car``): a plan beyond them has no concrete scenario."""
    return frozenset(limit.name for limit in settings.limits() if limit.of_a_car)


def spacing_limits(settings) -> frozenset[str]:
    """The relaxable limits that are the tool's spacing between cars, not a car's."""
    return frozenset(limit.name for limit in settings.limits() if not limit.of_a_car)


def tool_limit(plan: Plan, explanation: str, guide: Guide, settings, seed: int):
    """The error that says which setting of the tool binds, when the rejected ``plan`` (whose
    simulation the monitor explains with ``explanation``) came from one of ``planned``'s fallback
    planners; None for a plan within every setting."""
    if plan.stats.get("thinned_margins"):
        return MarginsBind(settings.describe_margins(), settings.thinned().describe_margins(), explanation)
    if plan.stats.get("finer_step"):
        return StepBinds(
            f"no plan in steps of {settings.dt:g} s; plans in steps of {settings.dt / 2:g} s exist, so the scenario itself "
            f"can be met at these values, but their simulation was not accepted (the planning step is a setting of the tool): "
            f"{explanation}"
        )
    if plan.stats.get("relaxed_limits"):
        names = binding_limits(guide, settings, seed)
        return LimitsBind(
            relaxed_names(settings, names), explanation=explanation, beyond_a_car=bool(names & car_limits(settings))
        )
    return None


def fallback_needed(plan: Plan, guide: Guide, settings, seed: int) -> str:
    """What a plan from one of ``planned``'s fallback planners needed, in a line (as ``tool_limit``
    says it of a rejected one); "" for a plan within every setting."""
    if plan.stats.get("thinned_margins"):
        return "no plan keeps the planner's full margins inside the scenario's ranges: this one keeps thinner ones (a setting of the tool)"
    if plan.stats.get("finer_step"):
        return "no plan exists in the planner's steps: this one is planned in half steps (a setting of the tool)"
    if plan.stats.get("relaxed_limits"):
        names = binding_limits(guide, settings, seed)
        whose = (
            "beyond a real car's: no car can drive this scenario"
            if names & car_limits(settings)
            else "the tool's spacing between cars, not a car's limit"
        )
        return f"no plan exists within the planner's vehicle limits: this one needs {' and '.join(relaxed_names(settings, names))} ({whose})"
    return ""


def binding_limits(guide: Guide, settings, seed: int) -> frozenset[str]:
    """The vehicle limits without which the sample has a plan (with the thinner margins): one at a
    time first, so that the report names the one that binds; then a car's limits alone, the
    spacing alone, all together; all of them when even that gives none."""
    settings = dataclasses.replace(settings.thinned() or settings, explain_unsatisfiable=False)

    def plannable(names) -> bool:
        try:
            relaxed = settings.relaxed(names)
            return next(_planner_for(guide(relaxed), relaxed, seed).plans(limit=1), None) is not None
        except NoPlanError:
            return False

    cars, spacing = car_limits(settings), spacing_limits(settings)
    for names in (*(frozenset({limit.name}) for limit in settings.limits()), cars, spacing):
        if plannable(names):
            return names
    return cars | spacing


def fallback_settings(settings, beyond_limits: bool = True) -> list[tuple[object, str]]:
    """The fallback planners' settings in the order ``planned`` tries them, each with the mark its
    plans carry in their stats: thinner margins, then half the step too, then relaxed limits (the
    spacing between cars first, then a car's limits too, unless ``beyond_limits`` is off). Empty
    when the settings have no fallback margins."""
    thinned = settings.thinned()
    if thinned is None:
        return []
    quiet = dataclasses.replace(thinned, explain_unsatisfiable=False)
    # the spacing first, then a car's limits too: a plan within a car's limits is one a car can
    # drive (a stop planned with every limit relaxed may brake harder than a car does)
    relaxed = [(quiet.relaxed(spacing_limits(quiet)), "relaxed_limits")] + (
        [(quiet.relaxed(), "relaxed_limits")] if beyond_limits else []
    )
    return [(quiet, "thinned_margins"), (quiet.finer(), "finer_step"), *relaxed]


def settings_of(plan: Plan, settings):
    """The settings of the planner that planned ``plan``: ``settings`` (``planned``'s first
    planner), or the fallback's its mark names (for relaxed limits, every limit relaxed)."""
    marked = [(fallback, mark) for fallback, mark in fallback_settings(settings) if plan.stats.get(mark)]
    return marked[-1][0] if marked else settings


def planned(
    guide: Guide, settings, seed: int, limit: int, fallbacks: bool = True, beyond_limits: bool = True
) -> Iterator[Plan]:
    """The plans of the sample ``guide`` gives (at most ``limit``), the one way every caller plans:
    the planner's own; or, when it has none at all, those of a planner that keeps
    ``settings.fallback_margins`` of its margins (``stats["thinned_margins"]``), or else of one that
    also plans in half the step (``stats["finer_step"]``), or else of one that drives beyond the
    vehicle limits (``settings.limits()``, ``stats["relaxed_limits"]``; without ``beyond_limits`` only
    the spacing between cars is relaxed, never a car's limits). Each planner solves the sample
    narrowed with its own margins (``guide``). Without ``fallbacks``, the planner's own plans only.
    A sample whose linear relaxation has no solution has no plan of any of them, and is refused
    before any search.

    Why: the margins and the limits are the planner's guesses at what the vehicles can track, not
    the scenario's constraints; a plan nearer the scenario's edges is simulated and monitored like
    any other, and an accepted simulation is an instance of the scenario. A scenario with no plan
    even then raises the first planner's error, explained (``settings.explain_unsatisfiable``) only
    then: its constraints clash (explaining before the fallbacks would cost a sample that one of
    them plans a whole diagnosis)."""
    # one deadline for the first plan, however many planners and searches it takes, not the whole
    # limit for each
    deadline = time.monotonic() + settings.time_limit
    _refuse_what_the_relaxation_proves(guide, settings, beyond_limits)
    if not fallbacks:
        yield from _planner_for(guide(settings), settings, seed).plans(limit=limit, deadline=deadline)
        return
    quiet = dataclasses.replace(settings, explain_unsatisfiable=False)
    first = _planner_for(guide(quiet), quiet, seed)
    plans = first.plans(limit=limit, deadline=deadline)
    try:
        plan = next(plans, None)
    except (PlanningTimeout, HorizonTooShort, UnsatisfiableScenario):
        raise  # a setting that binds, or guards that contradict themselves whatever the margins
    except NoPlanError as error:
        if (yield from _fallback_plans(guide, settings, seed, limit, beyond_limits, deadline)):
            return
        if settings.explain_unsatisfiable:
            _planner_for(guide(settings), settings, seed).explain_failure(error, deadline)
        raise error from None
    while plan is not None:
        yield plan
        plan = next(plans, None)


def _refuse_what_the_relaxation_proves(guide: Guide, settings, beyond_limits: bool) -> None:
    """Raise ``UnsatisfiableScenario`` when the linear relaxation (``relaxation``) proves that no
    planner, the fallbacks' included, has a plan for the sample: milliseconds, where the planner
    over every horizon, the fallbacks and the diagnosis take seconds. It reads the automaton
    of the widest fallback margins and the fastest speed any fallback plans."""
    from .errors import conflict_message
    from .relaxation import provably_unplannable

    widest = settings.thinned() or settings
    automaton = guide(widest)
    fastest = max(settings.relaxed().max_speed, settings.max_speed) if beyond_limits else settings.max_speed
    conflict = provably_unplannable(automaton, fastest, settings.route_extent())
    if conflict:
        raise UnsatisfiableScenario(
            "no plan exists at these values (its linear relaxation has no solution)\n"
            + conflict_message([conflict], automaton.parameters),
            [conflict],
            settings.summary(automaton.lanes),
            automaton.parameters,
            on_the_map=settings.on_the_map(automaton.lanes),
        )


def _fallback_plans(
    guide: Guide, settings, seed: int, limit: int, beyond_limits: bool, deadline: float
) -> Generator[Plan, None, bool]:
    """Yields the plans of the first fallback planner that has any (``planned``), the first due
    by ``deadline``, and returns whether one had."""
    for fallback, mark in fallback_settings(settings, beyond_limits):
        try:
            plans = _planner_for(guide(fallback), fallback, seed).plans(limit=limit, deadline=deadline)
            plan = next(plans, None)
        except NoPlanError:
            continue
        if plan is None:
            continue
        while plan is not None:
            plan.stats[mark] = 1.0
            yield plan
            plan = next(plans, None)
        return True
    return False
