"""The default driver: tracks a vehicle's waypoint schedule with frenetix-generated trajectories.

frenetix samples quintic/quartic Frenet trajectories and checks their feasibility; this module
ranks them by how closely they follow the waypoint schedule, and rejects those that would collide
or leave the road (frenetix checks neither). frenetix itself is imported when a driver starts, so
that importing the backend stays cheap.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...roads.road import Road
from ..driver import DriverBase, Trajectory, VehicleState
from ..geometry import CAR_LENGTH, CAR_WIDTH, MAX_STEER, WHEELBASE
from ..reference import Reference


@dataclass(frozen=True)
class _Frame:
    """The frame the drivers of a road sample in: frenetix's coordinate system along ``path``, and
    how its s and d relate to road coordinates. On a map the path runs along the route's lanes'
    left edge, where a lateral position in it is ``y`` less the lanes' width (``d_origin``); its s
    at road x is read from ``route_s`` (x plus the route's shift) against ``frame_s``, which equals
    ``route_s`` less its first value where that edge is the route's reference line (a lane offset
    or a median moves it: in a curve the edge is longer or shorter than the line, and where two
    roads of a route meet their reference lines may not, though their lanes do). ``turn``: the angle
    by which the world is turned in it."""

    coordinates: object
    route_s: np.ndarray
    frame_s: np.ndarray
    d_origin: float
    turn: float
    route_shift: float
    along_line: bool  # the path is the route's reference line (or the straight road's edge): s is x shifted

    @property
    def x_at_start(self) -> float:
        """Road x where the path begins."""
        return float(self.route_s[0]) - self.route_shift

    def s(self, x) -> np.ndarray:
        """The frame's s at road x."""
        if self.along_line:
            return np.asarray(x, dtype=float) - self.x_at_start
        return np.interp(np.asarray(x, dtype=float) + self.route_shift, self.route_s, self.frame_s)

    def x(self, s) -> np.ndarray:
        """Road x at the frame's s."""
        if self.along_line:
            return np.asarray(s, dtype=float) + self.x_at_start
        return np.interp(np.asarray(s, dtype=float), self.frame_s, self.route_s) - self.route_shift


_FRAMES: dict[tuple, _Frame] = {}


def _frame(road: Road) -> _Frame:
    """The frame of ``road`` (``_Frame``); building one costs tens of milliseconds, so it is built
    once per road extent.

    On the straight road, the line y = 0 (the right road edge), d being y. On a map, the route's
    lanes' left edge, sampled every metre along the route and run on straight 100 m before its
    start and 500 m past its end (a run goes on a few seconds past its plan), d being y less the
    lanes' width. The edge, not the route's reference line: where two roads of a route meet, their
    reference lines may lie a metre or two apart while their lanes continue one another
    (esmini's fabriksgatan), and frenetix projects nothing onto a line with a gap in it.

    frenetix's yaw-rate check differences its trajectories' headings without wrapping them: a
    trajectory whose heading crosses pi turns by 2 pi in a step and is infeasible (on a road
    heading west every car stopped where it crossed). The frame is the world turned so that the
    route's headings over the simulated extent lie around 0.
    """
    import frenetix

    key = (road.x_start, road.x_end, id(road.route), road.route_shift)
    if key not in _FRAMES:
        _FRAMES.clear()
        if road.route is None:
            xs = np.arange(road.x_start - 100.0, road.x_end + 200.0, 1.0)
            path = np.stack([xs, np.zeros_like(xs)], axis=1)
            _FRAMES[key] = _Frame(frenetix.CoordinateSystemWrapper(path), xs, xs - xs[0], 0.0, 0.0, 0.0, True)
        else:
            route = road.route
            before, after = 100.0, 500.0
            if route.closed:
                # a loop's line runs on past its end over its start: a car near the start would be
                # projected a lap on (esmini's velodrome jumped from 30 m to 2030 m). The frame keeps
                # to the lap, from where the road begins to where it ends
                before = max(0.0, -math.floor(road.x_start + road.route_shift))
                after = 0.0
            along = np.arange(-before, route.length + after + 0.5, 1.0)
            edge = route.lateral(along, route.width)  # the lanes' left edge where they are most
            x, y, _ = route.reference_line.pose(along, edge)
            along_line = not np.any(edge != 0.0)
            # frenetix's s is the length along its path: the route's where the path is its line
            frame_s = (
                along - along[0] if along_line else np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
            )
            _, _, heading = route.reference_line.pose(
                np.arange(road.x_start - 100.0, road.x_end + 100.0, 1.0) + road.route_shift
            )
            turn = float(heading.min() + heading.max()) / 2
            path = np.stack(_turned(x, y, -turn), axis=1)
            _FRAMES[key] = _Frame(
                frenetix.CoordinateSystemWrapper(path), along, frame_s, route.width, turn, road.route_shift, along_line
            )
    return _FRAMES[key]


