"""Stage 4: simulation, from a plan to a ``Simulation`` (its ``Trace`` is what the monitor reads).

The seam is ``Simulator`` (``interface.py``): a plan and ``SimulationLimits`` in, a simulation out.
The default backend is frenetix (``frenetix/``); ``backends.simulator(name)`` selects one by name.
The names below load on first use, so that the plugin can ask ``backends`` which simulators exist
without importing numpy, the planner's data or a backend.
"""

from importlib import import_module

_HOMES = {
    "CrossTraffic": "driver",
    "Driver": "driver",
    "DriverBase": "driver",
    "Trajectory": "driver",
    "VehicleState": "driver",
    "DriverFactory": "interface",
    "GoalRecord": "interface",
    "Reaction": "interface",
    "Replan": "interface",
    "Simulation": "interface",
    "SimulationLimits": "interface",
    "SimulationTimeout": "interface",
    "Simulator": "interface",
    "Reference": "reference",
    "Waypoint": "reference",
    "references": "reference",
    "Road": ".roads.road",  # the road model is roads'; a driver is given one
    "ActorSnapshot": "trace",
    "Incident": "trace",
    "Trace": "trace",
}


def __getattr__(name: str):
    if name in _HOMES:
        return getattr(import_module(f".{_HOMES[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def simulate(plan, dt: float = 0.1, drivers=None, time_limit: float | None = None, simulator=None):
    """Simulate ``plan`` with ``simulator`` (default: the frenetix backend)."""
    from .backends import simulator as named
    from .interface import SimulationLimits

    return (simulator or named()).simulate(plan, SimulationLimits(dt, time_limit), drivers)


__all__ = [*_HOMES, "simulate"]
