"""The pytest plugin: every ``.osc`` file is a test module, every scenario in it a test item.

An item is a property: *every* concrete instance of the scenario can be generated and conforms
to it. The refined strategy (default) lets Hypothesis sample the logical parameters, runs the
pipeline (plan, simulate, monitor, with the paper's bounded retries) for each sample, and shrinks
a failure to the simplest values that still fail; the base strategy checks the planner's first N
different plans. Both run through ``runner.Runner``.

A failure shows the values, the monitor's or planner's explanation, the artifacts of the shrunk
case and the command that replays it. A file that does not parse is one collection error with the
front end's message; the other files still run. Collection never runs a solver.

Like Hypothesis's and pytest-xdist's plugins, this module imports nothing heavy: the front end
loads when the first ``.osc`` file is collected, the planner, simulator and plotting when the
first scenario runs. A pytest session without ``.osc`` files pays for none of them.
"""

from __future__ import annotations

import json
import os
import shlex
import time
from dataclasses import replace
from pathlib import Path

import pytest

from .dut import NoSuchVehicle
from .outcomes import (
    DUT_FAILED,
    NO_PLAN,
    NOT_EXERCISED,
    OUTCOMES,
    STAGES,
    Tally,
    key,
    mostly_not_exercised,
    with_a_vehicle_under_test,
)
from .registries.drivers import BUILT_IN as BUILT_IN_DRIVERS
from .registries.oracles import ORACLES
from .settings import BASE, DUT_AUTO, DUT_NONE, OPTIONS, OPTIONS_BY_NAME, REFINED, OptionError, RunSettings
from .settings import dialect as parse_dialect

DEFAULT_ARTIFACTS = "roadlogic-artifacts"
SLOW_ACTORS = 3  # a scenario with more moving vehicles than this is marked slow
MAX_UNASKED_SAID = 10  # unasked changes an item's JUnit property lists
# plugin-only options: where failures are written, and a case to run alone
EXTRA_OPTIONS = (
    ("artifacts", "directory for the artifacts of failing cases", DEFAULT_ARTIFACTS),
    ("replay", "run only the case in this case.json (written for a failure), with this session's drivers", ""),
    ("allow-read", f"folders outside the rootdir that .osc imports may read from, separated by {os.pathsep!r}", ""),
    ("coverage", "write what the session covered of the scenarios' cover()/record() items to this JSON file", ""),
    (
        "coverage-db",
        "add what the session covered to this JSON file of earlier runs' coverage (made when missing), and report "
        "the sum; closure asks only buckets no run has hit",
        "",
    ),
    (
        "coverage-closure",
        "after an item's samples, one case for each cover bucket no case hit and no proof rules out: yes or no",
        "no",
    ),
)


def pytest_addhooks(pluginmanager) -> None:
    from . import hooks

    pluginmanager.add_hookspecs(hooks)


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("roadlogic", "scenario-based testing with OpenSCENARIO DSL files")

    def add(name: str, help: str, default, shown: str = "") -> None:
        ini = f"roadlogic_{name.replace('-', '_')}"
        shown = shown or ("none" if default in (None, "") else default)
        group.addoption(f"--roadlogic-{name}", default=None, help=f"{help} (ini: {ini}; default {shown})")
        parser.addini(ini, help, default="" if default is None else str(default))

    for option in OPTIONS:
        default = None if option.default is None else option.text(option.default)
        add(option.name, option.help, default, option.default_text)
    for name, help, default in EXTRA_OPTIONS:
        add(name, help, default)


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "roadlogic: a scenario collected from an .osc file")
    config.addinivalue_line("markers", "slow: a long scenario or suite; deselect with -m 'not slow'")
    config.stash[SETTINGS] = _settings(config)  # a bad option value stops the session here, once
    closure = _text(config, "coverage-closure")
    if closure not in (None, "", "yes", "no"):
        raise pytest.UsageError(f"roadlogic: --roadlogic-coverage-closure {closure!r}: give yes or no")
    from .artifacts.files import NotAnArtifactFolder, check_writable

    # a folder named by the user is tried for writing; the default only for what stands in its way, so
    # that a session in a read-only checkout without .osc files writes nothing
    named = config.getoption("--roadlogic-artifacts") is not None or bool(
        config.getini("roadlogic_artifacts") != DEFAULT_ARTIFACTS
    )
    try:
        check_writable(Path(config.rootpath) / _text(config, "artifacts"), probe=named)
    except NotAnArtifactFolder as error:
        raise pytest.UsageError(f"roadlogic: --roadlogic-artifacts (ini roadlogic_artifacts): {error}") from None
    replay = _text(config, "replay")
    if replay:
        from .case import Case, CaseFileError

        try:
            Case.load(replay)  # once, here: not as a failure of every item
        except CaseFileError as error:
            raise pytest.UsageError(f"roadlogic: --roadlogic-replay {replay}: {error}") from None
    config.pluginmanager.register(SessionSummary(), "roadlogic-summary")


