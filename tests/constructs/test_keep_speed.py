"""keep_speed(): the speed the phase starts with, held through the phase within 1.5 m/s (docs/language.md),
planned on every step and judged on every sample, in one phase rather than one per band of starting speeds."""

from __future__ import annotations

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.monitor import monitor
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings, GridPlanner, GridSettings
from tests.constructs.test_acceleration import speed_trace
from tests.planning.test_planning import check_run

GO_THEN_HOLD = """\
scenario s:
    car1: car
    do serial:
        go: car1.drive(duration: 3s) with:
            lane(1)
            speed([15mps..25mps], at: start)
        hold: car1.keep_speed(duration: 6s)
"""


@pytest.fixture(scope="module")
def automaton():
    return build_automaton(check_text(GO_THEN_HOLD, path="hold.osc").scenarios[0])


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_a_plan_holds_the_speed_its_kept_phase_starts_with_on_every_step(automaton, seed):
    plan = ContinuousPlanner(automaton, ContinuousSettings(random_start=True), seed).first()
    check_run(plan, automaton)  # every step of the kept phase within the band of its first speed
    hold = next(p for p, t in automaton.timings.items() if t.name == "hold")
    assert hold in {p for t in automaton.transitions for p in t.starts}


def test_the_grid_holds_a_kept_speed_exactly(automaton):
    plan = GridPlanner(automaton, GridSettings(), 1).first()
    check_run(plan, automaton)
    begun = next(step for step, tid in plan.transitions if tid != plan.transitions[0][1])
    speeds = {round(state.speed, 6) for state in plan.states["car1"][begun:]}
    assert len(speeds) == 1, speeds


def test_a_speed_that_wobbles_by_1_mps_inside_the_kept_phase_is_accepted(automaton):
    trace = speed_trace(automaton, [(0, 20), (3, 20), (5, 19), (7, 20), (9, 20)])
    verdict = monitor(automaton, trace)
    assert verdict.accepted, verdict.explain()


def test_a_speed_that_dips_by_2_mps_and_recovers_inside_the_kept_phase_is_rejected_at_keep_speed(automaton):
    # the phase's two ends read the same speed: only the samples between them show the dip. The
    # best run starts the kept phase as late as the durations let it, at 3.5 s (19.4 m/s)
    trace = speed_trace(automaton, [(0, 20), (3, 20), (5, 17.5), (7, 20), (9, 20)])
    verdict = monitor(automaton, trace)
    assert not verdict.accepted
    assert verdict.miss.guard.startswith("keep_speed() of car1 over hold"), verdict.miss.guard
    assert verdict.miss.values["max |dv|(car1)"] == pytest.approx(1.875, abs=0.05)
    assert verdict.miss.robustness == pytest.approx(-0.375, abs=0.05)
    assert "hold.osc:7:" in str(verdict.miss.locations[0])


def test_keep_speed_after_a_change_of_lane_does_not_multiply_the_automaton():
    text = """\
scenario s:
    ego: car
    npc: car
    do serial:
        p1: parallel(duration: 4s):
            npc.drive() with:
                lane(1)
            ego.change_lane(num_of_lanes: 1, side: left)
        p2: parallel(duration: 4s):
            npc.drive()
            ego.change_lane(num_of_lanes: 1, side: right) with:
                keep_speed()
"""
    automaton = build_automaton(check_text(text).scenarios[0])
    without = build_automaton(check_text(text.replace(" with:\n                keep_speed()", "")).scenarios[0])
    assert len(automaton.transitions) == len(without.transitions)


def test_a_speed_held_exactly_is_well_inside_keep_speed_not_at_its_edge(automaton):
    # |v - v(start)| is never below 0: a bound there read every held speed as robustness 0
    trace = speed_trace(automaton, [(0, 20), (9, 20)])
    verdict = monitor(automaton, trace)
    assert verdict.accepted and verdict.robustness > 0.4, verdict.explain()
