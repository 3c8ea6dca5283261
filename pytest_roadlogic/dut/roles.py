"""Who is under test, what drives it, and where its oracles fail: one ``UnderTest`` per run.

The vehicle under test is the scenario's own (the standard's ``dut.car``, or a vehicle named
``dut``) unless the ``dut`` option names another vehicle, or ``none`` (every vehicle follows its
plan: conformance scenarios, as the RoadLogic paper generates them). It drives itself with the
driver a ``pytest_roadlogic_driver`` hook gives it, else with the reference driver the
``dut-driver`` option names (``registries.drivers``). Every other vehicle is the scenario's.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from ..oracles import Thresholds
from ..registries.drivers import DEFAULT, reference_driver
from ..settings import DUT_NAMES

AUTO, NONE = "auto", "none"
# the spellings of the vehicle under test in scenario files (the standard's dut.car and
# dut.vehicle, CARLA's dut), declared once in settings for the front end and this module
STANDARD_NAMES = DUT_NAMES


class NoSuchVehicle(ValueError):
    """The ``dut`` option names a vehicle the scenario does not have."""


@dataclass(frozen=True)
class UnderTest:
    """Which vehicle is under test (``role``: auto, none or a name), its reference driver's name,
    the oracles' thresholds, and how often the other vehicles are replanned around it."""

    role: str = AUTO
    driver: str = DEFAULT
    thresholds: Thresholds = field(default_factory=Thresholds)
    # seconds between replans of the scenario's other vehicles while it drives (reactive execution);
    # 0: they follow their first plan whatever it does (open loop)
    replan_period: float = 0.25

    @classmethod
    def of(cls, settings) -> UnderTest:
        """Who is under test in a run of ``settings`` (``RunSettings``), and how it is judged."""
        return cls(settings.dut, settings.dut_driver, Thresholds.of(settings), settings.replan_period)

    def vehicle(self, vehicles: Sequence[str]) -> str | None:
        """The vehicle under test among the scenario's ``vehicles``, None when there is none."""
        if self.role == NONE:
            return None
        if self.role == AUTO:
            return next((name for name in STANDARD_NAMES if name in vehicles), None)
        if self.role not in vehicles:
            raise NoSuchVehicle(
                f"the vehicle under test {self.role!r} is not a vehicle of the scenario (its vehicles: "
                f"{', '.join(vehicles)}); give one of them, or auto or none"
            )
        return self.role

    def reference_driver(self):
        """A new reference driver of the kind ``driver`` names."""
        return reference_driver(self.driver)

    def drivers(self, vehicle: str | None, given: Callable[[str], object] | None):
        """The driver factory of a run: ``given`` (a hook's) first; the vehicle under test, when the
        hook gives it none, the reference driver; every other vehicle the simulator's own."""

        def factory(name: str):
            driver = given(name) if given else None
            if driver is None and name == vehicle:
                driver = self.reference_driver()
            return driver

        return factory
