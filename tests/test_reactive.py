"""Reactive execution: the rest of a scenario planned again from observed states, checked on the
plan's own terms (what is pinned is pinned, the run so far is kept, a constraint relative to the
vehicle under test follows where it really is) and end to end (the scenario happens around a
vehicle under test that does not drive as planned)."""

from __future__ import annotations

from pathlib import Path

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.dut import UnderTest
from pytest_roadlogic.pipeline import guided_planning, load_scenario, run_instances
from pytest_roadlogic.planning import settings_for
from pytest_roadlogic.planning.fallbacks import planned
from pytest_roadlogic.planning.plan import PlanState
from pytest_roadlogic.reactive import Replanner
from pytest_roadlogic.settings import RunSettings

ROOT = Path(__file__).resolve().parents[1]
CUT_IN = ROOT / "scenarios" / "dut" / "cut_in.osc"
VALUES = {
    "approach.duration": 3.0,
    "brake.duration": 4.2,
    "cut_in.duration": 3.5,
    "cut_in_gap": 23.7,
    "dut_speed": 28.9,
    "npc.change_speed.target": 18.4,
    "npc.drive.position.distance": 20.0,
    "npc.drive.speed.speed": 4.3,
}


@pytest.fixture(scope="module")
def planning():
    scenario = load_scenario(CUT_IN)
    guide, settings, seed = guided_planning(scenario, build_automaton(scenario), VALUES, settings_for(RunSettings()), 1)
    plan = next(planned(guide, settings, seed, 1))
    return Replanner(guide(settings), settings, seed, "dut.car"), plan


def observed_at(plan, step, **moved):
    """Every vehicle where ``plan`` has it at ``step``; ``moved``: vehicle -> (metres, m/s) added."""
    states = {}
    for vehicle, trajectory in plan.states.items():
        state = trajectory[step]
        dx, dv = moved.get(vehicle.replace(".", "_"), (0.0, 0.0))
        states[vehicle] = PlanState(state.position + dx, state.lane, state.speed + dv)
    return states


def test_a_replan_pins_every_vehicle_where_it_was_observed_and_keeps_the_run_so_far(planning):
    replanner, plan = planning
    step = 4
    observed = observed_at(plan, step, dut_car=(-6.0, -3.0))
    replan = replanner.replan(plan, step, observed)
    assert replan.plan is not None, replan.why
    for vehicle, state in observed.items():
        now = replan.plan.states[vehicle][step]
        assert now.position == pytest.approx(state.position, abs=1e-3)
        assert now.speed == pytest.approx(state.speed, abs=1e-3)
        assert now.lane == state.lane
    assert [t for t in replan.plan.transitions if t[0] < step] == [t for t in plan.transitions if t[0] < step]
    assert replan.plan.horizon > step


def test_the_vehicle_under_test_is_predicted_at_its_observed_speed_and_the_npc_meets_its_gap_to_where_it_really_is(
    planning,
):
    replanner, plan = planning
    step = 3
    replan = replanner.replan(plan, step, observed_at(plan, step, dut_car=(-10.0, -2.0)))
    assert replan.predicted, "a plan exists with the vehicle under test at its observed speed"
    dut = replan.plan.states["dut.car"]
    assert all(s.speed == pytest.approx(dut[step].speed, abs=1e-3) for s in dut[step:])
    # the cut-in ends cut_in_gap ahead of the vehicle under test (within the planning cell), in its lane
    cut_in_ends = plan.transitions[2][1]  # start, approach -> cut-in, cut-in -> brake, end
    end = next(at for at, transition in replan.plan.transitions if transition == cut_in_ends)
    npc = replan.plan.states["npc"][end]
    assert npc.lane == dut[end].lane
    assert npc.position - dut[end].position == pytest.approx(VALUES["cut_in_gap"], abs=1.5)


def test_no_vehicle_limit_binds_the_past_so_a_vehicle_under_test_that_braked_harder_than_a_plan_may_still_replans(
    planning,
):
    replanner, plan = planning
    # 6 m/s slower than a second before: beyond the plan's jerk limit, which binds only the future
    assert plan.states["dut.car"][1].speed - (plan.states["dut.car"][2].speed - 4.0) > 6.0
    replan = replanner.replan(plan, 2, observed_at(plan, 2, dut_car=(-3.0, -4.0)))
    assert replan.plan is not None, replan.why


def test_a_replan_that_finds_no_plan_says_why_and_keeps_nothing(planning):
    replanner, plan = planning
    # the npc observed 80 m behind and slower: no cut-in 23.7 m ahead of the vehicle under test can come
    replan = replanner.replan(plan, 5, observed_at(plan, 5, npc=(-80.0, -10.0)))
    assert replan.plan is None
    assert "cannot go on" in replan.why and "t=5 s" in replan.why


def test_with_replanning_the_cut_in_happens_around_a_vehicle_under_test_that_does_not_drive_as_planned():
    scenario = load_scenario(CUT_IN)
    reactive = next(run_instances(scenario, 1, values=VALUES, under_test=UnderTest(), max_tries=1))
    scripted = next(run_instances(scenario, 1, values=VALUES, under_test=UnderTest(replan_period=0), max_tries=1))
    assert reactive.verdict.accepted and not reactive.dut.failed, reactive.verdict.explain()
    assert reactive.simulation.replans and all(r.plan is not None for r in reactive.simulation.replans)
    assert not scripted.verdict.accepted and not scripted.simulation.replans