def _turned(x, y, angle: float) -> tuple[np.ndarray, np.ndarray]:
    """The points (x, y) turned by ``angle`` about the origin."""
    cos, sin = math.cos(angle), math.sin(angle)
    return cos * np.asarray(x) - sin * np.asarray(y), sin * np.asarray(x) + cos * np.asarray(y)


class FrenetixDriver(DriverBase):
    """Tracks the waypoint schedule with frenetix-generated trajectories."""

    horizon = 3.0  # s
    # which trajectories are sampled and how much of each is compared with the reference decide how
    # fast the car follows a change of speed: short ones, compared briefly (docs/decisions.md)
    durations = (0.5, 1.0, 2.0, 3.0)  # s, end times of the sampled trajectories
    speed_offsets = (-3.0, -1.5, -0.5, 0.0, 0.5, 1.5, 3.0)  # m/s around the reference end speed
    tracked = 0.5  # s of each trajectory compared with the reference
    # s of each trajectory checked for collisions and for leaving the road: further ahead than the
    # tracking compares, which alone lets collisions through (docs/decisions.md)
    guarded = 2.0
    low_velocity = 2.0  # m/s; below it frenetix plans lateral motion over distance, not time
    # weights of the tracking cost: squared errors of s (m), d (m) and v (m/s) over the tracked
    # window, and the clearance (m, beyond the boxes) kept from the others' trajectories; chosen by
    # the accepted share of refined samples (docs/decisions.md)
    position_weight, lateral_weight, speed_weight = 1.0, 2.0, 2.0
    # the lateral weight in a route's sharp bends (a turn at a junction, ``Route.slow_stretches``):
    # with the highway's, a car turning at 20 kph in a 16 m radius ran 1.3 m wide of its lane's
    # centre and off the road (the trajectories that keep the car where it is weigh as little as
    # those that bring it back); with this, 0.1 m
    bend_lateral_weight = 10.0
    longitudinal_clearance, lateral_clearance = 0.5, 0.2
    derivative_step = 0.05  # s, of the reference's numerical derivatives
    stop_deceleration: float | None = 3.0  # m/s^2 of the stopping sample
    # m/s^2 a vehicle braking as its scenario asks (its plan has brisk onsets) brakes at most,
    # where a trajectory that does not exists: a car's hard braking, the planner's limit and a half
    hardest_braking = 8.5
    # a trajectory's acceleration as the change of its speed, not frenetix's cartesian ``a``, which
    # is not the derivative of the speeds beside it: the next replanning starts from the chosen
    # trajectory's next state, and with too little acceleration the car lags every change of speed
    acceleration_from_speed = True
    # s between two samplings: in between, the car drives on along the trajectory it chose, unless
    # another vehicle is near (``near``: metres along and across the road, between centres), or a
    # new prediction crosses the trajectory; then it samples every step, as it always had
    replan_period = 0.3
    near = (6.0, 2.5)

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        import frenetix
        from frenetix.trajectory_functions import cost_functions as cf
        from frenetix.trajectory_functions import feasability_functions as ff

        self.vehicle = vehicle
        self.reference = reference
        self.road = road
        self.dt = dt
        self.frame = _frame(road)
        handler = frenetix.TrajectoryHandler(dt=dt)
        handler.add_feasability_function(
            # the steering angle a car has (MAX_STEER), as the curvature check's; frenetix's 0.4
            # allows no bend under 6.4 m, and a town corner (6.5 m at the lane's centre) left no
            # trajectory to a car a few centimetres inside it
            ff.CheckYawRateConstraint(deltaMax=MAX_STEER, wheelbase=WHEELBASE, wholeTrajectory=False)
        )
        handler.add_feasability_function(
            ff.CheckAccelerationConstraint(switchingVelocity=7.3, maxAcceleration=8.0, wholeTrajectory=False)
        )
        handler.add_feasability_function(
            ff.CheckCurvatureConstraint(deltaMax=MAX_STEER, wheelbase=WHEELBASE, wholeTrajectory=False)
        )
        handler.add_cost_function(cf.CalculateLateralJerkCost("lateral_jerk", 0.02))
        handler.add_cost_function(cf.CalculateLongitudinalJerkCost("longitudinal_jerk", 0.02))
        self.handler = handler
        self.fallbacks = 0
        self.tracked_steps = int(round(self.tracked / dt)) + 1  # samples compared: now and the tracked window
        self.guarded_steps = int(round(self.guarded / dt)) + 1
        self.replan_steps = max(1, int(round(self.replan_period / dt)))
        self._committed: Trajectory | None = None  # the chosen trajectory, index 0 being now
        self._age = 0  # steps driven along it
        # the route's sharp bends (metres along it, first and last), where the lateral error weighs more
        self.bends = tuple((a, b) for a, b, _ in road.route.slow_stretches) if road.route is not None else ()

    def retarget(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        """Follow ``reference`` from now on (a replan): the trajectory chosen for the old one is dropped."""
        self.reference = reference
        self._committed = None

    def _driven_on(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory | None:
        """The chosen trajectory one step on, when it is still to be followed: chosen less than a
        replanning period ago, long enough, ``state`` where it led, clear of the others, and no
        brisk change of speed due within the step."""
        committed = self._committed
        if committed is None or self._age + 1 >= self.replan_steps or len(committed.x) < self.guarded_steps + 2:
            return None
        if self.reference.next_onset(time) <= time + self.dt + 1e-9:
            return None  # a brisk change of speed is due: act on it at its instant
        expected = committed.state(1)
        if abs(expected.x - state.x) > 1e-9 or abs(expected.y - state.y) > 1e-9:
            return None
        along, across = self.near
        if any(abs(o.x[0] - state.x) < along and abs(o.y[0] - state.y) < across for o in others.values()):
            return None
        onward = committed.shifted()
        if self._collides(onward, others):
            return None
        self._committed, self._age = onward, self._age + 1
        return onward

    def _commit(self, trajectory: Trajectory) -> Trajectory:
        self._committed, self._age = trajectory, 0
        return trajectory

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        import frenetix
        import frenetix.trajectory_functions as tf

        onward = self._driven_on(time, state, others)
        if onward is not None:
            return onward
        self._committed = None
        low = bool(state.speed < self.low_velocity)
        speed, acceleration = state.speed, state.acceleration
        if self.road.route is None:
            heading = state.heading
            rear = np.array([state.x - np.cos(heading) * WHEELBASE / 2, state.y - np.sin(heading) * WHEELBASE / 2])
        else:
            # the rear axle mapped onto the map, turned as the route is there (as _along_route reads
            # it), and the car's own speed from its rate along the route (road coordinates' speed)
            rear_x = state.x - np.cos(state.heading) * WHEELBASE / 2
            rear_y = state.y - np.sin(state.heading) * WHEELBASE / 2
            x, y, heading = (float(v) for v in self.road.world(rear_x, rear_y, state.heading))
            rear = np.array(_turned(x, y, -self.frame.turn))  # in the frame's turned world
            heading = (heading - self.frame.turn + math.pi) % (2 * math.pi) - math.pi
            factor = self._own_speed_factor(rear_x, rear_y, state.heading)
            speed, acceleration = speed * factor, acceleration * factor
        cartesian = frenetix.CartesianPlannerState(rear, float(heading), float(speed), float(acceleration), 0.0)
        try:
            initial = frenetix.compute_initial_state(
                coordinate_system=self.frame.coordinates, x_0=cartesian, wheelbase=WHEELBASE, low_velocity_mode=low
            )
        except ValueError:
            # the car is where the frame has no projection (inside a bend tighter than its distance
            # from the route's reference line: a town corner of 6 m, fabriksgatan's): no trajectory
            # from here; it stands, counted as a fallback, and the verdict says what went wrong
            self.fallbacks += 1
            return Trajectory.standing(state, 2)
        handler = self.handler
        handler.add_function(
            tf.FillCoordinates(
                lowVelocityMode=low,
                initialOrientation=float(heading),
                coordinateSystem=self.frame.coordinates,
                horizon=self.horizon,
            )
        )
        handler.reset_Trajectories()
        handler.generate_trajectories(self._samples(time, state, initial), low)
        handler.evaluate_all_current_functions(True)
        candidates = [t for t in handler.get_sorted_trajectories() if t.feasible]
        if not candidates:
            self.fallbacks += 1
            return Trajectory.standing(state, 2)
        # the reference over the tracked window, evaluated once for all candidates; up to a brisk
        # change of speed still to come only, so that the car does not act on it before its time
        tracked = self.tracked_steps
        onset = self.reference.next_onset(time)
        if onset < time + tracked * self.dt:
            tracked = max(2, int((onset - time) / self.dt + 1e-9) + 1)
        times = time + np.arange(1, tracked) * self.dt
        along = self.reference.s(times)
        target = (
            self.frame.s(along) - WHEELBASE / 2,
            self._frame_d(times),
            self.reference.v(times),
        )
        costs = self._tracking_costs(
            target,
            candidates,
            (self.position_weight, self._lateral_weight(along), self.speed_weight),
            self.road.route is not None,
            self.hardest_braking * self.dt if len(self.reference.onsets) else None,
            self.guarded_steps,
        ) + np.array([c.cost for c in candidates])
        ranked = [candidates[i] for i in np.argsort(costs, kind="stable")[:40]]
        road_now = self._road_violation(Trajectory.standing(state))
        trajectories = []
        for candidate in ranked:  # copied one by one: the first safe one is usually the best ranked
            trajectory = self._copy(candidate)
            if not self._collides(trajectory, others) and self._road_violation(trajectory) <= road_now + 0.02:
                return self._commit(trajectory)
            trajectories.append(trajectory)
        # Nothing fully safe: prefer not colliding, then the least road violation, then tracking.
        self.fallbacks += 1
        return min(trajectories, key=lambda t: (self._collides(t, others), round(self._road_violation(t), 2)))

    def _samples(self, time: float, state: VehicleState, initial) -> np.ndarray:
        """The sampling rows frenetix generates trajectories from: per end time, every end speed
        around the reference's, ending laterally where the reference is (and, mid lane change,
        also where the car is). The reference is evaluated once for all end times."""
        lon, lat = list(initial.x0_lon), list(initial.x0_lat)
        d_now = float(lat[0])
        h = self.derivative_step
        durations = np.asarray(self.durations, dtype=float)
        ends = time + durations
        v_refs = self.reference.v(ends)
        # the lateral end state is the reference's, rate and curvature too: a candidate ending
        # mid lane change at rest (d' = 0) would stall the change, each replanning again
        around = self._frame_d(np.stack([ends - h, ends, ends + h], axis=1).ravel()).reshape(-1, 3)
        d_refs = around[:, 1]
        d_rates = (around[:, 2] - around[:, 0]) / (2 * h)
        d_curves = (around[:, 2] - 2 * around[:, 1] + around[:, 0]) / h**2
        # a vehicle whose plan changes its acceleration briskly also ends trajectories at the
        # reference's acceleration: one ending at rest (a = 0) cannot brake at 7 m/s^2 in half a
        # second without overshooting it
        if len(self.reference.onsets):
            a_refs = (self.reference.v(ends + h) - self.reference.v(ends - h)) / (2 * h)
        else:
            a_refs = np.zeros_like(ends)
        rows = []
        for duration, v_ref, a_ref, d_ref, d_rate, d_curve in zip(
            self.durations, v_refs.tolist(), a_refs.tolist(), d_refs.tolist(), d_rates.tolist(), d_curves.tolist()
        ):
            ends_v = {max(0.0, v_ref + o) for o in self.speed_offsets} | {max(0.0, state.speed - 3.0 * duration)}
            end_accelerations = (0.0, a_ref) if abs(a_ref) > 1e-6 and v_ref > 0 else (0.0,)
            for v_end in sorted(ends_v):
                for a_end in end_accelerations:
                    rows.append([0.0, duration, *lon, v_end, a_end, *lat, d_ref, d_rate, d_curve])
                    if d_now != d_ref:
                        rows.append([0.0, duration, *lon, v_end, a_end, *lat, d_now, 0.0, 0.0])
        if self.stop_deceleration:
            # a stop at a constant deceleration: "be at 0 in 1 s", replanned every step, only ever
            # halves the speed (the car crept at 1 m/s where the scenario asked for a standstill)
            duration = max(self.dt, state.speed / self.stop_deceleration)
            d_stop = float(self._frame_d(np.array([time + duration]))[0])
            rows.append([0.0, duration, *lon, 0.0, 0.0, *lat, d_stop, 0.0, 0.0])
        return np.array(rows, dtype=float)

    @staticmethod
    def _tracking_costs(
        target: tuple[np.ndarray, np.ndarray, np.ndarray],
        candidates: list,
        weights: tuple[float, float, float],
        rate_along: bool = False,
        braking_limit: float | None = None,
        guarded: int = 0,
    ) -> np.ndarray:
        """Mean squared distance from the reference (s of the rear axle, d, v) over the tracked
        window, for all candidates at once (they share the planning horizon, hence the length).
        ``rate_along``: the speed compared is the rate along the frame's line (on a map's route, whose
        plans are in lengths along it: a car in a curve's outer lane drives faster than that rate,
        in its inner lane slower), else the car's own speed. ``braking_limit`` (m/s lost per
        step): a candidate losing more in a step of the window or of its first ``guarded`` steps ranks behind every one that does
        not (a brisk stop tracked by catching up with the reference would brake harder than any car)."""
        s_ref, d_ref, v_ref = target
        curves = [c.curvilinear for c in candidates]  # each access copies frenetix's arrays: once
        along = [curve.s for curve in curves]
        n = min(len(s_ref) + 1, min(len(a) for a in along))
        m = n - 1
        s = np.array([a[1:n] for a in along])
        d = np.array([curve.d[1:n] for curve in curves])
        # the speeds from now on, read once: over the window, and over the guarded steps too when
        # the braking is limited
        k = max(n, guarded) if braking_limit is not None else n
        speeds = [curve.s_dot[:k] for curve in curves] if rate_along else [c.cartesian.v[:k] for c in candidates]
        v = np.array([speed[1:n] for speed in speeds])
        w_s, w_d, w_v = weights
        costs = (
            w_s * ((s - s_ref[:m]) ** 2).mean(axis=1)
            + w_d * ((d - d_ref[:m]) ** 2).mean(axis=1)
            + w_v * ((v - v_ref[:m]) ** 2).mean(axis=1)
        )
        if braking_limit is not None:
            lost = np.array([-np.diff(np.asarray(speed)).min(initial=0.0) for speed in speeds])
            costs = costs + 1e6 * (lost > braking_limit)
        return costs

    def _copy(self, candidate) -> Trajectory:
        # frenetix's arrays are views into memory freed with the sample: copy before keeping
        if self.road.route is None:
            heading = np.array(candidate.cartesian.theta, copy=True)
            rear_x = np.array(candidate.cartesian.x, copy=True)
            rear_y = np.array(candidate.cartesian.y, copy=True)
            speed = np.array(candidate.cartesian.v, copy=True)
        else:  # on a map, road coordinates: the speed is the rate along the route
            rear_x, rear_y, heading = self._along_route(candidate)
            speed = np.array(candidate.curvilinear.s_dot, copy=True)
        if self.acceleration_from_speed and len(speed) > 1:
            acceleration = np.gradient(speed, self.dt)
        else:
            acceleration = np.array(candidate.cartesian.a, copy=True)
        return Trajectory(
            x=rear_x + np.cos(heading) * WHEELBASE / 2,
            y=rear_y + np.sin(heading) * WHEELBASE / 2,
            heading=heading,
            speed=speed,
            acceleration=acceleration,
        )

    def _frame_d(self, times: np.ndarray) -> np.ndarray:
        """The reference's lateral position in the frame at ``times``: its y less the lanes' width."""
        return self.reference.d(times) - self.frame.d_origin

    def _lateral_weight(self, along: np.ndarray) -> float:
        """The weight of the lateral error over the tracked window whose centres are ``along``
        (road x): ``bend_lateral_weight`` where any lies in a sharp bend, else ``lateral_weight``."""
        if self.bends:
            s = np.asarray(along, dtype=float) + self.road.route_shift
            if any(bool(np.any((s >= a) & (s <= b))) for a, b in self.bends):
                return self.bend_lateral_weight
        return self.lateral_weight

    def _own_speed_factor(self, x: float, y: float, heading: float) -> float:
        """A car's own speed over its rate along the route, at road coordinates (x, y) turned by
        ``heading``: faster in a curve's outer lanes, slower in its inner ones."""
        route = self.road.route
        curvature = float(route.curvature(x + self.road.route_shift))
        return (1.0 - curvature * float(route.lateral(x + self.road.route_shift, y))) / max(float(np.cos(heading)), 0.5)

    def _along_route(self, candidate) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """A candidate's rear axle in road coordinates (its s and d in the frame) and its heading
        less the route's there: on a map, the centre is then half a wheelbase ahead along it."""
        s = self.frame.x(np.array(candidate.curvilinear.s, copy=True))
        d = np.array(candidate.curvilinear.d, copy=True) + self.frame.d_origin
        _, _, along = self.road.world(s, d)
        heading = np.array(candidate.cartesian.theta, copy=True) + self.frame.turn - along
        return s, d, (heading + np.pi) % (2 * np.pi) - np.pi

    def _steps(self, trajectory: Trajectory) -> int:
        return min(len(trajectory.x), self.guarded_steps)

    def _road_violation(self, trajectory: Trajectory) -> float:
        """How far (m) the rotated vehicle rectangle reaches beyond the road edges, at worst."""
        steps = self._steps(trajectory)
        heading = trajectory.heading[:steps]
        half = CAR_WIDTH / 2 * np.abs(np.cos(heading)) + CAR_LENGTH / 2 * np.abs(np.sin(heading)) + 0.1
        y = trajectory.y[:steps]
        # the edges move where a map's lanes begin or end (0 and the width on the straight road)
        right, left = self.road.right_edge(trajectory.x[:steps]), self.road.left_edge(trajectory.x[:steps])
        return float(max(0.0, (half - (y - right)).max(), (y + half - left).max()))

    def _collides(self, trajectory: Trajectory, others: dict[str, Trajectory]) -> bool:
        """Whether ``trajectory`` comes within the clearances of another's predicted trajectory at
        one of its next steps (an other's last predicted state held past its end)."""
        steps = self._steps(trajectory)
        if steps < 2:
            return False
        x, y = trajectory.x[1:steps], trajectory.y[1:steps]
        ks = np.arange(1, steps)
        for other in others.values():
            j = np.minimum(ks, len(other.x) - 1)
            close = (np.abs(x - other.x[j]) < CAR_LENGTH + self.longitudinal_clearance) & (
                np.abs(y - other.y[j]) < CAR_WIDTH + self.lateral_clearance
            )
            if close.any():
                return True
        return False
