"""The simulator seam: a plan and limits in, a ``Simulation`` out.

A backend is anything with a ``name`` and ``simulate(plan, limits, drivers)``: the default is the
frenetix backend (``simulation/frenetix/``: every vehicle driven in lockstep by a motion planner);
another (a co-simulation with CARLA or esmini, a vehicle-in-the-loop rig) is selected with the
``--roadlogic-simulator`` option, the ``pytest_roadlogic_simulator`` hook, or Python's
``run_scenario(..., simulator=...)``, and registered for the option under the
``pytest_roadlogic.simulators`` entry-point group (``backends.py``). What the monitor reads is the
``Trace``; the rest of a ``Simulation`` is for reports and plots.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

from ..planning.plan import Plan
from ..roads.road import Road
from .driver import Driver, VehicleState
from .reference import Reference, Waypoint
from .trace import Incident, Trace

# vehicle name -> the driver that should drive it, or None for the backend's own
DriverFactory = Callable[[str], "Driver | None"]


@dataclass(frozen=True)
class SimulationLimits:
    """How a simulation is run: its time step, and the wall-clock seconds it may take (None: no limit)."""

    dt: float = 0.1
    time_limit: float | None = None


@dataclass(frozen=True)
class Replan:
    """One replanning: when (the time of the observation), how long it took, the plan found (None:
    none), and how: the vehicle under test predicted at its speed or planned as any car, the run
    so far the monitor's through what was seen or the old plan's; why none."""

    time: float
    seconds: float
    plan: Plan | None
    predicted: bool = True
    why: str = ""
    seen: bool = True


class Reaction(Protocol):
    """The lockstep loop's ``react`` (reactive execution, ``pytest_roadlogic.reactive``): asked at
    every step, before the drivers plan, for new references of some vehicles from then on; it keeps
    the ``Replan`` of each time it replanned, for the ``Simulation``."""

    replans: list[Replan]

    def __call__(
        self,
        time: float,
        states: dict[str, VehicleState],
        road: Road,
        driven: dict[str, Reference],
        placed: Mapping[str, Road],
    ) -> dict[str, Reference] | None:
        """New references from ``time`` on for some vehicles, or None. ``states``: every vehicle's
        now; ``road``: the scenario's road, whose lanes references follow; ``driven``: each
        vehicle's reference being driven; ``placed``: each vehicle's road in the simulation (its
        route of the map and where the plan lies on it)."""


@dataclass(frozen=True)
class GoalRecord:
    """One waypoint of a vehicle and when it was reached (None: its time window passed first)."""

    waypoint: Waypoint
    reached_at: float | None


# m a car's centre may lie inside the junction at the start, or short of its end at the end, of a
# run in which it takes its turn (the tracking error of a simulated car at the plan's ends)
TURN_TOLERANCE = 2.0
# the share of a run's steps a vehicle driven without a trajectory of its own makes the run the
# simulator's failure more than the scenario's (Simulation.unfollowed)
UNFOLLOWED = 0.25


@dataclass
class Simulation:
    """What a run produced: the trace, the road, and each vehicle's reference (for plots)."""

    trace: Trace
    road: Road
    references: dict[str, Reference]
    dt: float
    fallbacks: dict[str, int] = field(default_factory=dict)
    stationary: tuple[str, ...] = ()  # standing obstacles, not driven
    goals: dict[str, list[GoalRecord]] = field(default_factory=dict)  # per driven vehicle, in order
    replans: list[Replan] = field(default_factory=list)  # a reactive execution's, in order; none for a scripted run
    # the road of each vehicle that drives another route of the map than ``road``'s (a different
    # way through a junction): its trace's x and y are along that road
    side_roads: dict[str, Road] = field(default_factory=dict)

    def turns_not_taken(self, drives_itself: frozenset[str] = frozenset()) -> list[Incident]:
        """An incident for each vehicle that drives along a route turning at a junction (its
        ``crossers``: ``along(path)``) and did not drive through the junction in the run: its
        centre short of the junction's first metre at the start and past its last at the end, as
        the planner plans it (within ``TURN_TOLERANCE``). The vehicles that ``drives_itself``
        names (a vehicle under test) are not asked: where they are at the end is their driver's
        (one that gave way may still be in the turn), which the oracles judge. Why: the monitor
        reads the scenario's guards, which are positions relative to other cars; whether a car
        took its turn is a fact of its route, checked here on the trace."""
        missed = []
        end = float(self.trace.times[-1]) if len(self.trace.times) else 0.0
        for vehicle, columns in self.trace.actors.items():
            if vehicle in drives_itself:
                continue
            road = self.road_of(vehicle)
            route = road.route
            if route is None or route.junction_span is None or vehicle not in route.crossers:
                continue
            first, last = route.junction_span
            x = columns["x"] + road.route_shift
            if x[0] > first + TURN_TOLERANCE or x[-1] < last - TURN_TOLERANCE:
                missed.append(Incident(end, f"turn not taken ({route.turn})", (vehicle,)))
        return missed

    def unfollowed(self) -> str:
        """A sentence naming the vehicles the simulator drove without a trajectory of their own
        (``fallbacks``: held where they were, or on the least bad of unsafe candidates) for at
        least ``UNFOLLOWED`` of the run's steps; "" when none. Why: a rejection of such a run says
        more of the simulator than of the scenario, and the report must say so."""
        steps = max(len(self.trace.times), 1)
        named = [
            f"{vehicle} in {count} of {steps} steps"
            for vehicle, count in self.fallbacks.items()
            if count >= UNFOLLOWED * steps
        ]
        if not named:
            return ""
        return (
            f"the simulator found no trajectory of its own for {' and '.join(named)}, so this run says more of "
            "the simulator than of the scenario; another backend may drive it (--roadlogic-simulator kinematic, "
            "or --simulator kinematic on the command line)"
        )

    def road_of(self, vehicle: str) -> Road:
        """The road ``vehicle``'s trace coordinates are on."""
        return self.side_roads.get(vehicle, self.road)


class SimulationTimeout(RuntimeError):
    """The simulation took longer than its time limit (wall clock)."""


@runtime_checkable
class Simulator(Protocol):
    """A simulation backend."""

    name: str

    def simulate(
        self, plan: Plan, limits: SimulationLimits, drivers: DriverFactory | None = None, react=None
    ) -> Simulation:
        """Drive every vehicle of ``plan`` from standstill through its waypoints and record the trace.

        ``drivers`` may drive some vehicles with the user's own planners (the vehicle under test);
        a backend that cannot take them raises ``TypeError`` when one is given. ``react`` (reactive
        execution: ``lockstep.React``) gives vehicles new references while the run goes on; a
        backend that cannot take it raises ``TypeError``. Raises ``SimulationTimeout`` past
        ``limits.time_limit``.
        """
        ...
