"""A sample with no plan, proved by the planning problem's linear relaxation before any search
(planning/relaxation.py): it must never refuse a sample some planner plans, and it names the
constraints that clash as the diagnosis does."""

from __future__ import annotations

import dataclasses

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning import NoPlanError, UnsatisfiableScenario, planner_for
from pytest_roadlogic.planning import settings_for as planner_settings
from pytest_roadlogic.planning.fallbacks import fallback_settings, planned
from pytest_roadlogic.planning.relaxation import provably_unplannable
from pytest_roadlogic.problem import problem_for
from pytest_roadlogic.settings import RunSettings
from tests.conftest import ROOT

CATCH_UP = ROOT / "scenarios" / "realistic" / "catch_up_band.osc"
OVERTAKE_GAP = ROOT / "benchmarks" / "scenarios" / "overtake_gap_band.osc"
FASTEST = 100.0  # m/s: the relaxed fallback's top speed (ContinuousSettings.relaxed())


def guided(path, values):
    problem = problem_for(load_scenario(path), values, planner_settings(RunSettings()), 1)
    return problem.guide, problem.settings, problem.seed


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


def test_a_gap_no_pass_at_the_allowed_speeds_closes_is_refused_though_the_lead_s_speed_is_named_only_throughout():
    """The overtaken car's speed is held by its phase throughout (an invariant), never in a guard of
    the ego's phases' ends: its travel between them is still bounded by that speed."""
    guide, settings, _ = guided(OVERTAKE_GAP, {"gap": 240.0})
    conflict = provably_unplannable(guide(settings.thinned()), FASTEST)
    assert conflict is not None
    # the lead's speed, the gap at the start, then per phase before the pass's end its duration
    # and the ego's speed, and the gap at the pass's end
    assert sorted(c.source.line for c in conflict) == [19, 21, 22, 24, 26, 27, 28]


@pytest.mark.parametrize(
    "path, name, low, high", [(CATCH_UP, "lead_gap", 170.0, 230.0), (OVERTAKE_GAP, "gap", 215.0, 235.0)]
)
@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(fraction=st.floats(0.0, 1.0))
def test_the_relaxation_never_refuses_a_gap_that_some_planner_plans(path, name, low, high, fraction):
    """Near the edge, where the relaxation and the planners part: whenever the relaxation refuses
    a sample, no fallback planner (the widest margins, half steps, limits beyond a car's) plans it."""
    gap = low + fraction * (high - low)
    guide, settings, seed = guided(path, {name: gap})
    if provably_unplannable(guide(settings.thinned()), FASTEST) is None:
        return
    for fallback, _ in fallback_settings(settings):
        quiet = dataclasses.replace(fallback, time_limit=20.0)
        try:
            plan = next(planner_for(guide(quiet), quiet, seed).plans(limit=1), None)
        except NoPlanError:
            plan = None
        assert plan is None, f"the relaxation refused {name} {gap:.1f} m, which {fallback} plans"


SWAP = """scenario swap:
    a: vehicle
    b: vehicle
    do parallel(duration: [5s..10s]):
        a.drive() with:
            lane(2)
            position(distance: [20m..30m], ahead_of: b, at: start)
        b.drive() with:
            lane(same_as: a{throughout})
            position(distance: [20m..30m], ahead_of: a, at: end)
"""


def relaxation_of(tmp_path, text: str):
    path = tmp_path / "swap.osc"
    path.write_text(text)
    guide, settings, _ = guided(path, {})
    return provably_unplannable(guide(settings.thinned()), FASTEST)


def test_two_cars_kept_in_one_lane_that_must_swap_order_are_refused_naming_the_lane_and_the_two_places(tmp_path):
    conflict = relaxation_of(tmp_path, SWAP.format(throughout=""))
    assert conflict is not None
    assert sorted((c.source.line, str(c)) for c in conflict) == [
        (7, "20 <= p(a) - p(b) <= 30"),
        (9, "l(b) = l(a)"),
        (10, "20 <= p(b) - p(a) <= 30"),
    ]


def test_two_cars_in_one_lane_only_at_the_ends_may_pass_and_are_left_to_the_planner(tmp_path):
    text = SWAP.format(throughout=", at: start)\n            lane(same_as: a, at: end")
    assert relaxation_of(tmp_path, text) is None
    path = tmp_path / "swap.osc"
    guide, settings, seed = guided(path, {})
    assert next(planned(guide, settings, seed, 1), None) is not None, "b passes a in the next lane"


RIGHT_OF_THE_RIGHTMOST_LANE = """scenario right_of_the_rightmost:
    ego: car
    npc: car
    do serial:
        get_ahead: parallel(duration: 10s):
            ego.drive() with:
                speed(20kph)
                lane(1, at: start)
            npc.drive() with:
                lane(right_of: ego, at: start)
                position(5m, behind: ego, at: start)
"""


def test_a_car_placed_right_of_one_in_the_rightmost_lane_is_refused_before_any_search_naming_the_two_lanes_as_written(
    tmp_path,
):
    path = tmp_path / "right_of.osc"
    path.write_text(RIGHT_OF_THE_RIGHTMOST_LANE)
    from pytest_roadlogic.planning.diagnosis import check_satisfiable

    automaton = build_automaton(load_scenario(path))
    with pytest.raises(UnsatisfiableScenario) as raised:
        check_satisfiable(automaton)  # before any search: the placements on the road are tried
    report = raised.value.report()
    named = {line.split(": error:")[0] for line in report.splitlines() if ": error:" in line}
    assert named == {f"{path}:8:17", f"{path}:10:17"}, report  # the two lanes, not the speed
    assert "ego in lane 1 cannot hold together with npc in the lane right of ego's (line 10)" in report
    assert "the standard's lane(1) is the rightmost lane, CARLA's (--dialect carla) the leftmost" in report


