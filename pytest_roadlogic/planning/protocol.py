"""What a planner encoding is, as the rest of the tool sees it: its settings, its planner, its name.

An encoding is a folder (``encodings/<name>/``) with its settings, its instance writer, its ``.lp``
files (``asp/<name>/``), its planner and its plan decoder, registered under its name
(``encodings.available()``; ``--roadlogic-encoding NAME``, ini ``roadlogic_encoding``, ``--encoding``
on the CLI). The pipeline, the fallbacks, the reactive execution, the sampler and the reports speak
only these protocols. Every capability is declared here and every encoding answers it, "cannot"
included: planning on a map's route (``on_route``), the fallback chain (``thinned``, ``finer``,
``limits``, ``relaxed``), replanning from an observed state (``replanning``, ``Planner.replan``) and
the diagnosis (``Planner.explain_failure``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar, Protocol

from ..logic.automaton import SymbolicAutomaton
from .errors import CannotPlanOnMap, CannotReplan  # noqa: F401 (the protocol's answers of "cannot")
from .plan import Plan, PlanState

if TYPE_CHECKING:
    from ..roads.route import Route
    from .relaxation import RouteExtent


@dataclass(frozen=True)
class Limit:
    """One vehicle limit a fallback planner may relax: its field, its value, the value it is relaxed
    to, its unit, whether it is a real car's (a plan beyond it has no concrete scenario) or the
    tool's spacing between cars, and why it has its value when that is not a car's own."""

    name: str
    value: float
    relaxed: float
    unit: str
    of_a_car: bool
    reason: str = ""

    def describe(self) -> str:
        why = f" ({self.reason})" if self.reason else ""
        return f"{self.name} {self.value:g} {self.unit}{why} relaxed to {self.relaxed:g}"


@dataclass(frozen=True)
class Past:
    """What a replan starts from: the planning step ``now``, every vehicle's ``observed`` state
    there, the run so far (``seen``: every vehicle's state at every step before; None: the run the
    driven plan took, its ``ran`` transitions (transition id, step)), the vehicle under test
    ``self_driven`` and whether it is ``predicted`` (holds its observed speed and lane) or planned
    as any car could drive."""

    now: int
    observed: dict[str, PlanState]
    seen: dict[int, dict[str, PlanState]] | None
    ran: tuple[tuple[int, int], ...]
    self_driven: str
    predicted: bool


class PlannerSettings(Protocol):
    """An encoding's settings: plain, frozen data (``dataclasses.replace`` makes variants)."""

    encoding: ClassVar[str]  # the name the encoding is registered under
    replanning: ClassVar[bool]  # whether its planner replans from an observed state (Planner.replan)
    dt: float  # seconds per planning step
    max_horizon: int  # steps
    time_limit: float  # seconds for one planning
    explain_unsatisfiable: bool  # find the constraints that clash when there is no plan
    random_start: bool  # the refined strategy's draws from the seed
    position_margin: float  # metres planned inside a position range
    speed_margin: float  # m/s planned inside a speed range
    route: (
        Route | None
    )  # the map's route these settings plan on (``on_route``), which each plan carries; None: the straight road

    def resolution(self) -> dict[str | None, float]:
        """How wide a band a sampled value is narrowed to, per physical dimension."""
        ...

    def margins(self) -> dict[str | None, float]:
        """How far inside a range's edges the plan keeps, per physical dimension."""
        ...

    max_speed: float  # m/s

    def thinned(self) -> PlannerSettings | None:
        """The settings of a second search with thinner margins, or None when there is none (then
        there is no fallback search at all)."""
        ...

    def finer(self) -> PlannerSettings:
        """These settings in half the planning step (a fallback: durations between whole steps)."""
        ...

    def limits(self) -> tuple[Limit, ...]:
        """The vehicle limits a fallback may relax, in the order a diagnosis tries them alone."""
        ...

    def relaxed(self, names: frozenset[str] | None = None) -> PlannerSettings:
        """These settings with the ``limits`` named (all by default) at their relaxed values."""
        ...

    def describe_margins(self) -> str:
        """The margins, with their units, for messages that blame them."""
        ...

    def on_route(self, route, others: tuple = ()) -> PlannerSettings:
        """These settings for a scenario on a map's ``route`` (``roads.Route``), and on ``others``
        (more routes of the map, each driven by its ``crossers``: vehicles that take other ways
        through a junction); ``CannotPlanOnMap`` from an encoding that plans one straight road only."""
        ...

    def at_origin(self, origin: float) -> PlannerSettings:
        """These settings with the plan's position 0 pinned at ``origin`` metres along the route
        (a replan stays where the simulation has the scenario); themselves off a map."""
        ...

    def with_road_speed(self, band: tuple[float, float]) -> PlannerSettings:
        """These settings with the start speeds (m/s) a vehicle the scenario names none for is
        preferred to have; themselves for an encoding without such a preference."""
        ...

    def with_self_driven(self, vehicle: str) -> PlannerSettings:
        """These settings with ``vehicle`` driving itself (the vehicle under test): its plan is
        a guess at what its own driver does, so it is planned as braking as briskly as a car can;
        themselves for an encoding that plans every vehicle alike."""
        ...

    def summary(self, lanes: int) -> str:
        """The vehicle limits and bounds on a road of ``lanes`` lanes, for messages that blame them."""
        ...

    def route_extent(self) -> RouteExtent | None:
        """Where along the map's route the vehicles may be, for the linear relaxation that proves a
        sample has no plan (``relaxation.RouteExtent``); None off a map (and for an encoding that
        plans one straight road)."""
        ...

    def on_the_map(self, lanes: int) -> str:
        """Where a map's routes let the vehicles be (on a road of ``lanes`` lanes): the stretch of
        each route its vehicles stay on, and its lanes that take a car along part of it only (a
        lane that begins or ends), for a message about constraints that cannot hold together; ""
        off a map."""
        ...


class Planner(Protocol):
    """Plans for one automaton: lazily, shortest (or a random start's drawn length) first."""

    automaton: SymbolicAutomaton
    settings: PlannerSettings
    seed: int
    stats: dict[str, float]

    def plans(self, limit: int | None = None, deadline: float | None = None) -> Iterator[Plan]:
        """Plans; ``NoPlanError`` (a subclass saying why) when there is none. The first plan is
        due by ``deadline`` (``time.monotonic()``; default: ``settings.time_limit`` from now) or
        ``PlanningTimeout``; each later one has the whole time limit from when it is asked."""
        ...

    def first(self) -> Plan: ...

    def instance_program(self) -> str:
        """The scenario's instance as this encoding writes it (``roadlogic plan --show-asp``)."""
        ...

    def explain(self, deadline: float | None = None) -> tuple | None:
        """A smallest group of the scenario's constraints that no plan meets, or None."""
        ...

    def explain_failure(self, error: Exception, deadline: float) -> None:
        """Raise the reason no plan exists, natural or not (``diagnosis.raise_reason``): a horizon
        limit that binds, the smallest group of constraints that clash, else ``error``."""
        ...

    def replan(self, past: Past, shortest: int) -> Plan | None:
        """The first plan, at least ``shortest`` steps long, that goes on from ``past``; None when
        none does; ``NoPlanError`` saying why. ``CannotReplan`` from an encoding whose settings
        say ``replanning = False``."""
        ...


@dataclass(frozen=True)
class Encoding:
    """One registered encoding: its name, its settings class (light: no solver is imported with it),
    and ``planner()``, which imports and returns its planner class (with clingo) on first use."""

    name: str
    settings: type
    planner: Callable[[], Callable[[SymbolicAutomaton, Any, int], Planner]]
    description: str
