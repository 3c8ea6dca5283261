"""The continuous-dynamics encoding (asp/continuous.lp): its plans obey the vehicle limits, exact
constant-acceleration kinematics, the lane rules, the gaps and the scenario's guards and durations,
checked here independently of the encoding."""

from pathlib import Path

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning.continuous import ContinuousPlanner, ContinuousSettings
from tests.test_planning import check_run

ROOT = Path(__file__).resolve().parent.parent
SETTINGS = ContinuousSettings()


def check_continuous_plan(plan, automaton, settings=SETTINGS):
    dt = plan.dt
    for v in plan.vehicles:
        states = plan.states[v]
        changes = [k for k in range(1, len(states)) if states[k].lane != states[k - 1].lane]
        for k, s in enumerate(states):
            assert settings.min_speed - 1e-6 <= s.speed <= settings.max_speed + 1e-6, f"{v} speed {s.speed} at {k}"
            assert 0 <= s.lane < automaton.lanes
            if k:
                p = states[k - 1]
                acceleration = (s.speed - p.speed) / dt
                assert settings.min_acceleration - 1e-6 <= acceleration <= settings.max_acceleration + 1e-6, f"{v} acceleration {acceleration} at {k}"
                assert s.position == pytest.approx(p.position + (p.speed + s.speed) / 2 * dt, abs=1e-6), f"{v} kinematics at {k}"
            if k >= 2:
                change = (s.speed - 2 * states[k - 1].speed + states[k - 2].speed) / dt
                assert abs(change) <= settings.max_jerk * dt + 1e-6, f"{v} acceleration jumps by {change} at {k}"
                assert abs(s.lane - p.lane) <= 1
        for a, b in zip(changes, changes[1:]):
            assert b - a >= settings.lane_change_gap
        for k in changes:
            assert k >= 2, f"{v} changes lane in the first step, before the simulation could start the move"
            assert min(states[k - 1].speed, states[k].speed) >= settings.lane_change_speed - 1e-6, f"{v} changes lane at a crawl at {k}"

    vehicles = plan.vehicles
    for i, a in enumerate(vehicles):
        for b in vehicles[i + 1 :]:
            for k in range(plan.horizon + 1):
                lanes_a = {plan.at(a, k).lane} | ({plan.at(a, k - 1).lane} if k else set())
                lanes_b = {plan.at(b, k).lane} | ({plan.at(b, k - 1).lane} if k else set())
                if lanes_a & lanes_b:
                    assert abs(plan.at(a, k).position - plan.at(b, k).position) >= settings.min_gap - 1e-6, f"{a} and {b} too close at {k}"
    check_run(plan, automaton)


@pytest.mark.parametrize("path", [ROOT / "scenarios" / "overtake.osc", ROOT / "scenarios" / "overtake_third_actor.osc", ROOT / "benchmarks" / "realistic" / "cut_in.osc"], ids=lambda p: p.stem)
@pytest.mark.parametrize("seed", [1, 2])
def test_a_continuous_plan_obeys_the_limits_the_kinematics_and_the_guards(path, seed):
    automaton = build_automaton(load_scenario(path))
    plan = ContinuousPlanner(automaton, SETTINGS, seed).first()
    check_continuous_plan(plan, automaton)


def test_speeds_are_not_on_a_grid():
    # cut_in asks for speeds in kph: whole m/s would be a coincidence, not a rule
    automaton = build_automaton(load_scenario(ROOT / "benchmarks" / "realistic" / "cut_in.osc"))
    plan = ContinuousPlanner(automaton, SETTINGS, 1).first()
    assert any(not float(s.speed).is_integer() for states in plan.states.values() for s in states)


def test_no_horizon_shorter_than_the_durations_allow_is_searched():
    automaton = build_automaton(load_scenario(ROOT / "benchmarks" / "realistic" / "follow_then_overtake.osc"))
    import time

    assert ContinuousPlanner(automaton, SETTINGS, 1).earliest_horizon(time.monotonic() + 30) == 24, "10 + 3 + 8 + 3 s at least"


def test_a_plan_without_a_run_up_is_simulated_from_its_first_state_and_can_be_accepted():
    from pytest_roadlogic.monitor import monitor
    from pytest_roadlogic.simulation import simulate

    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "change_lane.osc"))
    plan = ContinuousPlanner(automaton, SETTINGS, 1).first()
    assert plan.runup == 0
    simulation = simulate(plan)
    trace = simulation.trace
    for vehicle, states in plan.states.items():
        assert trace.actors[vehicle]["x"][0] == pytest.approx(states[0].position)
        assert trace.actors[vehicle]["speed"][0] == pytest.approx(states[0].speed), "no standstill start: the scenario's first instant is the simulation's"
    assert monitor(automaton, trace).accepted
