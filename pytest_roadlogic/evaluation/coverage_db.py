"""A coverage database across runs (``--roadlogic-coverage-db PATH``, ``roadlogic cover
--coverage-db PATH``): one JSON file of tallies (``coverage.write_json``'s format) that each run
adds its own to, as Hypothesis's example database keeps what earlier runs found.

A scenario's earlier tally counts only while the scenario is the one it was counted on: each
tally carries the fingerprint of its scenario's file (``fingerprint``), and a run drops an
earlier tally whose fingerprint differs (its buckets, ranges or proofs may no longer hold), and
says so. Closure reads the database too, so a bucket an earlier run hit is not asked again. The
file is replaced whole (written beside it, then renamed): a run that stops half way leaves the
earlier one; two sessions writing at once keep the last one's.
"""

from __future__ import annotations

import hashlib
import os
import tempfile
from pathlib import Path

from .coverage import ScenarioCoverage, merged, read_json, text_lines, write_json


def fingerprint(checked) -> str:
    """What an earlier tally of ``checked`` (a ``CheckedScenario``) must have been counted on: its
    file's bytes and its name ('' for a scenario given as text)."""
    if not checked.path:
        return ""
    try:
        text = Path(checked.path).read_bytes()
    except OSError:
        return ""
    return hashlib.sha256(text + b"\0" + checked.name.encode()).hexdigest()[:16]


def read(path: Path) -> list[ScenarioCoverage]:
    """The tallies in the database (none when it does not exist yet); ``ValueError`` saying why a
    file is not one."""
    return read_json(path) if Path(path).exists() else []


def earlier(path: Path | None, now: ScenarioCoverage) -> ScenarioCoverage | None:
    """The database's tally of ``now``'s scenario counted on the same file, else None (no
    database, none yet, or a file that is not one: closure then asks as without one)."""
    if path is None:
        return None
    try:
        found = read(path)
    except ValueError:
        return None
    return next((c for c in found if c.scenario == now.scenario and c.fingerprint == now.fingerprint), None)


def combined(before: list[ScenarioCoverage], now: list[ScenarioCoverage]) -> tuple[list[ScenarioCoverage], list[str]]:
    """The database after this run: each scenario's earlier tally added to this run's where the
    scenario is unchanged, this run's alone where it changed, the others kept as they were; and
    a sentence per earlier tally dropped."""
    current = {c.scenario: c for c in now}
    kept, dropped = [], []
    for old in before:
        new = current.get(old.scenario)
        if new is not None and new.fingerprint != old.fingerprint:
            dropped.append(f"{old.scenario}: its file changed since the earlier runs; their counts were dropped")
            continue
        kept.append(old)
    return merged([*kept, *now]), dropped


def write(path: Path, coverages: list[ScenarioCoverage]) -> None:
    """Replace the database with ``coverages`` whole (``OSError`` when it cannot be written)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, staging = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".partial", dir=path.parent)
    os.close(handle)
    try:
        write_json(coverages, Path(staging))
        os.replace(staging, path)
    finally:
        if os.path.exists(staging):
            os.unlink(staging)


def database_lines(
    path: Path, now: list[ScenarioCoverage], option: str
) -> tuple[list[str], list[ScenarioCoverage] | None]:
    """Add this run's tallies (``now``) to the database at ``path`` and write it back: the lines
    that report it (the sum over runs of this run's scenarios, what was dropped) and the
    database's tallies after; or the line saying why the file was neither read nor written
    (``option`` names the flag in it) and None."""
    try:
        before = read(path)
    except ValueError as error:
        return [
            f"roadlogic: {option} {path}: {error}; not added to, not overwritten: give a file it wrote or a new one"
        ], None
    after, dropped = combined(before, now)
    try:
        write(path, after)
    except OSError as error:
        return [f"roadlogic: {option} {path}: cannot write it ({error.strerror or error})"], None
    ours = [c for c in after if c.scenario in {c.scenario for c in now}]
    return [f"coverage database {path}: this run added to the earlier runs'", *dropped, *text_lines(ours)], ours
