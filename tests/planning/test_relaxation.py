"""A sample with no plan, proved by the planning problem's linear relaxation before any search
(planning/relaxation.py): it must never refuse a sample some planner plans, and it names the
constraints that clash as the diagnosis does."""

from __future__ import annotations

import dataclasses

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.pipeline import guided_planning, load_scenario
from pytest_roadlogic.planning import NoPlanError, UnsatisfiableScenario, planner_for
from pytest_roadlogic.planning import settings_for as planner_settings
from pytest_roadlogic.planning.fallbacks import fallback_settings, planned
from pytest_roadlogic.planning.relaxation import provably_unplannable
from pytest_roadlogic.settings import RunSettings
from tests.conftest import ROOT

CATCH_UP = ROOT / "scenarios" / "realistic" / "catch_up_band.osc"
FASTEST = 100.0  # m/s: the relaxed fallback's top speed (ContinuousSettings.relaxed())


def guided(path, values):
    scenario = load_scenario(path)
    return guided_planning(scenario, build_automaton(scenario), values, planner_settings(RunSettings()), 1)


def test_a_gap_no_allowed_speed_closes_in_time_is_refused_before_any_search_naming_what_clashes():
    guide, settings, seed = guided(CATCH_UP, {"lead_gap": 290.0})
    with pytest.raises(UnsatisfiableScenario) as raised:
        next(planned(guide, settings, seed, 1))
    (conflict,) = raised.value.conflicts
    # the duration, both speeds and both gaps: the diagnosis's own five
    assert sorted(c.source.line for c in conflict) == [14, 17, 20, 21, 22]
    assert "linear relaxation" in str(raised.value)


def test_a_gap_the_ego_can_close_is_left_to_the_planner():
    guide, settings, _ = guided(CATCH_UP, {"lead_gap": 150.0})
    assert provably_unplannable(guide(settings.thinned()), FASTEST) is None


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(gap=st.floats(170.0, 230.0))
def test_the_relaxation_never_refuses_a_gap_that_some_planner_plans(gap):
    """Near the edge, where the relaxation and the planners part: whenever the relaxation refuses
    a sample, no fallback planner (the widest margins, half steps, limits beyond a car's) plans it."""
    guide, settings, seed = guided(CATCH_UP, {"lead_gap": gap})
    if provably_unplannable(guide(settings.thinned()), FASTEST) is None:
        return
    for fallback, _ in fallback_settings(settings):
        quiet = dataclasses.replace(fallback, time_limit=20.0)
        try:
            plan = next(planner_for(guide(quiet), quiet, seed).plans(limit=1), None)
        except NoPlanError:
            plan = None
        assert plan is None, f"the relaxation refused lead_gap {gap:.1f} m, which {fallback} plans"
