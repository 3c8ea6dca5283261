"""A falsification campaign (``roadlogic falsify``): several searches for a failing case of one
scenario, each an independent job on an executor (``executors``).

One search learns from its own samples (``settings.search``: Hypothesis's targeting, or a backend
of ``falsification`` steered by cross-entropy from the first sample), so its samples run one after
another; searches from different seeds share nothing, and a cluster runs them side by side. Each
search runs as the pytest plugin runs an item (its samples planned, simulated and monitored, the
vehicle under test's margin or the monitor's robustness as Hypothesis's target), without the
example database (a search is fixed by its seed alone), and ends at its first failure, shrunk to
the simplest values that still fail, or after its budget. The campaign reports each search and
the first failure in the order of the searches: the same whichever executor ran them.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ..executors import Executor, SerialExecutor
from ..settings import RunSettings
from .scenario_source import ScenarioSource


@dataclass(frozen=True)
class Failure:
    """A failing case a search found: its values, outcome, kind of failure, why, and the command
    that replays it."""

    values: dict[str, Any]
    outcome: str
    kind: str
    message: str
    replay: str


@dataclass(frozen=True)
class SearchOutcome:
    """One search: its sampling seed, the samples it ran before its first failure (all of its
    budget without one), and the failure, shrunk (None without one)."""

    seed: int | str
    samples: int
    failure: Failure | None


def search_seeds(seed: int, searches: int) -> list[int | str]:
    """The sampling seeds of ``searches`` searches: the run's own first (the search a pytest item
    of this seed makes), then one per search derived from it."""
    return [seed, *(f"{seed}-search-{k}" for k in range(1, searches))]


def falsify(
    source: ScenarioSource,
    settings: RunSettings,
    searches: int,
    budget: int,
    executor: Executor | None = None,
    progress: Callable[[SearchOutcome, int, int], None] | None = None,
) -> list[SearchOutcome]:
    """``searches`` searches of ``budget`` samples each for a failing case of ``source``'s scenario
    under ``settings``, as jobs on ``executor``; each search's outcome, in the order of the seeds."""
    executor = executor or SerialExecutor()
    jobs = [(falsification_search, (source, settings, seed, budget)) for seed in search_seeds(settings.seed, searches)]
    found = []
    for done, outcome in enumerate(executor.results(jobs), 1):
        found.append(outcome)
        if progress is not None:
            progress(outcome, done, len(jobs))
    return found


class _Falsified(Exception):
    def __init__(self, result) -> None:
        super().__init__(result.message)
        self.result = result


def falsification_search(source: ScenarioSource, settings: RunSettings, seed: int | str, budget: int) -> SearchOutcome:
    """One search (a job): its samples until a failure, which Hypothesis then shrinks."""
    runner = source.runner(settings)
    ran = 0
    first: int | None = None  # the samples run when the first failure came (shrinking runs more)

    def each(result) -> None:
        nonlocal ran, first
        ran += 1
        if result.failed:
            first = ran if first is None else first
            raise _Falsified(result)

    try:
        runner.refined(each, count=budget, search=True, sampling_seed=seed, keep_examples=False)
    except _Falsified as found:
        result = found.result
        case = dataclasses.replace(result.case, path=str(source.path))
        failure = Failure(dict(case.values), result.outcome, result.kind, result.message, case.command())
        return SearchOutcome(seed, first or ran, failure)
    return SearchOutcome(seed, ran, None)
