"""``roadlogic run``: plan, simulate and monitor one scenario (or its first N plans); write the artifacts.

Exit codes: 0 the simulation was accepted (or the vehicle under test passed); 1 it was rejected, or
no plan exists; 2 the input is unusable."""

from __future__ import annotations

import argparse
from pathlib import Path

from ..outcomes import CONFORMANT
from ..settings import (
    BASE,
    REFINED,
)
from .commands import EXIT_ACCEPTED, EXIT_INPUT, EXIT_REJECTED, SUMMARIES
from .common import (
    DRIVER_HELP,
    RUN_FLAGS,
    artifacts_flag,
    driver_factory,
    driver_flag,
    flag,
    load_scenario,
    out_refused,
    reporting_input_errors,
    run_settings,
    scenario_command,
    setting_flags,
    show,
    values_flag,
    whole_instances,
)


def add(commands) -> None:
    """The ``run`` command's flags, and its action."""
    run = scenario_command(commands, "run", SUMMARIES["run"])
    setting_flags(run, RUN_FLAGS)
    run.add_argument("--out", type=Path, default=Path("out"), help="artifact directory (default out/)")
    artifacts_flag(run)
    run.add_argument(
        "--instances",
        type=flag(whole_instances),
        default=1,
        help="run the planner's first N different plans, artifacts in --out/instance-NNN (default 1)",
    )
    run.add_argument(
        "--values",
        type=values_flag,
        default=None,
        help="logical parameter values as JSON, e.g. '{\"start_gap\": 12.5}' (SI units)",
    )
    run.add_argument(
        "--driver", type=driver_flag, action="append", default=[], metavar="VEHICLE=MODULE:CLASS", help=DRIVER_HELP
    )
    run.set_defaults(action=_run)


def _run(args: argparse.Namespace) -> int:
    from ..runner import Runner

    if out_refused(args):
        return EXIT_INPUT
    if args.instances > 1:
        return _run_many(args)

    def run_one():
        runner = Runner(load_scenario(args), run_settings(args), driver_factory(dict(args.driver), args.file))
        case = (
            runner.case(strategy=REFINED, values=args.values) if args.values else runner.case(strategy=BASE, instance=0)
        )
        return runner.run_case(case)

    result = reporting_input_errors(args, run_one)
    return result if isinstance(result, int) else show(result, args.out, args.artifacts, dict(args.driver))


def _run_many(args: argparse.Namespace) -> int:
    """``run --instances N``: the planner's first N different plans (the base strategy), each
    simulated and monitored, a progress bar on stderr, artifacts per instance under ``--out``."""
    from ..artifacts.files import replaced_directory
    from ..artifacts.writer import ARTIFACT_NAMES, write_artifacts
    from ..runner import Runner

    def all_instances():
        with replaced_directory(
            args.out, ARTIFACT_NAMES
        ) as staging:  # the folder gets the new set whole, or keeps the old
            return list(instances(staging))

    def instances(staging: Path):
        from ..progress import ProgressBar

        runner = Runner(load_scenario(args), run_settings(args), driver_factory(dict(args.driver), args.file))
        conformant = 0
        bar = ProgressBar(args.instances)
        for result in runner.base(args.instances):
            done = result.case.instance + 1
            if result.run is None:  # the planner failed: the report is the exit path
                bar.close()
                yield f"instance {done}: {result.outcome}: {result.message}", False
                return
            directory = args.out / f"instance-{done:03d}"
            write_artifacts(result.run, staging / directory.name, animation=False, level=args.artifacts)
            conformant += not result.failed
            bar.update(done, f"{CONFORMANT} {conformant}")
            tries = result.run.tries
            yield (
                f"instance {done}: {result.outcome} after {tries} tr{'y' if tries == 1 else 'ies'}, {sum(result.seconds.values()):.2f} s  {directory}",
                not result.failed,
            )
        bar.close()

    results = reporting_input_errors(args, all_instances)
    if isinstance(results, int):
        return results
    for line, _ in results:
        print(line)
    conformant = sum(ok for _, ok in results)
    print(f"{conformant} of {len(results)} instances {CONFORMANT}")
    return EXIT_ACCEPTED if results and conformant == len(results) else EXIT_REJECTED
