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


def project_root(start: str | Path | None = None) -> Path:
    """The nearest folder at or above ``start`` (default: the working folder) that holds one of
    ``PROJECT_MARKERS``; ``start`` itself when none does."""
    here = Path(start if start is not None else Path.cwd()).resolve()
    for folder in (here, *here.parents):
        if any((folder / marker).exists() for marker in PROJECT_MARKERS):
            return folder
    return here


@dataclass(frozen=True)
class ReadRoots:
    """The folders under which a file that a scenario or case file names may be read."""

    folders: tuple[Path, ...]

    @classmethod
    def of(cls, *folders: str | Path | None, extra: Iterable[str | Path] = ()) -> ReadRoots:
        """Roots from folders (None skipped; a file stands for its folder), resolved once."""
        resolved: list[Path] = []
        for folder in (*folders, *extra):
            if folder is None:
                continue
            path = Path(folder).resolve()
            if path.is_file():
                path = path.parent
            if path not in resolved:
                resolved.append(path)
        return cls(tuple(resolved))

    @classmethod
    def around(cls, named: str | Path, extra: Iterable[str | Path] = ()) -> ReadRoots:
        """The default roots of a file the user named: the project's root and the file's folder."""
        return cls.of(project_root(), Path(named).resolve().parent, extra=extra)

    def allows(self, path: str | Path) -> bool:
        """Whether ``path`` (followed through symbolic links) lies under one of the roots."""
        try:
            target = Path(path).resolve()
        except (OSError, ValueError, RuntimeError):  # a name too long, a NUL byte, a loop of links
            return False
        return any(target == root or root in target.parents for root in self.folders)

    def check(self, path: str | Path, what: str) -> Path:
        """``path`` resolved, or ``OutsideRoots`` naming ``what`` and the roots (never its content)."""
        if not self.allows(path):
            raise OutsideRoots(f"{what} {str(path)!r} is outside the folders the tool reads ({self.describe()})")
        return Path(path).resolve()

    def describe(self) -> str:
        return ", ".join(str(folder) for folder in self.folders)


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
    if stat.S_ISREG(mode):
        return None
    kind = (
        "a folder"
        if stat.S_ISDIR(mode)
        else "a FIFO"
        if stat.S_ISFIFO(mode)
        else "a socket"
        if stat.S_ISSOCK(mode)
        else "a device"
    )
    return f"not a regular file ({kind})"


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
