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

from ..dimensions import CAR_LENGTH
from ..planning.plan import Plan
from ..roads.road import Road
from .driver import CrossTraffic, Driver, StationaryDriver, Trajectory, VehicleState, complete
from .geometry import boxes_overlap, corners
from .interface import DriverFactory, GoalRecord, Reaction, Simulation, SimulationLimits, SimulationTimeout
from .reference import TAIL, Reference, Waypoint, references
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


def _road_around(refs: dict[str, Reference], road: Road, beyond: float = 60.0) -> Road:
    """``road`` (the plan's lanes) long enough for every reference and ``beyond`` metres more."""
    start = min(r.start_position for r in refs.values())
    end = max(r.s(r.end_time + TAIL) for r in refs.values())
    return dataclasses.replace(road, x_start=math.floor(start - 30.0), x_end=math.ceil(float(end) + beyond))


class _Lockstep:
    """One run of the loop: ``__init__`` sets the drivers and the road up, ``step`` drives every
    vehicle one step on (after the reaction, if any), ``record`` writes the states at a step into
    the trace's columns, ``simulation`` closes the run."""

    def __init__(
        self,
        plan: Plan,
        dt: float,
        drivers: DriverFactory | None,
        default: Callable[[], Driver],
        held: Callable[[Reference, Road], bool],
        react: Reaction | None,
    ) -> None:
        self.plan, self.dt, self.react = plan, dt, react
        # a reference reads only the lanes' centre lines, not the road's extent: build them once and
        # size the road around them. On a map the lanes are as wide as the route's (a car in a lane
        # is at its centre there)
        route = plan.route
        lanes = Road(plan.lanes) if route is None else Road(plan.lanes, lane_width=route.lane_width)
        self.refs = refs = references(plan, lanes)
        # a replan may lengthen the run: room for about ten more seconds at highway speed
        beyond = 60.0 if react is None else 400.0
        own = {v: r for v, r in refs.items() if v not in plan.side_routes}
        road = _road_around(own or refs, lanes, beyond)
        if route is not None:  # on a map: where the plan placed itself on the route
            shift = plan.origin if plan.origin is not None else -road.x_start
            road = dataclasses.replace(road, route=route, route_shift=shift)
        self.road = road
        # each vehicle's road: the scenario's, or for a vehicle of another route of the map (a
        # different way through a junction) that route's, where the plan placed it
        self.roads = {v: road for v in refs}
        by_route: dict[tuple, list[str]] = {}
        for vehicle, (side, origin) in plan.side_routes.items():
            by_route.setdefault((id(side), origin), []).append(vehicle)
        for vehicles in by_route.values():
            side, origin = plan.side_routes[vehicles[0]]
            around = _road_around({v: refs[v] for v in vehicles}, Road(plan.lanes, lane_width=side.lane_width), beyond)
            side_road = dataclasses.replace(around, route=side, route_shift=origin)
            self.roads.update(dict.fromkeys(vehicles, side_road))
        self.active: dict[str, Driver] = {}
        for vehicle, reference in refs.items():
            if vehicle in plan.stationary or held(reference, self.roads[vehicle]):
                driver = StationaryDriver()
            else:
                driver = complete((drivers(vehicle) if drivers else None) or default())
            self.active[vehicle] = driver
        readers = {vehicle for vehicle, driver in self.active.items() if driver.reads_others}
        for vehicle, driver in self.active.items():
            driver.predicts(bool(readers - {vehicle}))
            driver.start(vehicle, refs[vehicle], self.roads[vehicle], dt)
        self.steps = self.last_step()
        self.states = {
            v: VehicleState(r.start_position, self.roads[v].center_y(r.waypoints[0].lane), 0.0, r.start_speed, 0.0)
            for v, r in refs.items()
        }
        self.predictions = {v: Trajectory.standing(s) for v, s in self.states.items()}
        self.columns = {
            v: {c: np.zeros(self.steps + 1) for c in ("x", "y", "heading", "speed", "acceleration", "lane")}
            for v in refs
        }
        self.incidents: list[Incident] = []
        self.goals = {v: _GoalSequence(r.waypoints) for v, r in refs.items() if v not in plan.stationary}
        self.crossings = _crossings(self.roads)

    def last_step(self) -> int:
        """The run lasts as long as the longest reference, and ``TAIL`` after."""
        return int(round((max(r.end_time for r in self.refs.values()) + TAIL) / self.dt))

    def record(self, k: int) -> None:
        """The states at step ``k``: their columns, the goals reached, the incidents (two vehicles
        of different routes compared in the world)."""
        time, roads, states = k * self.dt, self.roads, self.states
        for v, s in states.items():
            col = self.columns[v]
            col["x"][k], col["y"][k], col["heading"][k] = s.x, s.y, s.heading
            col["speed"][k], col["acceleration"][k], col["lane"][k] = s.speed, s.acceleration, roads[v].lane_at(s.y)
            if v in self.goals:
                self.goals[v].update(time, s.x, int(col["lane"][k]))
        names = list(states)
        for i, a in enumerate(names):
            if not roads[a].on_road(corners(states[a])) and not roads[a].on_junction(
                corners(_in_world(states[a], roads[a]))
            ):
                self.incidents.append(Incident(time, "off-road", (a,)))
            for b in names[i + 1 :]:
                if roads[a] is roads[b]:
                    touching = boxes_overlap(states[a], states[b])
                else:
                    touching = boxes_overlap(_in_world(states[a], roads[a]), _in_world(states[b], roads[b]))
                if touching:
                    self.incidents.append(Incident(time, "collision", (a, b)))

    def step(self, k: int) -> None:
        """Drive every vehicle from step ``k - 1`` to ``k``: the reaction's new references first
        (their drivers ``retarget``), then every driver plans from the same snapshot."""
        time = (k - 1) * self.dt
        retargeted = self.react(time, self.states, self.road, self.refs, self.roads) if self.react is not None else None
        for v, reference in (retargeted or {}).items():
            self.refs[v] = reference
            self.active[v].retarget(v, reference, self.roads[v], self.dt)
            self.goals[v].retarget(reference.waypoints, time)
        if retargeted:
            self.steps = max(self.steps, self.last_step())
            for col in self.columns.values():
                for name, values in col.items():
                    if len(values) < self.steps + 1:
                        col[name] = np.concatenate([values, np.zeros(self.steps + 1 - len(values))])
        chosen = {}
        for v, driver in self.active.items():
            # a driver sees the vehicles of its own route (road coordinates are a route's own), and
            # those of other routes as they come to where their ways meet its own
            others = {o: p for o, p in self.predictions.items() if o != v and self.roads[o] is self.roads[v]}
            if v in self.crossings:
                driver.see(self.cross_traffic(v))
            chosen[v] = driver.plan(time, self.states[v], others)
        for v, trajectory in chosen.items():
            self.states[v] = trajectory.state(1)
            self.predictions[v] = trajectory.shifted()

    def cross_traffic(self, vehicle: str) -> tuple[CrossTraffic, ...]:
        """The vehicles of other routes whose ways meet ``vehicle``'s ahead of it, each with the
        meeting and how far it has to go to it; a vehicle past a meeting is no longer in it."""
        own = self.states[vehicle]
        seen = []
        for other, start, end, other_start, length, kind in self.crossings[vehicle]:
            state = self.states[other]
            distance = other_start - state.x
            if end < own.x - CAR_LENGTH or distance < -(length + CAR_LENGTH):
                continue
            seen.append(CrossTraffic(other, kind, start, end, distance, length, state.speed, state.acceleration))
        return tuple(seen)

    def simulation(self) -> Simulation:
        """The run's ``Simulation``: its trace (world coordinates too on a map), goals and replans."""
        columns, road = self.columns, self.road
        for v in columns:
            columns[v]["lane"] = columns[v]["lane"].astype(int)
            if road.route is not None:
                col = columns[v]
                col["world_x"], col["world_y"], col["world_heading"] = self.roads[v].world(
                    col["x"], col["y"], col["heading"]
                )
        trace = Trace(np.round(np.arange(self.steps + 1) * self.dt, 6), columns, _merge(self.incidents))
        for sequence in self.goals.values():
            sequence.update(math.inf, math.nan, -1)  # windows still open at the end are misses
        return Simulation(
            trace,
            road,
            self.refs,
            self.dt,
            {v: d.fallbacks for v, d in self.active.items()},
            tuple(self.plan.stationary),
            {v: g.records for v, g in self.goals.items()},
            list(self.react.replans) if self.react is not None else [],
            {v: r for v, r in self.roads.items() if r is not road},
        )


