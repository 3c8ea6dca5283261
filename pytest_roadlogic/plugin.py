"""The pytest plugin: every ``.osc`` file is a test module, every scenario in it a test item.

An item is a property: *every* concrete instance of the scenario can be generated and conforms
to it. The refined strategy (default) lets Hypothesis sample the logical parameters, runs the
pipeline (plan, simulate, monitor, with the paper's bounded retries) for each sample, feeds the
monitor's robustness to ``hypothesis.target`` so the search drifts toward near-failures, and
shrinks a failure to the simplest values that still fail. The base strategy leaves the
parameters to the planner and checks its first N different plans.

A failure shows the values, the monitor's or planner's explanation, the artifacts of the shrunk
case and the command that replays it. A file that does not parse is one collection error with the
front end's message; the other files still run. Collection never runs a solver.
"""

from __future__ import annotations

import json
import re
import time
from contextlib import contextmanager
from dataclasses import replace
from argparse import ArgumentTypeError
from collections import Counter
from pathlib import Path

import pytest

from .case import BASE, REFINED, Case
from .cli import lane_count
from .frontend import OscError, check_file
from .planning import NoPlanError, PlanningTimeout, UnsatisfiableScenario

DEFAULT_SEED = 1
DEFAULT_ARTIFACTS = "roadlogic-artifacts"
DEFAULT_EXAMPLES = 10
SLOW_ACTORS = 3  # a scenario with more moving vehicles than this is marked slow
STAGES = ("automaton", "planning", "simulation", "monitoring", "artifacts")


def pytest_addhooks(pluginmanager) -> None:
    from . import hooks

    pluginmanager.add_hookspecs(hooks)


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("roadlogic", "scenario-based testing with OpenSCENARIO DSL files")

    def option(name: str, help: str, default: str, **kwargs) -> None:
        ini = f"roadlogic_{name.replace('-', '_')}"
        group.addoption(f"--roadlogic-{name}", default=None, help=f"{help} (ini: {ini}; default {default or 'see README'})", **kwargs)
        parser.addini(ini, help, default=default)

    option("strategy", "refined: sample the logical parameters with Hypothesis; base: the planner's first N plans", REFINED, choices=(REFINED, BASE))
    option("examples", "samples (refined) or plans (base) per scenario; default the Hypothesis profile's max_examples when --hypothesis-profile is given, else", str(DEFAULT_EXAMPLES))
    option("seed", "seed fixing sampling, planning and simulation", str(DEFAULT_SEED))
    option("artifacts", "directory for the artifacts of failing cases", DEFAULT_ARTIFACTS)
    option("lanes", "lanes of the road for every scenario (default: each scenario's own)", "")
    option("tries", "plans to try per case when the monitor rejects the simulation", "5")
    option("replay", "run only the case in this case.json (written for a failure), with this session's drivers", "")
    option("horizon", "planning horizon limit in steps", "25")
    option("plan-timeout", "seconds one planning may take", "60")
    option("sim-timeout", "seconds (wall clock) one simulation may take", "120")


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "roadlogic: a scenario collected from an .osc file")
    config.addinivalue_line("markers", "slow: a long scenario or suite; deselect with -m 'not slow'")
    _option(config, "lanes", _whole_or_none)  # a bad lanes value stops the session before collection
    config.pluginmanager.register(SessionSummary(), "roadlogic-summary")


def pytest_collect_file(file_path: Path, parent: pytest.Collector):
    if file_path.suffix == ".osc":
        return OscFile.from_parent(parent, path=file_path)
    return None


def _option(config: pytest.Config, name: str, cast=str):
    value = config.getoption(f"--roadlogic-{name}")
    return cast(value if value is not None else config.getini(f"roadlogic_{name.replace('-', '_')}"))


def _whole_or_none(text) -> int | None:
    """A lanes option or ini value: a count from 1 up, or nothing (the scenario's own road)."""
    if not str(text).strip():
        return None
    try:
        return lane_count(str(text))
    except ArgumentTypeError as error:
        raise pytest.UsageError(f"roadlogic lanes: {error}") from None


class OscWarning(pytest.PytestWarning):
    """A checker warning about an .osc file (an unused parameter, an idle actor)."""


class OscFile(pytest.File):
    def collect(self):
        try:
            checked = check_file(self.path, _option(self.config, "lanes", _whole_or_none))
            checked.raise_for_errors()
        except OscError as error:
            # A broken .osc file is reported, but must not stop the other scenarios from running
            # (pytest interrupts the session on collection errors otherwise). Errors in other
            # kinds of files keep pytest's rule.
            self.config.option.continue_on_collection_errors = True
            raise self.CollectError(error.report()) from None
        for warning in checked.warnings:
            self.warn(OscWarning(OscError([warning], sources=checked.sources).report()))
        for scenario in checked.scenarios:
            if scenario.runnable:
                item = ScenarioItem.from_parent(self, name=scenario.name, scenario=scenario)
                item.add_marker("roadlogic")
                if sum(not actor.stationary for actor in scenario.scenario.actors) > SLOW_ACTORS:
                    item.add_marker("slow")  # planning grows with the vehicles: select or deselect with -m
                yield item


