"""``roadlogic cover``: a coverage campaign over one scenario's cover()/record() items: its samples,
its buckets proved unreachable, and with ``--closure`` a case asked for each bucket still open,
serially, on a local process pool (``--jobs``) or on a Ray cluster (``--ray``).

Exit codes: 0 every bucket is hit its target times or proved unreachable; 1 some bucket is open;
2 the input is unusable (or the scenario has no cover item)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..settings import count as parse_count
from .commands import EXIT_ACCEPTED, EXIT_INPUT, EXIT_REJECTED, SUMMARIES
from .common import (
    RUN_FLAGS,
    executor_flags,
    flag,
    on_executor,
    reporting_input_errors,
    run_settings,
    scenario_command,
    scenario_source,
    setting_flags,
)


def add(commands) -> None:
    """The ``cover`` command's flags, and its action."""
    cover = scenario_command(commands, "cover", SUMMARIES["cover"])
    setting_flags(cover, RUN_FLAGS)
    cover.add_argument(
        "--samples", type=flag(parse_count), default=20, help="samples drawn from the seed and run (default 20)"
    )
    cover.add_argument(
        "--closure",
        action="store_true",
        help="then ask one case inside each bucket no sample hit and no proof rules out",
    )
    cover.add_argument("--coverage", type=Path, default=None, metavar="PATH", help="write the tally to this JSON file")
    cover.add_argument(
        "--coverage-db",
        type=Path,
        default=None,
        metavar="PATH",
        help="add the tally to this JSON file of earlier runs' (made when missing) and report the sum; --closure "
        "asks only buckets no run has hit",
    )
    executor_flags(cover, "samples, proofs and closure cases")
    cover.set_defaults(action=_cover)


def _cover(args: argparse.Namespace) -> int:
    source = scenario_source(args)
    checked = reporting_input_errors(args, source.load)
    if isinstance(checked, int):
        return checked
    if not checked.coverage:
        print(
            f"{args.file}: error: scenario {checked.name} has no cover() or record() item; nothing to cover"
            "\n    hint: add one to the scenario, e.g. cover(speed, unit: kph, range: [0..100], every: 20)",
            file=sys.stderr,
        )
        return EXIT_INPUT
    campaign = on_executor(args, lambda chosen: reporting_input_errors(args, lambda: _campaign(args, source, chosen)))
    if isinstance(campaign, int):
        return campaign
    return _report(args, checked, campaign)


def _campaign(args: argparse.Namespace, source, chosen):
    from ..evaluation.coverage_campaign import cover
    from ..progress import ProgressBar

    settings = run_settings(args)
    print(
        f"{args.file}: {args.samples} samples, seed {settings.seed}"
        f"{', then closure' if args.closure else ''}; {chosen.describe()}",
        file=sys.stderr,
    )
    bar: list = [None, ""]  # the stage's bar, and its stage

    def progress(stage: str, done: int, of: int) -> None:
        if bar[1] != stage:
            if bar[0] is not None:
                bar[0].close()
            bar[:] = [ProgressBar(of), stage]
        bar[0].update(done, stage)

    try:
        return cover(source, settings, args.samples, args.closure, chosen, progress, args.coverage_db)
    finally:
        if bar[0] is not None:
            bar[0].close()


def _report(args: argparse.Namespace, checked, campaign) -> int:
    from ..evaluation.closure import closed
    from ..evaluation.coverage import text_lines, write_json

    for line in text_lines([campaign.coverage]):
        print(line)
    outcomes = ", ".join(f"{n} {o}" for o, n in sorted(campaign.outcomes.items()))
    print(
        f"{campaign.samples} samples ({campaign.without_plan} without a plan, set aside)"
        + (
            f"; closure: {campaign.closure_cases} cases ({campaign.closure_without_plan} tries without a plan)"
            if args.closure
            else ""
        )
        + (f"; outcomes: {outcomes}" if outcomes else "")
    )
    if args.coverage is not None:
        try:
            write_json([campaign.coverage], args.coverage)
        except OSError as error:
            print(f"roadlogic cover: --coverage {args.coverage}: cannot write it ({error.strerror})", file=sys.stderr)
            return EXIT_INPUT
        print(f"coverage written to {args.coverage}")
    coverage = campaign.coverage
    if args.coverage_db is not None:
        from ..evaluation.coverage_db import database_lines

        lines, summed = database_lines(args.coverage_db, [campaign.coverage], "--coverage-db")
        if summed is None:
            print(lines[0].replace("roadlogic:", "roadlogic cover:", 1), file=sys.stderr)
            return EXIT_INPUT
        print("\n".join(lines))
        (coverage,) = summed
    # closed over every run the database holds, when it is given
    every = all(closed(item, coverage) for item in checked.coverage if item.kind == "cover")
    return EXIT_ACCEPTED if every else EXIT_REJECTED
