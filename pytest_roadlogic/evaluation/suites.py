"""Which scenarios one evaluation runs, and how many instances of each: ``BenchmarkSettings`` from
the folders a user names (the bench's front door, ``roadlogic bench``, only reads its flags).

The paper's scenarios are a folder's own ``.osc`` files (``scenarios/``); a realistic suite is every
``.osc`` file below its folders (``scenarios/realistic/``), each in the dialect its folder's
``conftest.py`` gives, less the files that declare no scenario to run (a suite's ``lib.osc``).
"""

from __future__ import annotations

from pathlib import Path

from ..confinement import osc_files
from ..frontend import OscError, check_file
from ..settings import RunSettings
from .bench import (
    PAPER_COUNTS,
    QUICK_COUNTS,
    REALISTIC_COUNTS,
    REALISTIC_QUICK_COUNTS,
    BenchmarkSettings,
    Suite,
    conftest_dialect,
)


def library_only(path: Path, dialect: str | None) -> bool:
    """A file that declares no scenario to run (a suite's lib.osc): as pytest collects no item from
    it, the bench runs none. A file with errors is not: the bench reports them."""
    try:
        checked = check_file(path, dialect=dialect)
    except OscError:
        return False
    return not checked.errors and not any(s.runnable for s in checked.scenarios)


def benchmark_settings(
    paths: list[Path],
    realistic_folders: list[Path],
    *,
    quick: bool,
    base: int | None,
    refined: int | None,
    run: RunSettings,
    paper_run: RunSettings,
    artifacts: bool,
    explicit_realistic: bool = True,
) -> tuple[BenchmarkSettings | None, list[str]]:
    """The settings of one evaluation, or None, and what to tell the user: the problems that stop it
    (a folder that does not exist, no .osc file to run) and the special files skipped. ``run``: the realistic suite's run settings (its timed phases
    need the continuous encoding, a run's default); ``paper_run``: the paper's scenarios'. A
    realistic folder that was not named explicitly is left out when it does not exist."""
    if not explicit_realistic:
        realistic_folders = [folder for folder in realistic_folders if folder.is_dir()]
    problems = [
        f"{path}: error: no such file or folder; give the .osc files or folders to evaluate"
        for path in [*paths, *realistic_folders]
        if not path.exists()
    ]
    files, skipped = osc_files(paths, recursive=False)
    suite, skipped_in_suite = osc_files(realistic_folders)
    if problems or not files:
        return None, [
            *skipped,
            *skipped_in_suite,
            *(problems or [f"{' '.join(map(str, paths))}: error: no .osc files there"]),
        ]
    dialects = {str(f): conftest_dialect(f, realistic_folders) for f in suite}
    realistic_files = [f for f in suite if not library_only(f, dialects[str(f)])]
    counts = QUICK_COUNTS if quick else PAPER_COUNTS
    realistic = None
    if realistic_files:
        realistic = Suite(
            tuple(realistic_files),
            *(REALISTIC_QUICK_COUNTS if quick else REALISTIC_COUNTS),
            run=run,
            dialects={str(f): dialects[str(f)] for f in realistic_files if dialects[str(f)] is not None},
        )
    settings = BenchmarkSettings(
        tuple(files),
        base=counts[0] if base is None else base,
        refined=counts[1] if refined is None else refined,
        run=paper_run,
        artifacts=artifacts,
        realistic=realistic,
    )
    return settings, [*skipped, *skipped_in_suite]
