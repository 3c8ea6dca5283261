"""Writing a file, or a folder of them, so that an interrupted run never leaves a half-written one behind."""

from __future__ import annotations

import os
import re
import shutil
import signal
import tempfile
import threading
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


class NotAnArtifactFolder(ValueError):
    """An output folder that holds files no run writes: replacing it could lose the user's work."""


@contextmanager
def replaced_directory(directory: Path, artifact: re.Pattern) -> Iterator[Path]:
    """A fresh staging folder beside ``directory`` to write a set of artifacts into, swapped in for
    ``directory`` as one set when the block ends, and removed when it fails or is interrupted.

    Why: a run into an existing ``--out`` overwrote file by file, so that an interrupted one left a
    mix of two runs' artifacts (issue 20). Ctrl-C during the swap (two renames) waits for it to end,
    so the folder holds the old set or the new one, never neither. A folder with names that
    ``artifact`` does not match is refused (``NotAnArtifactFolder``) before anything is written:
    ``--out .`` must not replace the working directory.
    """
    directory = Path(directory)
    check_replaceable(directory, artifact)
    directory.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{directory.name}.", suffix=".partial", dir=directory.parent))
    retired = None
    try:
        yield staging
        with _interrupts_deferred():
            if directory.exists():
                retired = staging.with_suffix(".old")
                os.replace(directory, retired)
            os.replace(staging, directory)
    finally:
        for leftover in (staging, retired):
            if leftover is not None and leftover.exists():
                shutil.rmtree(leftover, ignore_errors=True)


def check_replaceable(directory: Path, artifact: re.Pattern) -> None:
    """Raise ``NotAnArtifactFolder`` unless ``directory`` is new, empty, or holds only names ``artifact`` matches."""
    if not directory.exists():
        return
    if not directory.is_dir():
        raise NotAnArtifactFolder(f"{directory} is a file, not a folder of artifacts")
    foreign = sorted(p.name for p in directory.iterdir() if not artifact.fullmatch(p.name))
    if foreign:
        raise NotAnArtifactFolder(f"{directory} holds files a run does not write ({', '.join(foreign[:3])}{', ...' if len(foreign) > 3 else ''}); "
                                  "give a new or empty folder, or one a run wrote")


@contextmanager
def _interrupts_deferred() -> Iterator[None]:
    """Ctrl-C inside the block is raised when it ends (only the main thread receives signals)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    received: list[int] = []
    previous = signal.signal(signal.SIGINT, lambda number, frame: received.append(number))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        if received:
            raise KeyboardInterrupt
