"""Physical types and units that files declare, as CARLA scenario-runner suites do in a local library.

``type velocity is SI(m: 1, s: -1)`` names the dimension with those SI exponents;
``unit kph of velocity is SI(m: 1, s: -1, factor: 0.277777778)`` a unit of it, ``factor`` SI units
per unit. Every dimension is read (``units.dimension_of`` names it: ``angle``, ``temperature``);
the pipeline plans four (length, time, speed, acceleration), and a value of another is refused
only where it would be planned. A unit may have an ``offset`` (a temperature's zero): its SI value
is ``value * factor + offset``.

Physical literals are resolved when a file is parsed, before its imports are known: a file whose
literals use a unit it or an import declares is parsed again with those units
(``parse_with_declared_units``). A declaration of a built-in unit's name must have its dimension (a located error
otherwise); a factor or offset that departs from the standard's beyond rounding (1e-6 relative)
is read as the file declares it, with a located warning (CARLA's ``basic.osc`` writes mph as
0.447038889).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from ...confinement import ReadRoots, regular_file_problem
from .. import model
from ..errors import Diagnostic, OscError
from ..syntax.parser import parse_file
from ..syntax.standard_library import UNITS, standard_library
from ..syntax.units import dimension_of

FACTOR_TOLERANCE = 1e-6  # relative: CARLA's libraries write kph's factor with 9 digits


@dataclass
class DeclaredPhysics:
    """Types (name -> dimension, None when not modelled) and units (name -> dimension, factor)."""

    types: dict[str, str | None] = field(default_factory=lambda: dict(standard_library().types))
    units: dict[str, tuple[str, float]] = field(default_factory=dict)
    problems: list[Diagnostic] = field(default_factory=list)

    def table(self) -> dict[str, tuple[str | None, float]]:
        """The unit table to parse with: built-in units and the declared ones."""
        return {**UNITS, **self.units}


def declared_physics(files: Iterable[model.OscFile]) -> DeclaredPhysics:
    files = list(files)
    physics = DeclaredPhysics()
    for osc in files:
        for declared in osc.physical_types:
            dimension = dimension_of(declared.exponents)
            known = physics.types.get(declared.name, "absent")
            if known != "absent" and known != dimension:
                where = (
                    "in the standard library (osc.physical)"
                    if declared.name in standard_library().types
                    else "where declared before"
                )
                physics.problems.append(
                    Diagnostic(
                        declared.location,
                        f"type {declared.name!r} is {_show(dimension)} here but {_show(known)} {where}",
                        "give the type another name, or its exponents",
                    )
                )
                continue
            physics.types[declared.name] = dimension
    for osc in files:
        for unit in osc.units:
            if unit.type not in physics.types:
                physics.problems.append(
                    Diagnostic(
                        unit.location,
                        f"unit {unit.name!r} is of an unknown type {unit.type!r}",
                        f"declare it first: type {unit.type} is SI(...)",
                    )
                )
                continue
            dimension = physics.types[unit.type]
            if dimension_of(unit.exponents) != dimension:
                physics.problems.append(
                    Diagnostic(
                        unit.location,
                        f"unit {unit.name!r} has other SI exponents than its type {unit.type!r}",
                        "write the type's exponents in the unit's SI(...)",
                    )
                )
                continue
            if dimension is None:
                continue  # a unit of plain numbers
            if unit.factor <= 0:
                physics.problems.append(
                    Diagnostic(
                        unit.location,
                        f"unit {unit.name!r} needs a positive factor",
                        "factor: SI units per unit, e.g. 0.277777778 for kph",
                    )
                )
                continue
            standard_type = standard_library().unmodelled_units.get(unit.name)
            if standard_type is not None:
                physics.problems.append(
                    Diagnostic(
                        unit.location,
                        f"unit {unit.name!r} is declared as a {dimension} unit, but {unit.name} is a unit of {standard_type} in the standard library (osc.physical)",
                        "give the unit another name",
                    )
                )
                continue
            known = UNITS.get(unit.name) or physics.units.get(unit.name)
            if known is not None and known[0] != dimension:
                physics.problems.append(
                    Diagnostic(
                        unit.location,
                        f"unit {unit.name!r} is declared as a unit of {dimension}, but {unit.name} is a unit of {known[0]}",
                        "give the unit another name",
                    )
                )
                continue
            offset = (known[2] if len(known) > 2 else 0.0) if known is not None else 0.0
            if known is not None and not (
                math.isclose(known[1], unit.factor, rel_tol=FACTOR_TOLERANCE) and math.isclose(offset, unit.offset)
            ):
                # the file's own declaration is what its author's numbers mean: read, with a warning
                physics.problems.append(
                    Diagnostic(
                        unit.location,
                        f"unit {unit.name!r} is declared as {unit.factor:.9g} SI {dimension} units"
                        + (f" from {unit.offset:.9g}" if unit.offset else "")
                        + f"; the standard's {unit.name} is {known[1]:.9g}"
                        + (f" from {offset:.9g}" if offset else "")
                        + f" ({_departure(known[1], unit.factor)}); this file's values are read with its own",
                        "remove the declaration to use the standard's unit",
                        "warning",
                    )
                )
            physics.units[unit.name] = (
                (dimension, unit.factor, unit.offset) if unit.offset else (dimension, unit.factor)
            )
    return physics


def _departure(standard: float, declared: float) -> str:
    return f"{abs(declared - standard) / standard:.1e} relative"


def _show(dimension: str | None) -> str:
    return f"a {dimension}" if dimension is not None else "a dimension this tool does not model"


class _AnyUnit(dict):
    """A unit table that reads every unknown unit as a plain number (the first, tolerant parse)."""

    def __missing__(self, key: str) -> tuple[str | None, float]:
        return None, 1.0


def parse_with_declared_units(
    path: str | Path, roots: ReadRoots | None = None
) -> tuple[model.OscFile, dict[str, tuple[str | None, float]]]:
    """Parse ``path``; when it uses units that it or its imports declare, with those units.
    Returns the file and the unit table its imports are to be parsed with. Imports outside
    ``roots`` are not read (the checker reports them)."""
    try:
        parsed = parse_file(path)
    except OscError as error:
        if not any(d.message.startswith(_UNRESOLVED_UNIT) for d in error.diagnostics):
            raise
        original = error
    else:
        if not parsed.imports and not parsed.units:
            return parsed, UNITS
        # a unit that the file or an import declares otherwise than the standard is read as declared
        physics = declared_physics(_closure(Path(path), roots or ReadRoots.around(path)))
        if all(UNITS.get(name) == unit for name, unit in physics.units.items()):
            return parsed, UNITS
        table = physics.table()
        return parse_file(path, table), table
    files = _closure(Path(path), roots or ReadRoots.around(path))
    physics = declared_physics(files)
    try:
        if not physics.units:
            raise original
        table = physics.table()
        return parse_file(path, table), table
    except OscError as error:
        if not any(p.severity == "error" for p in physics.problems):
            raise
        # a unit still unresolved may be one whose declaration is wrong: report that as well
        sources = {**{f.path: f.source_text for f in files}, **error.sources}
        problems = [p for p in physics.problems if p.severity == "error"]
        raise OscError([*problems, *error.diagnostics], error.source_text, sources) from None


# how the parser reports a unit that its table does not resolve (Builder.unit)
_UNRESOLVED_UNIT = ("unknown unit", "not supported: unit")


def _closure(path: Path, roots: ReadRoots) -> list[model.OscFile]:
    """The file and everything it imports, parsed tolerantly (files that do not parse are left out:
    the checker reports them)."""
    files: list[model.OscFile] = []
    seen: set[Path] = set()
    named = path.resolve()
    stack = [named]
    while stack:
        current = stack.pop()
        if (
            current in seen
            or (current != named and current.suffix != ".osc")  # an import the checker refuses, never read
            or not roots.allows(current)
            or regular_file_problem(current) is not None
        ):
            continue
        seen.add(current)
        try:
            osc = parse_file(current, _AnyUnit(UNITS))
        except OscError:
            continue
        files.append(osc)
        stack.extend(target for item in osc.imports if (target := item.file(str(current))) is not None)
    return files
