"""A speed change's shape, the standard's ``dynamics_shape`` (``change_speed(target, rate_profile:
shape, rate_peak: p)``): linear at p throughout, cubic and sinusoidal from no acceleration to p
and back, step at once (at the car's limit). The plan keeps the shape on every step; the monitor
judges the peak the shape implies from the change and its time."""

import math

import numpy as np
import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.logic.automaton import SHAPE_PEAK_OVER_MEAN, ShapedSpeedChange
from pytest_roadlogic.monitor import monitor
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings
from pytest_roadlogic.planning.encodings.continuous.instance import SHAPE_SLACK, shape_share
from pytest_roadlogic.simulation import Trace
from tests.constructs.test_acceleration import speed_trace
from tests.planning.test_planning_continuous import check_continuous_plan

HEADER = "import osc.standard\n\nscenario top:\n    path: Path\n    car1: car\n"
CHANGE = (
    HEADER
    + """    do serial:
        cruise: car1.drive(duration: 3s) with:
            speed(25mps)
        change: car1.change_speed(target: {target}{arguments})
"""
)


def checked(target: str, arguments: str):
    return check_text(CHANGE.format(target=target, arguments=arguments), "top.osc")


def automaton_of(target: str, arguments: str):
    scenario = checked(target, arguments)
    scenario.raise_for_errors()
    return build_automaton(scenario.scenarios[0])


def shaped(automaton) -> ShapedSpeedChange:
    (rate,) = [r for t in automaton.timings.values() for r in t.rates]
    assert isinstance(rate, ShapedSpeedChange)
    return rate


def change_steps(plan, automaton) -> tuple[int, int]:
    """The plan's steps at which the change phase begins and ends."""
    (phase,) = [phase for phase, timing in automaton.timings.items() if timing.rates]
    begin = next(step for step, t in plan.transitions if phase in automaton.transitions[t].starts)
    end = next(step for step, t in plan.transitions if phase in automaton.transitions[t].ends)
    return begin, end


def test_the_standards_shapes_are_read_in_both_its_names_and_smooth_is_no_shape():
    plain = automaton_of("10mps", ", rate_peak: 3mpss")
    for old, new in (("constant", "linear"), ("asap", "step")):
        assert (
            automaton_of("10mps", f", rate_profile: {old}, rate_peak: 3mpss").describe()
            == automaton_of("10mps", f", rate_profile: {new}, rate_peak: 3mpss").describe()
        )
    assert automaton_of("10mps", ", rate_profile: smooth, rate_peak: 3mpss").describe() == plain.describe()
    assert shaped(automaton_of("10mps", ", rate_profile: cubic, rate_peak: 3mpss")).shape == "cubic"
    # a parameter of the standard's type gives its value
    text = CHANGE.format(target="10mps", arguments=", rate_profile: form, rate_peak: 3mpss").replace(
        "    car1: car\n", "    car1: car\n    form: dynamics_shape = sinusoidal\n"
    )
    scenario = check_text(text, "top.osc")
    scenario.raise_for_errors()
    assert shaped(build_automaton(scenario.scenarios[0])).shape == "sinusoidal"


def test_a_shape_with_a_peak_needs_the_peak_and_a_step_says_its_peak_has_no_effect():
    errors = [d for d in checked("10mps", ", rate_profile: linear").diagnostics if d.severity == "error"]
    assert [(d.location.line, d.location.column, d.message) for d in errors] == [
        (9, 50, "rate_profile: linear needs rate_peak: the peak acceleration of the change")
    ]
    warnings = [
        d for d in checked("10mps", ", rate_profile: step, rate_peak: 3mpss").diagnostics if d.severity == "warning"
    ]
    assert [d.message.split(":")[0] for d in warnings] == ["rate_peak has no effect with rate_profile"]
    wrong = [d for d in checked("10mps", ", rate_profile: left, rate_peak: 3mpss").diagnostics if d.severity == "error"]
    assert "takes linear, cubic, sinusoidal, step, constant, smooth or asap" in wrong[0].message


