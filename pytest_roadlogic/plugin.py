"""The pytest plugin: every ``.osc`` file is a test module, every scenario in it a test item.

An item runs the pipeline (plan, simulate, monitor, with the paper's bounded retries) and passes
when the monitor accepts the simulation. A rejection fails the item with the monitor's
explanation (which guard was not met, when it came closest, with which values) and the paths of
the artifacts to look at. A file that does not parse is one collection error with the front end's
message; the other files still run. Collection never runs a solver.
"""

from __future__ import annotations

import re
from argparse import ArgumentTypeError
from pathlib import Path

import pytest

from .cli import lane_count
from .frontend import OscError, Scenario, check_file
from .planning import NoPlanError, UnsatisfiableScenario

DEFAULT_SEED = 1
DEFAULT_ARTIFACTS = "roadlogic-artifacts"


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("roadlogic", "scenario-based testing with OpenSCENARIO DSL files")
    group.addoption("--roadlogic-seed", type=int, default=None, help=f"seed fixing planning and simulation (ini: roadlogic_seed; default {DEFAULT_SEED})")
    group.addoption("--roadlogic-artifacts", default=None, help=f"directory for plans, traces, scenarios and plots (ini: roadlogic_artifacts; default {DEFAULT_ARTIFACTS})")
    group.addoption("--roadlogic-lanes", type=int, default=None, help="lanes of the road (ini: roadlogic_lanes; default: from each scenario, at least 3)")
    parser.addini("roadlogic_seed", "seed fixing planning and simulation", default=str(DEFAULT_SEED))
    parser.addini("roadlogic_artifacts", "directory for the artifacts of every scenario run", default=DEFAULT_ARTIFACTS)
    parser.addini("roadlogic_lanes", "lanes of the road (default: from each scenario)", default="")


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "roadlogic: a scenario collected from an .osc file")
    config.addinivalue_line("markers", "slow: a long scenario or suite; deselect with -m 'not slow'")
    _option(config, "lanes", _whole_or_none)  # a bad lanes value stops the session before collection


def pytest_collect_file(file_path: Path, parent: pytest.Collector):
    if file_path.suffix == ".osc":
        return OscFile.from_parent(parent, path=file_path)
    return None


def _option(config: pytest.Config, name: str, cast=str):
    value = config.getoption(f"--roadlogic-{name}")
    return cast(value if value is not None else config.getini(f"roadlogic_{name}"))


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
            if scenario.behavior is not None:
                item = ScenarioItem.from_parent(self, name=scenario.name, scenario=scenario)
                item.add_marker("roadlogic")
                yield item


class ScenarioRejected(Exception):
    """The monitor rejected every simulation the pipeline tried."""


class ScenarioItem(pytest.Item):
    def __init__(self, *, scenario: Scenario, **kwargs) -> None:
        super().__init__(**kwargs)
        self.scenario = scenario

    def runtest(self) -> None:
        from .artifacts import write_artifacts
        from .pipeline import run_scenario

        config = self.config
        seed = _option(config, "seed", int)
        outcome = run_scenario(self.scenario, seed=seed)
        directory = Path(config.rootpath) / _option(config, "artifacts") / _safe_name(self.nodeid)
        # the animation takes seconds to render: only for a scenario that failed, where it helps
        paths = write_artifacts(outcome, directory, animation=not outcome.verdict.accepted)
        self.user_properties.append(("accepted", outcome.verdict.accepted))
        self.user_properties.append(("robustness", round(outcome.verdict.robustness, 3)))
        self.user_properties.append(("seed", seed))
        if not outcome.verdict.accepted:
            lines = [
                f"scenario {self.scenario.name} was not reproduced in simulation ({outcome.tries} plans tried, seed {seed})",
                outcome.verdict.explain(),
                "artifacts of the last try:",
                *(f"  {kind}: {path}" for kind, path in paths.items()),
                f"replay: roadlogic run {self.path} --scenario {self.scenario.name} --seed {seed}",
            ]
            raise ScenarioRejected("\n".join(lines))

    def repr_failure(self, excinfo, style=None):
        if isinstance(excinfo.value, (ScenarioRejected, OscError)):
            return str(excinfo.value)
        if isinstance(excinfo.value, UnsatisfiableScenario):
            return excinfo.value.report()
        if isinstance(excinfo.value, NoPlanError):
            return f"{self.path}: scenario {self.scenario.name}: no plan: {excinfo.value}"
        return super().repr_failure(excinfo, style=style)

    def reportinfo(self):
        return self.path, self.scenario.location.line - 1, f"scenario {self.scenario.name}"


def _safe_name(nodeid: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", nodeid).strip("_")
