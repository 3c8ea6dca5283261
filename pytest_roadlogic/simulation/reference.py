"""From a plan to what each driver tracks: timed waypoints and a smooth reference motion.

Every vehicle starts from standstill (as in the paper) when the plan has a run-up; a plan without
one (``Plan.runup == 0``, the continuous encoding's) is simulated from its first state. The plan's step 0 is the moment the
scenario starts, with the vehicles already moving, so the simulation begins with a *run-up*: all
vehicles leave standstill together, accelerate at one common rate until each reaches its own
step-0 speed, then cruise, arriving at their step-0 states together at ``runup`` seconds. Two
vehicles are equally fast while both accelerate and one pulls away (or closes in) after, so every
gap changes monotonically; the planner has made it safe at both ends (asp/grid/domain.lp, asp/continuous/dynamics.lp).

After the run-up the reference passes through every plan waypoint (position and speed, by cubic
Hermite interpolation) and moves laterally to the planned lane; a lane change between plan steps
k-1 and k is a smooth 3 s move centred half-way between them, so the centre crosses the lane line
between the two steps, as the plan says.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..planning.plan import Plan
from ..roads.road import Road

LANE_CHANGE_DURATION = 3.0  # s; fits between two lane changes (3 planning steps apart)
# s simulated after the plan's last step: the scenario's last phase may end then if its duration
# allows, and a car braking to a stop settles a little after its plan does (docs/decisions.md)
TAIL = 4.0
# m/s^2: a change of a brisk vehicle's planned acceleration (``Plan.brisk``) from one step to the
# next larger than a gentle plan's (the continuous encoding's 2 m/s^3 over its 1 s step): a step
# into braking or speeding up that the scenario asks, which its driver acts on at that instant
ONSET = 3.0
STANDSTILL = 0.1  # m/s: a reference this slow has stopped


@dataclass(frozen=True)
class Waypoint:
    """Where a vehicle should be at a time: a goal of its driver.

    The goal is reached when the vehicle's centre is within ``reach`` metres of ``position`` in
    ``lane`` at some instant of the time window ``time ± window``: half a planning step either way,
    so that consecutive windows meet but do not overlap.
    """

    time: float
    position: float
    lane: int
    speed: float
    window: float = 0.5  # s
    reach: float = 2.0  # m

    @property
    def earliest(self) -> float:
        return self.time - self.window

    @property
    def latest(self) -> float:
        return self.time + self.window

    def reached(self, time: float, x: float, lane: int) -> bool:
        return (
            self.earliest - 1e-9 <= time <= self.latest + 1e-9
            and lane == self.lane
            and abs(x - self.position) <= self.reach
        )


@dataclass
class Reference:
    """One vehicle's reference motion; ``s``/``v``/``d`` accept arrays of times."""

    vehicle: str
    runup: float
    runup_acceleration: float
    waypoints: list[Waypoint]
    road: Road
    brisk: bool = False  # whether the plan may step its acceleration (``Plan.brisk``): then it has onsets

    def __post_init__(self) -> None:
        self._times = np.array([w.time for w in self.waypoints])
        self._pos = np.array([w.position for w in self.waypoints])
        self._vel = np.array([w.speed for w in self.waypoints])
        if self.brisk:
            self._stop_at_rate()
        self._lanes = [w.lane for w in self.waypoints]
        speed, rate = self._vel[0], self.runup_acceleration
        # seconds into the run-up when the vehicle stops accelerating (never, with no run-up's rate)
        self._cruise_from = speed / rate if rate > 0 else np.inf
        # without a run-up the simulation starts in the plan's first state (the scenario's first
        # instant is the simulation's); with one, from standstill that far behind it
        self.runup_distance = speed * self.runup - speed**2 / (2 * rate) if self.runup > 0 else 0.0
        self.start_position = self._pos[0] - self.runup_distance
        self.start_speed = 0.0 if self.runup > 0 else float(speed)
        # the waypoint times at which the planned acceleration steps by more than ONSET: a driver
        # acts on such a change when it comes, not before (a smooth tracker that looks ahead brakes
        # early, and a phase asking the speed it held ends before its time); a standstill is none
        # (a car braking to a standstill keeps braking into it: no change it waits for)
        self.onsets = self._times[:0]
        if self.brisk:
            steps = np.diff(self._vel) / np.maximum(np.diff(self._times), 1e-9)
            jumps = np.abs(np.diff(np.concatenate([[0.0], steps])))
            self.onsets = self._times[:-1][(jumps > ONSET) & (self._vel[:-1] > STANDSTILL)]

    def _stop_at_rate(self) -> None:
        """A car braking briskly to a standstill stops at its braking rate. Its plan, in whole
        steps, reaches the standstill at the end of a step and so brakes gently over that last one
        (from 2 m/s to 0 in 1 s, where it braked at 6 m/s^2 before): tracked as planned, the car
        crept to a stop and its mean rate fell short of the asked one. The motion instead brakes on
        at the step before's rate and stands where that stops it (short of the planned place by at
        most half the last step's distance), standing there while the plan stands."""
        times, pos, vel = list(self._times), list(self._pos), list(self._vel)
        k = 1
        while k < len(vel) - 1:
            rate = (vel[k - 1] - vel[k]) / (times[k] - times[k - 1])
            last = (vel[k] - vel[k + 1]) / (times[k + 1] - times[k])
            if vel[k] > STANDSTILL and vel[k + 1] <= STANDSTILL and rate > last + 1e-6 and rate > ONSET:
                stop_time = times[k] + vel[k] / rate
                stop = pos[k] + vel[k] ** 2 / (2 * rate)
                times.insert(k + 1, stop_time)
                pos.insert(k + 1, stop)
                vel.insert(k + 1, 0.0)
                j = k + 2
                while j < len(vel) and vel[j] <= STANDSTILL:
                    pos[j] = stop
                    j += 1
                k = j
                continue
            k += 1
        self._times, self._pos, self._vel = np.array(times), np.array(pos), np.array(vel)

    def next_onset(self, time: float) -> float:
        """The first onset after ``time`` (s), or infinity."""
        later = self.onsets[self.onsets > time + 1e-9]
        return float(later[0]) if len(later) else np.inf

    @property
    def end_time(self) -> float:
        return float(self._times[-1])

    def s(self, t) -> np.ndarray:
        return self._evaluate(np.asarray(t, dtype=float))[0]

    def v(self, t) -> np.ndarray:
        return self._evaluate(np.asarray(t, dtype=float))[1]

    def position_and_speed(self, t) -> tuple[np.ndarray, np.ndarray]:
        """``s(t)`` and ``v(t)`` in one evaluation (a driver that reads both every cycle)."""
        return self._evaluate(np.asarray(t, dtype=float))

    def _evaluate(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        s = np.empty_like(t)
        v = np.empty_like(t)
        run = t < self.runup
        if run.any():
            tr = np.clip(t[run], 0, None)
            rate, speed = self.runup_acceleration, self._vel[0]
            accelerating = tr < self._cruise_from
            s[run] = self.start_position + np.where(
                accelerating, rate * tr**2 / 2, speed**2 / (2 * rate) + speed * (tr - self._cruise_from)
            )
            v[run] = np.where(accelerating, rate * tr, speed)
        plan = (~run) & (t <= self._times[-1])
        if plan.any():
            s[plan], v[plan] = _hermite(t[plan], self._times, self._pos, self._vel)
        tail = t > self._times[-1]
        if tail.any():
            s[tail] = self._pos[-1] + self._vel[-1] * (t[tail] - self._times[-1])
            v[tail] = self._vel[-1]
        return s, v

    def d(self, t) -> np.ndarray:
        """Reference lateral position (y of the centre)."""
        t = np.asarray(t, dtype=float)
        y = np.full_like(t, self.road.center_y(self._lanes[0]))
        for k in range(1, len(self._lanes)):
            if self._lanes[k] == self._lanes[k - 1]:
                continue
            middle = (self._times[k - 1] + self._times[k]) / 2
            u = np.clip((t - middle) / LANE_CHANGE_DURATION + 0.5, 0, 1)
            step = self.road.center_y(self._lanes[k]) - self.road.center_y(self._lanes[k - 1])
            y = y + step * (10 * u**3 - 15 * u**4 + 6 * u**5)
        return y


def references(plan: Plan, road: Road) -> dict[str, Reference]:
    duration = plan.runup
    result = {}
    for vehicle in plan.vehicles:
        waypoints = [
            Waypoint(duration + k * plan.dt, s.position, s.lane, s.speed, window=plan.dt / 2)
            for k, s in enumerate(plan.states[vehicle])
        ]
        result[vehicle] = Reference(
            vehicle, duration, plan.runup_acceleration, waypoints, road, brisk=vehicle in plan.brisk
        )
    return result


def _hermite(t: np.ndarray, times: np.ndarray, pos: np.ndarray, vel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    index = np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(times) - 2)
    t0, t1 = times[index], times[index + 1]
    h = t1 - t0
    u = (t - t0) / h
    p0, p1, m0, m1 = pos[index], pos[index + 1], vel[index] * h, vel[index + 1] * h
    h00, h10, h01, h11 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u, -2 * u**3 + 3 * u**2, u**3 - u**2
    s = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1
    dh00, dh10, dh01, dh11 = 6 * u**2 - 6 * u, 3 * u**2 - 4 * u + 1, -6 * u**2 + 6 * u, 3 * u**2 - 2 * u
    v = (dh00 * p0 + dh10 * m0 + dh01 * p1 + dh11 * m1) / h
    return s, v