def _text(config: pytest.Config, name: str) -> str | None:
    value = config.getoption(f"--roadlogic-{name}")
    if value is None:
        value = config.getini(f"roadlogic_{name.replace('-', '_')}")
    return value


def _settings(config: pytest.Config) -> RunSettings:
    """The run settings from options and ini keys, built once per session. ``--roadlogic-examples``
    falls back to the active Hypothesis profile's ``max_examples`` when a profile is chosen."""
    texts = {option.name: _text(config, option.name) for option in OPTIONS}
    if config.getoption("--roadlogic-examples") is None and config.getoption("hypothesis_profile", None) is not None:
        from hypothesis import settings

        texts["examples"] = str(settings().max_examples)
    try:
        settings = RunSettings.from_texts(texts, origin=lambda o: f"--roadlogic-{o.name} (ini {o.ini})")
    except OptionError as error:
        raise pytest.UsageError(f"roadlogic: {error}") from None
    if settings.shards > 1 and settings.strategy == BASE:
        raise pytest.UsageError(
            "roadlogic: --roadlogic-shards (ini roadlogic_shards): shards split the samples of the refined strategy; "
            "the base strategy's plans come one after another from one planner. Give --roadlogic-shards 1 or "
            "--roadlogic-strategy refined"
        )
    if settings.shards > settings.examples:
        # a shard with no sample of its own would fail with Hypothesis's max_examples=0
        raise pytest.UsageError(
            f"roadlogic: --roadlogic-shards (ini roadlogic_shards): {settings.shards} shards share "
            f"{settings.examples} examples, and each shard draws at least one; give at most {settings.examples} shards, "
            "or more examples with --roadlogic-examples"
        )
    if settings.dut_driver not in BUILT_IN_DRIVERS:
        # a package's driver: loaded once here, so that one that cannot load stops the session with why
        from .registries.drivers import UnknownDriver, reference_driver

        try:
            reference_driver(settings.dut_driver)
        except UnknownDriver as error:
            raise pytest.UsageError(f"roadlogic: --roadlogic-dut-driver (ini roadlogic_dut_driver): {error}") from None
    from .simulation.backends import available  # names only: no backend is imported

    if settings.simulator not in available():
        raise pytest.UsageError(
            f"roadlogic: --roadlogic-simulator (ini roadlogic_simulator): no simulator named {settings.simulator!r}; available: {', '.join(available())}"
        )
    return settings


SETTINGS = pytest.StashKey[RunSettings]()


def pytest_collect_file(file_path: Path, parent: pytest.Collector):
    if file_path.suffix == ".osc":
        from .confinement import regular_file_problem

        problem = regular_file_problem(file_path)
        if problem is not None:  # a FIFO named x.osc would be read forever
            parent.warn(OscWarning(f"{file_path}: skipped: {problem}"))
            return None
        return OscFile.from_parent(parent, path=file_path)
    return None


def read_roots(config: pytest.Config, path: Path):
    """Where an .osc file collected in this session may import from: the rootdir, the file's
    folder and the folders ``--roadlogic-allow-read`` names (confinement.ReadRoots)."""
    from .confinement import ReadRoots

    extra = [
        Path(config.rootpath) / folder.strip()
        for folder in (_text(config, "allow-read") or "").split(os.pathsep)
        if folder.strip()
    ]
    return ReadRoots.of(config.rootpath, Path(path).parent, extra=extra)


class OscWarning(pytest.PytestWarning):
    """A checker warning about an .osc file (an unused parameter, an idle actor)."""


ORACLE_OPTIONS = tuple(oracle.option for oracle in ORACLES)  # what pytest_roadlogic_oracles may set per scenario


