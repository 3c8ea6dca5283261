"""The construct registries by dialect name: what ``check_file(..., dialect=...)`` checks with.

A registry (``checked.Registry``) says what a dialect's actions and modifiers are; the constructs
provide them (``pytest_roadlogic.constructs``: ``standard`` and ``carla``), and any package may add
a dialect with an entry point in the ``pytest_roadlogic.dialects`` group whose object is a
registry. Looked up by name, as the simulators are (``simulation/backends.py``), so that the front
end, which the constructs are written in terms of, does not import them.
"""

from __future__ import annotations

import functools
from importlib import metadata

from ...settings import STANDARD_DIALECT
from .checked import Registry

ENTRY_POINT_GROUP = "pytest_roadlogic.dialects"


def names() -> list[str]:
    """Every dialect a package registers, the standard first."""
    found = sorted({point.name for point in metadata.entry_points(group=ENTRY_POINT_GROUP)})
    return sorted(found, key=lambda name: name != STANDARD_DIALECT)


@functools.cache
def registry(name: str = STANDARD_DIALECT) -> Registry:
    """The registry of dialect ``name``; ``ValueError`` naming the known ones when there is none."""
    for point in metadata.entry_points(group=ENTRY_POINT_GROUP):
        if point.name == name:
            return point.load()
    known = names()
    if not known:
        raise ValueError(
            f"no dialect is registered (not even {STANDARD_DIALECT!r}): install pytest-roadlogic, e.g. pip install -e ."
        )
    raise ValueError(f"unknown dialect {name!r}; give one of {', '.join(known)}")
