"""Running the evaluation: every scenario under both strategies, each instance timed and recorded.

The record of a run (``results.json``) holds everything the report shows, so the report can be
rebuilt, checked or compared later without simulating again. Each instance ends in one outcome:

- conformant: the monitor accepted a simulation (within the tries a rejection allows);
- non-conformant: every try was rejected;
- timed out: planning or simulation ran past its time limit;
- no plan: the planner proved that no plan exists (for a sample: at those values).

A scenario file that cannot be loaded is recorded as an error and the run goes on.
"""

from __future__ import annotations

import dataclasses
import json
import os
import platform
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import metadata
from pathlib import Path
from typing import Any

from ..artifacts import write_artifacts, write_text
from ..frontend import OscError
from ..pipeline import MAX_TRIES, Outcome, load_scenario, run_instances, run_scenario
from ..planning import NoPlanError, PlanningSettings, PlanningTimeout
from ..simulation import SimulationTimeout
from .occupancy import Occupancy

BASE, REFINED = "base", "refined"
STRATEGIES = (BASE, REFINED)
STAGES = ("planning", "simulation", "monitoring", "artifacts")
CONFORMANT, NON_CONFORMANT, TIMED_OUT, NO_PLAN = "conformant", "non-conformant", "timed out", "no plan"
OUTCOMES = (CONFORMANT, NON_CONFORMANT, TIMED_OUT, NO_PLAN)
RESULTS_FILE = "results.json"
PACKAGES = ("pytest-roadlogic", "clingo", "clingo-dl", "frenetix", "commonroad-io", "hypothesis", "numpy", "matplotlib", "pytest")


# instances per scenario: the paper's (which the targets are set for), and a run to try the setup
PAPER_COUNTS = (10, 50)
QUICK_COUNTS = (2, 5)


@dataclass(frozen=True)
class BenchmarkSettings:
    """What one evaluation runs; the defaults are the paper's."""

    paths: tuple[Path, ...]
    base: int = PAPER_COUNTS[0]
    refined: int = PAPER_COUNTS[1]
    seed: int = 1
    tries: int = MAX_TRIES
    planning_time_limit: float = 60.0
    simulation_time_limit: float = 120.0
    artifacts: bool = True  # plan, trace, CommonRoad XML, plot and verdict of every instance (timed)

    def count(self, strategy: str) -> int:
        return self.base if strategy == BASE else self.refined


@dataclass
class InstanceRecord:
    scenario: str
    strategy: str
    index: int
    outcome: str
    tries: int = 0
    seconds: dict[str, float] = field(default_factory=dict)  # per stage, summed over tries
    values: dict[str, Any] | None = None  # the sample (refined)
    robustness: float | None = None
    horizon: int | None = None  # planning steps of the simulated plan
    message: str = ""  # why it is not conformant
    occupancy: Occupancy | None = None  # of the last simulation (None without one)
    artifacts: str | None = None  # directory, relative to the output directory

    def to_json(self) -> dict[str, Any]:
        data = dataclasses.asdict(self)
        data["occupancy"] = self.occupancy.to_json() if self.occupancy is not None else None
        return data

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> "InstanceRecord":
        occupancy = Occupancy.from_json(data["occupancy"]) if data.get("occupancy") is not None else None
        return cls(**{**data, "occupancy": occupancy})


@dataclass
class BenchmarkResults:
    """Everything one evaluation measured, and the circumstances (machine, versions, seed)."""

    settings: dict[str, Any]
    environment: dict[str, Any]
    scenarios: list[str]  # in run order
    instances: list[InstanceRecord] = field(default_factory=list)
    errors: dict[str, str] = field(default_factory=dict)  # scenario -> why it could not run
    seconds: float = 0.0  # wall clock of the whole run

    def of(self, scenario: str, strategy: str) -> list[InstanceRecord]:
        return [r for r in self.instances if r.scenario == scenario and r.strategy == strategy]

    def save(self, directory: Path) -> Path:
        data = {**dataclasses.asdict(self), "instances": [r.to_json() for r in self.instances]}
        return write_text(directory / RESULTS_FILE, json.dumps(data, indent=1))

    @classmethod
    def load(cls, path: Path) -> "BenchmarkResults":
        data = json.loads(Path(path).read_text(encoding="utf-8"))
        return cls(**{**data, "instances": [InstanceRecord.from_json(r) for r in data["instances"]]})


Progress = Callable[[InstanceRecord, int, int], None]  # (record, done, total)


def run_benchmark(settings: BenchmarkSettings, out: Path, progress: Progress | None = None, command: list[str] | None = None) -> BenchmarkResults:
    """Run every scenario with the base strategy, then with the refined one; save results as they come.

    ``results.json`` in ``out`` is rewritten after each scenario and strategy, so an interrupted run
    keeps what it measured.
    """
    out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    settings_record = {**dataclasses.asdict(settings), "paths": [str(p) for p in settings.paths], "command": command}
    results = BenchmarkResults(settings_record, environment(), [p.stem for p in settings.paths])
    total = len(settings.paths) * (settings.base + settings.refined)
    done = 0

    def record(instance: InstanceRecord) -> None:
        nonlocal done
        done += 1
        results.instances.append(instance)
        if progress is not None:
            progress(instance, done, total)

    for path in settings.paths:
        try:
            scenario = load_scenario(path)
        except OscError as error:
            results.errors[path.stem] = error.report()
            done += settings.base + settings.refined
            continue
        for strategy in STRATEGIES:
            runner = _run_base if strategy == BASE else _run_refined
            runner(scenario, path.stem, settings, out, record)
            results.seconds = time.perf_counter() - started
            results.save(out)
    results.seconds = time.perf_counter() - started
    results.save(out)
    return results