class OscFile(pytest.File):
    def _oracles(self, scenario, settings: RunSettings) -> RunSettings:
        """``settings`` with the thresholds a ``pytest_roadlogic_oracles`` hook gives ``scenario``."""
        given = self.ihook.pytest_roadlogic_oracles(config=self.config, scenario=scenario)
        if not given:
            return settings
        values = {}
        for name, value in dict(given).items():
            if name not in ORACLE_OPTIONS:
                raise self.CollectError(
                    f"{self.path}: pytest_roadlogic_oracles gave {name!r} for scenario {scenario.name}; "
                    f"give {', '.join(ORACLE_OPTIONS)}"
                )
            option = OPTIONS_BY_NAME[name]
            try:
                values[option.field] = option.parse(str(value))
            except OptionError as error:
                raise self.CollectError(
                    f"{self.path}: pytest_roadlogic_oracles, {name} of scenario {scenario.name}: {error}"
                ) from None
        return replace(settings, **values)

    def collect(self):
        from .frontend import OscError, check_file

        settings = self.config.stash[SETTINGS]
        try:
            # ihook: the conftest.py files of this file's folders only (config.hook would ask every conftest
            # collected so far: a CARLA folder's hook read the files collected after it as CARLA's)
            dialect = self.ihook.pytest_roadlogic_dialect(config=self.config, path=self.path)
            if dialect is not None and dialect != settings.dialect:
                settings = replace(settings, dialect=parse_dialect(dialect))
            road_map = settings.road_map and Path(self.config.rootpath, settings.road_map)
            checked = check_file(
                self.path,
                settings.lanes,
                dialect=settings.dialect,
                roots=read_roots(self.config, self.path),
                road_map=road_map,
            )
            checked.raise_for_errors()
        except OscError as error:
            # A broken .osc file is reported, but must not stop the other scenarios from running
            # (pytest interrupts the session on collection errors otherwise). Errors in other
            # kinds of files keep pytest's rule.
            self.config.option.continue_on_collection_errors = True
            raise self.CollectError(error.report()) from None
        except OptionError as error:
            raise self.CollectError(f"{self.path}: pytest_roadlogic_dialect: {error}") from None
        except Exception as error:  # a bug of ours must not stop the other files either
            self.config.option.continue_on_collection_errors = True
            raise self.CollectError(
                f"{self.path}:1:1: error: internal error while checking ({type(error).__name__}: {error}); please report it"
            ) from None
        for warning in checked.warnings:
            self.warn(OscWarning(OscError([warning], sources=checked.sources).report()))
        from .sampling import Shard

        shards = [Shard(index, settings.shards) for index in range(settings.shards)]
        for scenario in checked.scenarios:
            if not scenario.runnable:
                continue
            judged = self._oracles(scenario, settings)
            for shard in shards:
                name = scenario.name if shard.count == 1 else f"{scenario.name}[{shard.index + 1}of{shard.count}]"
                item = ScenarioItem.from_parent(self, name=name, scenario=scenario, settings=judged, shard=shard)
                item.add_marker("roadlogic")
                if sum(not actor.stationary for actor in scenario.scenario.actors) > SLOW_ACTORS:
                    item.add_marker("slow")  # planning grows with the vehicles: select or deselect with -m
                yield item


class ScenarioFailed(Exception):
    """One concrete case of the scenario failed; carries its result. The artifacts are written
    once, for the final (shrunk) case."""

    def __init__(self, result, report: str = "", summary: str = "") -> None:
        super().__init__(report or result.message)
        self.result = result
        self.summary = summary  # what the item's failure says before the case (an item that tested nothing)


