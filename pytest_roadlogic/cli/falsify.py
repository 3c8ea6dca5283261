"""``roadlogic falsify``: a falsification campaign over one scenario: several searches for a
failing case, each from its own seed, serially, on a local process pool (``--jobs``) or on a Ray
cluster (``--ray``); each search ends at its first failure, shrunk, or after ``--budget`` samples.

Exit codes: 0 no search found a failure; 1 one did (the first in the order of the searches is
reported, with the command that replays it); 2 the input is unusable."""

from __future__ import annotations

import argparse
import json
import sys

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
    """The ``falsify`` command's flags, and its action."""
    falsify = scenario_command(commands, "falsify", SUMMARIES["falsify"])
    setting_flags(falsify, (*RUN_FLAGS, "search"))
    falsify.add_argument(
        "--searches", type=flag(parse_count), default=4, help="searches, each from its own seed (default 4)"
    )
    falsify.add_argument(
        "--budget", type=flag(parse_count), default=50, help="samples per search before it gives up (default 50)"
    )
    executor_flags(falsify, "searches")
    falsify.set_defaults(action=_falsify)


def _falsify(args: argparse.Namespace) -> int:
    if args.searches < 1 or args.budget < 1:
        print("roadlogic falsify: --searches and --budget need at least 1", file=sys.stderr)
        return EXIT_INPUT
    source = scenario_source(args)
    checked = reporting_input_errors(args, source.load)
    if isinstance(checked, int):
        return checked
    settings = run_settings(args)
    outcomes = on_executor(
        args, lambda chosen: reporting_input_errors(args, lambda: _searches(args, source, settings, chosen))
    )
    if isinstance(outcomes, int):
        return outcomes
    return _report(outcomes, args.budget)


def _searches(args: argparse.Namespace, source, settings, chosen):
    from ..evaluation.falsification_campaign import falsify
    from ..progress import ProgressBar

    print(
        f"{args.file}: {args.searches} searches ({settings.search}) of up to {args.budget} samples, "
        f"seed {settings.seed}; {chosen.describe()}",
        file=sys.stderr,
    )
    bar = ProgressBar(args.searches)
    failures = 0

    def progress(outcome, done: int, total: int) -> None:
        nonlocal failures
        failures += outcome.failure is not None
        bar.update(done, f"failures {failures}")

    try:
        return falsify(source, settings, args.searches, args.budget, chosen, progress)
    finally:
        bar.close()


def _report(outcomes, budget: int) -> int:
    for outcome in outcomes:
        found = outcome.failure
        said = (
            f"{found.kind} ({found.outcome}) after {outcome.samples} samples"
            if found is not None
            else f"no failure in {outcome.samples} samples"
        )
        print(f"search seed {outcome.seed}: {said}")
    failing = [o for o in outcomes if o.failure is not None]
    print(f"{len(failing)} of {len(outcomes)} searches found a failure (budget {budget} samples each)")
    if not failing:
        return EXIT_ACCEPTED
    first = failing[0].failure
    print(f"first failure (search seed {failing[0].seed}), shrunk: {first.kind} ({first.outcome})")
    print(f"  values: {json.dumps(first.values, sort_keys=True)}")
    print(f"  {first.message}")
    print(f"  replay: {first.replay}")
    return EXIT_REJECTED
