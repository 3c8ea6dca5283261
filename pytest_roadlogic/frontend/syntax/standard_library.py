"""The standard library shipped as ``.osc`` files (``pytest_roadlogic/stdlib/osc/``), read once.

``import osc.standard`` names these files, and they are where the standard's declarations live:
the physical types and units with their factors (the unit table every literal is read with), the
enums, the actor hierarchy, the actions, modifiers and condition methods with their parameters.
The tool's meaning of each construct is in ``pytest_roadlogic.constructs`` (and a test keeps each
construct's parameters equal to its declaration here); a construct declared here that the tool
does not provide is refused by name where it is used.

The files are read with the project's syntax (``frontend.syntax.syntax``, which needs no unit table of
its own) on first use, not at import, so the tables are lazy mappings (``LazyTable``). What they
declare is also shipped as ``stdlib/osc/declarations.json``, written from them by
``python -m pytest_roadlogic.frontend.syntax.regenerate --declarations`` and stamped with their digest:
while the digest matches, a run reads that table instead of parsing seven files (parsing them
costs a few tenths of a second of every run's start-up); when a file changed, the files are parsed.
"""

from __future__ import annotations

import functools
import hashlib
import json
from collections.abc import Callable, Iterator, Mapping
from dataclasses import asdict, dataclass
from pathlib import Path

from .syntax import parse_text
from .units import dimension_of

STDLIB_DIR = Path(__file__).resolve().parents[2] / "stdlib"
LIBRARY_ROOT = "osc"
DECLARATIONS_FILE = STDLIB_DIR / LIBRARY_ROOT / "declarations.json"


@dataclass(frozen=True)
class Declared:
    """An action, modifier or method of the standard library: its owner type and parameters
    (name -> declared type), and for a method its return type."""

    name: str
    owner: str | None
    parameters: tuple[tuple[str, str], ...]
    part: str  # the library part that declares it (osc.movement)
    returns: str | None = None


@dataclass(frozen=True)
class StandardLibrary:
    parts: dict[str, Path]  # osc.physical -> its file
    types: dict[str, str | None]  # physical type -> dimension (None: not modelled)
    units: dict[str, tuple[str, float]]  # modelled unit -> (dimension, SI factor)
    enums: dict[str, tuple[str, ...]]
    actors: dict[str, str | None]  # actor type -> parent
    actions: dict[str, Declared]
    modifiers: dict[str, Declared]
    methods: dict[str, Declared]
    unmodelled_units: dict[str, str]  # a unit of a dimension the pipeline does not model -> its type

    def ancestors(self, actor: str) -> list[str]:
        """``actor`` and its parents up the hierarchy (empty when it is not a standard actor)."""
        chain: list[str] = []
        current: str | None = actor
        while current is not None and current in self.actors and current not in chain:
            chain.append(current)
            current = self.actors[current]
        return chain


def part_file(name: str) -> Path | None:
    """The file of ``osc.<part>`` (``import osc.physical``), None when there is no such part."""
    pieces = name.split(".")
    if pieces[0] != LIBRARY_ROOT or len(pieces) != 2:
        return None
    path = STDLIB_DIR / LIBRARY_ROOT / f"{pieces[1]}.osc"
    return path if path.is_file() else None


def part_names() -> list[str]:
    return sorted(f"{LIBRARY_ROOT}.{p.stem}" for p in (STDLIB_DIR / LIBRARY_ROOT).glob("*.osc"))


def library_digest() -> str:
    """The digest of the library's files (their names and contents), which stamps the table
    ``declarations.json`` was written from."""
    digest = hashlib.sha256()
    for name in part_names():
        digest.update(name.encode() + b"\0" + part_file(name).read_bytes() + b"\0")
    return digest.hexdigest()


@functools.cache
def standard_library() -> StandardLibrary:
    """The library's declarations: from ``declarations.json`` while it was written from the files
    as they are, else from the files, read with the syntax alone (they declare the units every
    other file is read with, and write no literal with a unit themselves)."""
    shipped = _shipped_declarations()
    return shipped if shipped is not None else parse_library()