class ScenarioItem(pytest.Item):
    def __init__(self, *, scenario, settings: RunSettings, shard=None, **kwargs) -> None:
        from .sampling import Shard

        super().__init__(**kwargs)
        self.scenario = scenario  # a CheckedScenario
        self.settings = settings  # the session's, with this file's dialect
        self.shard = shard or Shard()  # which of the scenario's samples this item draws (--roadlogic-shards)
        self.tally = Tally()
        self.drivers = None  # the hook's drivers, recording which class drove which vehicle (set in runtest)
        self.failure_artifacts: tuple[dict, list[str]] | None = (
            None  # (artifact paths, replay commands) of the reported case
        )
        self.dut_reports: list = []  # the oracles' verdicts of the cases run (a vehicle under test drove)
        self.not_exercised = None  # the last case that was not exercised (a runner.CaseResult)
        self.unasked_cases = 0  # cases whose plan needed changes nothing asks for
        self.unasked_said: list[str] = []  # the last such plan's changes, as a user reads them
        self.coverage = None  # what the cases covered of its cover/record items (evaluation.coverage)
        self.proofs_asked: set[tuple[str, str]] = set()  # (cover item, bucket) asked of the planner

    # ---------------------------------------------------------------- running

    def runtest(self) -> None:
        from .case import Case, CaseFileError
        from .runner import Runner

        settings = self.settings
        self.user_properties += [("strategy", settings.strategy), ("seed", settings.seed)]
        if self.scenario.coverage:
            from .evaluation.coverage import ScenarioCoverage
            from .evaluation.coverage_db import fingerprint

            self.coverage = ScenarioCoverage.of(
                f"{self.nodeid.split('::')[0]}::{self.scenario.name}",
                self.scenario.coverage,
                fingerprint(self.scenario),
            )
        if self.shard.count > 1:
            self.user_properties.append(("shard", f"{self.shard.index + 1}/{self.shard.count}"))
        self.drivers = self._drivers()
        replay, case = _text(self.config, "replay"), None
        if replay:
            try:
                case = Case.load(replay).within(settings)
            except CaseFileError as error:
                raise pytest.UsageError(f"roadlogic: --roadlogic-replay {replay}: {error}") from None
        # a replayed case runs with its own settings (who is under test, with which reference driver,
        # its thresholds, tries, ...), as roadlogic replay runs it: the session's would replay a
        # defective vehicle under test's failure with the default driver, and pass
        runner = Runner(
            self.scenario,
            case.settings if case is not None else settings,
            self.drivers,
            self._simulator(),
            explain=settings.strategy == BASE,
        )
        missing = None
        try:
            if case is not None:
                self._replay(runner, case)
            elif settings.strategy == BASE:
                for result in runner.base():
                    self._count(result)
            else:
                sampling_seed = self.config.getoption("hypothesis_seed", None)
                if sampling_seed is not None:
                    sampling_seed = (
                        int(sampling_seed) if sampling_seed.lstrip("-").isdigit() else sampling_seed
                    )  # as Hypothesis reads it
                    self.user_properties.append(("hypothesis_seed", sampling_seed))
                with _hypothesis_statistics(self):
                    runner.refined(
                        self._count,
                        key=self.nodeid.encode(),
                        discarded=self._discard,
                        set_aside=lambda result: self.tally.aside(result.seconds),
                        sampling_seed=sampling_seed,
                        shard=self.shard,
                    )
                if self.coverage is not None and _text(self.config, "coverage-closure") == "yes":
                    self._close_coverage(runner)
            self._fail_if_mostly_not_exercised()
        except ScenarioFailed as failure:
            self._report_failure(runner, failure.result, failure.summary)
        except ExceptionGroup as group:
            # Hypothesis's FlakyFailure: a case failed, and not again when Hypothesis ran its values
            # once more (a time limit is wall-clock time, on a machine others share): the failure
            # is reported as it happened, saying so
            failed = _first_failure(group)
            if failed is None:
                raise
            again = "it did not fail again when rerun at the same values (a time limit counts wall-clock time)"
            self._report_failure(runner, failed.result, "; ".join(filter(None, (failed.summary, again))))
        except NoSuchVehicle as error:
            missing = error  # failed below, outside the handler: not as a chained "During handling"
        finally:
            self.user_properties += [
                ("examples", self.tally.cases),
                ("discarded", self.tally.discarded),
                ("set_aside", self.tally.set_aside),
            ]
            self.user_properties += [(key(outcome), self.tally.outcomes[outcome]) for outcome in OUTCOMES]
            self.user_properties += [(f"seconds_{stage}", round(self.tally.seconds[stage], 3)) for stage in STAGES]
            self.user_properties += _oracle_properties(self.dut_reports)
            self.user_properties.append(("unasked", self.unasked_cases))
            if self.coverage is not None:
                self._prove_unreachable()
                self.user_properties.append(("coverage", json.dumps(self.coverage.to_json())))
                # each record() item's values over the item's cases, in the order they ran
                self.user_properties += [
                    (f"record_{name}", ", ".join(tally.recorded))
                    for name, tally in self.coverage.items.items()
                    if tally.kind == "record"
                ]
            if self.unasked_said:
                self.user_properties.append(("unasked_changes", "; ".join(self.unasked_said[:MAX_UNASKED_SAID])))
        if missing is not None:
            pytest.fail(f"roadlogic: --roadlogic-dut: {missing}", pytrace=False)

    def _prove_unreachable(self) -> None:
        """Mark the cover buckets no case hit that no case can reach (``evaluation.reach``), with
        why; each bucket is asked once."""
        from .evaluation.reach import open_questions, unreachable

        for item, missed in open_questions(self.scenario, self.coverage):
            missed = [label for label in missed if (item.name, label) not in self.proofs_asked]
            self.proofs_asked.update((item.name, label) for label in missed)
            if missed:
                tally = self.coverage.items[item.name]
                tally.unreachable.update(unreachable(self.scenario, item, missed, self.settings, self.settings.seed))

    def _close_coverage(self, runner) -> None:
        """Coverage closure (``--roadlogic-coverage-closure yes``): the buckets no sample hit are
        first proved unreachable where they are, then each other one is asked for by one case with
        its parameters inside it (``evaluation.closure``), run and counted as any sample is."""
        from .evaluation.closure import closing_values, first_with_plan
        from .evaluation.coverage import merged
        from .evaluation.coverage_db import earlier

        self._prove_unreachable()
        cases = 0
        database = _text(self.config, "coverage-db")
        before = earlier(Path(database), self.coverage) if database else None
        # a bucket an earlier run of the database hit is not asked again
        covered = merged([before, self.coverage])[0] if before is not None else self.coverage
        for _, _, tries in closing_values(self.scenario, covered):
            result, aside = first_with_plan(
                tries, lambda values: runner.run_case(runner.case(strategy=REFINED, values=values))
            )
            for without_plan in aside:
                self.tally.aside(without_plan.seconds)
            if result is not None:
                cases += 1
                self._count(result)
        self.user_properties.append(("closure_cases", cases))

    def _drivers(self):
        from .simulation.named_drivers import RecordingDrivers

        hook = self.ihook.pytest_roadlogic_driver  # this item's folders' conftest.py files, as for the dialect
        return RecordingDrivers(lambda vehicle: hook(config=self.config, scenario=self.scenario, vehicle=vehicle))

    def _simulator(self):
        """The backend a ``pytest_roadlogic_simulator`` hook gives, else None (the option's)."""
        return self.ihook.pytest_roadlogic_simulator(config=self.config, scenario=self.scenario)

    def _count(self, result) -> None:
        """Count a case; a failed one ends the item (and, refined, starts the shrinking)."""
        self.tally.add(result.outcome, result.seconds)
        if self.coverage is not None:
            self.coverage.add(self.scenario.coverage, result.case.values, result.outcome, result.run)
        if result.run is not None and result.run.dut is not None:
            self.dut_reports.append(result.run.dut)
        if result.run is not None:
            from .evaluation.fidelity import said_unasked

            said = said_unasked(result.run.plan, result.run.automaton, result.run.scenario.registry)
            if said:  # no plan had only asked changes: the report says who did what
                self.unasked_cases += 1
                self.unasked_said = said
        if result.outcome == NOT_EXERCISED:
            self.not_exercised = result
        if result.failed:
            raise ScenarioFailed(result)

    def _fail_if_mostly_not_exercised(self) -> None:
        """An item whose cases mostly did not happen around the vehicle under test tested nothing: it
        fails, reported as a failing case is (the last such case's values, artifacts and replay)."""
        outcomes = self.tally.outcomes
        if mostly_not_exercised(outcomes):
            raise ScenarioFailed(
                self.not_exercised,
                summary=f"scenario {self.scenario.name}: {outcomes[NOT_EXERCISED]} of "
                f"{with_a_vehicle_under_test(outcomes)} cases were not exercised (the scenario did not happen "
                "around the vehicle under test, so they tested nothing); the last:",
            )

    def _discard(self, result) -> None:
        """A sample without a plan, set aside (``--roadlogic-no-plan discard``): counted, not failed."""
        self.tally.add(result.outcome, result.seconds)
        self.tally.discarded += 1

    def _replay(self, runner, case) -> None:
        """The one case of a case file, when it is this item's (other items are skipped), with this
        session's drivers (``runner`` runs with the case's settings): a run with other drivers than
        the case's is refused, not reported."""
        from .sampling import UnknownParameter

        if not _replays(self, case):
            pytest.skip(
                f"--roadlogic-replay runs {case.path}::{case.scenario} only"
                + (", in the shard that holds its values" if self.shard.count > 1 else "")
            )
        try:
            result = runner.run_case(case)
        except UnknownParameter as error:  # a case file's values are data: a located message, not a traceback
            refused = f"--roadlogic-replay {_text(self.config, 'replay')}: {error}"
        else:
            refused = ""
        if refused:
            pytest.fail(refused, pytrace=False)
        if result.run is not None and self.drivers.names != case.drivers:
            pytest.fail(
                f"--roadlogic-replay: the case was found with the drivers {_drivers_text(case.drivers)}, "
                f"this session drives with {_drivers_text(self.drivers.names)}; "
                "replay it from the session (conftest.py files) that found it",
                pytrace=False,
            )
        self._count(result)

    # ---------------------------------------------------------------- reporting

    def _report_failure(self, runner, result, summary: str = "") -> None:
        from .artifacts.writer import write_artifacts
        from .case import installed_versions
        from .confinement import unique_name
        from .evaluation.coverage import recorded_values
        from .frontend.semantics.logical import describe_values

        if result.outcome == NO_PLAN:
            result = runner.explained(result)  # the search did not ask why; ask for the reported case
        case = replace(
            result.case,
            path=self._relative(result.case.path),
            drivers=dict(self.drivers.names),
            versions=installed_versions(),
            recorded=recorded_values(self.scenario.coverage, result.case.values, result.run),
        )
        result = replace(result, case=case)
        why = result.message  # for a clash, the report with the constraints at their lines (runner._failure)
        directory = Path(self.config.rootpath) / _text(self.config, "artifacts") / unique_name(self.nodeid)
        paths: dict[str, Path] = {}
        if result.run is not None:
            started = time.perf_counter()
            paths = write_artifacts(result.run, directory, recorded=case.recorded)
            self.tally.seconds["artifacts"] += time.perf_counter() - started
        paths["case"] = case.save(directory / "case.json")
        where = "at" if case.strategy == REFINED else f"at instance {case.instance} of"
        if result.at_no_values:
            where = "at any values; for example at"
        shard = f", {self.shard}" if self.shard.count > 1 else ""
        lines = [summary] if summary else []
        lines += [
            f"scenario {self.scenario.name}: {result.kind} ({result.outcome}) {where} these values (seed {case.seed}{self._sampled_with()}{shard}, {self.tally.cases} examples run):"
        ]
        if case.values:
            for line in describe_values(self.scenario.parameters, case.values):
                alone = result.culprit is not None and line.startswith(f"{result.culprit} = ")
                lines.append(
                    f"  {line}" + (": no concrete scenario has this value, whatever the others" if alone else "")
                )
        else:
            lines.append("  (no logical parameters: the planner chose every value)")
        if case.recorded:
            lines.append("recorded: " + "; ".join(f"{name} {value}" for name, value in case.recorded.items()))
        if result.outcome == DUT_FAILED:
            lines.append(f"the vehicle under test failed after {result.run.tries} plans tried: {why}")
        elif result.run is not None:
            lines.append(f"after {result.run.tries} plans tried, the last simulation was {why}")
        else:
            lines.append(why)
        lines += ["artifacts:", *(f"  {kind}: {path}" for kind, path in paths.items())]
        # shell-quoted: a file named a'$(touch P)'b.osc must not run a command when the line is pasted
        replay = [
            f"{shlex.join(['pytest', self.nodeid, '--roadlogic-replay', str(paths['case']), *self._shard_option()])}   (with this session's drivers)",
            case.command(paths["case"]),
            case.command(),
        ]
        lines.append(f"replay: {replay[0]}")
        lines += [f"    or: {command}" for command in replay[1:]]
        self.failure_artifacts = (paths, replay)
        self.user_properties.append(("verdict", result.outcome))
        self.user_properties.append(("failure_kind", result.kind))
        self.user_properties.append(("failing_values", json.dumps(case.values, sort_keys=True)))
        self.user_properties.append(("culprit", result.culprit or ""))
        self.user_properties.append(("explanation", why.splitlines()[0] if why else ""))
        raise ScenarioFailed(result, "\n".join(lines))

    def _shard_option(self) -> list[str]:
        """What the replay command needs for this item's node id to exist."""
        return ["--roadlogic-shards", str(self.shard.count)] if self.shard.count > 1 else []

    def _sampled_with(self) -> str:
        seed = self.config.getoption("hypothesis_seed", None)
        return (
            f", samples drawn with --hypothesis-seed {seed}"
            if seed is not None and self.settings.strategy == REFINED
            else ""
        )

    def _relative(self, path: str) -> str:
        """``path`` relative to the rootdir, where it is under it: a case file that replays on another checkout."""
        try:
            return Path(path).resolve().relative_to(Path(self.config.rootpath).resolve()).as_posix()
        except ValueError:
            return path

    def repr_failure(self, excinfo, style=None):
        from .frontend import OscError

        if isinstance(excinfo.value, (ScenarioFailed, OscError)):
            return str(excinfo.value)
        return super().repr_failure(excinfo, style=style)

    def reportinfo(self):
        return self.path, self.scenario.scenario.location.line - 1, f"scenario {self.scenario.name}"


