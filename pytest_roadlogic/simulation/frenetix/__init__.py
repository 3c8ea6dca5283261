"""The frenetix backend: every vehicle starts from standstill on a straight CommonRoad road and is
driven in lockstep through its plan's waypoints by the frenetix motion planner (``driver.py``),
unless the user's ``drivers`` give a vehicle another driver (the vehicle under test)."""

from __future__ import annotations

from ...roads.road import Road
from ..lockstep import LockstepSimulator
from ..reference import Reference
from .driver import FrenetixDriver

# m/s below which a planned vehicle counts as standing still (remain_stationary's bound is 0.1)
STILL = 0.2


class FrenetixSimulator(LockstepSimulator):
    name = "frenetix"
    default_driver = FrenetixDriver

    def holds(self, reference: Reference, road: Road) -> bool:
        """On a map, a vehicle its plan holds at a standstill throughout (``remain_stationary``):
        frenetix lets a car standing in a curve creep (on the straight road it keeps them)."""
        return road.route is not None and all(abs(w.speed) < STILL for w in reference.waypoints)


__all__ = ["FrenetixDriver", "FrenetixSimulator"]
