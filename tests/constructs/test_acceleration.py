"""The acceleration modifier: the actor accelerates at a rate in the range while it moves in the
phase (a car braking to a standstill stands after). The checker reads it, the automaton hangs it on
the phase's timing, the planner keeps it on every step of the phase (stepping into it at once: the
vehicle's own dynamics), the monitor measures the mean, (v(end) - v(start)) / its length, from the
phase's start to its end or to a standstill, and the simulation brakes as the plan asks."""

from pathlib import Path

import numpy as np
import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import OscError, check_text
from pytest_roadlogic.monitor import monitor
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings
from pytest_roadlogic.simulation import Trace
from tests.planning.test_planning_continuous import check_continuous_plan

ROOT = Path(__file__).resolve().parents[2]
CORPUS_FILE = ROOT / "tests" / "corpus" / "50_acceleration.osc"


@pytest.fixture(scope="module")
def automaton():
    return build_automaton(load_scenario(CORPUS_FILE))


def test_the_timed_brake_carries_its_mean_acceleration_and_a_phase_without_duration_is_timed_for_it(automaton):
    by_name = {timing.name: timing for timing in automaton.timings.values()}
    brake, go = by_name["brake"], by_name["go"]
    assert (brake.low, brake.high) == (3.0, 6.0)
    assert [(r.actor, r.low, r.high) for r in brake.rates] == [("car1", -6.0, -3.0)]
    assert (go.low, go.high) == (0.0, float("inf")) and [(r.low, r.high) for r in go.rates] == [(1.0, 2.0)]
    assert "mean acceleration of car1 over brake in -6..-3 m/s^2" in automaton.describe()


@pytest.mark.parametrize("seed", [1, 2])
def test_a_plan_keeps_each_phases_mean_acceleration_in_range(automaton, seed):
    plan = ContinuousPlanner(automaton, ContinuousSettings(random_start=True), seed).first()
    check_continuous_plan(plan, automaton)  # check_run measures every phase's mean acceleration


def speed_trace(automaton, profile: list[tuple[float, float]], dt: float = 0.1, actor: str = "car1") -> Trace:
    """``actor`` driving the piecewise-linear speed ``profile`` ((time, speed) corners) in the lane its plan starts in."""
    lane = ContinuousPlanner(automaton, ContinuousSettings(), 1).first().states[actor][0].lane
    times = np.arange(0, profile[-1][0] + dt / 2, dt)
    speed = np.interp(times, *zip(*profile))
    x = np.concatenate([[0.0], np.cumsum((speed[1:] + speed[:-1]) / 2 * dt)])
    n = len(times)
    columns = {
        "x": x,
        "y": np.zeros(n),
        "heading": np.zeros(n),
        "speed": speed,
        "acceleration": np.gradient(speed, dt),
        "lane": np.full(n, lane),
    }
    return Trace(times, {actor: columns})


def test_a_brake_at_minus_4_25_mpsps_is_accepted(automaton):
    trace = speed_trace(automaton, [(0, 27), (4, 27), (8, 10), (9, 10), (16, 20), (17, 20)])
    verdict = monitor(automaton, trace)
    assert verdict.accepted, verdict.explain()


def test_a_brake_too_gentle_is_rejected_and_the_report_names_the_mean_acceleration_it_reached(automaton):
    # 27 to 10 m/s in 6 s: -2.83 m/s^2 wherever the run starts and ends the brake
    trace = speed_trace(automaton, [(0, 27), (4, 27), (10, 10), (11, 10), (18, 20), (19, 20)])
    verdict = monitor(automaton, trace)
    assert not verdict.accepted
    assert verdict.miss.guard == "mean acceleration of car1 over brake in -6..-3 m/s^2"
    assert verdict.miss.values["mean a(car1)"] == pytest.approx(-2.83, abs=0.01)
    assert verdict.miss.robustness == pytest.approx(-0.17, abs=0.01)
    assert "50_acceleration.osc:13:" in str(verdict.miss.locations[0])


HARD_STOP = """import osc.standard
scenario s:
    lead: car
    do serial:
        cruise: lead.drive(duration: 3s) with:
            lane(1)
            speed(100kph)
        stop: lead.change_speed(target: 0kph, duration: 6s) with:
            acceleration([-8mpsps..-6mpsps])
"""


@pytest.fixture(scope="module")
def hard_stop():
    checked = check_text(HARD_STOP, "hard_stop.osc")
    checked.raise_for_errors()
    return build_automaton(checked.scenarios[0])


