"""The lockstep loop: every vehicle driven by its own ``Driver`` at the same instants, the trace recorded.

All drivers plan at the same instants from the same snapshot: each sees the others' trajectories
of the previous cycle as predictions. Collisions (oriented-box overlap) and off-road states are
recorded in the trace as incidents rather than stopping the run, so that the monitor can explain them.
A backend built on per-vehicle drivers (the frenetix one) runs this loop with its default driver.
"""

from __future__ import annotations

import dataclasses
import math
import time as clock
from collections.abc import Callable

import numpy as np

from ..planning.plan import Plan
from .driver import Driver, StationaryDriver, Trajectory, VehicleState
from .geometry import boxes_overlap, corners
from .interface import DriverFactory, GoalRecord, Simulation, SimulationLimits, SimulationTimeout
from .reference import TAIL, Reference, Waypoint, references
from .road import Road
from .trace import Incident, Trace


class _GoalSequence:
    """A vehicle's waypoints as a sequence of goals: the current one is replaced by the next as
    soon as it is reached, or when its time window has passed (a miss)."""

    def __init__(self, waypoints: list[Waypoint]) -> None:
        self.waypoints = waypoints
        self.records: list[GoalRecord] = []

    @property
    def current(self) -> Waypoint | None:
        return self.waypoints[len(self.records)] if len(self.records) < len(self.waypoints) else None

    def retarget(self, waypoints: list[Waypoint], now: float) -> None:
        """Goals from ``now`` on are ``waypoints``' (a replan); those reached or missed stay as they were."""
        self.waypoints = [record.waypoint for record in self.records] + [w for w in waypoints if w.latest >= now]

    def update(self, time: float, x: float, lane: int) -> None:
        while (goal := self.current) is not None:
            if goal.reached(time, x, lane):
                self.records.append(GoalRecord(goal, round(time, 6)))
            elif time > goal.latest + 1e-9:
                self.records.append(GoalRecord(goal, None))
            else:
                return


def _road_around(refs: dict[str, Reference], lanes: int, beyond: float = 60.0) -> Road:
    start = min(r.start_position for r in refs.values())
    end = max(r.s(r.end_time + TAIL) for r in refs.values())
    return Road(lanes, x_start=math.floor(start - 30.0), x_end=math.ceil(float(end) + beyond))


# a reaction to the vehicles' states at a time: new references for some vehicles, from then on
React = Callable[[float, dict[str, VehicleState], Road, dict[str, Reference]], "dict[str, Reference] | None"]


