"""The ``roadlogic`` command.

    roadlogic run FILE.osc [--scenario NAME] [--seed S] [--out DIR] [--lanes N] [--tries N] [--instances N | --values JSON]
                  [--encoding continuous|grid] [--horizon N] [--plan-timeout S] [--sim-timeout S] [--simulator NAME]
    roadlogic check PATH... [--syntax-only] [--lanes N]
    roadlogic automaton FILE.osc [--scenario NAME] [--out FILE.dot] [--lanes N]
    roadlogic plan FILE.osc [--scenario NAME] [--plans N] [--seed S] [--lanes N] [--show-asp]
    roadlogic replay CASE.json [--out DIR]
    roadlogic replay FILE.osc [--scenario NAME] [--seed S] [--values JSON | --strategy base --instance K] [--out DIR]

Exit codes of ``run``: 0 the simulation was accepted; 1 it was rejected (or no plan exists);
2 the input is unusable (a file that does not parse or check, a bad option).
Exit codes of ``check``: 0 every file is fine; 1 some file has an error; 2 a path does not exist.
Exit codes of ``automaton``: 0 written; 2 the input is unusable.
Exit codes of ``plan``: 0 at least one plan; 1 no plan exists; 2 the input is unusable.
Exit codes of ``replay``: as ``run``.
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import itertools
import json
import os
import shlex
import sys
import time
from pathlib import Path

# Light imports only: `roadlogic --help` and argument errors must not load the pipeline; each
# command imports the stages it uses.
from .outcomes import CONFORMANT, PASSED
from .settings import (
    ARTIFACT_LEVELS,
    BASE,
    OPTIONS,
    OPTIONS_BY_NAME,
    REFINED,
    STRATEGIES,
    OptionError,
    RunSettings,
    whole_number,
)
from .settings import (
    count as parse_count,
)

EXIT_ACCEPTED, EXIT_REJECTED, EXIT_INPUT = 0, 1, 2
DRIVER_HELP = "drive VEHICLE with the class MODULE:CLASS (built without arguments; see pytest_roadlogic.simulation.Driver) instead of the simulator's own; repeat for several"
# the run settings as flags, read from settings.OPTIONS: those that say which road a scenario is
# on (every command about a scenario takes them), and the rest of what a case records
ROAD_FLAGS = ("lanes", "dialect", "map")
RUN_FLAGS = tuple(o.name for o in OPTIONS if o.in_case and o.name not in (*ROAD_FLAGS, "strategy"))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="roadlogic", description="Concrete, monitored simulations from OpenSCENARIO DSL scenarios."
    )
    commands = parser.add_subparsers(dest="command", required=True)
    run = _scenario_command(commands, "run", "plan, simulate and monitor one scenario; write the artifacts")
    _run_flags(run, RUN_FLAGS)
    run.add_argument("--out", type=Path, default=Path("out"), help="artifact directory (default out/)")
    _artifacts_flag(run)
    run.add_argument(
        "--instances",
        type=_flag(whole_instances),
        default=1,
        help="run the planner's first N different plans, artifacts in --out/instance-NNN (default 1)",
    )
    run.add_argument(
        "--values",
        type=_values,
        default=None,
        help="logical parameter values as JSON, e.g. '{\"start_gap\": 12.5}' (SI units)",
    )
    run.add_argument(
        "--driver", type=_driver, action="append", default=[], metavar="VEHICLE=MODULE:CLASS", help=DRIVER_HELP
    )
    replay = commands.add_parser(
        "replay", help="run one case again exactly: from the case.json of a failure, or from a file and values"
    )
    replay.add_argument("case", type=Path, help="a case.json written for a failure, or an .osc file")
    replay.add_argument("--scenario", help="with an .osc file: the scenario (default: the first)")
    replay.add_argument(
        "--strategy", choices=STRATEGIES, default=REFINED, help="with an .osc file: how the case was made"
    )
    replay.add_argument(
        "--values", type=_values, default=None, help="with an .osc file: the sampled values as JSON (refined)"
    )
    replay.add_argument(
        "--instance", type=_flag(parse_count), default=0, help="with an .osc file: which plan, from 0 (base)"
    )
    replay.add_argument(
        "--driver",
        type=_driver,
        action="append",
        default=[],
        metavar="VEHICLE=MODULE:CLASS",
        help="with an .osc file: " + DRIVER_HELP,
    )
    _run_flags(replay, ROAD_FLAGS, "with an .osc file: ")
    _run_flags(replay, RUN_FLAGS, "with an .osc file: ")
    replay.add_argument("--out", type=Path, default=Path("out"), help="artifact directory (default out/)")
    _artifacts_flag(replay)
    _allow_read(replay)
    check = commands.add_parser("check", help="parse and check .osc files and folders; print every problem")
    check.add_argument("paths", type=Path, nargs="+", help=".osc files or folders (searched recursively)")
    check.add_argument(
        "--syntax-only", action="store_true", help="stop after parsing (for files written for other tools)"
    )
    _run_flags(check, ROAD_FLAGS)
    _allow_read(check)
    automaton = _scenario_command(
        commands, "automaton", "write a scenario's symbolic automaton as Graphviz DOT (and PNG when dot is installed)"
    )
    automaton.add_argument("--out", type=Path, default=None, help="the DOT file to write (default: <scenario>.dot)")
    plan = _scenario_command(commands, "plan", "solve a scenario's planning problem and print the plans as tables")
    plan.add_argument("--plans", type=int, default=1, help="how many plans to enumerate (default 1)")
    _run_flags(plan, ("seed", "road-speed", "encoding", "horizon", "plan-timeout"))
    plan.add_argument("--show-asp", action="store_true", help="also print the generated instance program")
    bench = commands.add_parser(
        "bench", help="the paper's evaluation (RQ1 time and conformance, RQ2 diversity): results, plots and report.md"
    )
    bench.add_argument("paths", type=Path, nargs="*", default=None, help=".osc files or folders (default: scenarios/)")
    bench.add_argument(
        "--base",
        type=_flag(parse_count),
        default=None,
        help="instances per scenario with the base strategy (default 10, --quick 2)",
    )
    bench.add_argument(
        "--refined",
        type=_flag(parse_count),
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
    _run_flags(bench, RUN_FLAGS)
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
    args = parser.parse_args(argv)
    args.argv = list(sys.argv[1:] if argv is None else argv)
    command = {
        "run": _run,
        "check": _check,
        "automaton": _automaton,
        "plan": _plan,
        "replay": _replay,
        "bench": _bench,
    }[args.command]
    try:
        with contextlib.ExitStack() as args.held:  # what a command holds while it runs (its --out folder's claim)
            return command(args)
    except KeyboardInterrupt:
        # Ctrl-C: a line, not the traceback of wherever the solver or the simulation was
        print(f"roadlogic {args.command}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # the reader of our output went away (roadlogic check ... | head): stop quietly, as cat does
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nothing more to flush at exit
        except OSError:
            pass
        return 141


def _artifacts_flag(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--artifacts",
        choices=ARTIFACT_LEVELS,
        default="all",
        help="what to write to --out: none; essential (plan.json, trace.csv, verdict.json and case.json: what a "
        "replay and a reader of the verdict need, written in a fraction of the time); all (also the CommonRoad and "
        "OpenSCENARIO files, the plot and the GIF; default)",
    )


def _flag(parse):
    """An argparse type from a settings parser: its OptionError becomes argparse's message."""

    def convert(text: str):
        try:
            return parse(text)
        except OptionError as error:
            raise argparse.ArgumentTypeError(str(error)) from None

    convert.__name__ = getattr(parse, "__name__", "value")
    return convert