def test_a_car_asked_to_brake_hard_to_a_stop_steps_into_the_braking_and_stands_when_it_has_stopped(hard_stop):
    plan = ContinuousPlanner(hard_stop, ContinuousSettings(), 1).first()
    check_continuous_plan(plan, hard_stop)  # every step of the stop brakes within -8..-6, or stands
    speeds = [s.speed for s in plan.states["lead"]]
    stop_begins = next(step for step, transition in plan.transitions if transition == 1)
    first = speeds[stop_begins + 1] - speeds[stop_begins]
    assert -8 <= first <= -6, f"the first step of the stop brakes at {first:.2f} m/s^2, not at once"
    assert speeds[-1] == pytest.approx(0.0, abs=1e-6)  # stopped within the 6 s phase, standing after


def test_a_brake_to_a_standstill_is_judged_up_to_the_standstill(hard_stop):
    # 27.8 m/s to 0 in 4 s (-6.9 m/s^2), then 2 s standing: the phase's own mean would be -4.6
    trace = speed_trace(hard_stop, [(0, 27.78), (3, 27.78), (7, 0.0), (11, 0.0)], actor="lead")
    assert monitor(hard_stop, trace).accepted
    # at -4.6 m/s^2 to the same standstill the braking itself is too gentle
    gentle = speed_trace(hard_stop, [(0, 27.78), (3, 27.78), (9, 0.0), (11, 0.0)], actor="lead")
    verdict = monitor(hard_stop, gentle)
    assert not verdict.accepted and verdict.miss.values["mean a(lead)"] == pytest.approx(-4.6, abs=0.1)


def test_a_simulated_car_brakes_as_its_plan_asks_at_the_instant_it_asks(hard_stop):
    """The frenetix driver of a car whose plan steps into hard braking: no braking before the
    step, 6 m/s^2 within half a second after it, never beyond the asked 8 m/s^2 by 1 m/s^2."""
    from pytest_roadlogic.simulation import simulate

    plan = ContinuousPlanner(hard_stop, ContinuousSettings(), 1).first()
    trace = simulate(plan).trace
    times = trace.times
    acceleration = trace.actors["lead"]["acceleration"]
    onset = next(step for step, transition in plan.transitions if transition == 1) * plan.dt
    before = acceleration[times < onset - 0.05]
    assert before.min() > -1.5, f"brakes at {before.min():.1f} m/s^2 before the stop begins"
    within = acceleration[(times >= onset) & (times <= onset + 0.5)]
    assert within.min() <= -6.0, f"reaches only {within.min():.1f} m/s^2 half a second into the stop"
    assert acceleration.min() >= -9.0, f"brakes at {acceleration.min():.1f} m/s^2, beyond the asked 8 by more than 1"
    assert monitor(hard_stop, trace).accepted


def scenario(modifier: str) -> str:
    return f"""import osc.standard
scenario s:
    car1: car
    do car1.change_speed(target: 10mps, duration: 4s) with:
        {modifier}
"""


@pytest.mark.parametrize(
    "modifier, message",
    [
        ("acceleration(-3mpsps, at: end)", "not supported: acceleration at: end"),
        ("acceleration(3mps)", "acceleration"),
    ],
)
def test_an_acceleration_the_tool_cannot_read_is_a_located_error(modifier, message):
    checked = check_text(scenario(modifier), "a.osc")
    if checked.errors:
        report = checked.report()
    else:
        with pytest.raises(OscError) as raised:
            build_automaton(checked.scenarios[0])
        report = raised.value.report()
    assert "a.osc:5:" in report and message in report, report


def test_the_grid_encoding_refuses_the_acceleration_modifier_at_its_place(automaton):
    from pytest_roadlogic.planning import GridPlanner, GridSettings

    with pytest.raises(OscError) as raised:
        GridPlanner(automaton, GridSettings(), 1).first()
    report = raised.value.report()
    assert "50_acceleration.osc:13:" in report and "continuous" in report, report


STOP_AND_STAND = HARD_STOP.replace(
    "            acceleration([-8mpsps..-6mpsps])\n",
    "            acceleration([-8mpsps..-6mpsps])\n        stand: lead.drive(duration: 3s) with:\n            speed(0kph)\n",
)


def test_a_car_asked_to_stand_with_speed_0kph_is_accepted_standing_still():
    # it stops 4 s into the 6 s brake and stands 5 s: a drive at 0 km/h asks no progress of it (it
    # had been required to creep forward, and a car standing exactly still was not accepted)
    checked = check_text(STOP_AND_STAND, "stop_and_stand.osc")
    checked.raise_for_errors()
    automaton = build_automaton(checked.scenarios[0])
    trace = speed_trace(automaton, [(0, 27.78), (3, 27.78), (7, 0.0), (14, 0.0)], actor="lead")
    assert monitor(automaton, trace).accepted
