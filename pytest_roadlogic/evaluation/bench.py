"""Running the evaluation: every scenario under both strategies, each instance timed and recorded.

The record of a run (``results.json``) holds everything the report shows, so the report can be
rebuilt, checked or compared later without simulating again. Each instance ends in one of the
outcomes of ``pytest_roadlogic.outcomes`` (conformant, non-conformant, no plan, timed out); the
cases are run by ``pytest_roadlogic.runner``, as the plugin runs them.

A scenario file that cannot be loaded is recorded as an error and the run goes on.
"""

from __future__ import annotations

import dataclasses
import json
import os
import platform
import re
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..artifacts.files import write_text
from ..artifacts.writer import write_artifacts
from ..case import VERSIONED, installed_versions
from ..confinement import unique_name
from ..executors import Executor, SerialExecutor
from ..frontend import OscError
from ..frontend.semantics.logical import describe_values
from ..outcomes import NO_PLAN, STAGES
from ..runner import CaseResult, Runner, set_aside_sample
from ..settings import BASE, REFINED, RunSettings
from .coverage import recorded_values
from .fidelity import unasked_changes
from .occupancy import Occupancy
from .scenario_source import ScenarioSource

STRATEGIES = (BASE, REFINED)  # the order the bench runs them in
RESULTS_FILE = "results.json"
# what a bench writes in its --out folder (results, report, plots, each instance's artifacts, and
# the writer's temporary files): a folder holding anything else is not the bench's to write in
BENCH_NAMES = re.compile(r"results\.json|report\.md|rq[12]-[A-Za-z0-9_.-]*\.png|instances|\..*\.partial.*")


# instances per scenario: the paper's (which the targets are set for), and a run to try the setup
PAPER_COUNTS = (10, 50)
QUICK_COUNTS = (2, 5)
# the realistic suite's (scenarios/realistic/): its instances drive up to a minute with five vehicles,
# seconds to tens of seconds each, where the paper's take about one
REALISTIC_COUNTS = (2, 10)
REALISTIC_QUICK_COUNTS = (1, 2)


@dataclass(frozen=True)
class Suite:
    """A second set of scenarios run beside the paper's seven and reported apart from them (the
    targets are the paper's): the realistic suite, with its own counts and run settings (the
    continuous encoding, which its timed phases need) and each file's dialect."""

    paths: tuple[Path, ...]
    base: int = REALISTIC_COUNTS[0]
    refined: int = REALISTIC_COUNTS[1]
    run: RunSettings = field(default_factory=RunSettings)
    dialects: dict[str, str] = field(default_factory=dict)  # file path -> dialect, where not the run's

    def record(self) -> dict[str, Any]:
        return {
            "paths": [str(p) for p in self.paths],
            "base": self.base,
            "refined": self.refined,
            "encoding": self.run.encoding,
            "dialects": self.dialects,
        }


@dataclass(frozen=True)
class BenchmarkSettings:
    """What one evaluation runs; the defaults are the paper's."""

    paths: tuple[Path, ...]
    base: int = PAPER_COUNTS[0]
    refined: int = PAPER_COUNTS[1]
    run: RunSettings = field(default_factory=RunSettings)  # seed, tries, time limits, ...
    artifacts: bool = True  # plan, trace, CommonRoad XML, plot and verdict of every instance (timed)
    realistic: Suite | None = None

    def record(self) -> dict[str, Any]:
        """For results.json: flat, as the report reads it (seed, tries, time limits, ...)."""
        return {
            "paths": [str(p) for p in self.paths],
            "base": self.base,
            "refined": self.refined,
            "artifacts": self.artifacts,
            **dataclasses.asdict(self.run),
            "realistic": self.realistic.record() if self.realistic is not None else None,
        }

    def count(self, strategy: str) -> int:
        return self.base if strategy == BASE else self.refined

    def suites(self) -> list[tuple[tuple[Path, ...], int, int, RunSettings, dict[str, str]]]:
        """(files, base count, refined count, run settings, dialects) of the paper's suite, then the realistic one."""
        suites = [(self.paths, self.base, self.refined, self.run, {})]
        if self.realistic is not None:
            r = self.realistic
            suites.append((r.paths, r.base, r.refined, r.run, r.dialects))
        return suites


