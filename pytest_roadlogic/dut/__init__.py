"""The vehicle under test: who it is (``roles``) and reference drivers for it (``acc``).

A vehicle under test is given a goal, not a script: it drives itself (with the user's driver, or
a reference one), the oracles (``pytest_roadlogic.oracles``) say whether it failed, and the
monitor whether the scenario happened around it.
"""

from .roles import AUTO, NONE, REFERENCE_DRIVERS, STANDARD_NAMES, NoSuchVehicle, UnderTest

__all__ = ["AUTO", "NONE", "REFERENCE_DRIVERS", "STANDARD_NAMES", "NoSuchVehicle", "UnderTest"]