whole_instances = whole_number(1, "an instance count")


def _run_flags(command: argparse.ArgumentParser, names: tuple[str, ...], prefix: str = "") -> None:
    """The run settings ``names`` as flags, each read and checked by its ``settings.OPTIONS`` entry."""
    for name in names:
        option = OPTIONS_BY_NAME[name]
        command.add_argument(
            f"--{name}",
            type=_flag(option.parse),
            default=None,
            dest=f"setting_{name.replace('-', '_')}",
            metavar=name.upper().replace("-", "_"),
            help=f"{prefix}{option.help} (default {option.default_text})",
        )


def _run_settings(args: argparse.Namespace, **extra) -> RunSettings:
    """The run settings of a command: its flags, the defaults of settings.OPTIONS for the rest."""
    values = {}
    for name, option in OPTIONS_BY_NAME.items():
        value = getattr(args, f"setting_{name.replace('-', '_')}", None)
        if value is not None:
            values[option.field] = value
    return RunSettings(**values, **extra)


def _driver(text: str) -> tuple[str, str]:
    """A ``--driver`` option: ``VEHICLE=MODULE:CLASS``."""
    vehicle, _, name = text.partition("=")
    if not vehicle or ":" not in name or name.startswith(":") or name.endswith(":"):
        raise argparse.ArgumentTypeError(
            f"{text!r} is not VEHICLE=MODULE:CLASS, e.g. ego=tests.drivers:NeverChangesLane"
        )
    return vehicle, name


