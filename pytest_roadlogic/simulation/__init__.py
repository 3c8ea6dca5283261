"""Stage 4: simulation, from a plan to a ``Simulation`` (its ``Trace`` is what the monitor reads).

The seam is ``Simulator`` (``interface.py``): a plan and ``SimulationLimits`` in, a simulation out.
The default backend is frenetix (``frenetix/``); ``backends.simulator(name)`` selects one by name.
Importing this package loads neither frenetix nor CommonRoad: a backend loads them when it runs.
"""

from .driver import Driver, Trajectory, VehicleState
from .interface import DriverFactory, GoalRecord, Simulation, SimulationLimits, SimulationTimeout, Simulator
from .reference import Reference, Waypoint, references
from .road import Road
from .trace import ActorSnapshot, Incident, Trace


def simulate(plan, dt: float = 0.1, drivers: DriverFactory | None = None, time_limit: float | None = None, simulator: Simulator | None = None) -> Simulation:
    """Simulate ``plan`` with ``simulator`` (default: the frenetix backend)."""
    from .backends import simulator as named

    return (simulator or named()).simulate(plan, SimulationLimits(dt, time_limit), drivers)


__all__ = [
    "ActorSnapshot", "Driver", "DriverFactory", "GoalRecord", "Incident", "Reference", "Road", "Simulation", "SimulationLimits",
    "SimulationTimeout", "Simulator", "Trace", "Trajectory", "VehicleState", "Waypoint", "references", "simulate",
]
