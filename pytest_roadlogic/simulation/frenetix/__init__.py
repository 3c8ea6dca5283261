"""The frenetix backend: every vehicle starts from standstill on a straight CommonRoad road and is
driven in lockstep through its plan's waypoints by the frenetix motion planner (``driver.py``),
unless the user's ``drivers`` give a vehicle another driver (the vehicle under test)."""

from __future__ import annotations

from ..lockstep import LockstepSimulator
from .driver import FrenetixDriver


class FrenetixSimulator(LockstepSimulator):
    name = "frenetix"
    default_driver = FrenetixDriver


__all__ = ["FrenetixDriver", "FrenetixSimulator"]
