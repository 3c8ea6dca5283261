"""Blame: which sampled value is to blame for a sample that has no plan, and whether any has one.

A refined sample's values are drawn independently, but a scenario constrains them together. When
a sample has no plan, the question a tester asks is whether the file is wrong (a value that no
concrete scenario has, whatever the others: the *culprit*), the scenario is wrong as a whole (no
values at all have a plan), or only this combination has none (set aside). Each answer is a
planning alone (``has_plan``: no simulation), of the scenario narrowed to some of the values.
The runner asks; the pipeline and the planner know nothing of it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import Any

from .case import Case
from .frontend import CheckedScenario
from .frontend.semantics.logical import WAY
from .outcomes import CANNOT_INSTANTIATE
from .planning import PlannerSettings, settings_for
from .planning.fallbacks import planned
from .problem import problem_for
from .settings import RunSettings

# the ways through the map a value is tried alone on before it is blamed (``Blame.ways_to_try``)
WAYS_TRIED = 3


def has_plan(
    scenario: CheckedScenario,
    values: dict[str, object],
    seed: int = 1,
    settings: PlannerSettings | None = None,
    fallbacks: bool = True,
    beyond_limits: bool = True,
) -> bool:
    """Whether the scenario narrowed to ``values`` has a plan (planning alone: no simulation), with
    every fallback ``run_instances`` tries or, without ``fallbacks``, within the planner's margins
    and limits; without ``beyond_limits``, the fallbacks stay within a real car's limits
    (``planning.fallbacks.CAR_LIMITS`` are never relaxed). A planning timeout or a horizon that binds is no proof that
    the values have none, and counts as a plan."""
    from .planning import HorizonTooShort, NoPlanError, PlanningTimeout

    settings = dataclasses.replace(settings or settings_for(RunSettings()), explain_unsatisfiable=False)
    problem = problem_for(scenario, values, settings, seed)
    try:
        return (
            next(planned(problem.guide, problem.settings, problem.seed, 1, fallbacks, beyond_limits), None) is not None
        )
    except (PlanningTimeout, HorizonTooShort):
        return True
    except NoPlanError:
        return False


class Blame:
    """The blame for a scenario's samples without a plan, under one ``RunSettings``: whether the
    scenario has a plan at any values (asked once), and which value has none alone."""

    def __init__(self, scenario: CheckedScenario, settings: RunSettings) -> None:
        self.scenario = scenario
        self.settings = settings
        self._plannable: bool | None = None

    def blamed(self, case: Case, result, rerun: Callable[[Case], Any]):
        """A sample without a plan within the planner's margins and limits (``result``), with the
        value to blame for it (``culprit``), or none when only the values together have no plan.

        Why: parameters are drawn independently, but a scenario constrains them together (a brake
        of 3 s from 120 to 30 kph needs more than the 6 m/s^2 the file allows), so a sample can
        fall outside the logical scenario while every value in it lies inside. Such a sample is no
        instance to test, where a value that no concrete scenario has is a defect of the file
        (catch_up_band's gaps above its edge). A sample may have plans only beyond the planner's
        margins or jerk limit, whose simulations are then seldom accepted, while each of its values
        alone has plans within them (docs/decisions.md). So the values are tried alone first, within
        the margins and limits, and only a sample with a value that has none there is planned again
        with the fallbacks (``planning.fallbacks``, by ``rerun``), whose result it then reports. When that
        result is that only a plan beyond a real car's limits exists, the culprit is a value that
        alone has no plan within them even with the other fallbacks; without one, the sample is a
        combination no car can drive and is set aside like any other (follow_then_overtake's long
        passes from far behind to close ahead)."""
        # A way through the map is never to blame: the file asks for a junction of the map, and a
        # way of it on which the scenario has no plan is no defect of the file; its samples are set
        # aside, as combinations are. The other values are tried alone on the sample's own ways and
        # on the map's first WAYS_TRIED: one with no plan on any of them is taken to have none on
        # any way (trying every way is the map's size in plans).
        ways = {p.name for p in self.scenario.parameters if p.kind == WAY}
        values = {name: value for name, value in case.values.items() if name not in ways}
        taken = {name: value for name, value in case.values.items() if name in ways}
        if self._plannable is None:  # once per runner: one planning of the scenario as written
            self._plannable = has_plan(self.scenario, {}, self.settings.seed, settings_for(self.settings, False))
        if not self._plannable:
            result.at_no_values = True  # no value is to blame: none has a plan (infeasible_order)
            return result
        # a single value is the sample: it has no plan alone
        alone = len(case.values) == 1
        candidates = (
            list(values) if alone else self.without_plan_alone(values, fallbacks=False, first=False, ways=taken)
        )
        if (values or ways) and not candidates:
            return result
        result = rerun(case)
        if result.kind == CANNOT_INSTANTIATE and values:
            blamed = (
                candidates
                if alone
                else self.without_plan_alone({n: values[n] for n in candidates}, beyond_limits=False, ways=taken)
            )
            result.culprit = next(iter(blamed), None)
        return result

    def ways_to_try(self, taken: dict[str, Any]) -> list[dict[str, Any]]:
        """The ways a value is tried alone on: the sample's own (``taken``; none: the scenario's
        first), then the map's first answers unlike them, ``WAYS_TRIED`` in all. Why several: the
        sample's ways may be the map's first, and a value with no plan on one way of a town may
        have plans on the next junction."""
        tried = [taken]
        ways = self.scenario.ways
        if ways is None:
            return tried
        named = {p.name for p in self.scenario.parameters if p.kind == WAY}
        for combination in ways.combinations:
            if len(tried) >= WAYS_TRIED:
                break
            answer = {path: ways.labels[t] for path, t in zip(ways.paths, combination) if path in named}
            if answer != taken and answer not in tried:
                tried.append(answer)
        return tried

    def without_plan_alone(
        self,
        values: dict[str, Any],
        fallbacks: bool = True,
        first: bool = True,
        beyond_limits: bool = True,
        ways: dict[str, Any] | None = None,
    ) -> list[str]:
        """The sampled parameters whose value alone, the others left to their ranges, has no plan
        (only the first unless ``first`` is false; with ``fallbacks``, or within the planner's
        margins and limits; without ``beyond_limits``, none beyond a real car's limits); empty
        when each has one (then only the combination has none). Planning alone, one parameter at
        a time, in the order of the report. With ``ways`` (the ways through the map a sample
        took), a value has no plan alone when it has none on those nor on the map's first others
        (``ways_to_try``)."""
        settings = settings_for(self.settings, False)
        found = []
        for name, value in values.items():
            if any(
                has_plan(self.scenario, {name: value, **taken}, self.settings.seed, settings, fallbacks, beyond_limits)
                for taken in self.ways_to_try(ways or {})
            ):
                continue
            found.append(name)
            if first:
                break
        return found
