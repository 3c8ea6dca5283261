"""Writing a file so that an interrupted run never leaves a half-written one behind."""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path


@contextmanager
def replaced(path: Path) -> Iterator[Path]:
    """A temporary path beside ``path`` for a writer to write to, renamed into place when the block
    ends and removed when it fails. It keeps ``path``'s suffix, so that writers which pick their
    format from it (matplotlib, CommonRoad) still do."""
    temporary = path.parent / f".{path.name}.{os.getpid()}.partial{path.suffix}"
    try:
        yield temporary
        os.replace(temporary, path)
    finally:
        if temporary.exists():
            temporary.unlink()


def write_text(path: Path, text: str) -> Path:
    with replaced(path) as temporary:
        temporary.write_text(text, encoding="utf-8")
    return path
