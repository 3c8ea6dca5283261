"""Drivers: what moves a vehicle through its waypoints, one planning cycle at a time.

A driver sees its own state, its reference (the waypoints) and the other vehicles' predicted
trajectories, and returns a short trajectory; the lockstep loop (``lockstep.py``) advances the
vehicle along it by one time step. ``Driver`` is the whole interface, so a user can plug in their
own planner for the vehicle under test; the frenetix backend's ``FrenetixDriver``
(``simulation/frenetix/``) drives every other vehicle.

On a map whose routes meet (ways through a junction), a driver also sees, before it plans, the
vehicles of other routes whose ways meet its own (``CrossTraffic``): where the meeting lies on its
road and how far each of them has still to go to it along its own way, as a driver reads a
crossing and the cars coming to it.
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


@dataclass(frozen=True)
class CrossTraffic:
    """A vehicle of another route whose way meets this vehicle's: the meeting lies between
    ``start`` and ``end`` on this vehicle's road (its x); ``kind`` is "crossing" (the ways cross:
    the other is in it only while it passes) or "shared" (the ways join into one lane); the
    other's centre has ``distance`` metres to go along its own way to where the meeting begins
    there (negative once past that), ``length`` metres of its way are in the meeting, and it drives
    at ``speed`` (m/s) accelerating at ``acceleration`` (m/s^2)."""

    vehicle: str
    kind: str
    start: float
    end: float
    distance: float
    length: float
    speed: float
    acceleration: float


class Driver(Protocol):
    """What the lockstep loop calls of a driver (see the README for a custom driver). A driver
    derived from ``DriverBase`` answers ``see``, ``retarget`` and ``fallbacks`` by default; one
    that is not is completed so (``complete``)."""

    fallbacks: int  # steps it drove without a trajectory of its own (a fallback), for the report
    # whether ``plan`` reads the other vehicles' trajectories: while no other driver does, the
    # loop needs only the next state of a driver's trajectory (``predicts``)
    reads_others: bool

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        """Called once before the simulation, with the vehicle's reference and the road."""

    def predicts(self, needed: bool) -> None:
        """Called once before ``start``: whether another driver reads this one's trajectory past
        its next state (as a prediction). Without, a driver may return its next state only."""

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        """Called every time step; returns a trajectory starting at ``state``. ``others``: the
        vehicles of its own route, in its road's coordinates."""

    def see(self, traffic: tuple[CrossTraffic, ...]) -> None:
        """Called every time step before ``plan``, with the vehicles of other routes whose ways
        meet its own ahead of it (none on one road)."""

    def retarget(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        """Follow ``reference`` from now on (a replan of the reactive execution)."""


class DriverBase:
    """A driver's defaults: a replan starts it again on the new reference, it never falls back,
    it keeps the cross traffic it last saw in ``cross_traffic`` (a driver that plans along a
    plan made with every route, as the scenario's own vehicles' do, needs no more), it reads the
    others' trajectories, and its own are as long as it makes them."""

    fallbacks: int = 0
    cross_traffic: tuple[CrossTraffic, ...] = ()
    reads_others: bool = True  # a user's driver may: its predictions are kept for it

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        raise NotImplementedError

    def predicts(self, needed: bool) -> None:
        """Its trajectories are as long as it makes them, read or not."""

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        raise NotImplementedError

    def see(self, traffic: tuple[CrossTraffic, ...]) -> None:
        self.cross_traffic = traffic

    def retarget(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.start(vehicle, reference, road, dt)


class _Completed(DriverBase):
    """A user's driver with only ``start`` and ``plan``, given ``DriverBase``'s answers for the
    rest (a driver that reads the cross traffic derives from ``DriverBase`` and overrides ``see``)."""

    def __init__(self, driver) -> None:
        self.driver = driver

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.driver.start(vehicle, reference, road, dt)

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        return self.driver.plan(time, state, others)


def complete(driver) -> Driver:
    """``driver`` as the lockstep loop calls it: itself when it derives from ``DriverBase``, else
    its ``start`` and ``plan`` with ``DriverBase``'s answers for the rest."""
    return driver if isinstance(driver, DriverBase) else _Completed(driver)


class StationaryDriver(DriverBase):
    """Holds a stationary object where it stands: the plan's obstacles are not driven."""

    reads_others = False

    def start(self, vehicle: str, reference: Reference, road: Road, dt: float) -> None:
        self.steps = max(1, int(round(3.0 / dt)))

    def plan(self, time: float, state: VehicleState, others: dict[str, Trajectory]) -> Trajectory:
        return Trajectory.standing(VehicleState(state.x, state.y, state.heading, 0.0, 0.0), self.steps)