class ScenarioFailed(Exception):
    """One concrete case of the scenario failed: rejected by the monitor, or without a plan or in time.

    Carries what the report needs; the artifacts are written once, for the final (shrunk) case.
    """

    def __init__(self, case: Case, why: str, outcome=None, kind: str = "rejected", explain: bool = False) -> None:
        super().__init__(why)
        self.case, self.why, self.outcome, self.kind = case, why, outcome, kind
        self.explain = explain  # the planner was not asked why there is no plan: ask for the report


class ScenarioItem(pytest.Item):
    def __init__(self, *, scenario, **kwargs) -> None:
        super().__init__(**kwargs)
        self.scenario = scenario  # a CheckedScenario
        self.counts: Counter[str] = Counter()
        self.seconds: Counter[str] = Counter()

    # ---------------------------------------------------------------- running

    def runtest(self) -> None:
        config = self.config
        strategy = _option(config, "strategy")
        self.user_properties += [("strategy", strategy), ("seed", _option(config, "seed", int))]
        try:
            if _option(config, "replay"):
                self._replay(Case.load(_option(config, "replay")))
            elif strategy == BASE:
                self._base()
            else:
                self._refined()
        except ScenarioFailed as failure:
            self._report_failure(failure)
        finally:
            self.user_properties += [(k, self.counts[k]) for k in ("examples", "accepted", "rejected", "no_plan", "timed_out")]
            self.user_properties += [(f"seconds_{stage}", round(self.seconds[stage], 3)) for stage in STAGES]

    def _case(self, **kwargs) -> Case:
        config = self.config
        return Case(
            path=str(self.path), scenario=self.scenario.name, seed=_option(config, "seed", int),
            lanes=_option(config, "lanes", _whole_or_none), max_horizon=_option(config, "horizon", int),
            planning_time_limit=_option(config, "plan-timeout", float), simulation_time_limit=_option(config, "sim-timeout", float),
            max_tries=_option(config, "tries", int), **kwargs,
        )

    def _drivers(self):
        hook = self.config.hook.pytest_roadlogic_driver
        return lambda vehicle: hook(config=self.config, scenario=self.scenario, vehicle=vehicle)

    def _examples(self) -> int:
        value = self.config.getoption("--roadlogic-examples")
        if value is None and self.config.getoption("hypothesis_profile", None) is not None:
            from hypothesis import settings

            return settings().max_examples
        return int(value if value is not None else self.config.getini("roadlogic_examples"))

    def _refined(self) -> None:
        import hypothesis
        from hypothesis import HealthCheck

        from .pipeline import run_scenario
        from .sampling import strategy

        drivers = self._drivers()

        def example(values):
            case = self._case(values=values)
            self.counts["examples"] += 1
            with self._planning_failures(case, explain_later=True):
                outcome = run_scenario(
                    self.scenario, seed=case.seed, settings=replace(case.settings(), explain_unsatisfiable=False), max_tries=case.max_tries,
                    drivers=drivers, values=values, simulation_time_limit=case.simulation_time_limit,
                )
            self._count(outcome)
            hypothesis.target(-outcome.verdict.robustness, label="closeness to failure (-robustness)")
            if not outcome.verdict.accepted:
                raise ScenarioFailed(case, outcome.verdict.explain(), outcome)

        # one database entry per item, though every item runs this same function (the attribute
        # Hypothesis's own pytest integration sets for parametrized tests)
        example._hypothesis_internal_add_digest = self.nodeid.encode()
        profile = hypothesis.settings()
        settings = hypothesis.settings(
            # one failure per item: the report is about its shrunk case, whatever kind it is
            profile, max_examples=self._examples(), deadline=None, print_blob=False, report_multiple_bugs=False,
            suppress_health_check=[*profile.suppress_health_check, HealthCheck.too_slow, HealthCheck.filter_too_much],
        )
        test = hypothesis.seed(_option(self.config, "seed", int))(settings(hypothesis.given(strategy(self.scenario))(example)))
        test()

    def _base(self) -> None:
        from .pipeline import run_instances

        case = self._case(strategy=BASE)
        with self._planning_failures(case):
            for outcome in run_instances(
                self.scenario, self._examples(), seed=case.seed, settings=case.settings(), max_tries=case.max_tries, drivers=self._drivers(),
                simulation_time_limit=case.simulation_time_limit,
            ):
                self.counts["examples"] += 1
                self._count(outcome)
                if not outcome.verdict.accepted:
                    raise ScenarioFailed(self._case(strategy=BASE, instance=outcome.instance), outcome.verdict.explain(), outcome)

    def _replay(self, case: Case) -> None:
        """The one case of a case file, when it is this item's (other items are skipped)."""
        if Path(case.path).resolve() != self.path.resolve() or case.scenario != self.scenario.name:
            pytest.skip(f"--roadlogic-replay runs {case.path}::{case.scenario} only")
        self.counts["examples"] += 1
        with self._planning_failures(case):
            outcome = case.run(drivers=self._drivers())
        self._count(outcome)
        if not outcome.verdict.accepted:
            raise ScenarioFailed(case, outcome.verdict.explain(), outcome)

    @contextmanager
    def _planning_failures(self, case: Case, explain_later: bool = False):
        """A case without a plan, or out of planning time, fails as that case (and is counted)."""
        try:
            yield
        except PlanningTimeout as error:
            self.counts["timed_out"] += 1
            raise ScenarioFailed(case, f"planning timed out: {error}", kind="timed out") from None
        except UnsatisfiableScenario as error:
            self.counts["no_plan"] += 1
            raise ScenarioFailed(case, error.report(), kind="no plan") from None
        except NoPlanError as error:
            self.counts["no_plan"] += 1
            raise ScenarioFailed(case, f"no plan: {error}", kind="no plan", explain=explain_later) from None

    def _count(self, outcome) -> None:
        self.counts["accepted" if outcome.verdict.accepted else "rejected"] += 1
        for stage in STAGES:
            self.seconds[stage] += outcome.seconds.get(stage, 0.0)

    # ---------------------------------------------------------------- reporting

    def _report_failure(self, failure: ScenarioFailed) -> None:
        from .artifacts import write_artifacts
        from .sampling import describe_values, logical_parameters

        case = failure.case
        if failure.explain:
            failure.why = _why_no_plan(case, failure.why)
        directory = Path(self.config.rootpath) / _option(self.config, "artifacts") / _safe_name(self.nodeid)
        paths: dict[str, Path] = {}
        if failure.outcome is not None:
            started = time.perf_counter()
            paths = write_artifacts(failure.outcome, directory)
            self.seconds["artifacts"] += time.perf_counter() - started
        paths["case"] = case.save(directory / "case.json")
        what = f"{failure.kind} at" if case.strategy == REFINED else f"{failure.kind} at instance {case.instance} of"
        lines = [f"scenario {self.scenario.name}: {what} these values (seed {case.seed}, {self.counts['examples']} examples run):"]
        if case.values:
            lines += [f"  {line}" for line in describe_values(logical_parameters(self.scenario), case.values)]
        else:
            lines.append("  (no logical parameters: the planner chose every value)")
        if failure.outcome is not None:
            lines.append(f"after {failure.outcome.tries} plans tried, the last simulation was {failure.why}")
        else:
            lines.append(failure.why)
        lines += ["artifacts:", *(f"  {kind}: {path}" for kind, path in paths.items())]
        lines.append(f"replay: pytest '{self.nodeid}' --roadlogic-replay {paths['case']}   (with this session's drivers)")
        lines.append(f"    or: {case.command(paths['case'])}")
        lines.append(f"    or: {case.command()}")
        self.user_properties.append(("verdict", failure.kind))
        self.user_properties.append(("failing_values", json.dumps(case.values, sort_keys=True)))
        self.user_properties.append(("explanation", failure.why.splitlines()[0] if failure.why else ""))
        raise ScenarioFailed(case, "\n".join(lines), failure.outcome, failure.kind)

    def repr_failure(self, excinfo, style=None):
        if isinstance(excinfo.value, (ScenarioFailed, OscError)):
            return str(excinfo.value)
        return super().repr_failure(excinfo, style=style)

    def reportinfo(self):
        return self.path, self.scenario.scenario.location.line - 1, f"scenario {self.scenario.name}"


