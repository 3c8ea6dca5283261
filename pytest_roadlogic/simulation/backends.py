"""Simulation backends by name: the built-in ``frenetix`` (the default) and ``kinematic`` ones, and any a package registers.

A package adds a backend with an entry point in the ``pytest_roadlogic.simulators`` group whose
object is a ``Simulator`` class (or factory) taking no arguments; ``--roadlogic-simulator NAME``
(ini ``roadlogic_simulator``) then selects it. Backends are imported only when selected, so that a
session pays for none it does not use.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..registries.entry_points import registered_names

if TYPE_CHECKING:
    from .interface import Simulator

ENTRY_POINT_GROUP = "pytest_roadlogic.simulators"
DEFAULT = "frenetix"


class UnknownSimulator(ValueError):
    """A simulator name that no backend answers to."""


def _frenetix() -> Simulator:
    from .frenetix import FrenetixSimulator

    return FrenetixSimulator()


def _kinematic() -> Simulator:
    from .kinematic import KinematicSimulator

    return KinematicSimulator()


BUILT_IN = {"frenetix": _frenetix, "kinematic": _kinematic}


def available() -> list[str]:
    """Every backend name: the built-in ones, then the registered ones."""
    return list(registered_names(BUILT_IN, ENTRY_POINT_GROUP))


def simulator(name: str = DEFAULT) -> Simulator:
    """The backend called ``name``; ``UnknownSimulator`` (with the known names) when there is none."""
    from .interface import Simulator

    if name in BUILT_IN:
        return BUILT_IN[name]()
    from importlib import metadata  # read when a package's is asked for: not at start-up

    for point in metadata.entry_points(group=ENTRY_POINT_GROUP):
        if point.name == name:
            backend = point.load()()
            if not isinstance(backend, Simulator):
                raise UnknownSimulator(
                    f"the entry point {point.value} for simulator {name!r} does not give a simulator (needs name and simulate())"
                )
            return backend
    raise UnknownSimulator(f"no simulator named {name!r}; available: {', '.join(available())}")
