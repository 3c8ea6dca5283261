"""Diagnostics that point at a place in an ``.osc`` file.

Every problem a user can cause (bad syntax, an unknown name, a unit of the wrong kind, an
impossible scenario) is reported as ``path:line:col: error: message`` with the offending line and
a caret, never as a traceback, so that it reads like a compiler message and editors can jump to it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..confinement import UnreadableFile, read_bounded, shown

# the most of a file read to show one of its lines: what the front end reads of a file at most
# (frontend.syntax.limits.MAX_BYTES characters, 4 bytes each; limits imports this module, so not from there)
SHOWN_FILE_BYTES = 8_000_000


@dataclass(frozen=True)
class SourceLocation:
    """A position in a source file; line and column are 1-based, as editors count."""

    path: str
    line: int
    column: int

    def __str__(self) -> str:
        return f"{self.path}:{self.line}:{self.column}"


@dataclass(frozen=True)
class Diagnostic:
    location: SourceLocation
    message: str
    hint: str | None = None
    severity: str = "error"

    def format(self, source_text: str | None = None) -> str:
        lines = [f"{self.location}: {self.severity}: {self.message}"]
        text = source_text if source_text is not None else _read_quietly(self.location.path)
        if text is not None:
            source_lines = text.splitlines()
            if 1 <= self.location.line <= len(source_lines):
                line = source_lines[self.location.line - 1].replace("\t", " ")
                lines.append(f"    {line}")
                lines.append("    " + " " * max(0, self.location.column - 1) + "^")
        if self.hint:
            lines.append(f"    hint: {self.hint}")
        return shown("\n".join(lines))  # a file's escape sequences are shown, never sent to the terminal


def _read_quietly(path: str) -> str | None:
    """The text of a regular file to show a line of, None otherwise (a FIFO is never opened)."""
    try:
        return read_bounded(path, SHOWN_FILE_BYTES).decode("utf-8")
    except (UnreadableFile, UnicodeDecodeError):
        return None


@dataclass
class OscError(Exception):
    """One or more errors in a scenario file; ``str()`` gives the formatted report."""

    diagnostics: list[Diagnostic] = field(default_factory=list)
    source_text: str | None = None
    # path -> text, for reports that span several files (a file and its imports)
    sources: dict[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        super().__init__(self.report())

    def report(self) -> str:
        return "\n".join(d.format(self.sources.get(d.location.path, self.source_text)) for d in self.diagnostics)

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == "error"]

    def __str__(self) -> str:
        return self.report()


def error_at(location: SourceLocation, message: str, hint: str | None = None) -> OscError:
    return OscError([Diagnostic(location, message, hint)])
