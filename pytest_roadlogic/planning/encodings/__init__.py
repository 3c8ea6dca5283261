"""Planner encodings by name: the built-in ``continuous`` (the default) and ``grid``, and any a package registers.

A package adds an encoding with an entry point in the ``pytest_roadlogic.encodings`` group whose
object is a ``protocol.Encoding``; ``--roadlogic-encoding NAME`` (ini ``roadlogic_encoding``,
``--encoding`` on the CLI) then selects it. Only an encoding's settings are imported to look it up;
its planner, and with it the solver, on first use.
"""

from __future__ import annotations

from ...settings import ENCODING_ENTRY_POINTS, encoding_names
from ..protocol import Encoding
from .continuous import ENCODING as CONTINUOUS
from .grid import ENCODING as GRID

ENTRY_POINT_GROUP = ENCODING_ENTRY_POINTS
BUILT_IN = {CONTINUOUS.name: CONTINUOUS, GRID.name: GRID}


class UnknownEncoding(ValueError):
    """An encoding name that nothing answers to."""


def available() -> list[str]:
    """Every encoding's name: the built-in ones, then the registered ones."""
    return list(encoding_names())


def encoding(name: str) -> Encoding:
    """The encoding called ``name``; ``UnknownEncoding`` (with the known names) when there is none."""
    if name in BUILT_IN:
        return BUILT_IN[name]
    from importlib import metadata  # read when a package's is asked for: not at start-up

    for point in metadata.entry_points(group=ENTRY_POINT_GROUP):
        if point.name == name:
            found = point.load()
            if not isinstance(found, Encoding):
                raise UnknownEncoding(
                    f"the entry point {point.value} for encoding {name!r} does not give a pytest_roadlogic.planning.protocol.Encoding"
                )
            return found
    raise UnknownEncoding(f"no planner encoding named {name!r}; available: {', '.join(available())}")


def of_settings(settings) -> Encoding:
    """The encoding ``settings`` belong to (by their ``encoding`` name)."""
    return encoding(type(settings).encoding)
