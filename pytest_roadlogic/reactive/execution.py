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

from ..planning.plan import Plan, PlanState
from ..simulation.driver import VehicleState
from ..simulation.reference import Reference, references
from ..simulation.road import Road
from .replanner import Replan, Replanner


class ReactiveExecution:
    """The ``react`` of one simulation: replans ``plan`` every ``period`` seconds (whole planning steps)."""

    def __init__(self, replanner: Replanner, plan: Plan, period: float) -> None:
        self.replanner = replanner
        self.plan = plan
        self.every = max(1, int(round(period / plan.dt)))  # planning steps between replans
        self.replans: list[Replan] = []

    def __call__(
        self, time: float, states: dict[str, VehicleState], road: Road, driven: dict[str, Reference]
    ) -> dict[str, Reference] | None:
        plan = self.plan
        step = time / plan.dt
        if abs(step - round(step)) > 1e-6:
            return None
        step = int(round(step))
        # not at the start (the plan starts where the vehicles are), not once the plan has ended
        if step == 0 or step % self.every or step >= plan.horizon:
            return None
        observed = {v: PlanState(s.x, road.lane_at(s.y), s.speed) for v, s in states.items()}
        replan = self.replanner.replan(plan, step, observed)
        self.replans.append(replan)
        if replan.plan is None:
            return None
        self.plan = replan.plan
        now = step * plan.dt
        planned = references(replan.plan, road)
        return {
            vehicle: _spliced(driven[vehicle], planned[vehicle], now)
            for vehicle in plan.vehicles
            if vehicle != self.replanner.dut and vehicle not in plan.stationary
        }


def _spliced(old: Reference, new: Reference, now: float) -> Reference:
    """``old``'s waypoints before ``now`` and ``new``'s from it on."""
    waypoints = [w for w in old.waypoints if w.time < now - 1e-9] + [w for w in new.waypoints if w.time >= now - 1e-9]
    return Reference(old.vehicle, old.runup, old.runup_acceleration, waypoints, old.road)


def replanning_seconds(replans: list[Replan]) -> tuple[float, float]:
    """(median, 95th percentile) seconds per replan; (nan, nan) without any."""
    seconds = sorted(r.seconds for r in replans)
    if not seconds:
        return math.nan, math.nan
    return seconds[len(seconds) // 2], seconds[min(len(seconds) - 1, math.ceil(0.95 * len(seconds)) - 1)]
