"""Reference vehicles under test: adaptive cruise control with lane keeping, and three defective ones.

``AdaptiveCruiseControl`` is a ``simulation.Driver`` that is given a goal, not a script: it keeps
the lane it starts in and cruises at its set speed (the speed its plan starts it at, one the
scenario's constraints on it allow), following the vehicle ahead in its path by the ACC
model of Kesting, Treiber and Helbing (2010): the intelligent driver model (IDM, Treiber,
Hennecke and Helbing 2000)

    a_IDM = a_max * (1 - (v / v0)^4 - (s* / s)^2),   s* = s0 + v T + v dv / (2 sqrt(a_max b))

(s the gap to the vehicle ahead, bumper to bumper; dv the speed at which it closes in), blended
with the constant-acceleration heuristic a_CAH where the IDM would brake harder than the
situation needs: a car that cuts in close ahead but drives away faster is not braked for as if it
stood (the IDM alone braked at 8 m/s^2 for a car cutting in 5 m ahead at 3 m/s faster). Behind
one that brakes it brakes at least as hard as stopping ``standstill_gap`` behind where that one
stops takes. It brakes
harder than b when it must, down to ``max_braking``. Its waypoints are read for its start lane
and speed only.

On a map it also drives as its route asks: it slows for a sharp bend (a turn at a junction) to
the speed the bend's lanes allow (``Route.slow_stretches``), and it gives way at a crossing: a car
of another way that would be in the crossing (``CrossTraffic``) from less than ``crossing_gap``
seconds after it would have left it, at its speed and accelerating as it can, makes it stop a
metre short of the crossing until that car has passed (a gap-acceptance rule, as traffic
engineering models a driver turning across or into a road); it does not give way once it could no
longer stop short of the crossing. Where its way joins another's lane it gives way likewise (the
car on the lane must not have to close in on it: ``merging_gap``), and follows a car of the other
way that has joined its lane ahead of it.

Four defective variants make failures to find: ``LateAcc`` sees the vehicle ahead 1.5 s late,
``WeakBrakingAcc`` never brakes harder than 3 m/s^2, ``SlowAcquisitionAcc`` sees a vehicle that
enters its path only 2 s after it did, ``NonYieldingAcc`` never gives way at a crossing or where
its way joins another (it sees only the vehicles in its lane).

Why our own and not a package: CommonRoad's IDM planner does not install beside commonroad-io 2026.1
(pip cannot resolve it), and the model is ten lines; what a package would add (its own road
representation) is what this project already has.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass

import numpy as np

from ..dimensions import CAR_LENGTH, CAR_WIDTH
from ..roads.road import Road
from ..simulation.driver import CrossTraffic, DriverBase, Trajectory, VehicleState
from ..simulation.reference import Reference

HORIZON = 3.0  # s of trajectory returned each cycle (what the others see as its prediction)


@dataclass(frozen=True)
class IdmParameters:
    """The intelligent driver model's parameters (highway values from the literature)."""

    time_headway: float = 1.5  # s (T)
    standstill_gap: float = 3.0  # m (s0): where it stops behind a standing car
    max_acceleration: float = 1.5  # m/s^2 (a_max)
    comfortable_braking: float = 2.0  # m/s^2 (b)
    exponent: float = 4.0  # (delta)
    coolness: float = 0.99  # (c) how far the ACC model trusts the constant-acceleration heuristic


