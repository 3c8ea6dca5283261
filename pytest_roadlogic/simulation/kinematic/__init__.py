"""The kinematic backend: every vehicle tracks its plan's reference with a kinematic bicycle model
and a closed-form controller (``driver.py``), in the same lockstep loop as the frenetix backend
(the same trace, incidents, waypoints and reactive execution), for fast screening and for
comparison with Scenic's Newtonian simulator at equal fidelity. Selected with
``--roadlogic-simulator kinematic`` / ``roadlogic run --simulator kinematic``; frenetix stays the
default. A user's driver (the vehicle under test) drives its vehicle as under frenetix."""

from __future__ import annotations

from ..lockstep import LockstepSimulator
from .driver import KinematicDriver


class KinematicSimulator(LockstepSimulator):
    name = "kinematic"
    default_driver = KinematicDriver


__all__ = ["KinematicDriver", "KinematicSimulator"]