def _crossings(roads: dict[str, Road]) -> dict[str, list[tuple[str, float, float, float, float, str]]]:
    """Per vehicle on a map whose route meets another vehicle's: (that vehicle, where the meeting
    begins and ends on this one's road, where it begins on that one's road, its length there, its
    kind) for each meeting of the two routes (``roads.conflicts``)."""
    found: dict[str, list] = {}
    if len({id(road) for road in roads.values() if road.route is not None}) < 2:
        return found  # one road or none on a map's routes: nothing meets (and no geometry to import)
    from ..roads.conflicts import conflicts

    for v, road in roads.items():
        for o, other in roads.items():
            if other is road or road.route is None or other.route is None:
                continue
            for meeting in conflicts((road.route, other.route)):
                (a, b), (c, d) = meeting.first_span, meeting.second_span
                shift, other_shift = road.route_shift, other.route_shift
                found.setdefault(v, []).append((o, a - shift, b - shift, c - other_shift, d - c, meeting.kind))
    return found


def _in_world(state: VehicleState, road: Road) -> VehicleState:
    """``state`` (road coordinates of ``road``) in the map's coordinates."""
    x, y, heading = (float(v) for v in road.world(state.x, state.y, state.heading))
    return dataclasses.replace(state, x=x, y=y, heading=heading)