def _first_failure(group: BaseExceptionGroup) -> ScenarioFailed | None:
    """The first ``ScenarioFailed`` inside ``group`` (nested groups too), or None."""
    for error in group.exceptions:
        if isinstance(error, ScenarioFailed):
            return error
        if isinstance(error, BaseExceptionGroup) and (found := _first_failure(error)) is not None:
            return found
    return None


def _replays(item: ScenarioItem, case) -> bool:
    """Whether ``case`` is a case of ``item``: its file (relative to the rootdir) and its scenario."""
    return (
        (Path(item.config.rootpath) / case.path).resolve() == item.path.resolve()
        and case.scenario == item.scenario.name
        and (item.shard.count == 1 or item.shard.holds(case.values or {}))
    )


def pytest_collection_modifyitems(session: pytest.Session, config: pytest.Config, items: list) -> None:
    """With ``--roadlogic-replay``, a case that no collected item runs is a usage error, not
    every item skipped and a pass (exit 0). A vehicle under test that no collected scenario has is
    a usage error too (``--roadlogic-dut ghost``): each item would fail alike."""
    settings = config.stash.get(SETTINGS, None)
    scenarios = [item for item in items if isinstance(item, ScenarioItem)]
    if settings is not None and settings.dut not in (DUT_AUTO, DUT_NONE) and scenarios:
        if not any(settings.dut in {actor.name for actor in item.scenario.scenario.actors} for item in scenarios):
            raise pytest.UsageError(
                f"roadlogic: --roadlogic-dut (ini roadlogic_dut): no collected scenario has a vehicle {settings.dut!r}; "
                "give a vehicle of the scenarios, or auto (each scenario's dut) or none"
            )
    replay = _text(config, "replay")
    if not replay:
        return
    from .case import Case

    case = Case.load(replay)
    if not any(isinstance(item, ScenarioItem) and _replays(item, case) for item in items):
        raise pytest.UsageError(
            f"roadlogic: --roadlogic-replay {replay}: no collected scenario is {case.path}::{case.scenario}; "
            f"give pytest the folder or file that holds it (paths are relative to the rootdir {config.rootpath})"
        )


