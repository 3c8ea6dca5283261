"""The continuous encoding's settings (``ContinuousSettings``): vehicle limits, margins, the search's knobs.

Plain data, importable without clingo: the pipeline, the sampler and the reports read them.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, ClassVar

from ....settings import CONTINUOUS_HORIZON, ROAD_SPEED
from ...protocol import Limit
from ...relaxation import RouteExtent

if TYPE_CHECKING:
    from ....roads.conflicts import Alignment, Meeting
    from ....roads.route import Route

# the vehicle limits a fallback plans without, when no plan exists within them: (field, relaxed
# value, unit, whether a real car's). The relaxed values are beyond any car's, so a plan that needs
# them names the limit. A plan needing a car's limit relaxed asks more than a car can do: its values
# have no concrete scenario. The others (the gap between cars) are how closely the tool dares to
# plan cars: 8 m between centres is 3.5 m between bumpers, and a scenario may ask for less
RELAXED_LIMITS = (
    ("max_jerk", 50.0, "m/s^3", True),
    ("min_acceleration", -20.0, "m/s^2", True),
    ("max_acceleration", 12.0, "m/s^2", True),
    ("max_speed", 100.0, "m/s", True),
    ("closing_time", 0.0, "s", False),
    ("min_gap", 5.0, "m", False),
)


@dataclass(frozen=True)
class RouteFacts:
    """What the planner reads of one route of the map (asp/continuous/route.lp): the vehicles
    that drive through its junction (``Route.crossers``), where along it every vehicle stays,
    where its lanes take a car, its sharp bends and its junction. ``ContinuousSettings`` holds the
    first route's in fields of its own, the others' as ``side_routes``."""

    vehicles: frozenset[str]
    route_span: tuple[float, float]
    lane_spans: tuple[tuple[int, float, float], ...]
    slow_spans: tuple[tuple[float, float, float], ...]
    junction_span: tuple[float, float] | None
    route: Route = field(compare=False, repr=False)

    @classmethod
    def of(cls, route: Route) -> RouteFacts:
        from ....roads.route import ROUTE_MARGIN

        start, end = route.within or (0.0, route.length)
        return cls(
            route.crossers,
            (start + ROUTE_MARGIN, end - ROUTE_MARGIN),
            tuple((lane, first, last) for lane, (first, last) in sorted(route.spans().items())),
            route.slow_stretches,
            route.junction_span,
            route,
        )


@dataclass(frozen=True)
class ContinuousSettings:
    """The vehicle limits and planning bounds of the continuous encoding (SI units;
    ``planning.protocol.PlannerSettings``)."""

    encoding: ClassVar[str] = "continuous"
    replanning: ClassVar[bool] = True

    dt: float = 1.0  # seconds per step
    min_acceleration: float = -8.0  # m/s^2: hard braking of a real car
    max_acceleration: float = 4.0  # m/s^2
    max_jerk: float = 2.0  # m/s^3: how much the acceleration may change from one step to the next
    # m/s^3 for a vehicle the scenario asks an acceleration of (the acceleration modifier, a speed
    # change's rate_peak): a car braking as hard as its driver can reaches full braking within a
    # few tenths of a second, so such a plan may step to the asked rate from one step to the next
    brisk_jerk: float = 20.0
    # the vehicle under test, which drives itself: planned as braking as briskly as a car can, it
    # may stop, and whether it closes in at the plan's end is its driver's business (dynamics.lp)
    self_driven: str | None = None
    # m/s^2: the rates at which a car drives toward a target speed (CARLA's speed(v)), as a driver
    # would: neither a crawl over the phase nor the car's limit
    comfortable_acceleration: float = 2.0
    comfortable_deceleration: float = -3.0
    min_speed: float = 0.5  # m/s for a driving vehicle the scenario does not ask to stop
    max_speed: float = 70.0  # m/s
    # m/s at the first step where the scenario names no speed: a speed typical of the road (the
    # road-speed option; a highway's 80-130 kph), not the crawl a vertex of the linear program would pick
    road_speed: tuple[float, float] = ROAD_SPEED
    # m/s a start speed the scenario leaves open is at least, as a strong preference: the motion
    # planner tracks a crawl badly (the road's band itself is a weak one)
    start_floor: float = 8.0
    lane_change_speed: float = 5.0  # m/s at least while changing lane
    min_gap: float = 8.0  # m between the centres of two vehicles sharing a lane
    # m: the least gap between centres the planner keeps when the scenario itself asks two vehicles
    # to be closer than min_gap (0.5 m between bumpers; instance.spacing)
    closest_gap: float = 5.0
    # s: and more, by this many seconds of the speed at which the one behind closes in (a follower
    # 15 m behind at +15 m/s is a collision in the simulation, not a gap)
    closing_time: float = 1.0
    lane_change_gap: int = 3  # steps from one lane change of a vehicle to its next
    spread: float = 300.0  # m from the first vehicle within which the others start
    position_margin: float = 1.5  # m planned inside each side of a position range, when it fits
    speed_margin: float = 0.5  # m/s likewise for speeds
    headway_margin: float = 0.2  # s likewise for time headways
    # m/s^2 likewise for a phase's mean acceleration: the motion planner starts and ends a change
    # of speed late by up to a second (see _speed_lead), which moves the speeds at a 3 s phase's
    # ends by a few tenths of a m/s
    acceleration_margin: float = 0.4
    # s likewise for a sampled duration (the refined strategy's, sampling._band): the motion planner
    # meets a phase's entry condition up to about a second after the plan's step, so a phase planned
    # at its range's shortest is simulated shorter
    duration_margin: float = 1.0
    # when no plan keeps the margins, a second search keeps this fraction of them: the scenario may
    # have plans nearer its edges than the margins allow (catch_up_band: 0.5 m/s on both speeds over
    # 20 s moved its band's edge 20 m below the true one). Such a plan is simulated and monitored
    # like any other; when none is accepted, the margins are what binds (MarginsBind)
    fallback_margins: float = 0.2
    # on a map (asp/continuous/route.lp): where along its route every vehicle stays, first and last
    # metre, and where each lane that begins or ends takes a car ((lane, first, last), metres along
    # the route); None: the straight road, as long as the scenario needs
    route_span: tuple[float, float] | None = None
    lane_spans: tuple[tuple[int, float, float], ...] = ()
    # where the plan's position 0 (its first vehicle's start) lies along the route, when the
    # scenario asks for a curve (path_curve); None: anywhere the route_span allows
    origin_span: tuple[float, float] | None = None
    # the route's sharp bends (a turn at a junction): (first metre, last metre, m/s), a car between
    # them at most that fast; and the junction the vehicles in ``crossers`` drive through (first and
    # last metre along the route)
    slow_spans: tuple[tuple[float, float, float], ...] = ()
    junction_span: tuple[float, float] | None = None
    crossers: frozenset[str] = frozenset()
    route: Route | None = field(default=None, compare=False, repr=False)  # the map's route (on_route)
    # more routes of the map (routes 1, 2, ... after ``route``, 0), each driven by its vehicles
    # (vehicles that take other ways through a junction), and where any two routes meet
    # (``roads.conflicts``): the planner orders the vehicles of two routes through each meeting
    side_routes: tuple[RouteFacts, ...] = ()
    meetings: tuple[Meeting, ...] = ()
    # how the routes' positions are laid onto each other where they meet (``roads.conflicts``)
    alignments: tuple[Alignment, ...] = ()
    # m added along each route at both ends of a crossing of two routes: the first car through has
    # left it by this much when the next enters (a motion planner lags its plan by a metre or two)
    meeting_clearance: float = 2.0
    # why a limit has the value it has when not a car's own: (field, why), for the messages
    limit_reasons: tuple[tuple[str, str], ...] = ()
    max_horizon: int = CONTINUOUS_HORIZON  # steps
    time_limit: float = 60.0  # seconds for one solve, all horizons together
    # how the linear constraints are kept: "lazy" checks each complete choice with HiGHS and learns
    # nogoods from its conflicts (encodings/continuous/linear.py); "lpx" keeps them at every decision with
    # clingo-lpx's exact simplex (orders of magnitude slower on long scenarios)
    theory: str = "lazy"
    lpx_options: tuple[tuple[str, str], ...] = ()  # clingo-lpx's own (propagate-conflicts, select, ...)
    # when no plan exists, find the constraints that cannot hold together (UnsatisfiableScenario)
    explain_unsatisfiable: bool = True
    # seconds the diagnosis may spend deciding whether one constraint can leave the group that
    # clashes; past it the constraint stays (the group then may name one constraint more, and is
    # still one that clashes): a relaxed duration can leave every horizon up to the limit to refute
    removal_time_limit: float | None = 1.0
    # a random start (the refined strategy): start lanes and speeds the scenario leaves open are
    # drawn from the seed (as preferences), not left to the solver's and the LP's habits
    random_start: bool = False
    # s: how long a random start's plan may last when it is stretched past the shortest horizon the
    # scenario allows (drawn uniformly up to it, as the grid planner draws its plans' lengths up to
    # its 25-step horizon limit): plans all at their shortest horizon are alike
    stretch_limit: float = 25.0
    # m/s^2: a random start's driving vehicle prefers to accelerate at one of -drift, 0 and +drift,
    # drawn per vehicle, as the grid planner draws one of its accelerations; kept by the linear
    # program where the scenario and drift_speeds leave it free (a preference, never a reason for
    # no plan). Why: see start_preferences
    drift: float = 2.0
    # m/s: the speeds within which a drawn acceleration is kept (the grid's speed range): a vehicle
    # drifting down settles at the low one instead of crawling at min_speed, one drifting up at
    # the high one
    drift_speeds: tuple[float, float] = (2.0, 40.0)

    def on_route(self, route, others: tuple = ()) -> ContinuousSettings:
        """These settings for a scenario on a map's ``route`` (``roads.Route``): no vehicle faster
        than the route's sharpest curve lets a car hold (``roads.route.curve_speed``) and, in its
        sharp bends (a turn at a junction), than the bend lets it; each on the route and in a lane
        only where it is (``asp/continuous/route.lp``), the scenario starting in the curve it asks
        for, the vehicles that drive through the route's junction doing so, and a start speed the
        scenario leaves open at most the map's limit."""
        from ....roads.conflicts import alignments, conflicts
        from ....roads.route import MAX_LATERAL_ACCELERATION, curve_speed

        low, high = self.road_speed
        for limit in (r.speed_limit for r in (route, *others) if r.speed_limit is not None):
            low, high = min(low, limit), min(high, limit)
        tightest = min((route, *others), key=curve_speed)
        bend = curve_speed(tightest)
        reasons = ()
        if bend < self.max_speed:
            reasons = (
                (
                    "max_speed",
                    f"the sharpest curve of {tightest.name}, radius {1 / tightest.gentle_curvature():.0f} m, at "
                    f"{MAX_LATERAL_ACCELERATION:g} m/s^2 of lateral acceleration",
                ),
            )
        first = RouteFacts.of(route)
        return replace(
            self,
            road_speed=(low, high),
            max_speed=min(self.max_speed, bend),
            limit_reasons=reasons,
            route_span=first.route_span,
            lane_spans=first.lane_spans,
            origin_span=route.start_within,
            slow_spans=first.slow_spans,
            junction_span=first.junction_span,
            crossers=first.vehicles,
            route=route,
            side_routes=tuple(RouteFacts.of(other) for other in others),
            meetings=conflicts((route, *others)) if others else (),
            alignments=alignments((route, *others)) if others else (),
        )

    def resolution(self) -> dict[str | None, float]:
        """How wide a band a sampled value is narrowed to, per physical dimension, the band the
        plan may use (the planner keeps no margin inside it: ``SymbolicAutomaton.sampled``):
        positions, speeds and headways are real-valued here, so the plan lies within half a
        margin of the sample; durations still count whole steps."""
        return {
            "length": self.position_margin,
            "speed": self.speed_margin,
            "time": self.dt,
            "acceleration": 0.25,
            "headway": self.headway_margin,
        }

    def start_band(self) -> tuple[float, float]:
        """The start speeds (m/s) a driving vehicle is preferred to have where the scenario leaves
        them open: ``road_speed`` within the speed limits."""
        return max(self.road_speed[0], self.min_speed), min(self.road_speed[1], self.max_speed)

    def margins(self) -> dict[str | None, float]:
        """How far inside a range's edges the plan keeps, per physical dimension."""
        return {
            "length": self.position_margin,
            "speed": self.speed_margin,
            "headway": self.headway_margin,
            "acceleration": self.acceleration_margin,
            "time": self.duration_margin,
        }

    def thinned(self) -> ContinuousSettings | None:
        """These settings with ``fallback_margins`` of each margin, or None when there is no such second search."""
        if not 0 <= self.fallback_margins < 1:
            return None
        f = self.fallback_margins
        return replace(
            self,
            position_margin=self.position_margin * f,
            speed_margin=self.speed_margin * f,
            headway_margin=self.headway_margin * f,
            acceleration_margin=self.acceleration_margin * f,
            duration_margin=self.duration_margin * f,
            fallback_margins=1.0,
        )

    def finer(self) -> ContinuousSettings:
        """These settings in half the step (durations between whole seconds: a 0.5 s wait, a 3.6 s
        brake), over as many seconds, lane changes as far apart in seconds."""
        return replace(self, dt=self.dt / 2, max_horizon=self.max_horizon * 2, lane_change_gap=self.lane_change_gap * 2)

    def limits(self) -> tuple[Limit, ...]:
        """The ``RELAXED_LIMITS`` with their values here (and ``limit_reasons``)."""
        reasons = dict(self.limit_reasons)
        return tuple(
            Limit(name, getattr(self, name), relaxed, unit, of_a_car, reasons.get(name, ""))
            for name, relaxed, unit, of_a_car in RELAXED_LIMITS
        )

    def relaxed(self, names: frozenset[str] | None = None) -> ContinuousSettings:
        return replace(self, **{name: value for name, value, _, _ in RELAXED_LIMITS if names is None or name in names})

    def at_origin(self, origin: float) -> ContinuousSettings:
        return replace(self, origin_span=(origin, origin)) if self.route_span is not None else self

    def with_road_speed(self, band: tuple[float, float]) -> ContinuousSettings:
        return replace(self, road_speed=band)

    def with_self_driven(self, vehicle: str) -> ContinuousSettings:
        return replace(self, self_driven=vehicle)

    def describe_margins(self) -> str:
        return (
            f"speed_margin {self.speed_margin:g} m/s, position_margin {self.position_margin:g} m, "
            f"headway_margin {self.headway_margin:g} s, acceleration_margin {self.acceleration_margin:g} m/s^2, "
            f"duration_margin {self.duration_margin:g} s"
        )

    def route_extent(self) -> RouteExtent | None:
        """Where along the routes their vehicles may be (``route_span``, ``lane_spans``,
        ``origin_span``, each side route's span); None off a map."""
        if self.route_span is None:
            return None
        return RouteExtent(
            self.route_span,
            {lane: (first, last) for lane, first, last in self.lane_spans},
            self.origin_span,
            tuple((side.vehicles, side.route_span) for side in self.side_routes),
        )

    def on_the_map(self, lanes: int) -> str:
        """The stretch of each route its vehicles stay on (``route_span``, the side routes'), and
        the route's lanes that take a car only along part of it (``lane_spans``), each counted from
        the right, as a driver names them whatever the file's dialect: "every vehicle stays from
        30 to 150 m along its route (120 m); a car can be in the route's lane 1 from the right only
        from 189 to 404 m along it (215 m)"."""
        if self.route_span is None:
            return ""

        def stretch(span: tuple[float, float], along: str) -> str:
            return f"from {span[0]:.0f} to {span[1]:.0f} m along {along} ({span[1] - span[0]:.0f} m)"

        said = [
            f"{', '.join(sorted(side.vehicles))} "
            + (
                f"stays {stretch(side.route_span, 'its route')}"
                if len(side.vehicles) == 1
                else f"stay {stretch(side.route_span, 'their route')}"
            )
            for side in self.side_routes
        ]
        said.insert(0, f"every {'other ' if said else ''}vehicle stays {stretch(self.route_span, 'its route')}")
        for lane, first, last in self.lane_spans:
            place = f"a car can be in the route's lane {lanes - lane} from the right"
            if last < first:
                said.append(f"{place} nowhere")
            else:
                said.append(f"{place} only {stretch((first, last), 'it')}")
        return "; ".join(said)

    def summary(self, lanes: int) -> str:
        """The vehicle limits and bounds on a road of ``lanes`` lanes, for messages that blame them."""
        road = ""
        if self.route_span is not None:
            first, last = self.route_span
            road = f", every vehicle between {first:g} and {last:.0f} m along its route"
            if self.junction_span is not None and self.crossers:
                start, end = self.junction_span
                road += f" ({', '.join(sorted(self.crossers))} from before its junction at {start:.0f} m to past it at {end:.0f} m)"
        return (
            f"speeds {self.min_speed:g}..{self.max_speed:g} m/s, accelerations {self.min_acceleration:g}..{self.max_acceleration:g} m/s^2, "
            f"{lanes} lane{'' if lanes == 1 else 's'}, {self.min_gap:g} m gaps, at most {self.max_horizon} steps of {self.dt:g} s{road}"
        )
