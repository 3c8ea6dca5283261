"""Names by entry point: the built-in ones of a kind, then those installed packages register."""

from __future__ import annotations

from collections.abc import Iterable


def registered_names(built_in: Iterable[str], group: str) -> tuple[str, ...]:
    """The ``built_in`` names, then every other name an installed package registers under the
    entry point ``group`` (names only: nothing is imported)."""
    from importlib import metadata

    built_in = tuple(built_in)
    registered = [point.name for point in metadata.entry_points(group=group)]
    return (*built_in, *(name for name in registered if name not in built_in))
