"""Drivers: what moves a vehicle through its waypoints, one planning cycle at a time.

A driver sees its own state, its reference (the waypoints) and the other vehicles' predicted
trajectories, and returns a short trajectory; the lockstep loop (``lockstep.py``) advances the
vehicle along it by one time step. ``Driver`` is the whole interface, so a user can plug in their
own planner for the vehicle under test; the frenetix backend's ``FrenetixDriver``
(``simulation/frenetix/``) drives every other vehicle.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from ..roads.road import Road
from .reference import Reference


@dataclass(frozen=True)
class VehicleState:
    """A vehicle's centre position, heading (rad), speed (m/s) and acceleration (m/s^2)."""

    x: float
    y: float
    heading: float
    speed: float
    acceleration: float


@dataclass(frozen=True)
class Trajectory:
    """A short future motion at the simulation time step, index 0 being now."""

    x: np.ndarray
    y: np.ndarray
    heading: np.ndarray
    speed: np.ndarray
    acceleration: np.ndarray

    def state(self, index: int) -> VehicleState:
        index = min(index, len(self.x) - 1)
        return VehicleState(
            float(self.x[index]),
            float(self.y[index]),
            float(self.heading[index]),
            float(self.speed[index]),
            float(self.acceleration[index]),
        )

    def shifted(self) -> Trajectory:
        """The same motion seen one time step later (a prediction for the next cycle)."""
        if len(self.x) <= 1:
            return self
        return Trajectory(self.x[1:], self.y[1:], self.heading[1:], self.speed[1:], self.acceleration[1:])

    @staticmethod
    def standing(state: VehicleState, steps: int = 1) -> Trajectory:
        ones = np.ones(steps)
        return Trajectory(state.x * ones, state.y * ones, state.heading * ones, state.speed * ones, 0 * ones)


class Driver(Protocol):
    """What the lockstep loop calls of a driver (see the README for a custom driver). A driver
    derived from ``DriverBase`` answers ``retarget`` and ``fallbacks`` by default; one that is not
    is completed so (``complete``)."""

    fallbacks: int  # steps it drove without a trajectory of its own (a fallback), for the report

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        """Called once before the simulation, with the vehicle's reference and the road."""

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        """Called every time step; returns a trajectory starting at ``state``."""

    def retarget(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        """Follow ``reference`` from now on (a replan of the reactive execution)."""


class DriverBase:
    """A driver's defaults: a replan starts it again on the new reference, and it never falls back."""

    fallbacks: int = 0

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        raise NotImplementedError

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        raise NotImplementedError

    def retarget(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.start(vehicle, reference, road, dt)


class _Completed(DriverBase):
    """A user's driver with only ``start`` and ``plan``, given ``DriverBase``'s answers for the rest."""

    def __init__(self, driver) -> None:
        self.driver = driver

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.driver.start(vehicle, reference, road, dt)

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        return self.driver.plan(time, state, others)


def complete(driver) -> Driver:
    """``driver`` as the lockstep loop calls it: itself when it derives from ``DriverBase``, else
    its ``start`` and ``plan`` with ``DriverBase``'s ``retarget`` and ``fallbacks``."""
    return driver if isinstance(driver, DriverBase) else _Completed(driver)


class StationaryDriver(DriverBase):
    """Holds a stationary object where it stands: the plan's obstacles are not driven."""

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.steps = max(1, int(round(3.0 / dt)))

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        return Trajectory.standing(VehicleState(state.x, state.y, state.heading, 0.0, 0.0), self.steps)
