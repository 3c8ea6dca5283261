"""The automaton of the overtake has the shape of the paper's Figure 4."""

import math

import pytest

from pytest_roadlogic.automaton import LANE, POSITION, Bound, Term, build_automaton
from pytest_roadlogic.frontend import OscError, check_text


def test_overtake_automaton_is_the_papers_figure_4(overtake_automaton):
    a = overtake_automaton
    assert [loc.name for loc in a.locations] == ["init", "A", "B", "C", "fin"]
    edges = [(a.location(t.source).name, a.location(t.target).name, str(t.guard)) for t in a.transitions]
    assert edges == [
        ("init", "A", "l(v1) = l(v2) and 10 <= p(v2) - p(v1) <= 20"),
        ("A", "B", "l(v1) < l(v2)"),
        ("B", "C", "1 <= p(v1) - p(v2) <= 10"),
        ("C", "fin", "l(v1) = l(v2) and 5 <= p(v1) - p(v2) <= 10"),
    ]


def test_both_vehicles_drive_in_every_phase(overtake_automaton):
    for name in ("A", "B", "C"):
        loc = next(l for l in overtake_automaton.locations if l.name == name)
        assert loc.drivers == {"v1", "v2"}


def test_parallel_members_end_together():
    text = (
        "scenario s:\n  a: car\n  b: car\n  do parallel():\n"
        "    a.drive() with:\n      speed([5..10]mps, at: end)\n"
        "    b.drive() with:\n      speed([5..10]mps, at: end)\n"
    )
    a = build_automaton(check_text(text).scenarios[0])
    into_final = [t for t in a.transitions if t.target == a.final]
    assert len(into_final) == 1
    assert len(into_final[0].guard.atoms()) == 2


def test_one_of_is_a_union_with_one_initial_and_one_final_location():
    text = (
        "scenario s:\n  a: car\n  b: car\n  do one_of:\n"
        "    a.drive() with:\n      lane(left_of: b, at: end)\n"
        "    a.drive() with:\n      lane(right_of: b, at: end)\n"
    )
    a = build_automaton(check_text(text).scenarios[0])
    assert len(a.outgoing(a.initial)) == 2
    assert len([t for t in a.transitions if t.target == a.final]) == 2


def test_absolute_lanes_count_from_the_right_by_default():
    text = "scenario s:\n  a: car\n  do a.drive() with:\n    lane(1, at: start)\n    lane(1, from: left, at: end)\n"
    a = build_automaton(check_text(text).scenarios[0], lanes=3)
    start, end = [t.guard for t in a.transitions]
    assert (start.low, start.high) == (2, 2)  # rightmost of 3 is internal lane 2
    assert (end.low, end.high) == (0, 0)


def test_a_lane_outside_the_road_is_an_error_naming_the_convention():
    text = "scenario s:\n  a: car\n  do a.drive() with:\n    lane(4, at: start)\n"
    with pytest.raises(OscError) as caught:
        build_automaton(check_text(text, "l.osc").scenarios[0], lanes=3)
    assert "l.osc:4:10" in str(caught.value) and "rightmost" in str(caught.value)


def test_an_unknown_actor_is_an_error_at_its_use():
    text = "scenario s:\n  a: car\n  do a.drive() with:\n    position([1..2]m, behind: ghost, at: start)\n"
    with pytest.raises(OscError) as caught:
        build_automaton(check_text(text, "g.osc").scenarios[0])
    assert "g.osc:4:31: error: unknown actor 'ghost'" in str(caught.value)


def test_a_speed_where_a_length_is_expected_is_an_error():
    text = "scenario s:\n  a: car\n  b: car\n  do a.drive() with:\n    position(3mps, behind: b, at: start)\n"
    with pytest.raises(OscError) as caught:
        build_automaton(check_text(text, "d.osc").scenarios[0])
    assert "d.osc:5:14: error: expected a length" in str(caught.value)


class _S:
    def __init__(self, position, lane, speed):
        self.position, self.lane, self.speed = position, lane, speed


def test_guard_robustness_is_a_signed_margin_in_the_quantitys_units():
    ahead = Bound(Term(POSITION, "v1", "v2"), 5, 10)
    assert ahead.robustness({"v1": _S(17, 0, 0), "v2": _S(10, 0, 0)}) == pytest.approx(2.0)
    assert ahead.robustness({"v1": _S(12, 0, 0), "v2": _S(10, 0, 0)}) == pytest.approx(-3.0)
    left = Bound(Term(LANE, "v1", "v2"), -math.inf, -1)
    assert left.robustness({"v1": _S(0, 0, 0), "v2": _S(0, 1, 0)}) == pytest.approx(0.5)
    assert left.robustness({"v1": _S(0, 1, 0), "v2": _S(0, 1, 0)}) == pytest.approx(-0.5)