class SessionSummary:
    """Totals over every scenario item, also from pytest-xdist workers (their reports carry the counts)."""

    def __init__(self) -> None:
        self.items = 0
        self.counts: Counter[str] = Counter()

    @pytest.hookimpl
    def pytest_runtest_logreport(self, report) -> None:
        if report.when != "call":
            return
        properties = dict(report.user_properties)
        if "strategy" not in properties:
            return
        self.items += 1
        for key, value in properties.items():
            if isinstance(value, (int, float)) and not isinstance(value, bool) and key != "seed":
                self.counts[key] += value

    @pytest.hookimpl
    def pytest_terminal_summary(self, terminalreporter) -> None:
        if not self.items:
            return
        c = self.counts
        seconds = ", ".join(f"{stage} {c[f'seconds_{stage}']:.1f} s" for stage in STAGES)
        terminalreporter.write_sep("-", "roadlogic")
        terminalreporter.write_line(
            f"{self.items} scenarios, {c['examples']} examples: {c['accepted']} accepted, {c['rejected']} rejected, "
            f"{c['no_plan']} without a plan, {c['timed_out']} timed out"
        )
        terminalreporter.write_line(f"time per stage: {seconds}")


def _why_no_plan(case: Case, fallback: str) -> str:
    """The planner's explanation of a case without a plan: the constraints that cannot hold together."""
    try:
        case.run()
    except UnsatisfiableScenario as error:
        return error.report()
    except NoPlanError:
        pass
    return fallback


def _safe_name(nodeid: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", nodeid).strip("_")