@dataclass
class InstanceRecord:
    scenario: str
    strategy: str
    index: int
    outcome: str
    tries: int = 0
    seconds: dict[str, float] = field(default_factory=dict)  # per stage, summed over tries
    values: dict[str, Any] | None = None  # the sample (refined)
    # the sample as every report shows it (frontend.semantics.logical.describe_values): value, unit, line, kind
    described: list[str] = field(default_factory=list)
    robustness: float | None = None
    horizon: int | None = None  # planning steps of the simulated plan
    message: str = ""  # why it is not conformant
    occupancy: Occupancy | None = None  # of the last simulation (None without one)
    artifacts: str | None = None  # directory, relative to the output directory
    # lane and speed changes of the simulated plan that no construct of their vehicle asks for
    # (evaluation.fidelity; None without a plan)
    unasked: int | None = None

    def to_json(self) -> dict[str, Any]:
        data = dataclasses.asdict(self)
        data["occupancy"] = self.occupancy.to_json() if self.occupancy is not None else None
        return data

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> InstanceRecord:
        occupancy = Occupancy.from_json(data["occupancy"]) if data.get("occupancy") is not None else None
        return cls(**{**data, "occupancy": occupancy})


@dataclass
class BenchmarkResults:
    """Everything one evaluation measured, and the circumstances (machine, versions, seed)."""

    settings: dict[str, Any]
    environment: dict[str, Any]
    scenarios: list[str]  # the paper's suite, in run order: what the targets and RQ1/RQ2 cover
    instances: list[InstanceRecord] = field(default_factory=list)
    errors: dict[str, str] = field(default_factory=dict)  # scenario -> why it could not run
    seconds: float = 0.0  # wall clock of the whole run
    realistic: list[str] = field(default_factory=list)  # the realistic suite's scenarios, reported apart

    def of(self, scenario: str, strategy: str) -> list[InstanceRecord]:
        return [r for r in self.instances if r.scenario == scenario and r.strategy == strategy]

    def save(self, directory: Path) -> Path:
        data = {**dataclasses.asdict(self), "instances": [r.to_json() for r in self.instances]}
        return write_text(directory / RESULTS_FILE, json.dumps(data, indent=1))

    @classmethod
    def load(cls, path: Path) -> BenchmarkResults:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
        return cls(**{**data, "instances": [InstanceRecord.from_json(r) for r in data["instances"]]})


Progress = Callable[[InstanceRecord, int, int], None]  # (record, done, total)


def run_benchmark(
    settings: BenchmarkSettings,
    out: Path,
    progress: Progress | None = None,
    command: list[str] | None = None,
    executor: Executor | None = None,
) -> BenchmarkResults:
    """Run every scenario with the base strategy, then with the refined one; save results as they come.

    ``executor`` (default: serial, in this process) runs the jobs: each scenario's base strategy
    (the planner's plans come one after another), and each sample of the refined strategy alone.
    The samples are drawn up front from the seed (``sampling.drawn``), so every job is fixed by
    its arguments and the seed: the results are the serial run's, recorded in its order, whatever
    ran them (only the seconds differ, and run side by side the jobs share the cores). A sample
    set aside (``runner.set_aside_sample``) is not an instance: more samples are drawn for those,
    from the seed and the round, until the count is reached or the draws run dry.
    ``results.json`` in ``out`` is rewritten as records come, so an interrupted run keeps what it
    measured.
    """
    executor = executor or SerialExecutor()
    out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    settings_record = {**settings.record(), "command": command}
    results = BenchmarkResults(
        settings_record,
        {**environment(), "executor": executor.describe()},
        [p.stem for p in settings.paths],
        realistic=[p.stem for p in settings.realistic.paths] if settings.realistic is not None else [],
    )
    clashing = set(results.scenarios) & set(results.realistic)
    if clashing:
        raise ValueError(
            f"a realistic scenario has the name of one of the paper's: {', '.join(sorted(clashing))}; rename its file"
        )
    runs = _runs(settings)
    total = sum(run.count for run in runs)
    done = 0
    saved = 0.0

    def record(instance: InstanceRecord) -> None:
        nonlocal done
        done += 1
        if progress is not None:
            progress(instance, done, total)

    def unreadable(run: _Run) -> None:
        nonlocal done
        if run.error is not None and id(run) not in failed:
            failed.add(id(run))
            done += run.count  # none of its instances will come

    failed: set[int] = set()

    def save(now: bool = False) -> None:
        nonlocal saved
        if now or time.perf_counter() - saved > SAVE_EVERY:
            results.instances = [r for run in runs for r in run.kept()]
            results.errors = {run.source.path.stem: run.error for run in runs if run.error is not None}
            results.seconds = time.perf_counter() - started
            results.save(out)
            saved = time.perf_counter()

    base = [run for run in runs if run.strategy == BASE]
    drawing = [run for run in runs if run.strategy == REFINED and run.count > 0]
    for round_ in range(DRAW_ROUNDS):
        draws = executor.results([(_drawn_job, run.draw_job(round_)) for run in drawing])
        for run, (values, error) in zip(drawing, draws, strict=True):
            run.add_draws(values, error)
            unreadable(run)
        # the base strategy's jobs go with the first round's samples, the largest first
        calls = [(run, None, (_bench_job, (run.source, run.settings, out)), run.count) for run in base]
        calls += [(run, k, (_sample_job, run.sample_job(k, out)), 1) for run in drawing for k in run.to_run()]
        answers = executor.results([call for _, _, call, _ in calls], [size for _, _, _, size in calls])
        for (run, number, _, _), answer in zip(calls, answers, strict=True):
            for instance in run.answered(number, answer):
                record(instance)
            unreadable(run)
            save()
        base = []
        drawing = [run for run in drawing if run.wants_more()]
        if not drawing:
            break
    save(now=True)
    return results


