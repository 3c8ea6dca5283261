"""Reactive execution: while the simulation runs, the scenario's vehicles are replanned from what
the vehicles really do, every ``period`` seconds (``ReactiveExecution``, the lockstep's ``react``).

The vehicle under test drives itself; every other vehicle follows its plan until the next replan,
which pins every vehicle's observed state at the next planning step and plans the rest of the
scenario from there, the run of the automaton so far being the one through the states seen at the
steps before (``Replanner``). A vehicle's new reference keeps its old waypoints before now and takes
the replan's from now on. A replan that finds no plan leaves the plan as it is and is recorded
with why: from here the scenario cannot go on (the vehicle under test made it impossible).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from ..planning.plan import Plan, PlanState
from ..roads.road import Road
from ..simulation.driver import VehicleState
from ..simulation.reference import Reference, references
from .replanner import Replan, Replanner


class ReactiveExecution:
    """The ``react`` of one simulation: replans ``plan`` every ``period`` seconds.

    A replan between two planning steps plans from the next one: every vehicle's state there is
    predicted from the observation at its speed and acceleration (less than a step ahead), and
    the new plan takes over from that step (the drivers look ahead along their references: a
    replan changes what they aim for at once). The states at the planning steps are kept, for the
    run of the automaton so far (``Replanner``)."""

    def __init__(self, replanner: Replanner, plan: Plan, period: float, on_course_only: bool = False) -> None:
        self.replanner = replanner
        self.plan = plan
        self.period = period
        # replan only once the vehicle under test has left the course the plan being driven has
        # for it (``_on_course``), and only while what the others must still do depends on it
        # (``_settled``): where the others meet it only where their ways cross (a junction), that
        # plan stands until then; on one road the others follow and cut in around it all along,
        # and every period replans
        self.on_course_only = on_course_only
        self.meetings: dict[tuple[int, int], list] = {}  # (id of a route, id of another) -> where they meet
        self.next_time = period
        self.seen: dict[int, dict[str, PlanState]] = {}  # planning step -> vehicle -> state there
        self.replans: list[Replan] = []

    def _on_course(self, state: VehicleState | None, time: float) -> bool:
        """Whether the vehicle under test (``state`` at ``time``) drives as the plan being driven
        has it: within ``ON_COURSE_POSITION`` and ``ON_COURSE_SPEED`` of its planned position and
        speed there (read between the plan's steps as a straight line)."""
        plan, dut = self.plan, self.replanner.dut
        if state is None or dut not in plan.states:
            return False
        at = time / plan.dt
        k = min(int(at), plan.horizon - 1)
        share = min(max(at - k, 0.0), 1.0)
        here, there = plan.at(dut, k), plan.at(dut, k + 1)
        position = here.position + (there.position - here.position) * share
        speed = here.speed + (there.speed - here.speed) * share
        return abs(state.x - position) <= ON_COURSE_POSITION and abs(state.speed - speed) <= ON_COURSE_SPEED

    def _settled(self, states: dict[str, VehicleState], roads: Mapping[str, Road], step: int) -> bool:
        """Whether nothing the other vehicles must still do from ``step`` on depends on the vehicle
        under test: nothing ahead in the automaton names it (``SymbolicAutomaton.names_ahead``, from
        where the plan being driven is before ``step``), and its way and every other vehicle's meet
        nowhere either has still to pass: they cross (a lane they share never settles, nor does a
        vehicle on its own way, which keeps its distance to it) and one of the two is past the
        crossing by ``PASSED``. The plan being driven then stands as it is."""
        dut = self.replanner.dut
        mine = roads.get(dut)
        if dut not in states or mine is None or mine.route is None:
            return False
        automaton = self.replanner.automaton
        taken = [transition for k, transition in self.plan.transitions if k < step]
        location = automaton.transitions[taken[-1]].target if taken else automaton.initial
        if automaton.names_ahead(location, dut):
            return False
        from ..roads.conflicts import meetings_of

        for vehicle, state in states.items():
            theirs = roads[vehicle]
            if vehicle == dut or vehicle in self.plan.stationary:
                continue
            if theirs.route is None or theirs.route is mine.route:
                return False
            key = (id(mine.route), id(theirs.route))
            if key not in self.meetings:
                self.meetings[key] = meetings_of(0, mine.route, 1, theirs.route)
            for meeting in self.meetings[key]:
                if meeting.kind != "crossing":
                    return False
                dut_past = states[dut].x + mine.route_shift > meeting.first_span[1] + PASSED
                other_past = state.x + theirs.route_shift > meeting.second_span[1] + PASSED
                if not (dut_past or other_past):
                    return False
        return True

    def __call__(
        self,
        time: float,
        states: dict[str, VehicleState],
        road: Road,
        driven: dict[str, Reference],
        placed: Mapping[str, Road],
    ) -> dict[str, Reference] | None:
        plan = self.plan
        dt = plan.dt
        at_step = time / dt
        # each vehicle's lane is read on its own road (vehicles on different ways through a junction)
        roads = {vehicle: driven[vehicle].road if vehicle in driven else road for vehicle in states}
        if abs(at_step - round(at_step)) < 1e-6:
            self.seen[int(round(at_step))] = _observed(states, roads, 0.0)
        if time < self.next_time - 1e-6:
            return None
        while self.next_time < time + 1e-6:
            self.next_time += self.period
        step = math.ceil(at_step - 1e-6)
        # not at the start (the plan starts where the vehicles are), not once the plan has ended
        if step == 0 or step >= plan.horizon:
            return None
        if self.on_course_only and (
            self._on_course(states.get(self.replanner.dut), time) or self._settled(states, placed, step)
        ):
            return None
        observed = self.seen[step] if step * dt - time < 1e-6 else _observed(states, roads, step * dt - time)
        replan = self.replanner.replan(plan, step, observed, self.seen, time)
        self.replans.append(replan)
        if replan.plan is None:
            return None
        self.plan = replan.plan
        planned = references(replan.plan, road)
        return {
            vehicle: _spliced(driven[vehicle], planned[vehicle], step * dt)
            for vehicle in plan.vehicles
            if vehicle != self.replanner.dut and vehicle not in plan.stationary
        }


# how near the vehicle under test must be to where the plan being driven has it, along its road
# and in speed, for that plan to stand (ReactiveExecution.on_course_only)
ON_COURSE_POSITION = 0.5  # m
ON_COURSE_SPEED = 0.3  # m/s
# how far past a crossing of two ways a vehicle's centre is once it has left it (the crossing is
# where two cars' boxes grown by half a metre overlap; the planner widens it by as much)
PASSED = 2.0  # m


def _observed(states: dict[str, VehicleState], roads: dict[str, Road], ahead: float) -> dict[str, PlanState]:
    """Every vehicle's state as a plan states it, ``ahead`` seconds on: along its road (``roads``)
    at its speed and acceleration (never reversing), across it at its lateral speed (a vehicle
    halfway through a lane change is in the lane it is heading for once its centre has crossed the
    line)."""
    observed = {}
    for vehicle, s in states.items():
        speed = s.speed + s.acceleration * ahead
        if speed >= 0:
            distance = (s.speed + speed) / 2 * ahead
        else:  # it stops on the way
            speed, distance = 0.0, s.speed * s.speed / (-2 * s.acceleration)
        across = s.y + s.speed * math.sin(s.heading) * ahead
        observed[vehicle] = PlanState(s.x + distance * math.cos(s.heading), roads[vehicle].lane_at(across), speed)
    return observed


def _spliced(old: Reference, new: Reference, now: float) -> Reference:
    """``old``'s waypoints before ``now`` and ``new``'s from it on."""
    waypoints = [w for w in old.waypoints if w.time < now - 1e-9] + [w for w in new.waypoints if w.time >= now - 1e-9]
    return Reference(old.vehicle, old.runup, old.runup_acceleration, waypoints, old.road, brisk=new.brisk)


def replanning_seconds(replans: list[Replan]) -> tuple[float, float]:
    """(median, 95th percentile) seconds per replan; (nan, nan) without any."""
    seconds = sorted(r.seconds for r in replans)
    if not seconds:
        return math.nan, math.nan
    return seconds[len(seconds) // 2], seconds[min(len(seconds) - 1, math.ceil(0.95 * len(seconds)) - 1)]


def execution_for(plan: Plan, guide, settings, seed: int, dut: str, period: float) -> ReactiveExecution | None:
    """The reactive execution of ``plan`` around the vehicle under test ``dut``, replanned every
    ``period`` seconds with the planner that planned it (``guide`` and ``settings`` as
    ``planning.fallbacks.planned`` had them); None where the plan is driven as it is: a period
    of 0, an encoding that cannot replan from a state (the grid's), or a route laid onto none of
    the others, which has an origin of its own that a replan would move under its cars
    (docs/junctions.md)."""
    if not period or not settings.replanning:
        return None
    if plan.side_routes and not _laid_together(plan):
        return None
    from ..planning.fallbacks import settings_of

    planned_with = settings_of(plan, settings)
    if plan.origin is not None:
        # on a map the scenario stays where the simulation has it: a replan's positions are the
        # plan's, from the same place on the route
        planned_with = planned_with.at_origin(plan.origin)
    replanner = Replanner(guide(planned_with), planned_with, seed, dut)
    # vehicles on other ways through a junction meet the vehicle under test only where the ways do
    return ReactiveExecution(replanner, plan, period, on_course_only=bool(plan.side_routes))


def _laid_together(plan: Plan) -> bool:
    """Whether every route of ``plan`` is laid onto the first where they meet (``roads.conflicts.alignments``):
    a replan keeps the routes where the simulation has them through route 0's origin and the
    routes laid onto it."""
    from ..roads.conflicts import alignments

    routes = (plan.route, *dict.fromkeys(route for route, _ in plan.side_routes.values()))
    return {a.route for a in alignments(routes)} == set(range(1, len(routes)))