def _driver_factory(names: dict[str, str], scenario_file: Path, roots=None):
    """The drivers ``names`` gives, or ``DriverLoadError``; None when there are none (the
    simulator's own drive). ``names`` come from the command line only (``--driver``), never from a
    case file; they are imported as pytest would, from the working folder and the folders above
    the scenario inside the project (``roots``)."""
    from .simulation.named_drivers import drivers_from_names

    if not names:
        return None
    search = [
        Path.cwd(),
        *(folder for folder in scenario_file.resolve().parents if roots is None or roots.allows(folder)),
    ]
    return drivers_from_names(names, search)


def _drivers_of_case(case, given: dict[str, str]) -> dict[str, str]:
    """The drivers a case file's replay uses: those the command line gives, which must be the ones
    the case records. A case file is data: the module names in it are never imported on its word
    (it could name os:abort or sys:exit); the user names them with --driver after reading them."""
    from .simulation.named_drivers import DriverLoadError

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


def _values(text: str) -> dict:
    """A ``--values`` option: a JSON object from parameter names to values."""
    try:
        values = json.loads(text)
    except json.JSONDecodeError as error:
        raise argparse.ArgumentTypeError(f"not JSON ({error.msg}); write e.g. '{{\"start_gap\": 12.5}}'") from None
    if not isinstance(values, dict):
        raise argparse.ArgumentTypeError("give a JSON object of parameter names to values")
    return values


def _scenario_command(commands, name: str, help: str) -> argparse.ArgumentParser:
    """A subcommand about one scenario of one file, on a road of some lanes."""
    command = commands.add_parser(name, help=help)
    command.add_argument("file", type=Path, help="an .osc file")
    command.add_argument("--scenario", help="the scenario when the file declares several (default: the first)")
    _run_flags(command, ROAD_FLAGS)
    _allow_read(command)
    return command


def _allow_read(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--allow-read",
        type=Path,
        action="append",
        default=[],
        metavar="DIR",
        help="a folder outside the project that imports and case files may read from (repeat for several; default: the project's root "
        "and the named file's folder only)",
    )


def _roots(args: argparse.Namespace, named: Path):
    """The folders a file named on the command line may make the tool read (confinement.ReadRoots)."""
    from .confinement import ReadRoots

    return ReadRoots.around(named, extra=getattr(args, "allow_read", []))


