"""From a plan to what each driver tracks: timed waypoints and a smooth reference motion.

Every vehicle starts from standstill (as in the paper). The plan's step 0 is the moment the
scenario starts, with the vehicles already moving, so the simulation begins with a *run-up*: all
vehicles accelerate from rest and reach their planned step-0 states together at ``runup`` seconds.
They all cover the same distance in the run-up, so the gaps at standstill equal the planned gaps
at step 0 (which the planner already keeps safe).

After the run-up the reference passes through every plan waypoint (position and speed, by cubic
Hermite interpolation) and moves laterally to the planned lane; a lane change between plan steps
k-1 and k is a smooth 2 s move centred half-way between them, so the centre crosses the lane line
between the two steps, as the plan says.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..planning.plan import Plan
from .road import Road

RUNUP_MAX_ACCELERATION = 2.5  # m/s^2
LANE_CHANGE_DURATION = 2.0  # s
TAIL = 2.0  # s simulated after the plan's last step


@dataclass(frozen=True)
class Waypoint:
    """Where a vehicle should be at a time: a goal of its driver."""

    time: float
    position: float
    lane: int
    speed: float


@dataclass
class Reference:
    """One vehicle's reference motion; ``s``/``v``/``d`` accept arrays of times."""

    vehicle: str
    runup: float
    runup_distance: float
    waypoints: list[Waypoint]
    road: Road
    dt: float

    def __post_init__(self) -> None:
        self._times = np.array([w.time for w in self.waypoints])
        self._pos = np.array([w.position for w in self.waypoints])
        self._vel = np.array([w.speed for w in self.waypoints])
        self._lanes = [w.lane for w in self.waypoints]
        self.start_position = self._pos[0] - self.runup_distance

    @property
    def end_time(self) -> float:
        return float(self._times[-1])

    def s(self, t) -> np.ndarray:
        return self._evaluate(np.asarray(t, dtype=float))[0]

    def v(self, t) -> np.ndarray:
        return self._evaluate(np.asarray(t, dtype=float))[1]

    def _evaluate(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        s = np.empty_like(t)
        v = np.empty_like(t)
        # run-up: quintic from rest to (position, speed) of step 0 with zero end acceleration
        run = t < self.runup
        if run.any():
            s[run], v[run] = _quintic(np.clip(t[run], 0, None), self.runup, self.runup_distance, self._vel[0])
            s[run] += self.start_position
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


def _quintic(t: np.ndarray, duration: float, distance: float, end_speed: float) -> tuple[np.ndarray, np.ndarray]:
    """Rest-to-rest-acceleration quintic: s(0)=v(0)=a(0)=0, s(T)=D, v(T)=v, a(T)=0."""
    T, D, V = duration, distance, end_speed
    # s = c3 t^3 + c4 t^4 + c5 t^5 solving the three end conditions
    A = np.array([[T**3, T**4, T**5], [3 * T**2, 4 * T**3, 5 * T**4], [6 * T, 12 * T**2, 20 * T**3]])
    c3, c4, c5 = np.linalg.solve(A, np.array([D, V, 0.0]))
    return c3 * t**3 + c4 * t**4 + c5 * t**5, 3 * c3 * t**2 + 4 * c4 * t**3 + 5 * c5 * t**4


def _quintic_ok(duration: float, distance: float, end_speed: float) -> bool:
    t = np.linspace(0, duration, 60)
    s, v = _quintic(t, duration, distance, end_speed)
    a = np.gradient(v, t)
    return bool(v.min() >= -1e-6 and a.max() <= RUNUP_MAX_ACCELERATION and a.min() >= -RUNUP_MAX_ACCELERATION)


def runup(speeds: list[float]) -> tuple[float, float]:
    """The shortest run-up time and a common distance that every vehicle can drive comfortably."""
    for duration in np.arange(2.0, 40.0, 0.5):
        feasible = None
        for v in speeds:
            ds = np.linspace(0, v * duration, 80)
            ok = ds[[_quintic_ok(duration, d, v) for d in ds]]
            if ok.size == 0:
                feasible = None
                break
            interval = (ok.min(), ok.max())
            feasible = interval if feasible is None else (max(feasible[0], interval[0]), min(feasible[1], interval[1]))
            if feasible[0] > feasible[1]:
                break
        if feasible is not None and feasible[0] <= feasible[1]:
            return float(duration), float((feasible[0] + feasible[1]) / 2)
    raise ValueError(f"no comfortable run-up to the speeds {speeds}")


def references(plan: Plan, road: Road) -> dict[str, Reference]:
    duration, distance = runup([plan.at(v, 0).speed for v in plan.vehicles])
    result = {}
    for vehicle in plan.vehicles:
        waypoints = [
            Waypoint(duration + k * plan.dt, s.position, s.lane, s.speed) for k, s in enumerate(plan.states[vehicle])
        ]
        result[vehicle] = Reference(vehicle, duration, distance, waypoints, road, plan.dt)
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
