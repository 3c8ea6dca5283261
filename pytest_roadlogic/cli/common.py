"""What the ``roadlogic`` commands share: exit codes, flags read from ``settings.OPTIONS``, loading a
scenario, reporting unusable input (never a traceback), and refusing an ``--out`` that cannot be written."""

from __future__ import annotations

import argparse
import json
import shlex
import sys
import time
from pathlib import Path

from ..outcomes import PASSED
from ..settings import (
    ARTIFACT_LEVELS,
    OPTIONS,
    OPTIONS_BY_NAME,
    OptionError,
    RunSettings,
    whole_number,
)
from .commands import EXIT_ACCEPTED, EXIT_INPUT, EXIT_REJECTED

DRIVER_HELP = "drive VEHICLE with the class MODULE:CLASS (built without arguments; see pytest_roadlogic.simulation.Driver) instead of the simulator's own; repeat for several"

ROAD_FLAGS = ("lanes", "dialect", "map")

RUN_FLAGS = tuple(o.name for o in OPTIONS if o.in_case and o.name not in (*ROAD_FLAGS, "strategy"))

whole_instances = whole_number(1, "an instance count")


def artifacts_flag(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--artifacts",
        choices=ARTIFACT_LEVELS,
        default="all",
        help="what to write to --out: none; essential (plan.json, trace.csv, verdict.json and case.json: what a "
        "replay and a reader of the verdict need, written in a fraction of the time); all (also the CommonRoad and "
        "OpenSCENARIO files, the plot and the GIF; default)",
    )


def flag(parse):
    """An argparse type from a settings parser: its OptionError becomes argparse's message."""

    def convert(text: str):
        try:
            return parse(text)
        except OptionError as error:
            raise argparse.ArgumentTypeError(str(error)) from None

    convert.__name__ = getattr(parse, "__name__", "value")
    return convert


def setting_flags(command: argparse.ArgumentParser, names: tuple[str, ...], prefix: str = "") -> None:
    """The run settings ``names`` as flags, each read and checked by its ``settings.OPTIONS`` entry."""
    for name in names:
        option = OPTIONS_BY_NAME[name]
        command.add_argument(
            f"--{name}",
            type=flag(option.parse),
            default=None,
            dest=f"setting_{name.replace('-', '_')}",
            metavar=name.upper().replace("-", "_"),
            help=f"{prefix}{option.help} (default {option.default_text})",
        )


def run_settings(args: argparse.Namespace, **extra) -> RunSettings:
    """The run settings of a command: its flags, the defaults of settings.OPTIONS for the rest."""
    values = {}
    for name, option in OPTIONS_BY_NAME.items():
        value = getattr(args, f"setting_{name.replace('-', '_')}", None)
        if value is not None:
            values[option.field] = value
    return RunSettings(**values, **extra)


def driver_flag(text: str) -> tuple[str, str]:
    """A ``--driver`` option: ``VEHICLE=MODULE:CLASS``."""
    vehicle, _, name = text.partition("=")
    if not vehicle or ":" not in name or name.startswith(":") or name.endswith(":"):
        raise argparse.ArgumentTypeError(
            f"{text!r} is not VEHICLE=MODULE:CLASS, e.g. ego=tests.drivers:NeverChangesLane"
        )
    return vehicle, name


def driver_factory(names: dict[str, str], scenario_file: Path, roots=None):
    """The drivers ``names`` gives, or ``DriverLoadError``; None when there are none (the
    simulator's own drive). ``names`` come from the command line only (``--driver``), never from a
    case file; they are imported as pytest would, from the working folder and the folders above
    the scenario inside the project (``roots``)."""
    from ..simulation.named_drivers import drivers_from_names

    if not names:
        return None
    search = [
        Path.cwd(),
        *(folder for folder in scenario_file.resolve().parents if roots is None or roots.allows(folder)),
    ]
    return drivers_from_names(names, search)


def values_flag(text: str) -> dict:
    """A ``--values`` option: a JSON object from parameter names to values."""
    try:
        values = json.loads(text)
    except json.JSONDecodeError as error:
        raise argparse.ArgumentTypeError(f"not JSON ({error.msg}); write e.g. '{{\"start_gap\": 12.5}}'") from None
    if not isinstance(values, dict):
        raise argparse.ArgumentTypeError("give a JSON object of parameter names to values")
    return values