SAVE_EVERY = 2.0  # seconds between rewrites of results.json while records come
DRAW_ROUNDS = 10  # draws of a refined run: the first, then one per round of samples set aside


@dataclass
class _Run:
    """One scenario with one strategy in a bench: what its jobs need, and what they answered."""

    source: ScenarioSource
    settings: BenchmarkSettings
    strategy: str
    records: dict[int, InstanceRecord | None] = field(default_factory=dict)  # draw -> record (None: set aside)
    draws: list[dict[str, Any]] = field(default_factory=list)  # the refined samples, in draw order
    error: str | None = None
    dry: bool = False  # the last draw found no sample not drawn before

    @property
    def count(self) -> int:
        return self.settings.count(self.strategy)

    def draw_job(self, round_: int) -> tuple:
        # the first draw is the one a plain Hypothesis run of the seed makes; each next one, for
        # the samples set aside, is seeded by the round too, and draws as many more as there are
        # samples so far: a draw starts at the simplest sample (each range's low end), which the
        # first draw has, and may repeat others
        missing = self.count - len(self.kept())
        if round_ == 0:
            return self.source, missing, self.settings.run.seed
        return self.source, missing + len(self.draws), f"{self.settings.run.seed}-{round_}"

    def add_draws(self, values: list[dict[str, Any]] | None, error: str | None) -> None:
        """Take the samples of a draw not drawn before, as many as the run still misses."""
        if error is not None:
            self.error = error
            return
        missing = self.count - len(self.kept())
        new = []
        for v in values or []:
            if v not in self.draws and v not in new:
                new.append(v)
        new = new[:missing]
        self.dry = not new
        self.draws += new

    def to_run(self) -> list[int]:
        return [k for k in range(len(self.draws)) if k not in self.records] if self.error is None else []

    def sample_job(self, number: int, out: Path) -> tuple:
        return self.source, self.settings, self.draws[number], number, out

    def answered(self, number: int | None, answer) -> list[InstanceRecord]:
        """Take a job's answer (``number``: the sample's draw, None for the base strategy's job);
        the records it adds."""
        found, error = answer
        if error is not None:
            self.error = error
            return []
        if number is None:
            self.records = dict(enumerate(found))
            return found
        self.records[number] = found
        return [found] if found is not None else []

    def kept(self) -> list[InstanceRecord]:
        """The records so far in the serial run's order, refined ones numbered past those set
        aside, at most the run's count."""
        if self.strategy == BASE:
            return [self.records[k] for k in sorted(self.records)]
        kept = []
        for number in sorted(self.records):
            found = self.records[number]
            if found is not None and len(kept) < self.count:
                kept.append(dataclasses.replace(found, index=len(kept)))
        return kept

    def wants_more(self) -> bool:
        return self.error is None and not self.dry and len(self.kept()) < self.count


def _runs(settings: BenchmarkSettings) -> list[_Run]:
    """Every scenario with each strategy, in the order the serial run takes them."""
    runs = []
    for paths, base, refined, run, dialects in settings.suites():
        suite = dataclasses.replace(settings, base=base, refined=refined)
        for path in paths:
            dialect = dialects.get(str(path), run.dialect)
            file_settings = dataclasses.replace(suite, run=dataclasses.replace(run, dialect=dialect))
            source = ScenarioSource(Path(path), dialect=dialect)
            runs += [_Run(source, file_settings, strategy) for strategy in STRATEGIES]
    return runs


# ------------------------------------------------------------------ the jobs (run in a worker)