def test_lanes_that_some_placement_meets_are_left_to_the_planner():
    from pytest_roadlogic.logic.guards import LANE, Bound, Term, conjunction, lanes_conflict

    rightmost = Bound(Term(LANE, "ego"), 2, 2)
    right_of = Bound(Term(LANE, "npc", "ego"), 1, 1)
    left_of = Bound(Term(LANE, "npc", "ego"), -1, -1)
    assert lanes_conflict(conjunction([rightmost, right_of]), 3) == (rightmost, right_of)
    assert lanes_conflict(conjunction([rightmost, left_of]), 3) is None
    assert lanes_conflict(conjunction([right_of, left_of]), 3) == (right_of, left_of)
    assert lanes_conflict(right_of, 1) == (right_of,)  # no lane beside another on a one-lane road


def test_a_car_kept_in_the_leftmost_lane_that_another_must_pass_on_its_left_is_refused_before_any_search_with_the_road_s_lanes():
    """overtake_obstacle on a road of two lanes (a country road with its oncoming lane): v2 keeps
    lane 2, the leftmost, so v1 has no lane left of it. The run is in a location from the instant
    it enters it, so the lane kept (an invariant) and the side asked at that instant (the guard)
    hold together: refused at once, where the planner had searched every horizon."""
    from pytest_roadlogic.planning.diagnosis import check_satisfiable

    path = ROOT / "scenarios" / "overtake_obstacle.osc"
    automaton = build_automaton(load_scenario(path, lanes=2))
    with pytest.raises(UnsatisfiableScenario) as raised:
        check_satisfiable(automaton)
    report = raised.value.report()
    named = {line.split(": error:")[0] for line in report.splitlines() if ": error:" in line}
    assert named == {f"{path}:23:7", f"{path}:27:9"}, report  # keep_lane() and lane(left_of: v2)
    assert "the road has 2 driving lanes" in report
    check_satisfiable(build_automaton(load_scenario(path, lanes=3)))  # three lanes: left to the planner


RAMP = ROOT / "scenarios" / "roads" / "merge_from_ramp.osc"


def _ramp_with_the_npc_ahead(tmp_path, distance: str):
    """merge_from_ramp (the acceleration lane, lane 1, takes a car from about 190 to 405 m along
    its route) with the merging car starting ``distance`` ahead of the ego in it."""
    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "on_ramp.xodr").write_bytes((RAMP.parent / "maps" / "on_ramp.xodr").read_bytes())
    text = RAMP.read_text().replace("position(distance: [5m..20m], behind: ego, at: start)", distance)
    assert text != RAMP.read_text()
    path = tmp_path / "ramp.osc"
    path.write_text(text)
    return path


def test_a_car_asked_into_a_lane_where_the_map_has_none_is_refused_before_any_search_naming_the_lane(tmp_path):
    """On the map, a car in an acceleration lane 400-450 m ahead of another lies past the lane's
    end: the relaxation reads where the route's lanes take a car, and the refusal says where."""
    path = _ramp_with_the_npc_ahead(tmp_path, "position(distance: [400m..450m], ahead_of: ego, at: start)")
    guide, settings, seed = guided(path, {})
    automaton = guide(settings.thinned())
    assert provably_unplannable(automaton, FASTEST) is None  # on a straight road of any length
    conflict = provably_unplannable(automaton, FASTEST, settings.route_extent())
    assert conflict is not None and sorted(c.source.line for c in conflict) == [19, 20]
    with pytest.raises(UnsatisfiableScenario) as raised:
        next(planned(guide, settings, seed, 1))
    report = raised.value.report()
    assert "linear relaxation" in str(raised.value)
    assert "a car can be in the route's lane 1 from the right only from 189 to 404 m along it" in report


def test_a_car_the_acceleration_lane_can_hold_is_left_to_the_planner(tmp_path):
    path = _ramp_with_the_npc_ahead(tmp_path, "position(distance: [100m..150m], ahead_of: ego, at: start)")
    guide, settings, seed = guided(path, {})
    assert provably_unplannable(guide(settings.thinned()), FASTEST, settings.route_extent()) is None
    assert next(planned(guide, settings, seed, 1)) is not None


def test_a_car_on_another_way_through_the_junction_asked_to_drive_further_than_its_road_is_refused(tmp_path):
    """straight_crossing_paths with the crossing car at 30-50 kph for a minute (at least 500 m) and
    the ego's speed left open: only the crosser's own route (a side route) is too short for it."""
    suite = ROOT / "scenarios" / "junctions"
    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "crossing.xodr").write_bytes((suite / "maps" / "crossing.xodr").read_bytes())
    text = (suite / "straight_crossing_paths.osc").read_text()
    text = text.replace("parallel(duration: [14s..20s])", "parallel(duration: [60s..61s])")
    text = text.replace(
        "            along(ego_path)\n            speed([30kph..50kph])\n", "            along(ego_path)\n"
    )
    path = tmp_path / "long_crossing.osc"
    path.write_text(text)
    guide, settings, _ = guided(path, {})
    automaton, extent = guide(settings.thinned()), settings.route_extent()
    ((vehicles, (first, last)),) = extent.sides
    assert vehicles == {"crosser"} and last - first < 8.3 * 60.0
    assert provably_unplannable(automaton, FASTEST) is None  # on a straight road of any length
    conflict = provably_unplannable(automaton, FASTEST, extent)
    lines = text.splitlines()
    duration = next(n for n, line in enumerate(lines, 1) if "duration: [60s..61s]" in line)
    speed = next(n for n, line in enumerate(lines, 1) if "speed([30kph..50kph])" in line)
    assert conflict is not None and {c.source.line for c in conflict} == {duration, speed}
