"""Loading a file's imports: confined to the read roots, each file once, cycles and missing files reported at the import."""

from __future__ import annotations

from pathlib import Path

from ...confinement import ALLOW_READ_HINT, MISSING, regular_file_problem
from .. import model
from ..errors import OscError
from ..syntax.parser import parse_file
from ..syntax.standard_library import part_file, part_names


class ImportLoading:
    """A part of the checker (``checker._Checker``): its state is the checker's."""

    def _load_imports(self, osc: model.OscFile, stack: tuple[str, ...]) -> None:
        for item in osc.imports:
            target = item.file(osc.path)
            if target is None:
                if part_file(item.target) is None and item.target.startswith("osc."):
                    # other tools split the library differently (osc.helpers): read it as the whole
                    self.warning(
                        item.location,
                        f"the standard library has no part {item.target!r} here; read as osc.standard",
                        f"parts: {', '.join(part_names())}",
                    )
                elif part_file(item.target) is None:
                    self.error(
                        item.location,
                        f"unknown library {item.target!r}",
                        f'the standard library is osc.standard (parts: {", ".join(part_names())}); import a file by its path: import "lib.osc" or import lib.osc',
                    )
                continue
            if str(target) in stack:
                self.error(
                    item.location,
                    f"{item.target!r} imports itself (through {' -> '.join(Path(s).name for s in stack)})",
                    "remove the circular import",
                )
                continue
            if str(target) in self.files:  # keyed by resolved path: parse_file was given ``target``
                continue
            if target.suffix != ".osc":
                # never opened: a line of a file that is not a scenario would be shown in its syntax error
                self.error(
                    item.location,
                    f"the imported file {item.target!r} is not an .osc file",
                    "import scenario files only (name.osc)",
                )
                continue
            if not self.roots.allows(target):
                # never opened, never shown (import "/proc/self/environ" would show the environment)
                self.error(
                    item.location,
                    f"the imported file {item.target!r} is outside the folders the tool reads ({self.roots.describe()})",
                    ALLOW_READ_HINT,
                )
                continue
            if (problem := regular_file_problem(target)) is not None:
                if problem == MISSING:
                    self.error(
                        item.location,
                        f"cannot find the imported file {item.target!r}",
                        f"looked for {target}; paths are relative to the importing file",
                    )
                else:
                    self.error(
                        item.location,
                        f"cannot read the imported file {item.target!r}: {problem}",
                        "import an .osc file",
                    )
                continue
            try:
                imported = parse_file(target, self.units)
            except OscError as error:
                self.diagnostics.extend(error.diagnostics)
                self.sources.update(error.sources)
                self.error(item.location, f"the imported file {item.target!r} has errors (listed with it)")
                continue
            self.sources[imported.path] = imported.source_text
            self.files[imported.path] = imported
            self._load_imports(imported, stack + (str(target),))
            self._declarations(imported)
            self._modifier_declarations(imported)
            for unsupported in imported.unsupported:
                self._unsupported(unsupported)
            for scenario in imported.scenarios:
                if scenario.name in self.scenarios:
                    other = self.scenarios[scenario.name].location
                    self.error(
                        scenario.location,
                        f"scenario {scenario.name!r} is already declared in {other.path}:{other.line}",
                        "rename one of them",
                    )
                self.scenarios[scenario.name] = scenario