def test_a_linear_stop_brakes_at_its_peak_on_every_step_but_the_last():
    automaton = automaton_of("0kph", ", rate_profile: linear, rate_peak: 6mpss")
    plan = ContinuousPlanner(automaton, ContinuousSettings(), 1).first()
    check_continuous_plan(plan, automaton)
    begin, end = change_steps(plan, automaton)
    speeds = [s.speed for s in plan.states["car1"]]
    rates = [(speeds[k] - speeds[k - 1]) / plan.dt for k in range(begin + 1, end + 1)]
    assert all(-6.5 - 1e-6 <= a <= -5.5 + 1e-6 for a in rates[:-1]), rates
    assert -6.5 - 1e-6 <= rates[-1] <= 1e-6
    assert speeds[end] <= 0.5 + 1e-6


@pytest.mark.parametrize("shape", ["cubic", "sinusoidal"])
def test_a_smooth_shape_follows_its_curve_and_peaks_at_the_asked_rate(shape):
    automaton = automaton_of("10mps", f", rate_profile: {shape}, rate_peak: 4mpss")
    plan = ContinuousPlanner(automaton, ContinuousSettings(), 1).first()
    check_continuous_plan(plan, automaton)
    begin, end = change_steps(plan, automaton)
    speeds = [s.speed for s in plan.states["car1"]]
    length = end - begin
    start, final = speeds[begin], speeds[end]
    for k in range(1, length):
        expected = start + shape_share(shape, k / length) * (final - start)
        assert speeds[begin + k] == pytest.approx(expected, abs=SHAPE_SLACK + 1e-4)
    peak = SHAPE_PEAK_OVER_MEAN[shape] * abs(final - start) / (length * plan.dt)
    assert 3.5 - 1e-6 <= peak <= 4.5 + 1e-6


def test_a_step_is_planned_at_the_cars_limit():
    automaton = automaton_of("10mps", ", rate_profile: step")
    settings = ContinuousSettings()
    plan = ContinuousPlanner(automaton, settings, 1).first()
    check_continuous_plan(plan, automaton)
    begin, end = change_steps(plan, automaton)
    speeds = [s.speed for s in plan.states["car1"]]
    assert (speeds[begin + 1] - speeds[begin]) / plan.dt <= settings.min_acceleration + 1.0 + 1e-6


def braking_trace(automaton, rate: float, shape: str = "linear", dt: float = 0.1) -> Trace:
    """25 m/s for 3 s, then to 10 m/s in ``shape`` with its acceleration peaking at ``rate``, then held."""
    seconds = SHAPE_PEAK_OVER_MEAN[shape] * 15.0 / rate
    times = np.arange(0, 3 + seconds + 3 + dt / 2, dt)
    into = np.clip((times - 3) / seconds, 0, 1)
    share = into if shape == "linear" else (1 - np.cos(math.pi * into)) / 2
    return speed_trace(automaton, list(zip(times, 25.0 - 15.0 * share)), dt)


def test_the_monitor_judges_the_peak_a_shape_implies():
    linear = automaton_of("10mps", ", rate_profile: linear, rate_peak: 5mpss")
    assert monitor(linear, braking_trace(linear, 5.0)).accepted
    assert not monitor(linear, braking_trace(linear, 2.5)).accepted
    sinusoidal = automaton_of("10mps", ", rate_profile: sinusoidal, rate_peak: 5mpss")
    assert monitor(sinusoidal, braking_trace(sinusoidal, 5.0, "sinusoidal")).accepted
    # a linear change at 5 m/s^2 would be a sinusoidal one peaking at 7.9
    verdict = monitor(sinusoidal, braking_trace(sinusoidal, 5.0))
    assert not verdict.accepted
    assert "peak acceleration" in verdict.explain()
