"""A kinematic bicycle model that tracks a reference with a closed-form controller.

Longitudinal: the reference's acceleration fed forward, plus feedback on the speed and position
errors (``SPEED_GAIN``, ``POSITION_GAIN``: critically damped, about 1.4 s to settle), within a
car's limits (``MAX_ACCELERATION``, ``MAX_DECELERATION``). Lateral: pure pursuit of the
reference's lateral position a look-ahead distance ahead, the heading error turned into a steering
angle through the bicycle model (``WHEELBASE``), within ``MAX_STEER``. Every cycle the controller
is rolled out over ``HORIZON`` seconds against the reference: the first step is the vehicle's next
state, the rest what the other drivers see as its prediction. Positions are in the road's frame
(x along the road or route, y across it), as the lockstep loop keeps them.
"""

from __future__ import annotations

import math

import numpy as np

from ...roads.road import Road
from ..driver import DriverBase, Trajectory, VehicleState
from ..geometry import MAX_STEER, WHEELBASE
from ..reference import Reference

HORIZON = 3.0  # s of prediction
POSITION_GAIN = 0.5  # 1/s^2
SPEED_GAIN = 1.5  # 1/s
MAX_ACCELERATION = 4.0  # m/s^2
MAX_DECELERATION = 9.0  # m/s^2
HEADING_GAIN = 2.5  # 1/s
LOOK_AHEAD_TIME = 1.0  # s: the pursued point is this far ahead at the current speed, at least
LOOK_AHEAD_MIN = 4.0  # m


class KinematicDriver(DriverBase):
    """Tracks its reference with the kinematic bicycle model and the closed-form controller."""

    reads_others = False  # it tracks its plan, blind to the others (as Scenic's Newtonian cars are)
    rollout = True  # whether another driver reads its trajectory past the next state (``predicts``)

    def predicts(self, needed: bool) -> None:
        self.rollout = needed

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.reference, self.dt = reference, dt
        self.steps = max(2, int(round(HORIZON / dt)) + 1) if self.rollout else 2
        self._sampled = _Sampled(reference, dt)

    def retarget(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        """Follow ``reference`` from now on (a replan): the controller keeps no other state."""
        self.reference = reference
        self._sampled = _Sampled(reference, dt)

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        dt, n = self.dt, self.steps
        first = round(time / dt)
        look = max(LOOK_AHEAD_MIN, state.speed * LOOK_AHEAD_TIME)
        lead = look / max(state.speed, 1.0)
        s_ref, v_ref, ahead = self._sampled.window(first, n + 1, lead)
        x, y, heading, v = state.x, state.y, state.heading, state.speed
        xs, ys, hs, vs, accs = [x], [y], [heading], [v], [state.acceleration]
        atan, atan2, cos, sin, tan = math.atan, math.atan2, math.cos, math.sin, math.tan
        for k in range(n - 1):
            feedforward = (v_ref[k + 1] - v_ref[k]) / dt
            a = feedforward + SPEED_GAIN * (v_ref[k] - v) + POSITION_GAIN * (s_ref[k] - x)
            a = min(MAX_ACCELERATION, max(-MAX_DECELERATION, a))
            wanted = atan2(ahead[k] - y, look)
            yaw_rate = HEADING_GAIN * (wanted - heading)
            steer = atan(yaw_rate * WHEELBASE / v) if v > 0.1 else 0.0
            steer = min(MAX_STEER, max(-MAX_STEER, steer))
            x += v * cos(heading) * dt
            y += v * sin(heading) * dt
            heading += v / WHEELBASE * tan(steer) * dt
            v = max(0.0, v + a * dt)
            xs.append(x)
            ys.append(y)
            hs.append(heading)
            vs.append(v)
            accs.append(a)
        return Trajectory(np.array(xs), np.array(ys), np.array(hs), np.array(vs), np.array(accs))


class _Sampled:
    """A reference read at the simulation's instants ``k * dt``, sampled once in blocks as the run
    reaches them: the position and speed there, and the lateral position ``LOOK_AHEAD_TIME``
    later (the pursued point of any speed from ``LOOK_AHEAD_MIN`` m/s on). Why: evaluating the
    reference anew every cycle was most of a kinematic simulation's cost."""

    BLOCK = 256  # instants sampled at once

    def __init__(self, reference: Reference, dt: float) -> None:
        self.reference, self.dt = reference, dt
        self.s: list[float] = []
        self.v: list[float] = []
        self.d_ahead: list[float] = []

    def window(self, first: int, count: int, lead: float) -> tuple[list[float], list[float], list[float]]:
        """Positions, speeds and pursued lateral positions at instants ``first`` .. ``first +
        count - 1``, the latter ``lead`` seconds ahead of each."""
        end = first + count
        while len(self.s) < end:
            times = self.dt * np.arange(len(self.s), len(self.s) + self.BLOCK)
            s_ref, v_ref = self.reference.position_and_speed(times)
            self.s += s_ref.tolist()
            self.v += v_ref.tolist()
            self.d_ahead += self.reference.d(times + LOOK_AHEAD_TIME).tolist()
        if lead == LOOK_AHEAD_TIME:
            ahead = self.d_ahead[first:end]
        else:  # slower than LOOK_AHEAD_MIN: the pursued point lies further ahead in time
            ahead = self.reference.d(self.dt * np.arange(first, end) + lead).tolist()
        return self.s[first:end], self.v[first:end], ahead
