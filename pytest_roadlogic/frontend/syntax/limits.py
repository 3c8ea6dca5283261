"""What the front end reads at most: inputs beyond these are refused before parsing, at their place.

Why: the generated ANTLR parser recurses once per nesting level (a few dozen Python frames per
parenthesis of an expression), so deep nesting would end in a RecursionError that stops a whole
pytest session, and a huge identifier would go on into the renderer for minutes. The limits are
far above what hand-written scenarios reach (docs/decisions.md) and far below what the parser
survives under pytest's own stack.
"""

from __future__ import annotations

from ..errors import Diagnostic, OscError, SourceLocation
from .lexer import indentation_width

MAX_BRACKETS = 64  # (, [ and { open at one place
MAX_BLOCKS = 48  # indented blocks open at one line
MAX_BYTES = 2_000_000  # of one file
MAX_NAME = 256  # characters of one identifier
# A physical value in SI units (metres, seconds, m/s, m/s^2): far past a road scenario (1,000 km,
# 11 days) and far inside what the planner's rationals and the LP's floats carry exactly.
MAX_MAGNITUDE = 1e6


def check_limits(text: str, path: str) -> None:
    """Raise ``OscError`` at the first place where ``text`` goes past a limit of this module."""
    if len(text) > MAX_BYTES:
        _refuse(
            path,
            1,
            1,
            f"the file has {len(text):,} characters; the front end reads at most {MAX_BYTES:,}",
            "split it into several files",
        )
    blocks: list[int] = [0]
    for number, line in enumerate(text.split("\n"), start=1):
        stripped = line.lstrip(" \t")
        if stripped and not stripped.startswith("#"):
            width = indentation_width(line[: len(line) - len(stripped)])
            while blocks and width < blocks[-1]:
                blocks.pop()
            if width > blocks[-1]:
                blocks.append(width)
            if len(blocks) - 1 > MAX_BLOCKS:
                _refuse(
                    path,
                    number,
                    width + 1,
                    f"blocks nested {len(blocks) - 1} deep; the front end reads at most {MAX_BLOCKS}",
                    "flatten the behavior, or move a part into a scenario of its own and call it",
                    text,
                )
    depth, line, column, quote, comment = 0, 1, 0, "", False
    name_start, name_length = (0, 0), 0
    for char in text:
        column += 1
        if char == "\n":
            line, column, comment = line + 1, 0, False
            name_length = 0
            continue
        if comment:
            continue
        if quote:
            if char == quote:
                quote = ""
            continue
        if char.isalnum() or char == "_":
            if name_length == 0:
                name_start = (line, column)
            name_length += 1
            if name_length > MAX_NAME:
                _refuse(path, *name_start, f"a name or number longer than {MAX_NAME} characters", "shorten it", text)
            continue
        name_length = 0
        if char == "#":
            comment = True
        elif char in "\"'":
            quote = char
        elif char in "([{":
            depth += 1
            if depth > MAX_BRACKETS:
                _refuse(
                    path,
                    line,
                    column,
                    f"brackets nested {depth} deep; the front end reads at most {MAX_BRACKETS}",
                    "split the expression with a parameter or a def",
                    text,
                )
        elif char in ")]}":
            depth = max(0, depth - 1)


def _refuse(path: str, line: int, column: int, message: str, hint: str, text: str | None = None) -> None:
    raise OscError([Diagnostic(SourceLocation(path, line, column), message, hint)], text)
