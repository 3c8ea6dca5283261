"""The numbers the report shows, computed from a run's records and nothing else.

Kept apart from the report's formatting so that a test can recompute them from ``results.json``
and compare them with what ``report.md`` says.
"""

from __future__ import annotations

import math
import statistics
from dataclasses import dataclass

from ..outcomes import CONFORMANT, OUTCOMES, STAGES, TIMED_OUT
from ..settings import BASE, REFINED
from .bench import STRATEGIES, BenchmarkResults, InstanceRecord
from .occupancy import mean_pairwise, similarity_matrix

# the acceptance targets
BASE_CONFORMANT = 1.0
REFINED_CONFORMANT = 0.98


@dataclass(frozen=True)
class StrategySummary:
    """One scenario under one strategy."""

    scenario: str
    strategy: str
    instances: int
    outcomes: dict[str, int]
    mean_seconds: dict[str, float]  # per instance and stage
    total_seconds: float  # all instances, all stages
    mean_tries: float  # over instances with a simulation
    similarity: list[list[float]]  # pairwise Jaccard of the instances with a simulation
    mean_similarity: float
    unasked: int = 0  # instances whose plan has a change no construct of its vehicle asks for

    @property
    def conformant(self) -> float:
        return self.outcomes[CONFORMANT] / self.instances if self.instances else math.nan


def summarize(records: list[InstanceRecord], scenario: str, strategy: str) -> StrategySummary:
    simulated = [r for r in records if r.occupancy is not None]
    matrix = similarity_matrix([r.occupancy for r in simulated])
    return StrategySummary(
        scenario,
        strategy,
        len(records),
        {outcome: sum(r.outcome == outcome for r in records) for outcome in OUTCOMES},
        {stage: statistics.fmean(r.seconds.get(stage, 0.0) for r in records) if records else 0.0 for stage in STAGES},
        sum(sum(r.seconds.values()) for r in records),
        statistics.fmean(r.tries for r in simulated) if simulated else math.nan,
        matrix,
        mean_pairwise(matrix),
        sum(bool(r.unasked) for r in records),
    )


def summaries(results: BenchmarkResults) -> dict[tuple[str, str], StrategySummary]:
    return {
        (scenario, strategy): summarize(results.of(scenario, strategy), scenario, strategy)
        for scenario in [*results.scenarios, *results.realistic]
        if scenario not in results.errors
        for strategy in STRATEGIES
    }


@dataclass(frozen=True)
class Target:
    name: str
    met: bool
    detail: str


def targets(results: BenchmarkResults, table: dict[tuple[str, str], StrategySummary]) -> list[Target]:
    """The acceptance targets, each met or not, with the scenarios that miss it."""
    scenarios = [s for s in results.scenarios if s not in results.errors]
    base_misses = [s for s in scenarios if not table[s, BASE].conformant >= BASE_CONFORMANT]
    refined_misses = [s for s in scenarios if not table[s, REFINED].conformant >= REFINED_CONFORMANT]
    timeouts = [s for s in scenarios if table[s, REFINED].outcomes[TIMED_OUT]]
    diversity_misses = [s for s in scenarios if not table[s, REFINED].mean_similarity < table[s, BASE].mean_similarity]
    errors = sorted(results.errors)

    def detail(misses: list[str]) -> str:
        return "all scenarios" if not misses else "missed by " + ", ".join(misses)

    return [
        Target(
            "every scenario loads and runs",
            not errors,
            "all scenarios" if not errors else "failed: " + ", ".join(errors),
        ),
        Target("base strategy: 100% conformant", not base_misses, detail(base_misses)),
        Target(
            f"refined strategy: at least {REFINED_CONFORMANT:.0%} conformant",
            not refined_misses,
            detail(refined_misses),
        ),
        Target("refined strategy: no timeouts", not timeouts, detail(timeouts)),
        Target("refined mean similarity below base", not diversity_misses, detail(diversity_misses)),
    ]


def targets_met(results: BenchmarkResults, table: dict[tuple[str, str], StrategySummary]) -> tuple[bool, list[str]]:
    """Whether every target is met, and one line per target for a terminal."""
    found = targets(results, table)
    return all(t.met for t in found), [f"{'met' if t.met else 'MISSED'}: {t.name} ({t.detail})" for t in found]
