"""Why a scenario has no plan: the diagnosis every encoding shares.

``check_satisfiable`` refuses, before any solving, an automaton whose every path to the end crosses a
self-contradicting guard. ``raise_reason`` turns a planner's ``NoPlanError`` into the reason: the
horizon limit when the phases' durations alone need longer (a setting binds), else the smallest
group of the scenario's own constraints that no plan meets (``smallest_conflict``, from clingo's
unsatisfiable cores over the horizons the durations allow), else the error as it is. A planner is
any ``core.IncrementalPlanner``: the diagnosis asks it for its relaxable instance, its controls and
its window, so that each encoding is explained in its own terms.
"""

from __future__ import annotations

import time

import clingo

from ..logic.automaton import SymbolicAutomaton, Timing
from ..logic.guards import conjunction, contradiction, lanes_conflict, required_bounds
from .errors import NoPlanError, PlanningTimeout, UnsatisfiableScenario, conflict_message
from .facts import relaxable_constraints


def check_satisfiable(automaton: SymbolicAutomaton) -> None:
    """Raise ``UnsatisfiableScenario`` when every path to the end crosses a transition whose instant
    no state meets: two bounds of its guard and of the invariant of the location it enters (the
    run is there from that instant) that contradict each other, or lanes no placement on the road's
    lanes meets (a car kept in the leftmost lane and another left of it). The groups named are
    those of the blocked transitions the run reaches furthest from its start: of a scenario's
    alternatives (a lane kept, read as one per lane), the one that came closest to the end."""
    blocked = {}
    for transition in automaton.transitions:
        invariant = automaton.location(transition.target).invariant
        at_its_instant = conjunction([*required_bounds(transition.guard), *required_bounds(invariant)])
        group = contradiction(at_its_instant) or lanes_conflict(at_its_instant, automaton.lanes)
        if group is not None:
            blocked[transition.id] = group
    if not blocked:
        return
    depth = {automaton.initial: 0}  # locations the run reaches by unblocked transitions, breadth first
    frontier = [automaton.initial]
    while frontier:
        location = frontier.pop(0)
        for transition in automaton.outgoing(location):
            if transition.id not in blocked and transition.target not in depth:
                depth[transition.target] = depth[location] + 1
                frontier.append(transition.target)
    if automaton.final in depth:
        return
    reached = [t for t in automaton.transitions if t.id in blocked and t.source in depth]
    furthest = max((depth[t.source] for t in reached), default=0)
    conflicts = list(dict.fromkeys(blocked[t.id] for t in reached if depth[t.source] == furthest))
    conflicts = conflicts or list(dict.fromkeys(blocked.values()))
    raise UnsatisfiableScenario(
        conflict_message(conflicts, automaton.parameters),
        conflicts,
        parameters=automaton.parameters,
        lanes=automaton.lanes,
    )


def raise_reason(planner, error: NoPlanError, deadline: float, window=None) -> None:
    """Raise the reason there is no plan: the horizon limit when the phases' durations alone
    need longer (a setting binds, not the scenario), else the constraints that cannot hold
    together, when a diagnosis finds them in time, else ``error`` as it is. ``window``: the
    planning's own, whose answers it reuses."""
    try:
        planner.needed_horizon(deadline, window)
    except PlanningTimeout:
        pass  # no time to tell: go on to the diagnosis, which says what it finds
    conflict = smallest_conflict(planner, deadline)
    if conflict:
        raise UnsatisfiableScenario(
            f"{error}\n" + conflict_message([conflict], planner.automaton.parameters),
            [conflict],
            planner.settings.summary(planner.automaton.lanes),
            planner.automaton.parameters,
            on_the_map=planner.settings.on_the_map(planner.automaton.lanes),
        ) from None
    if conflict == ():
        raise NoPlanError(
            f"{error}: none even with every constraint of the scenario relaxed, so no group of them is to "
            f"blame; the planner's bounds are ({planner.settings.summary(planner.automaton.lanes)}): on a map, "
            "give the scenario a road with more room (path_length, a longer road or junction approach) or ask "
            "the vehicles to travel less (shorter durations, lower speeds)"
        ) from None
    raise error


def smallest_conflict(planner, deadline: float | None = None) -> tuple | None:
    """A smallest group of the scenario's constraints that no plan up to the horizon limit meets.

    Every bound and duration gets an external that relaxes it, and each horizon is solved as in
    planning, assuming none is relaxed: clingo's unsatisfiable cores name the assumptions that
    failed, and their union over the horizons is a group that cannot hold together. Removing
    one member at a time, and keeping it out whenever the rest still fail at every horizon,
    makes the group minimal; with a ``removal_time_limit`` setting, a member whose removal is not
    decided within it stays (the group still cannot hold together, it may name one constraint
    too many). ``()`` when relaxing everything still leaves no plan (the settings, or the road,
    alone forbid one); None when time runs out.
    """
    constraints = relaxable_constraints(planner.automaton)
    if not constraints:
        return None
    deadline = deadline if deadline is not None else time.monotonic() + planner.settings.time_limit
    settings = planner.widened() or planner.settings
    program = planner.instance_for(settings, relaxable=True)
    try:
        if _failing(planner, program, settings, [], len(constraints), deadline) is not None:
            return ()  # no plan even with every constraint relaxed
        core = _failing(planner, program, settings, list(range(len(constraints))), len(constraints), deadline)
        if not core:
            return None
        budget = planner.settings.removal_time_limit
        for k in list(core):
            if k in core:
                step_deadline = deadline if budget is None else min(deadline, time.monotonic() + budget)
                try:
                    smaller = _failing(
                        planner, program, settings, [c for c in core if c != k], len(constraints), step_deadline
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


def _failing(planner, program: str, settings, kept: list[int], count: int, deadline: float) -> list[int] | None:
    """Grow the horizon as in planning with the constraints ``kept`` (the rest may be relaxed):
    None when some horizon has a plan, else the union of the unsatisfiable cores."""
    relaxed = [clingo.Function("relaxed", [clingo.Number(k)]) for k in range(count)]
    # only the horizons the kept durations allow (a relaxed one leaves its phase open)
    window = planner.window(deadline, program, [(relaxed[k], False) for k in kept])
    earliest = window.earliest(settings.max_horizon)
    if earliest is None:
        # the kept durations let no run end within the horizon limit: they fail among themselves,
        # whatever the bounds, and are named (a brake of 6.3-7.3 s that must equal a 0.5-1 s wait
        # plus a 3-3.5 s lane change)
        timings = {
            k for k, constraint in enumerate(relaxable_constraints(planner.automaton)) if isinstance(constraint, Timing)
        }
        return sorted(k for k in kept if k in timings)
    last = window.last_horizon(settings.max_horizon)
    control = planner.control_for(program)
    union: set[int] = set()
    for horizon in range(earliest, last + 1):
        if horizon == earliest:
            planner.advance_to(control, horizon)
            for atom in relaxed:
                control.assign_external(atom, None)  # free: what is not kept may be relaxed
            literal = {control.symbolic_atoms[atom].literal: k for k, atom in enumerate(relaxed)}
        else:
            planner.advance(control, horizon)
        with control.solve(assumptions=[(relaxed[k], False) for k in kept], async_=True) as handle:
            planner.wait(handle, deadline, "no time left to explain why there is no plan")
            if handle.get().satisfiable:
                return None
            union.update(literal[abs(lit)] for lit in handle.core() if abs(lit) in literal)
    return sorted(union)
