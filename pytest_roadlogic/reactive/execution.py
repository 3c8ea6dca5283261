"""Reactive execution: while the simulation runs, the scenario's vehicles are replanned from what
the vehicles really do, every ``period`` seconds (``ReactiveExecution``, the lockstep's ``react``).

The vehicle under test drives itself; every other vehicle follows its plan until the next replan,
which pins every vehicle's observed state at the current step and plans the rest of the scenario
from there (``Replanner``). A vehicle's new reference keeps its old waypoints before now and takes
the replan's from now on. A replan that finds no plan leaves the plan as it is and is recorded
with why: from here the scenario cannot go on (the vehicle under test made it impossible).
"""

from __future__ import annotations

import math

from ..planning.plan import Plan
from ..simulation.driver import VehicleState
from ..simulation.reference import Reference, Waypoint
from ..simulation.road import Road
from .replanner import Observed, Replan, Replanner


class ReactiveExecution:
    """The ``react`` of one simulation: replans ``plan`` every ``period`` seconds (whole planning steps)."""

    def __init__(self, replanner: Replanner, plan: Plan, period: float) -> None:
        self.replanner = replanner
        self.plan = plan
        self.every = max(1, int(round(period / plan.dt)))  # planning steps between replans
        self.replans: list[Replan] = []

    def __call__(
        self, time: float, states: dict[str, VehicleState], road: Road, references: dict[str, Reference]
    ) -> dict[str, Reference] | None:
        plan = self.plan
        step = time / plan.dt
        if abs(step - round(step)) > 1e-6:
            return None
        step = int(round(step))
        # not at the start (the plan starts where the vehicles are), not once the plan has ended
        if step == 0 or step % self.every or step >= plan.horizon:
            return None
        observed = {v: Observed(s.x, s.speed, road.lane_at(s.y)) for v, s in states.items()}
        replan = self.replanner.replan(plan, step, observed)
        self.replans.append(replan)
        if replan.plan is None:
            return None
        self.plan = replan.plan
        return {
            vehicle: _spliced(references[vehicle], replan.plan, vehicle, step)
            for vehicle in plan.vehicles
            if vehicle != self.replanner.dut and vehicle not in plan.stationary
        }


def _spliced(old: Reference, plan: Plan, vehicle: str, step: int) -> Reference:
    """``old``'s waypoints before ``step`` and ``plan``'s from it on."""
    now = step * plan.dt
    kept = [w for w in old.waypoints if w.time < now - 1e-9]
    new = [
        Waypoint(k * plan.dt, s.position, s.lane, s.speed, window=plan.dt / 2)
        for k, s in enumerate(plan.states[vehicle])
        if k >= step
    ]
    return Reference(vehicle, old.runup, old.runup_acceleration, kept + new, old.road)


def replanning_seconds(replans: list[Replan]) -> tuple[float, float]:
    """(median, 95th percentile) seconds per replan; (nan, nan) without any."""
    seconds = sorted(r.seconds for r in replans)
    if not seconds:
        return math.nan, math.nan
    return seconds[len(seconds) // 2], seconds[min(len(seconds) - 1, math.ceil(0.95 * len(seconds)) - 1)]
