"""The standard's remaining motion vocabulary, each read as the README's scenario model says:
``distance(d)`` (metres covered in the phase), ``keep_position()`` (stand still),
``assign_speed(v)`` (the speed at the phase's start), ``change_speed(target, rate_peak: a)`` (the
acceleration within -a..a; its shapes: test_speed_shapes.py), ``change_lane([1..2], side)`` (one of those counts),
``along(path)`` and ``avoid_collisions(true)`` (always true on this tool's one road)."""

import numpy as np
import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import OscError, check_text
from pytest_roadlogic.logic.automaton import Travelled
from pytest_roadlogic.logic.guards import LANE
from pytest_roadlogic.monitor import monitor
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings, GridPlanner, GridSettings
from pytest_roadlogic.simulation import Trace
from tests.planning.test_planning_continuous import check_continuous_plan

HEADER = "import osc.standard\n\nscenario top:\n    path: Path\n    car1: car\n"

DISTANCE = (
    HEADER
    + """    do serial:
        cruise: car1.drive(duration: [3s..5s]) with:
            speed([15mps..25mps])
        run: car1.drive() with:
            distance([100m..120m])
            speed([15mps..25mps])
"""
)


def automaton_of(text: str):
    checked = check_text(text, "top.osc")
    checked.raise_for_errors()
    return build_automaton(checked.scenarios[0])


def test_distance_is_a_bound_over_the_phases_two_ends_on_a_phase_timed_for_it():
    automaton = automaton_of(DISTANCE)
    run = next(t for t in automaton.timings.values() if t.name == "run")
    assert (run.low, run.high) == (0.0, float("inf"))
    assert [(type(r), r.low, r.high) for r in run.rates] == [(Travelled, 100.0, 120.0)]
    assert "distance travelled of car1 over run in 100..120 m" in automaton.describe()


@pytest.mark.parametrize("seed", [1, 2])
def test_a_plan_covers_the_asked_distance_in_the_phase(seed):
    automaton = automaton_of(DISTANCE)
    plan = ContinuousPlanner(automaton, ContinuousSettings(random_start=True), seed).first()
    check_continuous_plan(plan, automaton)  # check_run measures every phase's distance


def cruise_trace(automaton, speed: float, seconds: float, dt: float = 0.1) -> Trace:
    lane = ContinuousPlanner(automaton, ContinuousSettings(), 1).first().states["car1"][0].lane
    times = np.arange(0, seconds + dt / 2, dt)
    n = len(times)
    columns = {
        "x": speed * times,
        "y": np.zeros(n),
        "heading": np.zeros(n),
        "speed": np.full(n, speed),
        "acceleration": np.zeros(n),
        "lane": np.full(n, lane),
    }
    return Trace(times, {"car1": columns})


def test_the_monitor_measures_the_distance_and_names_it_when_no_run_meets_it():
    automaton = automaton_of(DISTANCE)
    # 20 m/s for 10 s: 4 s of cruise, then 110 m in 5.5 s is there to be found
    assert monitor(automaton, cruise_trace(automaton, 20.0, 10.0)).accepted
    # 20 m/s for 7.5 s: after the shortest cruise (3 s) 90 m are left, never 100 m
    verdict = monitor(automaton, cruise_trace(automaton, 20.0, 7.5))
    assert not verdict.accepted
    assert "distance travelled of car1 over run in 100..120 m" in verdict.explain()


def test_the_grid_encoding_refuses_distance_at_its_place():
    automaton = automaton_of(DISTANCE)
    with pytest.raises(OscError, match="distance modifier"):
        GridPlanner(automaton, GridSettings(), 1).first()


@pytest.mark.parametrize(
    "modifier, message",
    [
        ("distance(-5m)", "must not be negative"),
        ("distance(3s)", "expects a length"),
        ("avoid_collisions(false)", "not supported: avoid_collisions(false)"),
        ("avoid_collisions(3)", "takes true or false"),
        ("along(other)", "takes the scenario's road"),
    ],
)
def test_a_motion_modifier_the_tool_cannot_read_is_a_located_error(modifier, message):
    text = HEADER + f"    do car1.drive(duration: 5s) with:\n        {modifier}\n"
    checked = check_text(text, "top.osc")
    errors = [d for d in checked.diagnostics if d.severity == "error"]
    assert errors and message in errors[0].message, [d.message for d in errors]
    assert errors[0].location.line == 7


def test_along_and_avoid_collisions_ask_nothing_more_than_the_road_and_the_collision_rule():
    plain = automaton_of(HEADER + "    do car1.drive(duration: 5s)\n")
    written = automaton_of(
        HEADER + "    do car1.drive(path, duration: 5s) with:\n        along(path)\n        avoid_collisions(true)\n"
    )
    assert written.describe() == plain.describe()


def test_keep_position_stands_still_and_assign_speed_holds_at_the_phases_start():
    automaton = automaton_of(
        HEADER
        + """    parked: vehicle
    do parallel(duration: 6s):
        parked.keep_position()
        serial:
            car1.assign_speed(20mps)
            car1.change_speed(target: 10mps, rate_peak: 3mpss)
"""
    )
    assert not any("parked" in location.drivers for location in automaton.locations)  # no progress asked of it
    plan = ContinuousPlanner(automaton, ContinuousSettings(), 1).first()
    check_continuous_plan(plan, automaton)
    parked = plan.states["parked"]
    assert all(abs(s.speed) <= 0.1 + 1e-6 for s in parked)
    assert abs(plan.states["car1"][0].speed - 20.0) <= 0.5 + 1e-6
    peak = [r for t in automaton.timings.values() for r in t.rates]
    assert [(r.low, r.high) for r in peak] == [(-3.0, 3.0)]


def test_change_lane_with_a_range_of_lanes_may_change_one_or_two():
    automaton = automaton_of(
        HEADER
        + "    do car1.drive(duration: 6s) with:\n        lane(1, at: start)\n        change_lane([1..2], left)\n"
    )
    assert automaton.lanes >= 3
    ends = set()
    for transition in automaton.transitions:
        for bound in _bounds(transition.guard):
            if bound.term.quantity == LANE and bound.term.reference is None and bound.low == bound.high:
                ends.add(bound.low)
    start = automaton.lanes - 1  # lane(1) is the rightmost
    assert {start - 1, start - 2} <= ends


def _bounds(guard):
    parts = getattr(guard, "parts", None)
    if parts is None:
        inner = getattr(guard, "guard", None)
        return _bounds(inner) if inner is not None else ([guard] if hasattr(guard, "term") else [])
    return [b for p in parts for b in _bounds(p)]
