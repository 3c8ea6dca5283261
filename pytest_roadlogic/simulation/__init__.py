"""Stage 4: simulation with CommonRoad and frenetix (``simulate``), from a plan to a ``Trace``."""

from .driver import Driver, FrenetixDriver, Trajectory, VehicleState
from .reference import Reference, Waypoint, references
from .road import Road
from .simulator import Simulation, road_for, simulate
from .trace import ActorSnapshot, Incident, Trace

__all__ = [
    "ActorSnapshot", "Driver", "FrenetixDriver", "Incident", "Reference", "Road", "Simulation", "Trace",
    "Trajectory", "VehicleState", "Waypoint", "references", "road_for", "simulate",
]
