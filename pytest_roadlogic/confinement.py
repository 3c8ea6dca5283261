"""Where the tool may read and write: scenario files and case files are data, never a way out.

A tool that runs in CI on files from pull requests must not be talked into reading a file the
project does not hold (``import "/proc/self/environ"`` printed the first line of the environment,
tokens and all, in its error) nor into writing beside it (a scenario named ``|../../../x|`` made
``roadlogic automaton`` write three folders above the working one). So:

- every file the tool *reads* because a file told it to (an ``import``, a case file's ``path``) is
  inside one of the ``ReadRoots``: the project's root (pytest's rootdir; for the ``roadlogic``
  command, the nearest folder above the working one that holds a project file), the folder of the
  file the user named, and any folder the user names with ``--allow-read``. Anything else is
  refused without being opened;
- every file name the tool *writes* that comes from a scenario goes through ``safe_name``, so it
  stays inside the folder the user gave.

Nothing heavy is imported here: the plugin loads it in every session.
"""

from __future__ import annotations

import errno
import os
import re
import stat
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

# files that mark a project's root folder, as pytest's rootdir search and version control know it
PROJECT_MARKERS = ("pyproject.toml", "setup.cfg", "setup.py", "tox.ini", "pytest.ini", ".git")


class OutsideRoots(ValueError):
    """A path a file asked the tool to read that lies outside every folder it may read."""


def too_wide(folder: Path) -> bool:
    """Whether ``folder`` is one the tool never reads everything under: the file system's root and
    the home folder (run from ``/``, a container's default, the working folder would be the read
    root, and ``import "/proc/self/environ"`` show a CI job's secrets)."""
    folder = folder.resolve()
    try:
        home = Path.home().resolve()
    except (RuntimeError, KeyError, OSError):  # no home folder known
        home = None
    return folder == Path(folder.anchor) or folder == home


def project_root(start: str | Path | None = None) -> Path | None:
    """The nearest folder at or above ``start`` (default: the working folder) that holds one of
    ``PROJECT_MARKERS``, never the file system's root or the home folder; None when there is none:
    then only the folder of the file the user named is read (``ReadRoots.around``)."""
    here = Path(start if start is not None else Path.cwd()).resolve()
    for folder in (here, *here.parents):
        if too_wide(folder):
            return None
        if any((folder / marker).exists() for marker in PROJECT_MARKERS):
            return folder
    return None


@dataclass(frozen=True)
class ReadRoots:
    """The folders under which a file that a scenario or case file names may be read."""

    folders: tuple[Path, ...]
    # single files that may be read although their folder may not (a file the user named in ``/``
    # or the home folder: that file, not its neighbours)
    files: tuple[Path, ...] = ()

    @classmethod
    def of(cls, *folders: str | Path | None, extra: Iterable[str | Path] = ()) -> ReadRoots:
        """Roots from folders (None skipped; a file stands for its folder, or for itself alone
        when its folder is ``too_wide``), resolved once. ``extra`` are the user's own
        ``--allow-read`` folders, taken as given."""
        resolved: list[Path] = []
        files: list[Path] = []
        for folder in folders:
            if folder is None:
                continue
            path = Path(folder).resolve()
            if path.is_file():
                if too_wide(path.parent):
                    files.append(path)
                    continue
                path = path.parent
            if too_wide(path):
                continue
            if path not in resolved:
                resolved.append(path)
        for folder in extra:
            path = Path(folder).resolve()
            if path not in resolved:
                resolved.append(path)
        return cls(tuple(resolved), tuple(files))

    @classmethod
    def around(cls, named: str | Path, extra: Iterable[str | Path] = ()) -> ReadRoots:
        """The default roots of a file the user named: the project's root (none above a working
        folder with no project marker) and the file's folder, or the file alone when that folder
        is ``/`` or the home folder."""
        named = Path(named).resolve()
        return cls.of(project_root(), named if named.is_file() else named.parent, extra=extra)

    def allows(self, path: str | Path) -> bool:
        """Whether ``path`` (followed through symbolic links) lies under one of the roots or is
        one of the files allowed alone."""
        try:
            target = Path(path).resolve()
        except (OSError, ValueError, RuntimeError):  # a name too long, a NUL byte, a loop of links
            return False
        return target in self.files or any(target == root or root in target.parents for root in self.folders)

    def check(self, path: str | Path, what: str) -> Path:
        """``path`` resolved, or ``OutsideRoots`` naming ``what`` and the roots (never its content)."""
        if not self.allows(path):
            raise OutsideRoots(f"{what} {str(path)!r} is outside the folders the tool reads ({self.describe()})")
        return Path(path).resolve()

    def describe(self) -> str:
        return ", ".join(str(place) for place in (*self.folders, *self.files)) or "none"


