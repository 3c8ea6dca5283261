"""The grid encoding's settings (``GridSettings``): the paper's integer grid of cells and steps.

Plain data, importable without clingo: the pipeline, the sampler and the reports read them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import ClassVar

from ....settings import DEFAULT_HORIZON, DEFAULT_PLAN_TIMEOUT
from ...errors import CannotPlanOnMap
from ...protocol import Limit


@dataclass(frozen=True)
class GridSettings:
    """The grid encoding's vehicle limits and planning bounds (``planning.protocol.PlannerSettings``)."""

    encoding: ClassVar[str] = "grid"
    replanning: ClassVar[bool] = False  # its planner plans whole scenarios from their start only
    route: ClassVar[None] = None  # it plans on no map (on_route says CannotPlanOnMap)
    dt: float = 1.0  # seconds per planning step
    grid: float = 1.0  # metres per cell (the road's lanes come with the automaton)
    min_speed: float = 2.0  # m/s; positive, so that no vehicle stops (domain rule 1)
    max_speed: float = 40.0  # m/s
    # m/s the plan starts with: a moderate start keeps the run-up short and the plan easy for a
    # motion planner to track; a scenario that cannot start so is planned with any allowed start
    # speed instead (widen_initial_speed)
    initial_speed: tuple[float, float] = (8.0, 14.0)
    widen_initial_speed: bool = True
    accelerations: tuple[float, ...] = (-2.0, 0.0, 2.0)  # m/s^2, applied for a whole step
    min_gap: float = 8.0  # m between the centres of two vehicles sharing a lane
    lane_change_gap: int = 3  # steps from one lane change of a vehicle to its next
    initial_spread: float = 60.0  # m; other vehicles start within this distance of the first
    # m; start positions are chosen as a zone of this width (an atom the search can vary and a
    # plan be excluded by), the cell within it by the difference-logic solver
    start_zone: float = 5.0
    position_margin: float = 1.5  # m planned inside each side of a position range, when it fits
    speed_margin: float = 0.5  # m/s likewise for speed ranges
    runup_acceleration: float = 2.0  # m/s^2 with which every vehicle leaves standstill
    max_horizon: int = DEFAULT_HORIZON  # steps
    time_limit: float = DEFAULT_PLAN_TIMEOUT  # seconds for one solve, all horizons together
    # when no plan exists, find the constraints that cannot hold together (UnsatisfiableScenario);
    # a search over many samples turns it off and asks only for the one it reports
    explain_unsatisfiable: bool = True
    # seconds the diagnosis may spend deciding whether one constraint can leave the group that
    # clashes (None: as long as the time limit allows); see ContinuousSettings
    removal_time_limit: float | None = None
    # the refined strategy's instances are independent samples: its first plan follows random
    # preferences drawn from the seed (start_preferences) and lasts a random number of steps from
    # the shortest horizon to max_horizon, instead of being the solver's first answer at the shortest
    random_start: bool = False

    def thinned(self) -> None:
        """None: the grid encoding has no fallback search (``planning.fallbacks``), so a sample it
        has no plan for is reported at once; the continuous settings answer with thinner margins."""
        return None

    def finer(self) -> GridSettings:
        """These settings in half the step (the grid itself stays)."""
        return replace(self, dt=self.dt / 2, max_horizon=self.max_horizon * 2, lane_change_gap=self.lane_change_gap * 2)

    def limits(self) -> tuple[Limit, ...]:
        """None: the grid's domain rules are the paper's, never relaxed."""
        return ()

    def relaxed(self, names: frozenset[str] | None = None) -> GridSettings:
        return self

    def describe_margins(self) -> str:
        return f"speed_margin {self.speed_margin:g} m/s, position_margin {self.position_margin:g} m"

    def on_route(self, route, others: tuple = ()) -> GridSettings:
        """Cannot: the grid plans one straight road of integer cells."""
        raise CannotPlanOnMap(
            f"the grid encoding plans on one straight road: {route.name} needs the continuous encoding "
            "(leave out the encoding option)"
        )

    def at_origin(self, origin: float) -> GridSettings:
        return self

    def with_road_speed(self, band: tuple[float, float]) -> GridSettings:
        """Themselves: the grid draws start speeds from ``initial_speed``, not a road's band."""
        return self

    def with_self_driven(self, vehicle: str) -> GridSettings:
        """Themselves: the grid plans every vehicle with the same accelerations."""
        return self

    def summary(self, lanes: int) -> str:
        """The domain rules' numbers on a road of ``lanes`` lanes, for messages that blame them."""
        return (
            f"speeds {self.min_speed:g}..{self.max_speed:g} m/s, accelerations {min(self.accelerations):g}..{max(self.accelerations):g} m/s^2, "
            f"{lanes} lane{'' if lanes == 1 else 's'}, {self.min_gap:g} m gaps, at most {self.max_horizon} steps of {self.dt:g} s"
        )

    def route_extent(self) -> None:
        """None: the grid plans one straight road (``on_route`` says it cannot plan on a map)."""
        return None

    def on_the_map(self, lanes: int) -> str:
        """ "": the grid plans one straight road, every lane all along it."""
        return ""

    def resolution(self) -> dict[str | None, float]:
        """The smallest difference the plan can express, per physical dimension (for sampled values)."""
        return {
            "length": self.grid,
            "speed": self.grid / self.dt,
            "time": self.dt,
            "acceleration": self.grid / self.dt**2,
        }

    def margins(self) -> dict[str | None, float]:
        """How far inside a range's edges the plan keeps, per physical dimension."""
        return {"length": self.position_margin, "speed": self.speed_margin}

    def cells_per_step(self, speed: float) -> float:
        return speed * self.dt / self.grid

    def speeds(self) -> range:
        return range(
            math.ceil(self.cells_per_step(self.min_speed)), math.floor(self.cells_per_step(self.max_speed)) + 1
        )

    def initial_speeds(self) -> range:
        """The start speeds in cells per step."""
        low, high = self.initial_speed
        return range(
            max(math.ceil(self.cells_per_step(low) - 1e-9), self.speeds()[0]),
            min(math.floor(self.cells_per_step(high) + 1e-9), self.speeds()[-1]) + 1,
        )

    def runup_steps(self, cells_per_step: int) -> int:
        """Steps a vehicle needs from standstill to ``cells_per_step`` at the run-up rate."""
        return math.ceil(cells_per_step * self.grid / self.dt / self.runup_acceleration / self.dt - 1e-9)

    def runup_distance(self, speed: float, duration: float) -> float:
        """Metres a vehicle covers in a run-up of ``duration`` s: it accelerates to ``speed``, then cruises."""
        return speed * duration - speed**2 / (2 * self.runup_acceleration)

    def acceleration_cells(self) -> list[int]:
        cells = []
        for a in self.accelerations:
            value = a * self.dt * self.dt / self.grid
            if not float(value).is_integer() or int(value) % 2:
                raise ValueError(
                    f"acceleration {a} m/s^2 is not an even number of cells per step^2 (exact kinematics need it)"
                )
            cells.append(int(value))
        return cells