def drive_in_lockstep(
    plan: Plan,
    limits: SimulationLimits,
    drivers: DriverFactory | None,
    default: Callable[[], Driver],
    react: React | None = None,
) -> Simulation:
    """Drive every vehicle of ``plan`` from standstill through its waypoints.

    ``drivers`` maps a vehicle name to a custom driver (or ``None`` for ``default()``); stationary
    objects are never driven. ``limits.time_limit`` (seconds of wall clock) bounds a run whose
    driver (a plugged-in one, say) is far slower than expected; it raises ``SimulationTimeout``.
    ``react`` (reactive execution, ``pytest_roadlogic.reactive``) is asked at every step, before the
    drivers plan, for new references of some vehicles: their drivers follow those from then on
    (``retarget``, else ``start`` again), and the run lasts as long as the longest reference.
    """
    dt, time_limit = limits.dt, limits.time_limit
    deadline = clock.monotonic() + time_limit if time_limit is not None else math.inf
    lanes = plan.lanes
    # a reference reads only the lanes' centre lines, not the road's extent: build them once and
    # size the road around them
    refs = references(plan, Road(lanes))
    # a replan may lengthen the run: room for about ten more seconds at highway speed
    road = _road_around(refs, lanes, 60.0 if react is None else 400.0)
    if plan.route is not None:  # on a map: where the plan placed itself on the route
        shift = plan.origin if plan.origin is not None else -road.x_start
        road = dataclasses.replace(road, route=plan.route, route_shift=shift)
    active: dict[str, Driver] = {}
    for vehicle, reference in refs.items():
        if vehicle in plan.stationary or (road.route is not None and _held_still(reference)):
            driver = StationaryDriver()
        else:
            driver = (drivers(vehicle) if drivers else None) or default()
        driver.start(vehicle, reference, road, dt)
        active[vehicle] = driver

    def last_step() -> int:  # the run lasts as long as the longest reference, and TAIL after
        return int(round((max(r.end_time for r in refs.values()) + TAIL) / dt))

    steps = last_step()
    states = {
        v: VehicleState(r.start_position, road.center_y(r.waypoints[0].lane), 0.0, r.start_speed, 0.0)
        for v, r in refs.items()
    }
    predictions = {v: Trajectory.standing(s) for v, s in states.items()}
    columns = {
        v: {c: np.zeros(steps + 1) for c in ("x", "y", "heading", "speed", "acceleration", "lane")} for v in refs
    }
    incidents: list[Incident] = []
    goals = {v: _GoalSequence(r.waypoints) for v, r in refs.items() if v not in plan.stationary}

    def record(k: int) -> None:
        time = k * dt
        for v, s in states.items():
            col = columns[v]
            col["x"][k], col["y"][k], col["heading"][k] = s.x, s.y, s.heading
            col["speed"][k], col["acceleration"][k], col["lane"][k] = s.speed, s.acceleration, road.lane_at(s.y)
            if v in goals:
                goals[v].update(time, s.x, int(col["lane"][k]))
        names = list(states)
        for i, a in enumerate(names):
            if not road.on_road(corners(states[a])):
                incidents.append(Incident(time, "off-road", (a,)))
            for b in names[i + 1 :]:
                if boxes_overlap(states[a], states[b]):
                    incidents.append(Incident(time, "collision", (a, b)))

    record(0)
    k = 0
    while k < steps:
        k += 1
        if clock.monotonic() > deadline:
            raise SimulationTimeout(
                f"the simulation took over its limit of {time_limit:g} s at {k * dt:.1f} s of {steps * dt:.1f} s simulated"
            )
        time = (k - 1) * dt
        retargeted = react(time, states, road, refs) if react is not None else None
        for v, reference in (retargeted or {}).items():
            refs[v] = reference
            driver = active[v]
            if hasattr(driver, "retarget"):
                driver.retarget(reference)
            else:
                driver.start(v, reference, road, dt)
            goals[v].retarget(reference.waypoints, time)
        if retargeted:
            steps = max(steps, last_step())
            for col in columns.values():
                for name, values in col.items():
                    if len(values) < steps + 1:
                        col[name] = np.concatenate([values, np.zeros(steps + 1 - len(values))])
        chosen = {}
        for v, driver in active.items():
            others = {o: p for o, p in predictions.items() if o != v}
            chosen[v] = driver.plan(time, states[v], others)
        for v, trajectory in chosen.items():
            states[v] = trajectory.state(1)
            predictions[v] = trajectory.shifted()
        record(k)
    for v in columns:
        columns[v]["lane"] = columns[v]["lane"].astype(int)
        if road.route is not None:
            col = columns[v]
            col["world_x"], col["world_y"], col["world_heading"] = road.world(col["x"], col["y"], col["heading"])
    trace = Trace(np.round(np.arange(steps + 1) * dt, 6), columns, _merge(incidents))
    fallbacks = {v: getattr(d, "fallbacks", 0) for v, d in active.items()}
    for sequence in goals.values():
        sequence.update(math.inf, math.nan, -1)  # windows still open at the end are misses
    return Simulation(
        trace,
        road,
        refs,
        dt,
        fallbacks,
        tuple(plan.stationary),
        {v: g.records for v, g in goals.items()},
        list(getattr(react, "replans", [])),
    )


class LockstepSimulator:
    """A backend built on per-vehicle drivers: the lockstep loop with ``default_driver`` for every
    vehicle no user's driver drives (``frenetix``, ``kinematic``)."""

    name: str
    default_driver: Callable[[], Driver]

    def simulate(
        self, plan: Plan, limits: SimulationLimits, drivers: DriverFactory | None = None, react=None
    ) -> Simulation:
        return drive_in_lockstep(plan, limits, drivers, self.default_driver, react)


def _held_still(reference: Reference) -> bool:
    """Whether a plan holds a vehicle at a standstill throughout (``remain_stationary``). On a map
    such a car is held, not driven: frenetix lets a car standing in a curve creep (0.1 m/s, 0.3 m
    in 10 s in the 500 m curve; none on the straight road, where it keeps driving them)."""
    return all(abs(w.speed) < STILL for w in reference.waypoints)


# m/s below which a planned vehicle counts as standing still (remain_stationary's bound is 0.1)
STILL = 0.2


def _merge(incidents: list[Incident]) -> list[Incident]:
    """Keep the first instant of each continuing incident."""
    merged: list[Incident] = []
    last: dict[tuple, float] = {}
    for incident in incidents:
        key = (incident.kind, incident.actors)
        if key not in last or incident.time - last[key] > 0.15:
            merged.append(incident)
        last[key] = incident.time
    return merged