class AdaptiveCruiseControl(DriverBase):
    """Adaptive cruise control with lane keeping, a reference vehicle under test (see the module)."""

    idm = IdmParameters()
    reaction_delay = 0.0  # s between seeing the vehicle ahead and acting on it
    max_braking = 8.0  # m/s^2: the hardest it brakes
    yields = True  # whether it gives way to the cars of other ways (see the module)
    crossing_gap = 2.0  # s it leaves between another car in a crossing and itself
    merging_gap = 3.0  # s ahead of a car of the lane it joins, at the least, when it joins ahead
    bend_braking = 1.0  # m/s^2 at which it brakes for a sharp bend ahead, or to stop at a crossing

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.vehicle, self.dt = vehicle, dt
        self.lane_y = road.center_y(reference.waypoints[0].lane)
        self.set_speed = max(float(reference.waypoints[0].speed), 1.0)
        # what it saw each cycle: (time, gap, closing speed, acceleration ahead), read reaction_delay late
        self.seen: deque[tuple[float, float, float, float]] = deque()
        # the sharp bends of its route, in its road's x: (first, last, the speed it takes them at)
        route = road.route
        self.bends = (
            ()
            if route is None
            else tuple((a - road.route_shift, b - road.route_shift, v) for a, b, v in route.slow_stretches)
        )

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        others = {**others, **self._joined(state)}
        self.seen.append((time, *self._ahead(state, others)))
        while len(self.seen) > 1 and self.seen[1][0] <= time - self.reaction_delay + 1e-9:
            self.seen.popleft()
        _, gap, closing, ahead_acceleration = self.seen[0]
        acceleration = min(
            self.acceleration(state.speed, gap, closing, ahead_acceleration),
            self._for_bends(state),
            self._giving_way(state) if self.yields else math.inf,
        )
        acceleration = max(-self.max_braking, min(self.idm.max_acceleration, acceleration))
        return self._trajectory(state, acceleration)

    def _for_bends(self, state: VehicleState) -> float:
        """The acceleration that takes it into the next sharp bend no faster than the bend allows,
        braking evenly once that takes ``bend_braking`` (as a driver brakes for a corner: late, not
        from afar), and holds it to that speed in the bend (inf: no bend ahead)."""
        best = math.inf
        for first, last, speed in self.bends:
            if last < state.x:
                continue
            if first <= state.x:
                best = min(best, (speed - state.speed) / 1.0)
            elif state.speed > speed:
                needed = (state.speed**2 - speed**2) / (2 * max(first - state.x, 0.5))
                if needed >= self.bend_braking:
                    best = min(best, -needed)
        return best

    def _clearing_time(self, state: VehicleState, distance: float) -> float:
        """Seconds it takes to drive ``distance`` metres from ``state``, accelerating as it can
        up to its set speed."""
        a, v = self.idm.max_acceleration, state.speed
        top = max(self.set_speed, v)
        to_top = (top**2 - v**2) / (2 * a)
        if distance <= to_top:
            return (-v + math.sqrt(v * v + 2 * a * distance)) / a
        return (top - v) / a + (distance - to_top) / top

    def _giving_way(self, state: VehicleState) -> float:
        """The acceleration that stops it a metre short of the first meeting where a car of
        another way comes too soon (inf: none does, or it could no longer stop short)."""
        front = state.x + CAR_LENGTH / 2
        best = math.inf
        for other in self.cross_traffic:
            room = other.start - front - 1.0
            if room < 0 or state.speed**2 > 2 * self.max_braking * room * 0.8:
                continue  # in it, or too near to stop short: it goes on
            if not self._comes_too_soon(state, other):
                continue
            if state.speed < 0.1:
                best = min(best, 0.0)  # waiting at the crossing
                continue
            # as a driver stops at a line: on at its speed until stopping there takes bend_braking
            needed = state.speed**2 / (2 * max(room, 0.1))
            if needed >= self.bend_braking:
                best = min(best, -needed)
        return best

    def _comes_too_soon(self, state: VehicleState, other: CrossTraffic) -> bool:
        """Whether ``other`` would be in the meeting while it passes there, or less than the gap
        after (a crossing: until its rear has left; a lane it joins: until it is a gap ahead)."""
        speed = max(other.speed, 0.1)
        leaves = (other.distance + other.length + CAR_LENGTH / 2) / speed
        if leaves < 0:
            return False  # gone past
        arrives = (other.distance - CAR_LENGTH / 2) / speed
        if other.kind == "crossing":
            passed = self._clearing_time(state, other.end - state.x + CAR_LENGTH / 2)
            return arrives < passed + self.crossing_gap
        if other.distance <= 0:
            return False  # in the lane it joins ahead of it: it follows that car (_joined)
        joined = self._clearing_time(state, other.start - state.x + CAR_LENGTH)
        return arrives < joined + self.merging_gap

    def _joined(self, state: VehicleState) -> dict[str, Trajectory]:
        """The cars of another way that have joined its lane ahead of it, as vehicles of its own
        road (where they are along the lane both share)."""
        found = {}
        for other in self.cross_traffic:
            if other.kind != "shared" or other.distance > 0:
                continue
            x = other.start - other.distance
            found[other.vehicle] = Trajectory(
                np.array([x]),
                np.array([self.lane_y]),
                np.array([0.0]),
                np.array([other.speed]),
                np.array([other.acceleration]),
            )
        return found

    def acceleration(self, speed: float, gap: float, closing: float, ahead_acceleration: float = 0.0) -> float:
        """The ACC model's acceleration at ``speed``, ``gap`` (inf: no one ahead) behind a vehicle
        it closes in on at ``closing`` m/s and that accelerates at ``ahead_acceleration``."""
        p = self.idm
        free = 1.0 - (speed / self.set_speed) ** p.exponent
        if not math.isfinite(gap):
            return p.max_acceleration * free
        gap = max(gap, 0.1)
        desired = p.standstill_gap + max(
            0.0, speed * p.time_headway + speed * closing / (2 * math.sqrt(p.max_acceleration * p.comfortable_braking))
        )
        idm = p.max_acceleration * (free - (desired / gap) ** 2)
        # the constant-acceleration heuristic: what keeps it clear if the one ahead keeps accelerating
        lead_speed, lead_acceleration = speed - closing, min(ahead_acceleration, p.max_acceleration)
        if lead_acceleration < 0 and lead_speed * closing <= -2 * gap * lead_acceleration:
            # the one ahead stops before it would be reached
            cah = speed**2 * lead_acceleration / (lead_speed**2 - 2 * gap * lead_acceleration)
        else:
            cah = lead_acceleration - max(closing, 0.0) ** 2 / (2 * gap)
        if closing > 0 and ahead_acceleration < -0.1:
            # the one ahead brakes: at least what stops it standstill_gap behind where that one stops
            # (the blend below is no emergency brake: from 30 m/s 40 m behind a lead braking at
            # 7 m/s^2 it ended at no gap at all)
            room = gap - p.standstill_gap + lead_speed**2 / (2 * -ahead_acceleration)
            emergency = -(speed**2) / (2 * max(room, 0.1))
        else:
            emergency = math.inf
        if idm >= cah:
            return min(idm, emergency)
        b = p.comfortable_braking
        return min((1 - p.coolness) * idm + p.coolness * (cah + b * math.tanh((idm - cah) / b)), emergency)

    def _ahead(self, state: VehicleState, others: dict[str, Trajectory]) -> tuple[float, float, float]:
        """(gap, closing speed, its acceleration) to the nearest vehicle ahead in its path;
        (inf, 0, 0) when there is none."""
        best = (math.inf, 0.0, 0.0)
        for trajectory in others.values():
            other = trajectory.state(0)
            if other.x > state.x and abs(other.y - state.y) < CAR_WIDTH:
                gap = max(other.x - state.x - CAR_LENGTH, 0.0)
                if gap < best[0]:
                    best = (gap, state.speed - other.speed, other.acceleration)
        return best

    def _trajectory(self, state: VehicleState, acceleration: float) -> Trajectory:
        """Constant ``acceleration`` (never below standstill) along its lane's centre, which it
        steers back to within about a second."""
        n = max(2, int(round(HORIZON / self.dt)) + 1)
        t = np.arange(n) * self.dt
        speed = np.maximum(state.speed + acceleration * t, 0.0)
        # distance: integrate the clipped speed (trapezoids), so a stop stays a stop
        x = state.x + np.concatenate([[0.0], np.cumsum((speed[1:] + speed[:-1]) / 2 * self.dt)])
        y = self.lane_y + (state.y - self.lane_y) * np.exp(-t / 0.5)
        heading = np.arctan2(np.gradient(y, self.dt), np.maximum(speed, 0.1))
        heading[0] = state.heading
        # what the speeds do over each step: a car that stops within a step brakes only as hard as
        # stopping takes (a -8 m/s^2 command at 0.01 m/s is no 8 m/s^2 stop)
        applied = np.append(np.diff(speed) / self.dt, acceleration if speed[-1] > 0 else 0.0)
        return Trajectory(x, y, heading, speed, applied)


