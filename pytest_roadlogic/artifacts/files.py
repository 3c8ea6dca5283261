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

    Why: a run into an existing ``--out`` that overwrote file by file would, interrupted, leave a
    mix of two runs' artifacts. Ctrl-C during the swap (two renames) waits for it to end,
    so the folder holds the old set or the new one, never neither. A folder with names that
    ``artifact`` does not match is refused (``NotAnArtifactFolder``) before anything is written:
    ``--out .`` must not replace the working directory.
    """
    directory = Path(directory)
    check_replaceable(directory, artifact)
    directory.parent.mkdir(parents=True, exist_ok=True)
    remove_stale(directory)
    staging = Path(
        tempfile.mkdtemp(prefix=f".{directory.name}.{os.getpid()}.", suffix=".partial", dir=directory.parent)
    )
    staging.chmod(0o777 & ~_umask())  # mkdtemp's 0700 would have become the artifacts folder's mode
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


def check_writable(directory: Path, probe: bool = True) -> None:
    """Raise ``NotAnArtifactFolder`` unless a folder can be made at ``directory``: asked when a
    command or session starts, so that ``--out /proc/x`` or an artifacts path that is a file stops
    it at once rather than with a traceback at the first failure. With
    ``probe``, a folder is made and removed in the nearest folder that exists, which says what
    permissions do; without, only that no file stands in the way (nothing is written)."""
    directory = Path(directory)
    try:
        existing = directory
        while not existing.exists() and existing != existing.parent:
            existing = existing.parent
    except OSError as error:  # a name longer than the file system allows, a NUL byte
        raise NotAnArtifactFolder(
            f"{str(directory)[:100]!r}{'...' if len(str(directory)) > 100 else ''} cannot be a folder ({error.strerror}); "
            "give another folder"
        ) from None
    if existing == directory and not directory.is_dir():
        raise NotAnArtifactFolder(f"{directory} is a file, not a folder of artifacts")
    if not existing.is_dir():
        raise NotAnArtifactFolder(f"{existing} is a file: no folder can be made under it")
    if not probe:
        return
    try:
        os.rmdir(tempfile.mkdtemp(prefix=".roadlogic-probe.", dir=existing))
    except OSError as error:
        raise NotAnArtifactFolder(
            f"cannot make a folder in {existing} ({error.strerror}); give a folder you can write"
        ) from None


def check_replaceable(directory: Path, artifact: re.Pattern) -> None:
    """Raise ``NotAnArtifactFolder`` unless ``directory`` is new, empty, or holds only names ``artifact`` matches."""
    check_writable(directory)
    if not directory.exists():
        return
    if not directory.is_dir():
        raise NotAnArtifactFolder(f"{directory} is a file, not a folder of artifacts")
    foreign = sorted(p.name for p in directory.iterdir() if not artifact.fullmatch(p.name))
    if foreign:
        raise NotAnArtifactFolder(
            f"{directory} holds files a run does not write ({', '.join(foreign[:3])}{', ...' if len(foreign) > 3 else ''}); "
            "give a new or empty folder, or one a run wrote"
        )


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True  # another user's process
    return True


def remove_stale(directory: Path) -> None:
    """Remove what a killed run left beside ``directory``: its ``.NAME.PID.*.partial`` staging
    folders and files (``kill -9`` during ``run --out`` leaves them), when that process
    is gone."""
    pattern = re.compile(rf"\.{re.escape(directory.name)}\.(\d+)\..*(partial|old).*")
    try:
        entries = list(directory.parent.iterdir())
    except OSError:
        return
    for entry in entries:
        match = pattern.fullmatch(entry.name)
        if match is None or _alive(int(match.group(1))):
            continue
        if entry.is_dir() and not entry.is_symlink():
            shutil.rmtree(entry, ignore_errors=True)
        else:
            entry.unlink(missing_ok=True)


class FolderBusy(NotAnArtifactFolder):
    """Another run is writing the same output folder."""


@contextmanager
def claimed(directory: Path) -> Iterator[None]:
    """Hold ``directory`` for one run: a second run into it, while this one lasts, is refused
    (``FolderBusy``) instead of both reporting success with one set lost. The claim is a lock on
    ``.NAME.lock`` beside the folder, which the system releases when the process ends, however it
    ends; the file is removed when the block ends."""
    import fcntl

    directory = Path(directory)
    check_writable(directory)
    directory.parent.mkdir(parents=True, exist_ok=True)
    lock = directory.parent / f".{directory.name}.lock"
    with open(lock, "a+") as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise FolderBusy(
                f"another run is writing {directory}; wait for it to end, or give another folder"
            ) from None
        try:
            yield
        finally:
            lock.unlink(missing_ok=True)


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