def _planning_settings(settings: BenchmarkSettings) -> PlanningSettings:
    # a sample without a plan is counted, not explained: the diagnosis costs seconds per sample
    return PlanningSettings(time_limit=settings.planning_time_limit, explain_unsatisfiable=False)


def _run_base(scenario, name: str, settings: BenchmarkSettings, out: Path, record: Callable[[InstanceRecord], None]) -> None:
    """The planner's first N different plans. A timeout ends the sequence (the planner's search
    state is gone with it); the instances it did not reach are recorded as timed out too, and a
    planner that runs out of plans leaves the rest without a plan."""
    index = 0
    try:
        for outcome in run_instances(
            scenario, settings.base, seed=settings.seed, settings=_planning_settings(settings), max_tries=settings.tries,
            simulation_time_limit=settings.simulation_time_limit,
        ):
            record(_record(outcome, name, BASE, index, None, settings, out))
            index += 1
        ending, message = NO_PLAN, "the planner has no further plan"
    except (PlanningTimeout, SimulationTimeout) as error:
        ending, message = TIMED_OUT, str(error)
    except NoPlanError as error:
        ending, message = NO_PLAN, str(error)
    for k in range(index, settings.base):
        record(InstanceRecord(name, BASE, k, ending, message=message))


def _run_refined(scenario, name: str, settings: BenchmarkSettings, out: Path, record: Callable[[InstanceRecord], None]) -> None:
    """N samples of the logical parameters, drawn by Hypothesis from the run's seed exactly as the
    pytest plugin draws them, each planned, simulated and monitored once (with retries)."""
    import hypothesis
    from hypothesis import HealthCheck, Phase

    from ..sampling import strategy

    planning = _planning_settings(settings)
    count = 0

    def sample(values: dict[str, Any]) -> None:
        nonlocal count
        if count >= settings.refined:
            return
        started = time.perf_counter()
        try:
            outcome = run_scenario(
                scenario, seed=settings.seed, settings=planning, max_tries=settings.tries, values=values,
                simulation_time_limit=settings.simulation_time_limit,
            )
        except (PlanningTimeout, SimulationTimeout) as error:
            instance = InstanceRecord(name, REFINED, count, TIMED_OUT, values=values, message=str(error), seconds=_elapsed(started))
        except NoPlanError as error:
            instance = InstanceRecord(name, REFINED, count, NO_PLAN, values=values, message=str(error), seconds=_elapsed(started))
        else:
            instance = _record(outcome, name, REFINED, count, values, settings, out)
        count += 1
        record(instance)

    # the default profile, not the one loaded (a CI profile's derandomize would override the seed):
    # the same seed must draw the same samples everywhere
    profile = hypothesis.settings.get_profile("default")
    search = hypothesis.settings(
        profile, max_examples=settings.refined, database=None, deadline=None, derandomize=False, phases=[Phase.generate],
        print_blob=False, suppress_health_check=list(HealthCheck),
    )
    hypothesis.seed(settings.seed)(search(hypothesis.given(strategy(scenario))(sample)))()


def _elapsed(started: float) -> dict[str, float]:
    return {stage: 0.0 for stage in STAGES} | {"planning": time.perf_counter() - started}


def _record(outcome: Outcome, name: str, strategy: str, index: int, values, settings: BenchmarkSettings, out: Path) -> InstanceRecord:
    seconds = {stage: outcome.seconds.get(stage, 0.0) for stage in STAGES}
    seconds["planning"] += outcome.seconds.get("automaton", 0.0)
    directory = None
    if settings.artifacts:
        started = time.perf_counter()
        relative = Path("instances") / name / f"{strategy}-{index + 1:03d}"
        write_artifacts(outcome, out / relative, animation=False)
        seconds["artifacts"] = time.perf_counter() - started
        directory = relative.as_posix()
    verdict = outcome.verdict
    return InstanceRecord(
        name, strategy, index, CONFORMANT if verdict.accepted else NON_CONFORMANT, outcome.tries, seconds, values,
        verdict.robustness, outcome.plan.horizon, "" if verdict.accepted else verdict.explain(),
        Occupancy.of_trace(outcome.simulation.trace), directory,
    )


def environment() -> dict[str, Any]:
    """The machine and the versions a run was measured with."""
    versions = {"python": platform.python_version()}
    for package in PACKAGES:
        try:
            versions[package] = metadata.version(package)
        except metadata.PackageNotFoundError:
            versions[package] = "not installed"
    return {
        "platform": platform.platform(),
        "processor": _cpu_model(),
        "cpus": os.cpu_count(),
        "memory_gib": _memory_gib(),
        "versions": versions,
        "executable": sys.executable,
        "date": time.strftime("%Y-%m-%d %H:%M:%S %Z"),
    }


def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def _memory_gib() -> float | None:
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemTotal:"):
                return round(int(line.split()[1]) / 2**20, 1)
    except OSError:
        pass
    return None
