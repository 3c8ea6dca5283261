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
from ..geometry import WHEELBASE
from ..reference import Reference

HORIZON = 3.0  # s of prediction
POSITION_GAIN = 0.5  # 1/s^2
SPEED_GAIN = 1.5  # 1/s
MAX_ACCELERATION = 4.0  # m/s^2
MAX_DECELERATION = 9.0  # m/s^2
HEADING_GAIN = 2.5  # 1/s
MAX_STEER = 0.5  # rad
LOOK_AHEAD_TIME = 1.0  # s: the pursued point is this far ahead at the current speed, at least
LOOK_AHEAD_MIN = 4.0  # m


class KinematicDriver(DriverBase):
    """Tracks its reference with the kinematic bicycle model and the closed-form controller."""

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.reference, self.dt = reference, dt
        self.steps = max(2, int(round(HORIZON / dt)) + 1)

    def retarget(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        """Follow ``reference`` from now on (a replan): the controller keeps no other state."""
        self.reference = reference

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        dt, n = self.dt, self.steps
        times = time + dt * np.arange(n + 1)
        s_ref, v_ref = self.reference.position_and_speed(times)
        look = max(LOOK_AHEAD_MIN, state.speed * LOOK_AHEAD_TIME)
        ahead = self.reference.d(times + look / max(state.speed, 1.0))
        x, y, heading, v = state.x, state.y, state.heading, state.speed
        xs, ys, hs, vs, accs = [x], [y], [heading], [v], [state.acceleration]
        # plain floats in the loop: a numpy scalar per term was most of a cycle's cost
        s_ref, v_ref, ahead = s_ref.tolist(), v_ref.tolist(), ahead.tolist()
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