def _hypothesis_statistics(item: pytest.Item):
    """Collect the refined search's statistics where Hypothesis's pytest plugin looks for them
    (``item.hypothesis_statistics``), as it does for ``@given`` tests, which these items are not,
    so that ``--hypothesis-show-statistics`` prints them."""
    import contextlib

    try:
        from hypothesis.statistics import collector, describe_statistics
    except ImportError:  # a Hypothesis without the statistics collector: no section, nothing else lost
        return contextlib.nullcontext()

    def note(statistics) -> None:
        statistics["nodeid"] = item.nodeid
        item.hypothesis_statistics = describe_statistics(statistics)

    return collector.with_value(note)


def _oracle_properties(reports: list) -> list[tuple[str, object]]:
    """JUnit properties of the vehicle under test over an item's cases: each oracle's value
    nearest to failing (``dut_<value key>``; none without a vehicle under test)."""
    if not reports:
        return []
    values = [report.values() for report in reports]

    def worst(oracle) -> object:
        found = [v[oracle.value_key] for v in values if v[oracle.value_key] is not None]
        return oracle.worst(found) if found else "inf"

    return [("vehicle_under_test", reports[0].vehicle)] + [
        (f"dut_{oracle.value_key}", worst(oracle)) for oracle in ORACLES
    ]


