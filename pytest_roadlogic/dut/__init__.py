"""The vehicle under test: who it is (``roles``) and reference drivers for it (``reference_drivers``; ``registries.drivers`` names them).

A vehicle under test is given a goal, not a script: it drives itself (with the user's driver, or
a reference one), the oracles (``pytest_roadlogic.oracles``) say whether it failed, and the
monitor whether the scenario happened around it.
"""

from ..registries.drivers import UnknownDriver, driver_names, reference_driver
from .roles import AUTO, NONE, STANDARD_NAMES, NoSuchVehicle, UnderTest

__all__ = [
    "AUTO",
    "NONE",
    "STANDARD_NAMES",
    "NoSuchVehicle",
    "UnderTest",
    "UnknownDriver",
    "driver_names",
    "reference_driver",
]
