"""The monitor accepts traces that realise the scenario and names the guard a bad trace misses."""

import numpy as np
import pytest

from pytest_roadlogic.monitor import monitor
from pytest_roadlogic.simulation import Trace
from pytest_roadlogic.simulation.trace import Incident

DT = 0.5


def make_trace(v1_x, v1_lane, v2_x, v2_lane, speeds=(10.0, 10.0)):
    n = len(v1_x)

    def columns(x, lane, speed):
        return {
            "x": np.array(x, float),
            "y": np.zeros(n),
            "heading": np.zeros(n),
            "speed": np.full(n, speed),
            "acceleration": np.zeros(n),
            "lane": np.array(lane, int),
        }

    return Trace(np.arange(n) * DT, {"v1": columns(v1_x, v1_lane, speeds[0]), "v2": columns(v2_x, v2_lane, speeds[1])})


def overtake_trace():
    # v1 starts 15 m behind v2 in lane 1, moves left, passes, returns 7.5 m ahead
    v2 = [100 + 10 * k for k in range(10)]
    gaps = [-15, -12, -9, -5, 0, 4, 7, 7.5, 8, 8.5]
    v1 = [b + g for b, g in zip(v2, gaps)]
    lanes_v1 = [1, 1, 0, 0, 0, 0, 0, 1, 1, 1]
    return make_trace(v1, lanes_v1, v2, [1] * 10)


def test_a_real_overtake_is_accepted_with_positive_robustness(overtake_automaton):
    verdict = monitor(overtake_automaton, overtake_trace())
    assert verdict.accepted and verdict.robustness >= 0
    assert [events for _, events in verdict.run][-1].endswith("C end")


def test_staying_in_lane_fails_at_the_left_of_guard_with_values(overtake_automaton):
    trace = overtake_trace()
    trace.actors["v1"]["lane"][:] = 1  # v1 never leaves v2's lane
    verdict = monitor(overtake_automaton, trace)
    assert not verdict.accepted and verdict.robustness < 0
    assert verdict.furthest == "A"
    assert verdict.miss.guard == "l(v1) - l(v2) = -1"
    assert verdict.miss.target == "B"
    assert verdict.miss.values == {"l(v1) - l(v2)": 0.0}
    assert "stuck in A" in verdict.explain() and "l(v1) - l(v2) = -1" in verdict.explain()


def test_not_getting_far_enough_ahead_fails_at_the_final_guard(overtake_automaton):
    trace = overtake_trace()
    v2 = trace.actors["v2"]["x"]
    trace.actors["v1"]["x"][:] = v2 + np.array([-15, -12, -9, -5, 0, 2, 3, 3.5, 4, 4.2])
    verdict = monitor(overtake_automaton, trace)
    assert not verdict.accepted
    assert verdict.furthest == "C"
    assert verdict.miss.target == "fin"
    assert verdict.miss.values["p(v1) - p(v2)"] == pytest.approx(4.2)
    assert verdict.miss.time == 4.5


def test_a_driver_that_stops_breaks_forward_progress(overtake_automaton):
    trace = overtake_trace()
    trace.actors["v2"]["x"][3:] = trace.actors["v2"]["x"][3]  # v2 stands still from t=1.5 s
    assert not monitor(overtake_automaton, trace).accepted


def test_a_collision_rejects_an_otherwise_conformant_trace(overtake_automaton):
    trace = overtake_trace()
    trace.incidents.append(Incident(2.0, "collision", ("v1", "v2")))
    verdict = monitor(overtake_automaton, trace)
    assert not verdict.accepted and "collision of v1 and v2" in verdict.explain()


def test_a_wait_must_last_its_time():
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import check_text

    text = "scenario s:\n  v1: car\n  do serial:\n    v1.drive()\n    wait elapsed(2s)\n    v1.drive() with:\n      lane(0 + 1, at: end)\n"
    automaton = build_automaton(check_text(text).scenarios[0])

    def trace(lanes):
        n = len(lanes)
        columns = {
            "x": np.arange(n) * 5.0,
            "y": np.zeros(n),
            "heading": np.zeros(n),
            "speed": np.full(n, 10.0),
            "acceleration": np.zeros(n),
            "lane": np.array(lanes),
        }
        return Trace(np.arange(n) * DT, {"v1": columns})

    # at 0.5 s per sample, the wait needs 3 to 5 samples (1.5..2.5 s) between its start and end
    assert monitor(automaton, trace([0, 0, 0, 0, 0, 0, 0, 2])).accepted
    assert not monitor(automaton, trace([0, 0, 0, 0, 2])).accepted