def _plan(args: argparse.Namespace) -> int:
    from .planning import planner_for, settings_for
    from .planning.fallbacks import fallback_needed, planned

    def solve():
        scenario, automaton = _load_automaton(args)
        settings = _run_settings(args)
        planner_settings = settings_for(settings)
        planner = planner_for(automaton, planner_settings, settings.seed)
        if args.show_asp:
            print(planner.instance_program())
        started = time.perf_counter()
        # as a run plans: before "no plan", thinner margins, a finer step and relaxed limits (a plan
        # that needs one says so below); the constraints named when none has one clash for those too
        plans = planned(lambda _: automaton, planner_settings, settings.seed, args.plans)
        plans = list(itertools.islice(plans, args.plans))
        return scenario, automaton, plans, time.perf_counter() - started, planner_settings, settings.seed

    solved = _reporting_input_errors(args, solve)
    if isinstance(solved, int):
        return solved
    scenario, automaton, plans, seconds, planner_settings, seed = solved
    events = {t.id: t.label for t in automaton.transitions}
    for plan in plans:
        print(
            f"plan {plan.index + 1} of scenario {scenario.name} (seed {plan.seed}): horizon {plan.horizon} steps of {plan.dt:g} s"
        )
        print(plan.table(functools.partial(scenario.registry.lane_number, lanes=plan.lanes)))
        for step, transition in plan.transitions:
            print(f"  step {step}: {events[transition]}")
        needed = fallback_needed(plan, lambda _: automaton, planner_settings, seed)
        if needed:
            print(f"  {needed}")
        _print_unasked(plan, automaton, scenario.registry, indent="  ")
    print(f"{len(plans)} plan{'s' if len(plans) != 1 else ''} in {seconds:.3f} s")
    return 0


def _automaton(args: argparse.Namespace) -> int:
    from .artifacts.automaton import write_dot

    loaded = _reporting_input_errors(args, lambda: _load_automaton(args))
    if isinstance(loaded, int):
        return loaded
    scenario, automaton = loaded
    from .confinement import safe_name

    # the name is the scenario's, which may be quoted (|../../../x|): it must not lead out of the working folder
    written = write_dot(
        automaton, args.out or Path(f"{safe_name(scenario.name)}.dot"), title=f"{scenario.name} ({args.file})"
    )
    print(automaton.describe())
    print(f"{len(automaton.locations)} locations, {len(automaton.transitions)} transitions")
    for kind, path in written.items():
        print(f"  {kind:<4} {path}")
    if "png" not in written:
        print("  (no PNG: Graphviz's dot is not installed)")
    return 0


def osc_files(paths: list[Path], recursive: bool = True) -> list[Path]:
    """``confinement.osc_files``, each special file it skipped said on stderr."""
    from .confinement import osc_files as found

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
    from .automaton import build_automaton
    from .frontend import OscError, parse_file
    from .frontend import check_file as check

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
            path, args.syntax_only, args.setting_lanes, args.setting_dialect, _roots(args, path), args.setting_map
        )
        if report:
            print(report)
        if not ok:
            failed += 1
    print(f"{len(files)} files, {len(files) - failed} ok, {failed} with errors")
    return 1 if failed else 0


def _load(args: argparse.Namespace):
    from .pipeline import load_scenario

    return load_scenario(
        args.file, args.scenario, args.setting_lanes, args.setting_dialect, _roots(args, args.file), args.setting_map
    )


def _load_automaton(args: argparse.Namespace):
    from .automaton import build_automaton

    scenario = _load(args)
    return scenario, build_automaton(scenario)


def _reporting_input_errors(args: argparse.Namespace, action):
    """``action()``, or the exit code after printing why the input is unusable (never a traceback)."""
    from .case import CaseFileError
    from .dut import NoSuchVehicle
    from .frontend import OscError
    from .planning import NoPlanError, UnsatisfiableScenario
    from .registries.drivers import UnknownDriver
    from .sampling import UnknownParameter
    from .simulation.backends import UnknownSimulator
    from .simulation.named_drivers import DriverLoadError

    try:
        return action()
    except OscError as error:
        print(error.report(), file=sys.stderr)
        return EXIT_INPUT
    except (UnknownParameter, CaseFileError, UnknownSimulator, UnknownDriver) as error:
        print(f"{args.file}: error: {error}", file=sys.stderr)
        return EXIT_INPUT
    except NoSuchVehicle as error:
        print(f"{args.file}: error: --dut: {error}", file=sys.stderr)
        return EXIT_INPUT
    except DriverLoadError as error:
        replay_hint = (
            f" (pytest --roadlogic-replay {shlex.quote(str(args.file))})" if str(args.file).endswith(".json") else ""
        )
        print(
            f"{args.file}: error: {error}; other drivers would not reproduce the case\n"
            f"    hint: make the module importable from here, or run it with pytest from the session whose conftest.py gives it{replay_hint}",
            file=sys.stderr,
        )
        return EXIT_INPUT
    except KeyError as error:
        print(f"{args.file}: error: no scenario named {error.args[0]!r} in the file", file=sys.stderr)
        return EXIT_INPUT
    except UnsatisfiableScenario as error:
        print(error.report(), file=sys.stderr)
        return EXIT_REJECTED
    except NoPlanError as error:
        print(f"{args.file}: no plan: {error}", file=sys.stderr)
        return EXIT_REJECTED


