"""The frenetix backend: every vehicle starts from standstill on a straight CommonRoad road and is
driven in lockstep through its plan's waypoints by the frenetix motion planner (``driver.py``),
unless the user's ``drivers`` give a vehicle another driver (the vehicle under test)."""

from __future__ import annotations

from ...planning.plan import Plan
from ..interface import DriverFactory, Simulation, SimulationLimits
from ..lockstep import drive_in_lockstep
from .driver import FrenetixDriver


class FrenetixSimulator:
    name = "frenetix"

    def simulate(
        self, plan: Plan, limits: SimulationLimits, drivers: DriverFactory | None = None, react=None
    ) -> Simulation:
        return drive_in_lockstep(plan, limits, drivers, FrenetixDriver, react)


__all__ = ["FrenetixDriver", "FrenetixSimulator"]