def drive_in_lockstep(
    plan: Plan,
    limits: SimulationLimits,
    drivers: DriverFactory | None,
    default: Callable[[], Driver],
    react: Reaction | None = None,
    held: Callable[[Reference, Road], bool] = lambda reference, road: False,
) -> Simulation:
    """Drive every vehicle of ``plan`` from standstill through its waypoints.

    ``drivers`` maps a vehicle name to a custom driver (or ``None`` for ``default()``); stationary
    objects, and those the backend holds (``held``), are never driven. ``limits.time_limit``
    (seconds of wall clock) bounds a run whose driver (a plugged-in one, say) is far slower than
    expected; it raises ``SimulationTimeout``. ``react`` (reactive execution) is asked at every
    step, before the drivers plan, for new references of some vehicles: their drivers follow
    those from then on (``Driver.retarget``), and the run lasts as long as the longest reference.
    """
    deadline = clock.monotonic() + limits.time_limit if limits.time_limit is not None else math.inf
    run = _Lockstep(plan, limits.dt, drivers, default, held, react)
    run.record(0)
    k = 0
    while k < run.steps:
        k += 1
        if clock.monotonic() > deadline:
            raise SimulationTimeout(
                f"the simulation took over its limit of {limits.time_limit:g} s at {k * limits.dt:.1f} s of "
                f"{run.steps * limits.dt:.1f} s simulated"
            )
        run.step(k)
        run.record(k)
    return run.simulation()


class LockstepSimulator:
    """A backend built on per-vehicle drivers: the lockstep loop with ``default_driver`` for every
    vehicle no user's driver drives (``frenetix``, ``kinematic``)."""

    name: str
    default_driver: Callable[[], Driver]

    def holds(self, reference: Reference, road: Road) -> bool:
        """Whether this backend holds the vehicle of ``reference`` still instead of driving it (a
        quirk of its driver's); none by default."""
        return False

    def simulate(
        self, plan: Plan, limits: SimulationLimits, drivers: DriverFactory | None = None, react: Reaction | None = None
    ) -> Simulation:
        return drive_in_lockstep(plan, limits, drivers, self.default_driver, react, self.holds)


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
