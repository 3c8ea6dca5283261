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

from .reference import Reference
from .road import Road


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
    """The interface every driver implements (see the README for a custom driver)."""

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        """Called once before the simulation, with the vehicle's reference and the road."""

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        """Called every time step; returns a trajectory starting at ``state``."""


class StationaryDriver:
    """Holds a stationary object where it stands: the plan's obstacles are not driven."""

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.steps = max(1, int(round(3.0 / dt)))

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        return Trajectory.standing(VehicleState(state.x, state.y, state.heading, 0.0, 0.0), self.steps)
