"""Coverage closure by construction (``closing_values``): after a run's samples, one case asked
for each cover bucket no case hit and no proof rules out, its parameters held inside the bucket.

Random sampling hits a narrow bucket (or a narrow combination of a cross) only by chance, and
keeps drawing the wide ones; a bucket is a region of the parameter space, so a case can simply be
drawn from it. The case is a sample like any other: planned, simulated, monitored, counted.
Values the run takes at an event are the run's, not the sample's: their buckets are not asked.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from typing import Any

from ..frontend.semantics.checked import CheckedScenario
from ..frontend.semantics.coverage import Bucket, CoverItem, held
from ..outcomes import NO_PLAN
from .coverage import ScenarioCoverage

# where in a bucket (a share of its width, within the parameter's range) the values a closure
# tries lie, in the order tried: a bucket reachable only near one edge has no plan in its middle;
# a cross tries every combination of CROSS_SHARES, its middle first, then its corners
SHARES = (0.5, 0.2, 0.8, 0.02, 0.98)
CROSS_SHARES = (0.5, 0.02, 0.98)


def closing_values(checked: CheckedScenario, coverage: ScenarioCoverage) -> list[tuple[str, str, list[dict[str, Any]]]]:
    """(item, bucket label, values to try in order) for each bucket of ``checked``'s cover items
    on logical parameters that ``coverage`` has not hit and not proved unreachable: each holds
    every parameter inside its bucket and its own range (a choice: itself), at the ``SHARES`` of
    the bucket's width (a cross: each combination of ``CROSS_SHARES``)."""
    items = {item.name: item for item in checked.coverage}
    parameters = {p.name: p for p in checked.parameters}
    asked = []
    for item in checked.coverage:
        if item.kind != "cover" or item.observed is not None:
            continue
        parts = [items[name] for name in item.crossed] if item.crossed else [item]
        if any(part.observed is not None for part in parts):
            continue
        tally = coverage.items[item.name]
        for bucket in item.buckets:
            if tally.buckets.get(bucket.label, 0) >= item.target or bucket.label in tally.unreachable:
                continue
            holds = held(item, bucket, items)
            if len(holds) == 1:
                combinations = [(share,) for share in SHARES]
            else:
                combinations = sorted(
                    itertools.product(CROSS_SHARES, repeat=len(holds)), key=lambda c: sum(abs(x - 0.5) > 0 for x in c)
                )
            tries = []
            for shares in combinations:
                values = {
                    part.parameter: _inside(parameters[part.parameter], b, share)
                    for (part, b), share in zip(holds, shares)
                }
                if values not in tries:
                    tries.append(values)
            asked.append((item.name, bucket.label, tries))
    return asked


def _inside(parameter, bucket: Bucket, share: float) -> Any:
    if bucket.choice is not None:
        return bucket.choice
    low, high = max(bucket.low, parameter.low), min(bucket.high, parameter.high)
    value = low + (high - low) * share
    return round(value) if parameter.integer else round(value, 1)


def closed(item: CoverItem, coverage: ScenarioCoverage) -> bool:
    """Whether every bucket of ``item`` is hit its target times or proved unreachable."""
    tally = coverage.items[item.name]
    return all(hits >= item.target or label in tally.unreachable for label, hits in tally.buckets.items())


def first_with_plan(tries: list[dict[str, Any]], run: Callable[[dict[str, Any]], Any]) -> tuple[Any, list[Any]]:
    """One bucket's closure case: ``run`` (values -> ``runner.CaseResult``) on its tries in order
    until one has a plan; (that result, None when none has, and the results before it, each
    without a plan: set aside as a sample without a plan is). The bucket has plans (no proof
    rules it out), only not at every value tried."""
    aside = []
    for values in tries:
        result = run(values)
        if result.outcome != NO_PLAN:
            return result, aside
        aside.append(result)
    return None, aside
