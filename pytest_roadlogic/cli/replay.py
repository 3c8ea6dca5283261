"""``roadlogic replay``: run one case again exactly, from the case.json of a failure or from a file
and values. Exit codes as ``run``'s."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..settings import (
    REFINED,
    STRATEGIES,
)
from ..settings import count as parse_count
from .commands import EXIT_INPUT, SUMMARIES
from .common import (
    DRIVER_HELP,
    ROAD_FLAGS,
    RUN_FLAGS,
    allow_read,
    artifacts_flag,
    driver_factory,
    driver_flag,
    flag,
    out_refused,
    read_roots,
    reporting_input_errors,
    run_settings,
    setting_flags,
    show,
    values_flag,
)


def add(commands) -> None:
    """The ``replay`` command's flags, and its action."""
    replay = commands.add_parser("replay", help=SUMMARIES["replay"])
    replay.add_argument("case", type=Path, help="a case.json written for a failure, or an .osc file")
    replay.add_argument("--scenario", help="with an .osc file: the scenario (default: the first)")
    replay.add_argument(
        "--strategy", choices=STRATEGIES, default=REFINED, help="with an .osc file: how the case was made"
    )
    replay.add_argument(
        "--values", type=values_flag, default=None, help="with an .osc file: the sampled values as JSON (refined)"
    )
    replay.add_argument(
        "--instance", type=flag(parse_count), default=0, help="with an .osc file: which plan, from 0 (base)"
    )
    replay.add_argument(
        "--driver",
        type=driver_flag,
        action="append",
        default=[],
        metavar="VEHICLE=MODULE:CLASS",
        help="with an .osc file: " + DRIVER_HELP,
    )
    setting_flags(replay, ROAD_FLAGS, "with an .osc file: ")
    setting_flags(replay, RUN_FLAGS, "with an .osc file: ")
    replay.add_argument("--out", type=Path, default=Path("out"), help="artifact directory (default out/)")
    artifacts_flag(replay)
    allow_read(replay)
    replay.set_defaults(action=_replay)


def _replay(args: argparse.Namespace) -> int:
    from dataclasses import replace as replaced

    from ..case import Case
    from ..runner import replay

    def run_again():
        if args.case.suffix == ".json":
            from ..confinement import ReadRoots, project_root

            # the project's root, not the case file's folder, which may be anywhere; with no project
            # above the working folder, the case file's folder (never / or the home folder)
            roots = ReadRoots.of(project_root() or args.case.resolve().parent, extra=args.allow_read)
            case = Case.load(args.case).within(run_settings(args))
            case = replaced(case, path=str(case.scenario_file(args.case, roots)))
            drivers_of_case(case, dict(args.driver))
            for difference in case.version_differences():
                print(
                    f"{args.case}: warning: written with {difference}; the replay may plan or drive otherwise",
                    file=sys.stderr,
                )
        else:
            from ..frontend import load_file

            roots = read_roots(args, args.case)
            name = (
                load_file(
                    args.case, args.setting_lanes, dialect=args.setting_dialect, roots=roots, road_map=args.setting_map
                )
                .scenario_to_run(args.scenario)
                .name
            )
            identity = {"values": args.values or {}} if args.strategy == REFINED else {"instance": args.instance}
            case = Case.of(
                args.case, name, run_settings(args), strategy=args.strategy, drivers=dict(args.driver), **identity
            )
        return replay(case, drivers=driver_factory(case.drivers, Path(case.path), roots), roots=roots)

    args.file = args.case
    if out_refused(args):
        return EXIT_INPUT
    result = reporting_input_errors(args, run_again)
    return result if isinstance(result, int) else show(result, args.out, args.artifacts, dict(args.driver))


def drivers_of_case(case, given: dict[str, str]) -> dict[str, str]:
    """The drivers a case file's replay uses: those the command line gives, which must be the ones
    the case records. A case file is data: the module names in it are never imported on its word
    (it could name os:abort or sys:exit); the user names them with --driver after reading them."""
    from ..simulation.named_drivers import DriverLoadError

    if given == case.drivers:
        return given
    recorded = (
        ", ".join(f"{vehicle} by {name!r}" for vehicle, name in sorted(case.drivers.items()))
        or "the simulator's own only"
    )
    flags = ", ".join(f"{vehicle} by {name!r}" for vehicle, name in sorted(given.items())) or "none"
    raise DriverLoadError(
        f"the case was found with the drivers {recorded}; the command line gives {flags}. A case file's module names are not "
        "imported on its word: read them, then give each as --driver VEHICLE=MODULE:CLASS"
    )