def scenario_command(commands, name: str, help: str) -> argparse.ArgumentParser:
    """A subcommand about one scenario of one file, on a road of some lanes."""
    command = commands.add_parser(name, help=help)
    command.add_argument("file", type=Path, help="an .osc file")
    command.add_argument("--scenario", help="the scenario when the file declares several (default: the first)")
    setting_flags(command, ROAD_FLAGS)
    allow_read(command)
    return command


def allow_read(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--allow-read",
        type=Path,
        action="append",
        default=[],
        metavar="DIR",
        help="a folder outside the project that imports and case files may read from (repeat for several; default: the project's root "
        "and the named file's folder only)",
    )


def read_roots(args: argparse.Namespace, named: Path):
    """The folders a file named on the command line may make the tool read (confinement.ReadRoots)."""
    from ..confinement import ReadRoots

    return ReadRoots.around(named, extra=getattr(args, "allow_read", []))


def executor_flags(command: argparse.ArgumentParser, what: str) -> None:
    """``--jobs`` and ``--ray``: where a campaign's independent jobs (``what``) run."""
    from ..settings import processes

    command.add_argument(
        "--jobs",
        type=flag(processes),
        default=1,
        help=f"{what} at once, each in a process of its own (default 1: in this process, each one's seconds "
        "measured alone); the results are the serial run's",
    )
    command.add_argument(
        "--ray",
        default=None,
        metavar="ADDRESS",
        help=f"run the {what} on a Ray cluster (the [ray] extra): its head's HOST:PORT, 'auto' on one of its "
        "nodes, or 'local' for this machine's CPUs; the results are the serial run's (docs/cluster.md)",
    )


def on_executor(args: argparse.Namespace, work):
    """``work(executor)`` on the executor ``--jobs`` or ``--ray`` asks for, closed after; instead
    the exit code, after saying why, when that executor cannot run."""
    from ..executors import ExecutorError, executor

    try:
        with executor(args.jobs, args.ray) as chosen:
            return work(chosen)
    except ExecutorError as error:
        print(f"roadlogic {args.command}: --{'ray' if args.ray is not None else 'jobs'}: {error}", file=sys.stderr)
        return EXIT_INPUT


def scenario_source(args: argparse.Namespace):
    """Where the scenario a command names is (``evaluation.scenario_source.ScenarioSource``): its
    file, name, lanes, dialect, the folders it may read, and its map."""
    from ..evaluation.scenario_source import ScenarioSource

    return ScenarioSource(
        args.file,
        args.scenario,
        args.setting_lanes,
        args.setting_dialect,
        read_roots(args, args.file),
        args.setting_map,
    )


def load_scenario(args: argparse.Namespace):
    return scenario_source(args).load()


def load_automaton(args: argparse.Namespace):
    from ..automaton import build_automaton

    scenario = load_scenario(args)
    return scenario, build_automaton(scenario)


def reporting_input_errors(args: argparse.Namespace, action):
    """``action()``, or the exit code after printing why the input is unusable (never a traceback)."""
    from ..case import CaseFileError
    from ..dut import NoSuchVehicle
    from ..frontend import OscError
    from ..planning import NoPlanError, UnsatisfiableScenario
    from ..registries.drivers import UnknownDriver
    from ..sampling import UnknownParameter
    from ..simulation.backends import UnknownSimulator
    from ..simulation.named_drivers import DriverLoadError

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


def out_refused(args: argparse.Namespace) -> bool:
    """``--out`` names a folder that a run may not replace: say so before running (True)."""
    from ..artifacts.files import NotAnArtifactFolder, check_replaceable, claimed
    from ..artifacts.writer import ARTIFACT_NAMES

    try:
        check_replaceable(args.out, ARTIFACT_NAMES)
        args.held.enter_context(claimed(args.out))  # held until the command ends: a second run into it is refused
    except NotAnArtifactFolder as error:
        print(f"roadlogic {args.command}: --out: {error}", file=sys.stderr)
        return True
    return False


