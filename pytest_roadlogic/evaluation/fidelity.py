"""Least action, counted: the lane and speed changes of a plan that no construct of the vehicle
asks for (docs/language.md, "What a vehicle is asked to do").

Written from the definition, not from the encoding (``asp/least_action.lp``), so that a test can
hold the planner to it: a change during step t (from step t-1 to step t) is *asked* when the
location the plan's run is in at step t-1 lists it for the vehicle (``Location.asks``: a construct
of the vehicle's phase there asks for a lane or a speed, or one of its next phase asks for it at
that phase's first instant), or, for a speed the vehicle is asked to drive toward there
(``Location.toward``: CARLA's ``speed(v)``), when it moves toward that speed without passing it.
A speed change counts when the mean acceleration over the step is above ``SPEED_CHANGE`` in
size, but braking is asked by the standard's avoid_collisions (on by default) while another
vehicle or an obstacle is ahead in a lane the vehicle occupies (one changing lane occupies both
lanes in that step). A vehicle that drives through the junction of a route that turns (``along(path)``:
``Route.crossers``) is asked by the road to change speed: it slows for the turn and drives on after
it. Where a vehicle starts (its lane and speed) is no change. A phase that asks its vehicle to hold
one speed (``Location.steady``: CARLA's ``position(..., at: end)``, which its runner reaches at
one speed) does not ask a change made there for a later phase: a change after the phase's first
step toward a speed the vehicle is asked to drive toward later in the run (and not here) is
unasked, but for braking for the vehicle ahead.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass

from ..logic.automaton import SymbolicAutomaton
from ..planning.plan import Plan

SPEED_CHANGE = 0.5  # m/s^2: a mean acceleration over a step below this is holding the speed
# m/s a speed driven toward a band may end past it: the plan's values are rounded decimals
SPEED_TOLERANCE_STEP = 0.05


@dataclass(frozen=True)
class UnaskedChange:
    """A lane or speed change of ``vehicle`` during step ``step`` that nothing of its own asks for."""

    vehicle: str
    step: int
    kind: str  # "lane" or "speed"
    before: float
    after: float

    def __str__(self) -> str:
        return self.described()

    def described(self, lane_number: Callable[[int], int] | None = None) -> str:
        """The change in a user's terms: lanes as ``lane_number(index)`` gives them (the scenario's
        dialect's numbering, as the plan's table shows them; default the planner's index, 0 the
        leftmost), speeds in m/s and kph: the message and the table name a lane alike."""
        if self.kind == "lane":
            number = lane_number or (lambda index: index)
            return (
                f"{self.vehicle} changes from lane {number(int(self.before))} to {number(int(self.after))} "
                f"at step {self.step}, unasked"
            )
        return (
            f"{self.vehicle} changes speed from {self.before:.1f} m/s ({self.before * 3.6:.0f} kph) to "
            f"{self.after:.1f} m/s ({self.after * 3.6:.0f} kph) at step {self.step}, unasked"
        )


def locations_by_step(plan: Plan, automaton: SymbolicAutomaton) -> list[int]:
    """The location the plan's run is in at each step (after the transitions of that step)."""
    return automaton.run_locations(dict(plan.transitions), plan.horizon)