def _drivers_text(names: dict[str, str]) -> str:
    return ", ".join(f"{vehicle}: {name}" for vehicle, name in sorted(names.items())) or "the simulator's own only"


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call):
    """With pytest-html, a failing scenario's report carries its plot, animation and replay commands."""
    outcome = yield
    report = outcome.get_result()
    failure = getattr(item, "failure_artifacts", None)
    if report.when == "call" and failure is not None and item.config.pluginmanager.hasplugin("html"):
        from .artifacts.html_report import report_extras

        report.extras = [*getattr(report, "extras", []), *report_extras(*failure)]


class SessionSummary:
    """Totals over every scenario item, also from pytest-xdist workers (their reports carry the counts)."""

    def __init__(self) -> None:
        self.items = 0
        self.counts: dict[str, float] = {}
        self.test_points: list = []  # dut.catalogue.TestPoint of each item with a vehicle under test
        self.coverage: list = []  # evaluation.coverage.ScenarioCoverage of each item with cover/record items

    @pytest.hookimpl
    def pytest_runtest_logreport(self, report) -> None:
        if report.when != "call":
            return
        properties = dict(report.user_properties)
        if "strategy" not in properties:
            return
        self.items += 1
        from .dut.catalogue import point_from

        point = point_from(report.nodeid, properties, report.passed, "" if report.passed else str(report.longrepr))
        if point is not None:
            self.test_points.append(point)
        if "coverage" in properties:
            from .evaluation.coverage import ScenarioCoverage

            self.coverage.append(ScenarioCoverage.from_json(json.loads(properties["coverage"])))
        for name, value in properties.items():
            if isinstance(value, (int, float)) and not isinstance(value, bool) and name != "seed":
                self.counts[name] = self.counts.get(name, 0) + value

    @pytest.hookimpl
    def pytest_terminal_summary(self, terminalreporter, config) -> None:
        if not self.items:
            return
        self._coverage_summary(terminalreporter, config)
        c = self.counts
        outcomes = ", ".join(f"{c.get(key(o), 0)} {o}" for o in OUTCOMES)
        seconds = ", ".join(f"{stage} {c.get(f'seconds_{stage}', 0):.1f} s" for stage in STAGES)
        terminalreporter.write_sep("-", "roadlogic")
        discarded = (
            f" ({c['discarded']} samples without a plan discarded: --roadlogic-no-plan discard)"
            if c.get("discarded")
            else ""
        )
        terminalreporter.write_line(f"{self.items} scenarios, {c.get('examples', 0)} examples: {outcomes}{discarded}")
        if c.get("set_aside"):
            terminalreporter.write_line(
                f"{c['set_aside']} samples set aside: each of their values has plans within the planner's margins and limits, but not together"
            )
        if c.get("unasked"):
            terminalreporter.write_line(
                f"{c['unasked']} examples needed changes nothing in their scenario asks for (no plan had only asked "
                "ones): the item's JUnit property unasked_changes says which vehicle did what"
            )
        terminalreporter.write_line(f"time per stage: {seconds}")
        if self.test_points:
            from .dut.catalogue import grade, text_table

            terminalreporter.write_sep("-", "vehicle under test")
            for line in text_table(self.test_points):
                terminalreporter.write_line(line)
            terminalreporter.write_line(grade(self.test_points))

    def _coverage_summary(self, terminalreporter, config) -> None:
        """The cover/record items' report, merged over items and workers; written to the
        ``--roadlogic-coverage`` file when one is named (a file that cannot be written is said, not raised)."""
        if not self.coverage:
            return
        from .evaluation.coverage import merged, text_lines, write_json
        from .evaluation.coverage_db import database_lines

        coverages = merged(self.coverage)
        terminalreporter.write_sep("-", "roadlogic coverage")
        for line in text_lines(coverages):
            terminalreporter.write_line(line)
        if self.counts.get("closure_cases"):
            terminalreporter.write_line(
                f"closure: {self.counts['closure_cases']} cases asked for buckets the samples had not hit"
            )
        path = _text(config, "coverage")
        if path:
            try:
                write_json(coverages, Path(path))
            except OSError as error:
                terminalreporter.write_line(
                    f"roadlogic: --roadlogic-coverage {path}: cannot write it ({error.strerror})"
                )
            else:
                terminalreporter.write_line(f"coverage written to {path}")
        database = _text(config, "coverage-db")
        if database:
            for line in database_lines(Path(database), coverages, "--roadlogic-coverage-db")[0]:
                terminalreporter.write_line(line)

    @pytest.hookimpl(optionalhook=True)
    def pytest_html_results_summary(self, prefix, summary, postfix) -> None:
        """With pytest-html, the vehicle under test's test points and grade head the report, and
        the coverage picture follows them."""
        if self.test_points:
            from .dut.catalogue import html_table

            prefix.append(html_table(self.test_points))
        if self.coverage:
            from .evaluation.coverage import merged
            from .evaluation.coverage_html import html_summary

            prefix.append(html_summary(merged(self.coverage)))
