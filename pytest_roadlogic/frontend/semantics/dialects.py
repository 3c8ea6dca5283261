"""The construct registries by dialect name: what ``check_file(..., dialect=...)`` checks with.

A registry (``checked.Registry``) says what a dialect's actions and modifiers are; the constructs
provide the built-in ones (``pytest_roadlogic.constructs``: ``standard`` and ``carla``), and any
package may add a dialect with an entry point in the ``pytest_roadlogic.dialects`` group whose
object is a registry. Looked up by name, as the simulators are (``simulation/backends.py``), so
that the front end, which the constructs are written in terms of, does not import them; the
installed packages' entry points are read only for a name that is not built in (reading them
costs every run tens of milliseconds).
"""

from __future__ import annotations

import functools
from importlib import import_module

from ...registries.entry_points import registered_names
from ...settings import DIALECT_ENTRY_POINTS, DIALECTS, STANDARD_DIALECT
from .checked import Registry

ENTRY_POINT_GROUP = DIALECT_ENTRY_POINTS
# the package whose DIALECTS holds the built-in registries by name, imported when a file is read
CONSTRUCTS = "pytest_roadlogic.constructs"


def names() -> list[str]:
    """Every dialect's name: the built-in ones (the standard first), then those packages register."""
    return list(registered_names(DIALECTS, ENTRY_POINT_GROUP))


@functools.cache
def registry(name: str = STANDARD_DIALECT) -> Registry:
    """The registry of dialect ``name``; ``ValueError`` naming the known ones when there is none."""
    if name in DIALECTS:
        return import_module(CONSTRUCTS).DIALECTS[name]
    from importlib import metadata  # read when a package's dialect is asked for: not at start-up

    for point in metadata.entry_points(group=ENTRY_POINT_GROUP):
        if point.name == name:
            return point.load()
    raise ValueError(f"unknown dialect {name!r}; give one of {', '.join(names())}")