ALLOW_READ_HINT = "copy the file into the project, or name its folder with --allow-read DIR (roadlogic) or --roadlogic-allow-read DIR (pytest)"


MISSING = os.strerror(errno.ENOENT)  # "No such file or directory", as the system says it


def regular_file_problem(path: str | Path) -> str | None:
    """Why ``path`` is not a file to read (missing, a folder, a FIFO, a device), None when it is one.
    Asked before opening: reading a FIFO named ``x.osc`` waited forever."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return MISSING
    except (OSError, ValueError) as error:  # a name too long, a NUL byte
        return getattr(error, "strerror", None) or "cannot be read"
    return None if stat.S_ISREG(mode) else f"not a regular file ({_kind(mode)})"


def _kind(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a FIFO"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "a device"


class UnreadableFile(ValueError):
    """A file that is not a regular file, cannot be opened, or holds more than the bound it is read
    with (``too_large``); ``str()`` says which, never what it holds."""

    def __init__(self, reason: str, too_large: bool = False) -> None:
        super().__init__(reason)
        self.too_large = too_large


def read_bounded(path: str | Path, limit: int) -> bytes:
    """The bytes of the regular file ``path``, at most ``limit`` of them, else ``UnreadableFile``.

    Every file a scenario, a case file or a map names is read through here. The kind is judged on
    the open descriptor (opened without blocking, so a FIFO cannot hold the open, nor a link
    swapped after a ``stat`` change what is read) and the size by what is read, not by ``stat``:
    a link to ``/dev/zero`` has size 0 and no end."""
    if (problem := regular_file_problem(path)) is not None:  # a device is never even opened
        raise UnreadableFile(problem)
    try:
        handle = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0))
    except (OSError, ValueError) as error:
        raise UnreadableFile(getattr(error, "strerror", None) or "cannot be read") from None
    try:
        mode = os.fstat(handle).st_mode
        if not stat.S_ISREG(mode):
            raise UnreadableFile(f"not a regular file ({_kind(mode)})")
        chunks: list[bytes] = []
        size = 0
        while size <= limit:
            chunk = os.read(handle, min(1 << 20, limit + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
    except OSError as error:
        raise UnreadableFile(error.strerror or "cannot be read") from None
    finally:
        os.close(handle)
    if size > limit:
        raise UnreadableFile(f"more than {limit:,} bytes", too_large=True)
    return b"".join(chunks)


_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def shown(text: str) -> str:
    """``text`` safe to print: every control character (escape sequences that set a terminal's
    title or clear its screen, bidirectional overrides) written as its ``\\x..`` escape; tabs and
    line breaks kept. The one place text from a file or an option is made printable."""
    return _CONTROL.sub(lambda match: match.group().encode("unicode_escape").decode("ascii"), text)


_UNSAFE = re.compile(r"[^A-Za-z0-9_.-]+")


def safe_name(text: str, fallback: str = "scenario") -> str:
    """``text`` as one file name that stays in its folder: runs of anything but letters, digits,
    ``_``, ``.`` and ``-`` become ``_``, and so do runs of dots (no ``..``); no leading dot (no
    hidden file) or ``_``; at most 100
    characters; ``fallback`` when nothing is left. The one place a name from a scenario or a test
    id becomes part of a path."""
    name = re.sub(r"\.{2,}", "_", _UNSAFE.sub("_", text))
    name = re.sub(r"_{2,}", "_", name).strip("_").lstrip(".").strip("_")
    return name[:100] or fallback


def unique_name(text: str) -> str:
    """``safe_name(text)`` made unique to ``text``: its first 90 characters and a short hash of the
    whole, so two texts never share one (``ä.osc::plain`` and ``ö.osc::plain``, or names equal in
    their first 100 characters, would share an artifacts folder)."""
    import hashlib

    digest = hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()[:10]
    return f"{safe_name(text)[:90]}-{digest}"


def osc_files(paths: Iterable[str | Path], recursive: bool = True) -> tuple[list[Path], list[str]]:
    """The ``.osc`` files named, or below the folders named (a folder's own only, unless
    ``recursive``), and a warning for each special file skipped there: a FIFO named ``x.osc`` made
    ``roadlogic check`` wait forever. A file named is kept as it is, to be refused where it is read."""
    found: list[Path] = []
    skipped: list[str] = []
    for path in map(Path, paths):
        if not path.is_dir():
            found.append(path)
            continue
        for file in sorted(path.rglob("*.osc") if recursive else path.glob("*.osc")):
            if (problem := regular_file_problem(file)) is not None:
                skipped.append(f"{file}: warning: skipped: {problem}")
            else:
                found.append(file)
    return found, skipped