def _run(args: argparse.Namespace) -> int:
    from .runner import Runner

    if _out_refused(args):
        return EXIT_INPUT
    if args.instances > 1:
        return _run_many(args)

    def run_one():
        runner = Runner(_load(args), _run_settings(args), _driver_factory(dict(args.driver), args.file))
        case = (
            runner.case(strategy=REFINED, values=args.values) if args.values else runner.case(strategy=BASE, instance=0)
        )
        return runner.run_case(case)

    result = _reporting_input_errors(args, run_one)
    return result if isinstance(result, int) else _show(result, args.out, args.artifacts, dict(args.driver))


def _run_many(args: argparse.Namespace) -> int:
    """``run --instances N``: the planner's first N different plans (the base strategy), each
    simulated and monitored, a progress bar on stderr, artifacts per instance under ``--out``."""
    from .artifacts.files import replaced_directory
    from .artifacts.writer import ARTIFACT_NAMES, write_artifacts
    from .runner import Runner

    def all_instances():
        with replaced_directory(
            args.out, ARTIFACT_NAMES
        ) as staging:  # the folder gets the new set whole, or keeps the old
            return list(instances(staging))

    def instances(staging: Path):
        from .progress import ProgressBar

        runner = Runner(_load(args), _run_settings(args), _driver_factory(dict(args.driver), args.file))
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

    results = _reporting_input_errors(args, all_instances)
    if isinstance(results, int):
        return results
    for line, _ in results:
        print(line)
    conformant = sum(ok for _, ok in results)
    print(f"{conformant} of {len(results)} instances {CONFORMANT}")
    return EXIT_ACCEPTED if results and conformant == len(results) else EXIT_REJECTED


def _replay(args: argparse.Namespace) -> int:
    from dataclasses import replace as replaced

    from .case import Case
    from .runner import replay

    def run_again():
        if args.case.suffix == ".json":
            from .confinement import ReadRoots, project_root

            # the project's root, not the case file's folder, which may be anywhere; with no project
            # above the working folder, the case file's folder (never / or the home folder)
            roots = ReadRoots.of(project_root() or args.case.resolve().parent, extra=args.allow_read)
            case = Case.load(args.case).within(_run_settings(args))
            case = replaced(case, path=str(case.scenario_file(args.case, roots)))
            _drivers_of_case(case, dict(args.driver))
            for difference in case.version_differences():
                print(
                    f"{args.case}: warning: written with {difference}; the replay may plan or drive otherwise",
                    file=sys.stderr,
                )
        else:
            from .frontend import load_file

            roots = _roots(args, args.case)
            name = (
                load_file(
                    args.case, args.setting_lanes, dialect=args.setting_dialect, roots=roots, road_map=args.setting_map
                )
                .scenario_to_run(args.scenario)
                .name
            )
            identity = {"values": args.values or {}} if args.strategy == REFINED else {"instance": args.instance}
            case = Case.of(
                args.case, name, _run_settings(args), strategy=args.strategy, drivers=dict(args.driver), **identity
            )
        return replay(case, drivers=_driver_factory(case.drivers, Path(case.path), roots), roots=roots)

    args.file = args.case
    if _out_refused(args):
        return EXIT_INPUT
    result = _reporting_input_errors(args, run_again)
    return result if isinstance(result, int) else _show(result, args.out, args.artifacts, dict(args.driver))


