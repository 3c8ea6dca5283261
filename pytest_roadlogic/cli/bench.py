"""``roadlogic bench``: the paper's evaluation (RQ1 time and conformance, RQ2 diversity): results,
plots and report.md."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..outcomes import CONFORMANT
from ..settings import count as parse_count
from .commands import EXIT_ACCEPTED, EXIT_INPUT, EXIT_REJECTED, SUMMARIES
from .common import (
    RUN_FLAGS,
    executor_flags,
    flag,
    on_executor,
    run_settings,
    setting_flags,
)


def add(commands) -> None:
    """The ``bench`` command's flags, and its action."""
    bench = commands.add_parser("bench", help=SUMMARIES["bench"])
    bench.add_argument("paths", type=Path, nargs="*", default=None, help=".osc files or folders (default: scenarios/)")
    bench.add_argument(
        "--base",
        type=flag(parse_count),
        default=None,
        help="instances per scenario with the base strategy (default 10, --quick 2)",
    )
    bench.add_argument(
        "--refined",
        type=flag(parse_count),
        default=None,
        help="instances per scenario with the refined strategy (default 50, --quick 5)",
    )
    bench.add_argument(
        "--quick",
        action="store_true",
        help="a small run (2 base and 5 refined instances per scenario, 1 and 2 realistic) to try the setup",
    )
    bench.add_argument(
        "--realistic",
        type=Path,
        action="append",
        default=None,
        metavar="FOLDER",
        help="a suite run beside the paper's and reported apart, its .osc files at any depth, each in the dialect its folder's "
        "conftest.py gives (default: scenarios/realistic/ when no paths are given)",
    )
    bench.add_argument("--no-realistic", action="store_true", help="run the paper's scenarios only")
    executor_flags(bench, "scenarios' base strategies and refined samples")
    setting_flags(bench, RUN_FLAGS)
    bench.add_argument(
        "--out", type=Path, default=Path("bench-report"), help="report directory (default bench-report/)"
    )
    bench.add_argument(
        "--no-artifacts", action="store_true", help="do not write each instance's plan, trace, CommonRoad XML and plot"
    )
    bench.add_argument(
        "--report-only",
        action="store_true",
        help="rebuild report.md and the plots from --out/results.json, without running",
    )
    bench.set_defaults(action=_bench)


def _bench(args: argparse.Namespace) -> int:
    """Run the evaluation (or read a run's results) and write its report; exit 0 when every target
    is met, 1 when one is missed, 2 when the input is unusable."""
    from ..evaluation import BenchmarkResults, summaries, targets_met, write_report
    from ..evaluation.bench import RESULTS_FILE

    if args.report_only:
        try:
            results = BenchmarkResults.load(args.out / RESULTS_FILE)
        except (OSError, ValueError, KeyError, TypeError) as error:
            print(
                f"{args.out / RESULTS_FILE}: error: cannot read the results of a run ({error}); run roadlogic bench first",
                file=sys.stderr,
            )
            return EXIT_INPUT
    else:
        if args.base == 0 and args.refined == 0:
            print(
                "roadlogic bench: --base 0 and --refined 0 leave nothing to run; give at least one instance",
                file=sys.stderr,
            )
            return EXIT_INPUT
        settings = _bench_settings(args)
        if settings is None:
            return EXIT_INPUT
        if _bench_out_refused(args):
            return EXIT_INPUT
        results = _bench_run(args, settings)
        if isinstance(results, int):
            return results
    table = summaries(results)
    report = write_report(results, args.out, table)
    met, lines = targets_met(results, table)
    print("\n".join(lines))
    print(f"report: {report}")
    return EXIT_ACCEPTED if met else EXIT_REJECTED


def _bench_out_refused(args: argparse.Namespace) -> bool:
    """``--out`` of the bench names a folder it may not write (a file, one holding files the bench
    does not write, one another bench holds, a name the system refuses): say so before running
    (True): a user's own files are never overwritten, and two benches never mix their results."""
    from ..artifacts.files import NotAnArtifactFolder, check_replaceable, claimed
    from ..evaluation.bench import BENCH_NAMES, RESULTS_FILE

    try:
        args.held.enter_context(claimed(args.out))  # first: a second bench into it is told so
        check_replaceable(args.out, BENCH_NAMES)
        if args.out.is_dir() and any(args.out.iterdir()) and not (args.out / RESULTS_FILE).is_file():
            # the names a bench writes, but no results of one: a user's own report.md, say
            raise NotAnArtifactFolder(
                f"{args.out} holds files but no {RESULTS_FILE}: not a folder a bench wrote; give a new or empty folder"
            )
    except NotAnArtifactFolder as error:
        from ..confinement import shown

        print(f"roadlogic bench: --out: {shown(str(error))}", file=sys.stderr)
        return True
    return False


def _bench_settings(args: argparse.Namespace):
    """The bench's suites from its arguments (``evaluation.suites``), or None after saying why not."""
    from ..evaluation.suites import benchmark_settings

    given_paths = bool(args.paths)
    paths = args.paths or [Path("scenarios")]
    realistic = (
        args.realistic if args.realistic is not None else ([] if given_paths else [Path("scenarios") / "realistic"])
    )
    settings, problems = benchmark_settings(
        paths,
        [] if args.no_realistic else realistic,
        quick=args.quick,
        base=args.base,
        refined=args.refined,
        run=run_settings(args),
        # the paper's evaluation (docs/evaluation.md) runs on the grid encoding unless one is given
        paper_run=run_settings(args, **({} if args.setting_encoding else {"encoding": "grid"})),
        artifacts=not args.no_artifacts,
        explicit_realistic=args.realistic is not None,
    )
    for problem in problems:
        print(problem, file=sys.stderr)
    return settings


def _bench_run(args: argparse.Namespace, settings):
    """Run the bench's suites with a progress bar on stderr, on the executor ``--jobs`` or ``--ray``
    asks for; the results, or the exit code after saying why the executor cannot run."""
    return on_executor(args, lambda chosen: _bench_on(args, settings, chosen))


def _bench_on(args: argparse.Namespace, settings, executor):
    """Run the bench's suites on ``executor``; the results."""
    from ..evaluation import run_benchmark

    total = len(settings.paths) * (settings.base + settings.refined)
    also = ""
    if (realistic := settings.realistic) is not None:
        total += len(realistic.paths) * (realistic.base + realistic.refined)
        also = f"; {len(realistic.paths)} realistic, {realistic.base} base and {realistic.refined} refined each"
    print(
        f"{len(settings.paths)} scenarios, {settings.base} base and {settings.refined} refined instances each{also} "
        f"({total} in all), seed {settings.run.seed}; {executor.describe()}",
        file=sys.stderr,
    )
    from ..progress import ProgressBar

    bar = ProgressBar(total)
    conformant = 0

    def progress(record, done: int, total: int) -> None:
        nonlocal conformant
        conformant += record.outcome == CONFORMANT
        bar.update(done, f"{record.scenario} {record.strategy}  {CONFORMANT} {conformant}")

    results = run_benchmark(settings, args.out, progress, command=["roadlogic", *args.argv], executor=executor)
    bar.close()
    for message in results.errors.values():
        print(message, file=sys.stderr)
    return results
