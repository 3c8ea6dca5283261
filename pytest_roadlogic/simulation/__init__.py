"""Stage 4: simulation with CommonRoad and frenetix (``simulate``), from a plan to a ``Trace``."""

from .driver import Driver, FrenetixDriver, Trajectory, VehicleState
from .reference import Reference, Waypoint, references
from .road import Road
from .simulator import Simulation, SimulationTimeout, road_for, simulate
from .trace import ActorSnapshot, Incident, Trace

__all__ = [
    "ActorSnapshot", "Driver", "FrenetixDriver", "Incident", "Reference", "Road", "Simulation", "SimulationTimeout", "Trace",
    "Trajectory", "VehicleState", "Waypoint", "references", "road_for", "simulate",
]