def _bench_job(
    source: ScenarioSource, settings: BenchmarkSettings, out: Path
) -> tuple[list[InstanceRecord], str | None]:
    """One scenario's base strategy: its instances' records, or the file's error report."""
    try:
        scenario = source.load()
    except OscError as error:
        return [], error.report()
    records: list[InstanceRecord] = []
    _run_base(scenario, source.path.stem, settings, out, records.append)
    return records, None


def _drawn_job(source: ScenarioSource, count: int, seed: int | str) -> tuple[list[dict[str, Any]], str | None]:
    """``count`` samples of a scenario drawn from ``seed``, or the file's error report."""
    from ..sampling import drawn

    try:
        return drawn(source.load(), count, seed), None
    except OscError as error:
        return [], error.report()


def _sample_job(
    source: ScenarioSource, settings: BenchmarkSettings, values: dict[str, Any], number: int, out: Path
) -> tuple[InstanceRecord | None, str | None]:
    """One sample of the refined strategy (``number``: its draw), planned, simulated and monitored
    once (with retries): its record, None when it is set aside."""
    runner = source.runner(settings.run)
    result = runner.sample(values)
    if set_aside_sample(result):
        return None, None
    return _record(result, source.path.stem, REFINED, number, settings, out, runner.scenario.parameters), None


def _run_base(
    scenario, name: str, settings: BenchmarkSettings, out: Path, record: Callable[[InstanceRecord], None]
) -> None:
    """The planner's first N different plans. A planning failure ends the sequence (the planner's
    search state is gone with it); the instances it did not reach get its outcome too, and a
    planner that runs out of plans leaves the rest without a plan."""
    # a case without a plan is counted, not explained: the diagnosis costs seconds per case
    runner = Runner(scenario, settings.run, explain=False)
    index = 0
    ending, message = NO_PLAN, "the planner has no further plan"
    for result in runner.base(settings.base):
        if result.run is None:
            ending, message = result.outcome, result.message
            break
        record(_record(result, name, BASE, index, settings, out))
        index += 1
    for k in range(index, settings.base):
        record(InstanceRecord(name, BASE, k, ending, message=message))


def _record(
    result: CaseResult,
    name: str,
    strategy: str,
    index: int,
    settings: BenchmarkSettings,
    out: Path,
    parameters=(),
) -> InstanceRecord:
    seconds = {stage: result.seconds.get(stage, 0.0) for stage in STAGES}
    values = result.case.values if strategy == REFINED else None
    described = describe_values(parameters, values or {})
    if result.run is None:
        return InstanceRecord(
            name,
            strategy,
            index,
            result.outcome,
            values=values,
            described=described,
            message=result.message,
            seconds=seconds,
        )
    outcome = result.run
    directory = None
    if settings.artifacts:
        started = time.perf_counter()
        relative = Path("instances") / unique_name(name) / f"{strategy}-{index + 1:03d}"
        recorded = recorded_values(outcome.scenario.coverage, values or {}, outcome)
        write_artifacts(outcome, out / relative, animation=False, recorded=recorded)
        seconds["artifacts"] = time.perf_counter() - started
        directory = relative.as_posix()
    verdict = outcome.verdict
    return InstanceRecord(
        name,
        strategy,
        index,
        result.outcome,
        outcome.tries,
        seconds,
        values,
        described,
        verdict.robustness,
        outcome.plan.horizon,
        result.message,
        Occupancy.of_trace(outcome.simulation.trace),
        directory,
        len(unasked_changes(outcome.plan, outcome.automaton)),
    )


def conftest_dialect(path: Path, roots: list[Path]) -> str | None:
    """The dialect pytest would read ``path`` in: what the nearest ``pytest_roadlogic_dialect`` hook
    of a ``conftest.py`` between the file and its suite folder returns (CARLA suites say so in a
    conftest.py beside their files), None where none does. The bench runs outside pytest, so it
    calls the hook itself, as the plugin's hook call would."""
    import importlib.util

    path = Path(path).resolve()
    tops = [Path(r).resolve() for r in roots]
    for folder in path.parents:
        conftest = folder / "conftest.py"
        if conftest.is_file():
            spec = importlib.util.spec_from_file_location(
                f"_roadlogic_bench_conftest_{abs(hash(str(conftest)))}", conftest
            )
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
            hook = getattr(module, "pytest_roadlogic_dialect", None)
            answer = hook(config=None, path=path) if hook is not None else None
            if answer is not None:
                return answer
        if folder in tops or not any(top in folder.parents for top in tops):
            return None
    return None


def environment() -> dict[str, Any]:
    """The machine and the versions a run was timed on."""
    versions = {**dict.fromkeys(VERSIONED, "not installed"), **installed_versions()}
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