class LateAcc(AdaptiveCruiseControl):
    """A defective adaptive cruise control: it acts on what it saw 1.5 s before."""

    reaction_delay = 1.5


class WeakBrakingAcc(AdaptiveCruiseControl):
    """A defective adaptive cruise control: it never brakes harder than 3 m/s^2."""

    max_braking = 3.0


class SlowAcquisitionAcc(AdaptiveCruiseControl):
    """A defective adaptive cruise control: when another vehicle becomes the nearest ahead in its
    path, it sees that one only 2 s later (a slow target acquisition: blind to a car that has just
    cut in, or to a stopped one that a car changing lane has just revealed); meanwhile it follows
    the next one ahead, or none."""

    acquisition_delay = 2.0  # s

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        super().start(vehicle, reference, road, dt)
        self.nearest: str | None = None  # the nearest vehicle ahead in its path, and since when
        self.since = 0.0

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        ahead = []
        for name, trajectory in others.items():
            other = trajectory.state(0)
            if other.x > state.x and abs(other.y - state.y) < CAR_WIDTH:
                ahead.append((other.x, name))
        nearest = min(ahead)[1] if ahead else None
        if nearest != self.nearest:
            self.nearest, self.since = nearest, time
        if nearest is not None and time - self.since < self.acquisition_delay - 1e-9:
            others = {name: trajectory for name, trajectory in others.items() if name != nearest}
        return super().plan(time, state, others)


class NonYieldingAcc(AdaptiveCruiseControl):
    """A defective adaptive cruise control: it never gives way to a car of another way, at a
    crossing or where its way joins another's lane (it brakes only for the car ahead in its lane)."""

    yields = False