def _out_refused(args: argparse.Namespace) -> bool:
    """``--out`` names a folder that a run may not replace: say so before running (True)."""
    from .artifacts.files import NotAnArtifactFolder, check_replaceable, claimed
    from .artifacts.writer import ARTIFACT_NAMES

    try:
        check_replaceable(args.out, ARTIFACT_NAMES)
        args.held.enter_context(claimed(args.out))  # held until the command ends: a second run into it is refused
    except NotAnArtifactFolder as error:
        print(f"roadlogic {args.command}: --out: {error}", file=sys.stderr)
        return True
    return False


def _show(result, out: Path, level: str = "all", drivers: dict[str, str] | None = None) -> int:
    """Write the artifacts of a case at ``level`` (``ARTIFACT_LEVELS``; with them the case file, when
    the scenario is inside the project, so that ``roadlogic replay out/case.json`` runs it again with
    ``drivers``) and print its stages, verdict and files; the exit code of ``run``. A case without
    a simulation prints why on stderr (the constraints that clash, at their places)."""
    from .artifacts.files import replaced_directory
    from .artifacts.writer import ARTIFACT_NAMES, write_artifacts
    from .planning import UnsatisfiableScenario

    case = result.case
    if result.run is None:
        prefix = "" if isinstance(result.error, UnsatisfiableScenario) else f"{case.path}: "
        print(f"{prefix}{result.message}", file=sys.stderr)
        return EXIT_REJECTED
    outcome = result.run
    # the verdict first, then the artifacts (the plot and the GIF are most of a small run's wall)
    result.seconds.pop("artifacts", None)
    print(
        f"scenario {case.scenario} (seed {case.seed}): {result.outcome} after {outcome.tries} tr{'y' if outcome.tries == 1 else 'ies'}"
    )
    for stage, seconds in result.seconds.items():
        print(f"  {stage:<12} {seconds:7.3f} s")
    print(outcome.verdict.explain())
    _print_unasked(outcome.plan, outcome.automaton, outcome.scenario.registry)
    if outcome.dut is not None:
        print(oracle_line(outcome.dut, len(outcome.simulation.replans)))
        if result.message:
            print(f"{result.outcome}: {result.message}")
    if level != "none":
        sys.stdout.flush()
        started = time.perf_counter()
        with replaced_directory(out, ARTIFACT_NAMES) as staging:  # the folder gets the new set whole, or keeps the old
            written = write_artifacts(outcome, staging, level=level)
            case_file = _case_file(result.case, drivers or {}, staging / "case.json")
            paths = {kind: out / path.name for kind, path in {**written, **case_file}.items()}
        result.seconds["artifacts"] = time.perf_counter() - started
        print(f"  {'artifacts':<12} {result.seconds['artifacts']:7.3f} s")
        for kind, path in paths.items():
            print(f"  {kind:<12} {path}")
    if outcome.dut is not None:
        return EXIT_ACCEPTED if result.outcome == PASSED else EXIT_REJECTED
    return EXIT_ACCEPTED if outcome.verdict.accepted else EXIT_REJECTED


def _case_file(case, drivers: dict[str, str], path: Path) -> dict[str, Path]:
    """The run's case file at ``path`` ({"case": path}), its scenario named relative to the project's
    root (a case file names no absolute path); none outside a project, or when the scenario is
    outside it: ``roadlogic replay`` reads a case's scenario inside the project only."""
    from dataclasses import replace

    from .case import installed_versions
    from .confinement import project_root

    root = project_root()
    if root is None:
        return {}
    try:
        relative = Path(case.path).resolve().relative_to(root.resolve())
    except ValueError:
        return {}
    recorded = replace(case, path=relative.as_posix(), drivers=drivers, versions=installed_versions())
    return {"case": recorded.save(path)}