def _one_car_trace(lanes):
    # 10 m/s at the first sample only: a phase that asks for it at its start starts there
    n = len(lanes)
    speed = np.full(n, 12.0)
    speed[0] = 10.0
    columns = {
        "x": np.arange(n) * 5.0,
        "y": np.zeros(n),
        "heading": np.zeros(n),
        "speed": speed,
        "acceleration": np.zeros(n),
        "lane": np.array(lanes),
    }
    return Trace(np.arange(n) * DT, {"v1": columns})


TIMED = (
    "scenario s:\n  v1: car\n  do serial:\n    a: v1.drive(duration: {a}) with:\n      speed(10mps, at: start)\n"
    "    v1.drive() with:\n      lane(2)\n"
)


@pytest.mark.parametrize(
    "duration, lanes, why",
    [
        # the car reaches lane 2 (index 1) after 3.5 s, where a lasts at most 2 s
        ("[1s..2s]", [0] * 7 + [1] * 4, "a lasts 1..2 s but had lasted 2.0 s by t = 2.0 s, before the guard held"),
        # the car is in lane 2 at 1-1.5 s only, where a lasts at least 3 s
        ("[3s..4s]", [0] * 2 + [1] * 2 + [0] * 7, "a lasts 3..4 s but had lasted 1.5 s there (1.5 s short)"),
    ],
)
def test_a_guard_that_held_out_of_time_is_explained_by_the_duration_not_as_never_held(duration, lanes, why):
    """Issue 20: a rejection must not print values that meet the guard it says never held."""
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import check_text

    verdict = monitor(build_automaton(check_text(TIMED.format(a=duration)).scenarios[0]), _one_car_trace(lanes))
    assert not verdict.accepted and verdict.miss.robustness >= 0
    explanation = verdict.explain()
    assert "never held" not in explanation and "held, but not in time" in explanation, explanation
    assert why in explanation, explanation


STANDING = (
    "scenario s:\n  v1: car\n  v2: car\n  do parallel(duration: [4s..6s]):\n    v1.drive()\n"
    "    v2.drive() with:\n      speed([10mps..12mps])\n"
)


def _two_cars(v1_x):
    n = len(v1_x)
    return make_trace(v1_x, [1] * n, np.arange(n) * 5.5, [1] * n, speeds=(10.0, 11.0))


@pytest.mark.parametrize(
    "v1_x, stood",
    [([0.0] * 20, "v1 stood still from t = 0.0 s"), ([min(5.0 * k, 30.0) for k in range(20)], "from t = 3.0 s")],
    ids=["never moved", "stopped before the phase could end"],
)
def test_a_run_stuck_because_a_vehicle_stood_still_says_so_not_that_a_guard_that_held_never_did(v1_x, stood):
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import check_text

    automaton = build_automaton(check_text(STANDING).scenarios[0])
    verdict = monitor(automaton, _two_cars(v1_x))
    assert not verdict.accepted
    assert stood in verdict.explain() and "makes forward progress" in verdict.explain()
    assert "never held" not in verdict.explain()
    # both moving on, the same guard and duration: accepted
    assert monitor(automaton, _two_cars([5.0 * k for k in range(20)])).accepted


def test_a_vehicle_under_test_that_stops_for_a_while_in_its_drive_is_not_stuck_the_others_still_are():
    """A vehicle that drives itself may stop where its own driving asks (giving way at a junction):
    its drive asks it no forward progress; the scenario's other vehicles' drives still do."""
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import check_text

    automaton = build_automaton(check_text(STANDING).scenarios[0])
    waits = _two_cars([5.0 * k if k < 4 else 15.0 + 5.0 * max(k - 8, 0) for k in range(20)])  # stands 2 s
    # the scenario begins with the trace: the stop lies inside its drive
    assert "v1 stood still from t = 1.5 s" in monitor(automaton, waits, begins_by=0.0).explain()
    assert monitor(automaton.driving_itself("v1"), waits, begins_by=0.0).accepted
    assert not monitor(automaton.driving_itself("v2"), waits, begins_by=0.0).accepted