def unasked_changes(plan: Plan, automaton: SymbolicAutomaton) -> list[UnaskedChange]:
    """Every lane change and speed change in ``plan`` that no construct of its vehicle asks for."""
    where = locations_by_step(plan, automaton)
    found: list[UnaskedChange] = []
    # the vehicles that drive through a junction: each route's crossers (a vehicle of another
    # route than the scenario's drives along its path through the junction)
    turning = (plan.route.crossers if plan.route is not None else frozenset()) | {
        v for v, (route, _) in plan.side_routes.items() if route.junction_span is not None
    }
    for vehicle, states in plan.states.items():
        if vehicle in plan.stationary:
            continue
        for step in range(1, plan.horizon + 1):
            location = automaton.location(where[step - 1])
            before, after = states[step - 1], states[step]
            if after.lane != before.lane and not location.asked(vehicle, "lane"):
                found.append(UnaskedChange(vehicle, step, "lane", before.lane, after.lane))
            acceleration = (after.speed - before.speed) / plan.dt
            if abs(acceleration) <= SPEED_CHANGE or vehicle in turning:
                continue
            if location.asked(vehicle, "speed") and not _for_later(plan, automaton, where, vehicle, step):
                continue
            band = location.toward(vehicle)
            if band is not None and _toward(before.speed, after.speed, band.low, band.high):
                continue  # toward the speed it is asked to drive toward, not past it
            if acceleration < 0 and _brakes_for_ahead(plan, vehicle, step):
                continue  # braking for the vehicle ahead: avoid_collisions asks it
            found.append(UnaskedChange(vehicle, step, "speed", before.speed, after.speed))
    return found


def _for_later(plan: Plan, automaton: SymbolicAutomaton, where: list[int], vehicle: str, step: int) -> bool:
    """Whether the speed change of ``vehicle`` during ``step`` is made, inside a phase that asks it
    to hold one speed (``Location.steady``) and after that phase's first step, toward a speed it is
    asked to drive toward only later in the run."""
    here = automaton.location(where[step - 1])
    if vehicle not in here.steady() or step < 2 or where[step - 2] != where[step - 1]:
        return False
    before, after = plan.at(vehicle, step - 1).speed, plan.at(vehicle, step).speed
    for later in dict.fromkeys(where[step:]):
        band = automaton.location(later).toward(vehicle)
        if later != where[step - 1] and band is not None:
            target = (band.low + band.high) / 2
            return abs(after - target) < abs(before - target)
    return False


def said_unasked(plan: Plan, automaton: SymbolicAutomaton, registry) -> list[str]:
    """Each unasked change of ``plan`` in a user's terms: lanes numbered as the file's dialect
    numbers them (``registry.lane_number``), speeds in m/s and kph. What ``roadlogic plan`` and
    ``run`` print and the pytest item's ``unasked_changes`` property holds."""
    lane_number = functools.partial(registry.lane_number, lanes=plan.lanes)
    return [change.described(lane_number) for change in unasked_changes(plan, automaton)]


def _toward(before: float, after: float, low: float, high: float) -> bool:
    """Whether a change of speed from ``before`` to ``after`` moves toward the band ``low..high``
    without passing it (within ``SPEED_TOLERANCE_STEP``)."""
    if before <= high and after >= before:
        return after <= high + SPEED_TOLERANCE_STEP
    if before >= low and after <= before:
        return after >= low - SPEED_TOLERANCE_STEP
    return False


def _brakes_for_ahead(plan: Plan, vehicle: str, step: int) -> bool:
    """Whether, during ``step``, ``vehicle`` may brake for a vehicle (or an obstacle) ahead of it in
    its lane: the lane it is in at the step's end, or at its start when it stays in that lane (a
    car pulling out from behind another does not brake for it). The other vehicle occupies both
    lanes in a step in which it changes lane (a move across the line, as the planner and the
    simulation have it)."""
    if _ahead_in_lane(plan, vehicle, step):
        return True
    stays = plan.at(vehicle, step).lane == plan.at(vehicle, step - 1).lane
    return stays and bool(_ahead_in_lane(plan, vehicle, step - 1))


def _ahead_in_lane(plan: Plan, vehicle: str, step: int) -> list[str]:
    """The vehicles (and obstacles) ahead of ``vehicle`` at ``step`` in the lane it is in."""
    lane = plan.at(vehicle, step).lane
    position = plan.at(vehicle, step).position
    return [
        other
        for other in plan.vehicles
        if other != vehicle and lane in _occupied(plan, other, step) and plan.at(other, step).position > position
    ]


def _occupied(plan: Plan, vehicle: str, step: int) -> set[int]:
    lanes = {plan.at(vehicle, step).lane}
    if step > 0:
        lanes.add(plan.at(vehicle, step - 1).lane)
    return lanes
