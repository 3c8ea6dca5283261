"""Reference drivers of a vehicle under test by name: the built-in ones and any a package registers.

A package adds one with an entry point in the ``pytest_roadlogic.drivers`` group whose object is a
``simulation.Driver`` class (or a factory) taking no arguments; ``--roadlogic-dut-driver NAME``
(ini ``roadlogic_dut_driver``, ``roadlogic run --dut-driver NAME``, a case file's ``dut_driver``)
then drives the vehicle under test with it whenever no ``pytest_roadlogic_driver`` hook gives one.
Names are read without importing anything; a driver is imported when a run builds it.
"""

from __future__ import annotations

from importlib import import_module

from .entry_points import registered_names

ENTRY_POINT_GROUP = "pytest_roadlogic.drivers"
DEFAULT = "acc"
# the built-in ones, as "module:class" in this package, loaded when a run builds one
BUILT_IN = {
    "acc": "pytest_roadlogic.dut.reference_drivers:AdaptiveCruiseControl",
    "late-acc": "pytest_roadlogic.dut.reference_drivers:LateAcc",
    "weak-braking-acc": "pytest_roadlogic.dut.reference_drivers:WeakBrakingAcc",
    "slow-acquisition-acc": "pytest_roadlogic.dut.reference_drivers:SlowAcquisitionAcc",
    "non-yielding-acc": "pytest_roadlogic.dut.reference_drivers:NonYieldingAcc",
}


class UnknownDriver(ValueError):
    """A reference driver's name that no built-in driver or entry point answers to, or an entry
    point that gives no driver."""


def driver_names() -> tuple[str, ...]:
    """Every reference driver's name: the built-in ones, then those packages register."""
    return registered_names(BUILT_IN, ENTRY_POINT_GROUP)


def reference_driver(name: str = DEFAULT):
    """A new driver of the kind ``name`` names (a ``simulation.Driver``: the lockstep loop
    completes one that answers only start and plan); ``UnknownDriver`` when none answers to it."""
    if name in BUILT_IN:
        module, _, attribute = BUILT_IN[name].partition(":")
        return getattr(import_module(module), attribute)()
    from importlib import metadata  # read when a package's driver is asked for: not at start-up

    for point in metadata.entry_points(group=ENTRY_POINT_GROUP):
        if point.name == name:
            try:
                driver = point.load()()
            except Exception as error:  # a package's code: whatever it raises is its entry point's fault
                raise UnknownDriver(
                    f"the entry point {point.value} for the reference driver {name!r} cannot be loaded: "
                    f"{type(error).__name__}: {error}; reinstall or fix the package that declares it"
                ) from None
            # a package's object, checked once here: the loop calls these two on every vehicle it drives
            if not all(callable(getattr(driver, method, None)) for method in ("start", "plan")):
                raise UnknownDriver(
                    f"the entry point {point.value} for the reference driver {name!r} gives no driver "
                    "(it needs start() and plan(); see pytest_roadlogic.simulation.Driver)"
                )
            return driver
    raise UnknownDriver(f"no reference driver named {name!r}; available: {', '.join(driver_names())}")
