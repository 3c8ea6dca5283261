"""Reading ``.osc`` files and text into the scenario model, with the standard library's units.

``parse_text`` / ``parse_file`` read syntax only (``frontend.syntax.syntax``), physical literals in the
units the standard library declares unless a table is given (a file that declares its own units is
read again with them: ``frontend.semantics.physical``). Problems are collected, not printed, and raised
together as one ``OscError``: a user fixing a file wants every mistake in one run, not one per run.

The parser judges spelling only (syntax, units, literal forms). Whether names exist and values have
the right kind is the checker's job, so that ``roadlogic check --syntax-only`` can read files
written for other tools' libraries.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from ...confinement import UnreadableFile, read_bounded
from .. import model
from ..errors import Diagnostic, OscError, SourceLocation
from . import syntax
from .limits import MAX_BYTES
from .standard_library import UNITS, standard_library


def parse_text(
    text: str, path: str = "<string>", units: Mapping[str, tuple[str | None, float]] | None = None
) -> model.OscFile:
    """Parse OS2 source text; raise ``OscError`` naming every syntax error found. ``units``: the
    table physical literals are read with (default: the standard library's)."""
    return syntax.parse_text(text, path, UNITS if units is None else units, standard_library().unmodelled_units)


def parse_file(path: str | Path, units: Mapping[str, tuple[str | None, float]] | None = None) -> model.OscFile:
    path = Path(path)
    try:
        # a character is at most 4 bytes; never blocks on a FIFO, never reads a device
        data = read_bounded(path, 4 * MAX_BYTES)
    except UnreadableFile as problem:
        raise OscError(
            [
                Diagnostic(
                    SourceLocation(str(path), 1, 1),
                    f"cannot read the file: {problem}",
                    "split it into several files" if problem.too_large else "give an .osc file",
                )
            ],
            "",
        ) from None
    try:
        text = data.decode("utf-8").replace("\r\n", "\n").replace("\r", "\n")  # as text mode reads it
    except UnicodeDecodeError as exc:
        data = exc.object
        line = data.count(b"\n", 0, exc.start) + 1
        column = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
        shown = data[data.rfind(b"\n", 0, exc.start) + 1 :].split(b"\n", 1)[0].decode("utf-8", errors="replace")
        raise OscError(
            [
                Diagnostic(
                    SourceLocation(str(path), line, column),
                    f"the file is not valid UTF-8: byte 0x{data[exc.start]:02x} ({exc.reason})",
                    "save it as UTF-8",
                )
            ],
            "\n" * (line - 1) + shown,
        ) from None
    return parse_text(text, str(path), units)
