"""``roadlogic check``: parse and check .osc files and folders; print every problem.

Exit codes: 0 every file is fine; 1 some file has an error; 2 a path does not exist."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .commands import EXIT_INPUT, SUMMARIES
from .common import ROAD_FLAGS, allow_read, read_roots, setting_flags


def add(commands) -> None:
    """The ``check`` command's flags, and its action."""
    check = commands.add_parser("check", help=SUMMARIES["check"])
    check.add_argument("paths", type=Path, nargs="+", help=".osc files or folders (searched recursively)")
    check.add_argument(
        "--syntax-only", action="store_true", help="stop after parsing (for files written for other tools)"
    )
    setting_flags(check, ROAD_FLAGS)
    allow_read(check)
    check.set_defaults(action=_check)


def osc_files(paths: list[Path], recursive: bool = True) -> list[Path]:
    """``confinement.osc_files``, each special file it skipped said on stderr."""
    from ..confinement import osc_files as found

    files, skipped = found(paths, recursive)
    for warning in skipped:
        print(warning, file=sys.stderr)
    return files


def checked_report(
    path: Path,
    syntax_only: bool = False,
    lanes: int | None = None,
    dialect: str | None = None,
    roots=None,
    road_map: str | None = None,
) -> tuple[bool, str]:
    """Whether the file is free of errors, and the formatted report; never raises for bad input.

    Beyond the front end's checks, each scenario's automaton is built, so that a construct the
    automaton cannot translate is reported here rather than when the scenario runs.
    """
    from ..automaton import build_automaton
    from ..frontend import OscError, parse_file
    from ..frontend import check_file as check

    try:
        if syntax_only:
            parse_file(path)
            return True, ""
        checked = check(path, lanes, dialect=dialect, roots=roots, road_map=road_map)
        reports = [checked.report()] if checked.diagnostics else []
        ok = not checked.errors
        for scenario in checked.scenarios if ok else ():
            if scenario.runnable:
                try:
                    build_automaton(scenario)
                except OscError as error:
                    ok = False
                    reports.append(OscError(error.diagnostics, sources=checked.sources).report())
        return ok, "\n".join(reports)
    except OscError as error:
        return False, error.report()
    except Exception as error:  # a bug of ours must not hide the other files' results
        return (
            False,
            f"{path}:1:1: error: internal error while checking ({type(error).__name__}: {error}); please report it",
        )


def _check(args: argparse.Namespace) -> int:
    missing = [p for p in args.paths if not p.exists()]
    if missing:
        for path in missing:
            print(f"{path}: error: no such file or folder", file=sys.stderr)
        return EXIT_INPUT
    files = osc_files(args.paths)
    failed = 0
    for path in files:
        ok, report = checked_report(
            path, args.syntax_only, args.setting_lanes, args.setting_dialect, read_roots(args, path), args.setting_map
        )
        if report:
            print(report)
        if not ok:
            failed += 1
    print(f"{len(files)} files, {len(files) - failed} ok, {failed} with errors")
    return 1 if failed else 0