def print_unasked(plan, automaton, registry, indent: str = "") -> None:
    """The plan's changes that no construct of their vehicle asks for, in the file's lane numbers
    (``registry``'s dialect), under ``roadlogic plan``'s table and ``roadlogic run``'s verdict."""
    from ..evaluation.fidelity import said_unasked

    said = said_unasked(plan, automaton, registry)
    if not said:
        return
    if plan.stats.get("least_action", 1.0) == 0.0:  # planned allowing unasked changes: none did without
        print(
            f"{indent}no plan has every vehicle do only what it is asked; this one has the fewest changes nothing asks for:"
        )
    else:
        print(f"{indent}changes in this plan that nothing asks for:")
    print("\n".join(f"{indent}  {line}" for line in said))


def show(result, out: Path, level: str = "all", drivers: dict[str, str] | None = None) -> int:
    """Write the artifacts of a case at ``level`` (``ARTIFACT_LEVELS``; with them the case file, when
    the scenario is inside the project, so that ``roadlogic replay out/case.json`` runs it again with
    ``drivers``) and print its stages, verdict and files; the exit code of ``run``. A case without
    a simulation prints why on stderr (the constraints that clash, at their places)."""
    from dataclasses import replace

    from ..artifacts.files import replaced_directory
    from ..artifacts.writer import ARTIFACT_NAMES, write_artifacts
    from ..evaluation.coverage import recorded_values
    from ..planning import UnsatisfiableScenario

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
    if not outcome.verdict.accepted and (unfollowed := outcome.simulation.unfollowed()):
        print(f"  {unfollowed}")
    print_unasked(outcome.plan, outcome.automaton, outcome.scenario.registry)
    recorded = recorded_values(outcome.scenario.coverage, case.values, outcome)
    if recorded:
        print("  recorded: " + "; ".join(f"{name} {value}" for name, value in recorded.items()))
    if outcome.dut is not None:
        print(oracle_line(outcome.dut, len(outcome.simulation.replans)))
        if result.message:
            print(f"{result.outcome}: {result.message}")
    if level != "none":
        sys.stdout.flush()
        started = time.perf_counter()
        with replaced_directory(out, ARTIFACT_NAMES) as staging:  # the folder gets the new set whole, or keeps the old
            written = write_artifacts(outcome, staging, level=level, recorded=recorded)
            case_file = write_case_file(replace(case, recorded=recorded), drivers or {}, staging / "case.json")
            paths = {kind: out / path.name for kind, path in {**written, **case_file}.items()}
        result.seconds["artifacts"] = time.perf_counter() - started
        print(f"  {'artifacts':<12} {result.seconds['artifacts']:7.3f} s")
        for kind, path in paths.items():
            print(f"  {kind:<12} {path}")
    if outcome.dut is not None:
        return EXIT_ACCEPTED if result.outcome == PASSED else EXIT_REJECTED
    return EXIT_ACCEPTED if outcome.verdict.accepted else EXIT_REJECTED


def write_case_file(case, drivers: dict[str, str], path: Path) -> dict[str, Path]:
    """The run's case file at ``path`` ({"case": path}), its scenario named relative to the project's
    root (a case file names no absolute path); none outside a project, or when the scenario is
    outside it: ``roadlogic replay`` reads a case's scenario inside the project only."""
    from dataclasses import replace

    from ..case import installed_versions
    from ..confinement import project_root

    root = project_root()
    if root is None:
        return {}
    try:
        relative = Path(case.path).resolve().relative_to(root.resolve())
    except ValueError:
        return {}
    recorded = replace(case, path=relative.as_posix(), drivers=drivers, versions=installed_versions())
    return {"case": recorded.save(path)}


def oracle_line(report, replans: int) -> str:
    """The oracles' values of a vehicle under test in a line (``inf``: no one ahead in its path)."""
    from ..oracles import ORACLES

    values = report.values()
    measured = ", ".join(
        f"{oracle.title} {'inf' if values[oracle.value_key] is None else values[oracle.value_key]} {oracle.unit}"
        for oracle in ORACLES
    )
    return f"vehicle under test {report.vehicle}: {measured}, {replans} replans"