def _shipped_declarations() -> StandardLibrary | None:
    try:
        table = json.loads(DECLARATIONS_FILE.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(table, dict) or table.get("digest") != library_digest():
        return None

    def declared(entries: dict) -> dict[str, Declared]:
        return {
            name: Declared(e["name"], e["owner"], tuple(map(tuple, e["parameters"])), e["part"], e["returns"])
            for name, e in entries.items()
        }

    return StandardLibrary(
        {name: part_file(name) for name in part_names()},
        table["types"],
        {name: tuple(unit) for name, unit in table["units"].items()},
        {name: tuple(members) for name, members in table["enums"].items()},
        table["actors"],
        declared(table["actions"]),
        declared(table["modifiers"]),
        declared(table["methods"]),
        table["unmodelled_units"],
    )


def parse_library() -> StandardLibrary:
    """The library's declarations read from its ``.osc`` files."""
    parts = {name: part_file(name) for name in part_names()}
    files = {name: parse_text(path.read_text(encoding="utf-8"), str(path), {}) for name, path in parts.items()}
    types: dict[str, str | None] = {}
    units: dict[str, tuple[str, float]] = {}
    enums: dict[str, tuple[str, ...]] = {}
    actors: dict[str, str | None] = {}
    actions: dict[str, Declared] = {}
    modifiers: dict[str, Declared] = {}
    methods: dict[str, Declared] = {}
    unmodelled: dict[str, str] = {}
    for part, osc in files.items():
        for declared in osc.physical_types:
            types[declared.name] = dimension_of(declared.exponents)
        for unit in osc.units:
            if (dimension := dimension_of(unit.exponents)) is not None:
                units[unit.name] = (dimension, unit.factor, unit.offset) if unit.offset else (dimension, unit.factor)
            else:
                unmodelled[unit.name] = unit.type
        for enum in osc.enums:
            enums[enum.name] = enum.members
        for actor in osc.types:
            actors[actor.name] = actor.parent
        for action in osc.scenarios:
            actions[action.name] = Declared(
                action.name, action.actor_type, tuple((f.name, f.type) for f in action.fields), part
            )
        for modifier in osc.modifier_declarations:
            modifiers[modifier.name] = Declared(
                modifier.name, modifier.owner, tuple((f.name, f.type) for f in modifier.parameters), part
            )
        for extension in osc.extensions:
            for method in extension.scenario.methods:
                methods[method.name] = Declared(
                    method.name,
                    extension.target,
                    tuple((f.name, f.type) for f in method.parameters),
                    part,
                    method.return_type,
                )
    return StandardLibrary(parts, types, units, enums, actors, actions, modifiers, methods, unmodelled)


def declarations_text(library: StandardLibrary) -> str:
    """``library``'s tables as the text of ``declarations.json``, stamped with the files' digest."""
    table = {"digest": library_digest()}
    table.update({name: value for name, value in asdict(library).items() if name != "parts"})
    return json.dumps(table, indent=1) + "\n"


class LazyTable(Mapping):
    """A read-only table built from the standard library on first use."""

    def __init__(self, build: Callable[[StandardLibrary], Mapping]) -> None:
        self._build = build

    @functools.cached_property
    def _table(self) -> Mapping:
        return self._build(standard_library())

    def __getitem__(self, key):
        return self._table[key]

    def __iter__(self) -> Iterator:
        return iter(self._table)

    def __len__(self) -> int:
        return len(self._table)

    def __repr__(self) -> str:
        return f"LazyTable({dict(self._table)!r})"


# unit name -> (dimension, factor to SI): the modelled units the standard library declares
# (stdlib/osc/physical.osc), read on first use
UNITS: Mapping[str, tuple[str, float]] = LazyTable(lambda library: library.units)
