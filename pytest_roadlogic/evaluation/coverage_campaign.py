"""A coverage campaign (``cover``): a scenario's samples, its proofs of unreachable buckets and its
closure cases, each an independent job on an executor (``executors``), tallied as one serial run
tallies them.

The samples are drawn up front from the run's seed (``sampling.drawn``), so that which cases run
does not depend on where or in which order they run; each job loads the scenario once per worker
process (``scenario_source.ScenarioSource``) and sends back a tally of its own (``ScenarioCoverage``, plain
data) that the campaign adds up in the order of the jobs. Then every bucket no sample hit is
asked of the planner (``reach.unreachable``, one job per item), and with ``closure`` each bucket
still open gets a case with its parameters inside it (``closure.closing_values``, one job per
bucket: its tries in order until one has a plan). The pytest plugin tallies the same way, item by
item; a campaign is for runs larger than one machine (``--ray``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..executors import Executor, SerialExecutor
from ..frontend.semantics.checked import CheckedScenario
from ..outcomes import NO_PLAN
from ..settings import DISCARD, REFINED, RunSettings
from .closure import closing_values, first_with_plan
from .coverage import ScenarioCoverage, merged
from .coverage_db import earlier, fingerprint
from .reach import open_questions, unreachable
from .scenario_source import ScenarioSource


@dataclass
class CampaignCoverage:
    """What a campaign covered (``coverage``) and the cases it ran: samples drawn, those with no
    plan (set aside, as the plugin sets them aside), and closure cases run and set aside."""

    coverage: ScenarioCoverage
    samples: int = 0
    without_plan: int = 0
    closure_cases: int = 0
    closure_without_plan: int = 0
    outcomes: dict[str, int] = field(default_factory=dict)

    def count(self, outcome: str) -> None:
        self.outcomes[outcome] = self.outcomes.get(outcome, 0) + 1


Progress = Callable[[str, int, int], None]  # (stage, done, of)


def cover(
    source: ScenarioSource,
    settings: RunSettings,
    samples: int,
    closure: bool = False,
    executor: Executor | None = None,
    progress: Progress | None = None,
    database: Path | None = None,
) -> CampaignCoverage:
    """``samples`` samples of ``source``'s scenario drawn from ``settings.seed``, each run as a
    job; the buckets none hit proved unreachable where the planner proves it; with ``closure``,
    a case asked for each bucket still open (open in the coverage ``database`` of earlier runs
    too, when one is given: ``coverage_db``). The tally is the serial run's on any executor."""
    from ..sampling import drawn

    executor = executor or SerialExecutor()
    progress = progress or (lambda stage, done, of: None)
    checked = source.load()
    label = f"{source.path}::{checked.name}"
    campaign = CampaignCoverage(ScenarioCoverage.of(label, checked.coverage, fingerprint(checked)))
    values = drawn(checked, samples, settings.seed)
    jobs = [(source, settings, v) for v in values]
    for done, (outcome, tally) in enumerate(executor.results([(covered_case, job) for job in jobs]), 1):
        campaign.samples += 1
        campaign.without_plan += outcome == NO_PLAN
        campaign.count(outcome)
        campaign.coverage = _added(campaign.coverage, tally)
        progress("samples", done, len(jobs))
    _prove(checked, source, settings, campaign, executor)
    if closure:
        before = earlier(database, campaign.coverage)
        asked = closing_values(checked, merged([before, campaign.coverage])[0] if before else campaign.coverage)
        jobs = [(source, settings, tries) for _, _, tries in asked]
        for done, (ran, set_aside, outcome, tally) in enumerate(
            executor.results([(closing_case, job) for job in jobs]), 1
        ):
            campaign.closure_cases += ran
            campaign.closure_without_plan += set_aside
            if ran:
                campaign.count(outcome)
            campaign.coverage = _added(campaign.coverage, tally)
            progress("closure", done, len(jobs))
    return campaign


def _added(into: ScenarioCoverage, tally: ScenarioCoverage) -> ScenarioCoverage:
    return merged([into, tally])[0]


def _prove(
    checked: CheckedScenario, source: ScenarioSource, settings: RunSettings, campaign: CampaignCoverage, executor
) -> None:
    """Mark the buckets no case hit that the planner proves no case can reach (one job per item)."""
    jobs = [(source, settings, item.name, missed) for item, missed in open_questions(checked, campaign.coverage)]
    for (_, _, name, _), found in zip(jobs, executor.results([(proved_unreachable, job) for job in jobs]), strict=True):
        campaign.coverage.items[name].unreachable.update(found)


# ------------------------------------------------------------------ the jobs (run in a worker)


def covered_case(source: ScenarioSource, settings: RunSettings, values: dict[str, Any]) -> tuple[str, ScenarioCoverage]:
    """One sample run (planned, simulated, monitored): its outcome and what it covered."""
    checked = source.load()
    # as the plugin runs a sample: the fallbacks only where a sample without a plan is discarded
    result = _run(source, settings, values, fallbacks=settings.no_plan == DISCARD)
    tally = ScenarioCoverage.of(f"{source.path}::{checked.name}", checked.coverage)
    tally.add(checked.coverage, values, result.outcome, result.run)
    return result.outcome, tally


def closing_case(
    source: ScenarioSource, settings: RunSettings, tries: list[dict[str, Any]]
) -> tuple[bool, int, str, ScenarioCoverage]:
    """One bucket's closure: its tries in order until one has a plan. (whether a case ran, the
    tries set aside without a plan, the case's outcome, what it covered)."""
    checked = source.load()
    tally = ScenarioCoverage.of(f"{source.path}::{checked.name}", checked.coverage)
    result, aside = first_with_plan(tries, lambda values: _run(source, settings, values, fallbacks=True))
    if result is None:
        return False, len(aside), NO_PLAN, tally
    tally.add(checked.coverage, result.case.values, result.outcome, result.run)
    return True, len(aside), result.outcome, tally


def proved_unreachable(source: ScenarioSource, settings: RunSettings, name: str, labels: list[str]) -> dict[str, str]:
    """Of item ``name``'s buckets ``labels``, those no case can reach, with why."""
    checked = source.load()
    item = next(i for i in checked.coverage if i.name == name)
    return unreachable(checked, item, labels, settings, settings.seed)


def _run(source: ScenarioSource, settings: RunSettings, values: dict[str, Any], fallbacks: bool):
    runner = source.runner(settings)
    return runner.run_case(runner.case(strategy=REFINED, values=values), explain=False, fallbacks=fallbacks)