def _print_unasked(plan, automaton, registry, indent: str = "") -> None:
    """The plan's changes that no construct of their vehicle asks for, in the file's lane numbers
    (``registry``'s dialect), under ``roadlogic plan``'s table and ``roadlogic run``'s verdict."""
    from .evaluation.fidelity import said_unasked

    said = said_unasked(plan, automaton, registry)
    if said:
        print(
            f"{indent}no plan has every vehicle do only what it is asked; this one has the fewest changes nothing asks for:"
        )
        print("\n".join(f"{indent}  {line}" for line in said))


def oracle_line(report, replans: int) -> str:
    """The oracles' values of a vehicle under test in a line (``inf``: no one ahead in its path)."""
    from .oracles import ORACLES

    values = report.values()
    measured = ", ".join(
        f"{oracle.title} {'inf' if values[oracle.value_key] is None else values[oracle.value_key]} {oracle.unit}"
        for oracle in ORACLES
    )
    return f"vehicle under test {report.vehicle}: {measured}, {replans} replans"


def _bench(args: argparse.Namespace) -> int:
    """Run the evaluation (or read a run's results) and write its report; exit 0 when every target
    is met, 1 when one is missed, 2 when the input is unusable."""
    from .evaluation import BenchmarkResults, summaries, targets_met, write_report
    from .evaluation.bench import RESULTS_FILE

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
    from .artifacts.files import NotAnArtifactFolder, check_replaceable, claimed
    from .evaluation.bench import BENCH_NAMES, RESULTS_FILE

    try:
        args.held.enter_context(claimed(args.out))  # first: a second bench into it is told so
        check_replaceable(args.out, BENCH_NAMES)
        if args.out.is_dir() and any(args.out.iterdir()) and not (args.out / RESULTS_FILE).is_file():
            # the names a bench writes, but no results of one: a user's own report.md, say
            raise NotAnArtifactFolder(
                f"{args.out} holds files but no {RESULTS_FILE}: not a folder a bench wrote; give a new or empty folder"
            )
    except NotAnArtifactFolder as error:
        from .confinement import shown

        print(f"roadlogic bench: --out: {shown(str(error))}", file=sys.stderr)
        return True
    return False


def _bench_settings(args: argparse.Namespace):
    """The bench's suites from its arguments (``evaluation.suites``), or None after saying why not."""
    from .evaluation.suites import benchmark_settings

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
        run=_run_settings(args),
        # the paper's evaluation (docs/evaluation.md) runs on the grid encoding unless one is given
        paper_run=_run_settings(args, **({} if args.setting_encoding else {"encoding": "grid"})),
        artifacts=not args.no_artifacts,
        explicit_realistic=args.realistic is not None,
    )
    for problem in problems:
        print(problem, file=sys.stderr)
    return settings


def _bench_run(args: argparse.Namespace, settings):
    """Run the bench's suites with a progress bar on stderr; the results."""
    from .evaluation import run_benchmark

    total = len(settings.paths) * (settings.base + settings.refined)
    also = ""
    if (realistic := settings.realistic) is not None:
        total += len(realistic.paths) * (realistic.base + realistic.refined)
        also = f"; {len(realistic.paths)} realistic, {realistic.base} base and {realistic.refined} refined each"
    print(
        f"{len(settings.paths)} scenarios, {settings.base} base and {settings.refined} refined instances each{also} "
        f"({total} in all), seed {settings.run.seed}",
        file=sys.stderr,
    )
    from .progress import ProgressBar

    bar = ProgressBar(total)
    conformant = 0

    def progress(record, done: int, total: int) -> None:
        nonlocal conformant
        conformant += record.outcome == CONFORMANT
        bar.update(done, f"{record.scenario} {record.strategy}  {CONFORMANT} {conformant}")

    results = run_benchmark(settings, args.out, progress, command=["roadlogic", *args.argv])
    bar.close()
    for message in results.errors.values():
        print(message, file=sys.stderr)
    return results


if __name__ == "__main__":
    raise SystemExit(main())
