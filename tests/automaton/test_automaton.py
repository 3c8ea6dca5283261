"""The automaton of the overtake has the shape of the paper's Figure 4."""

import itertools
import math

import pytest

from pytest_roadlogic.automaton import LANE, POSITION, Bound, Term, build_automaton
from pytest_roadlogic.frontend import OscError, check_text
from tests.conftest import OVERTAKE


def test_overtake_automaton_is_the_papers_figure_4_with_left_of_the_adjacent_lane(overtake_automaton):
    """The paper's Figure 4, but for left_of: the standard's lane(left_of: x) is the lane next to
    x's (its lane: argument defaults to 1), where the paper wrote any lane left of it."""
    a = overtake_automaton
    assert [loc.name for loc in a.locations] == ["init", "A", "B", "C", "fin"]
    edges = [(a.location(t.source).name, a.location(t.target).name, str(t.guard)) for t in a.transitions]
    assert edges == [
        ("init", "A", "l(v1) = l(v2) and 10 <= p(v2) - p(v1) <= 20"),
        ("A", "B", "l(v1) - l(v2) = -1"),
        ("B", "C", "1 <= p(v1) - p(v2) <= 10"),
        ("C", "fin", "l(v1) = l(v2) and 5 <= p(v1) - p(v2) <= 10"),
    ]


def test_both_vehicles_drive_in_every_phase(overtake_automaton):
    for name in ("A", "B", "C"):
        loc = next(location for location in overtake_automaton.locations if location.name == name)
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
    a = build_automaton(check_text(text).scenarios[0])
    start, end = [t.guard for t in a.transitions]
    assert (start.low, start.high) == (2, 2)  # rightmost of 3 is internal lane 2
    assert (end.low, end.high) == (0, 0)


def test_lane_without_arguments_is_lane_1_as_the_standards_default():
    text = "scenario s:\n  a: car\n  do a.drive() with:\n    lane(at: start)\n    lane(lane: 1, at: end)\n"
    start, end = [t.guard for t in build_automaton(check_text(text).scenarios[0]).transitions]
    assert (start.low, start.high) == (end.low, end.high) == (2, 2)


def lateral(arguments: str):
    """(reference, low, high) of the lane bound that ``lateral(arguments, at: start)`` of a beside b makes."""
    text = f"scenario s:\n  a: car\n  b: car\n  do a.drive() with:\n    lateral({arguments}, at: start)\n"
    checked = check_text(text, "d.osc")
    assert not checked.errors, checked.report()
    start, _ = [t.guard for t in build_automaton(checked.scenarios[0]).transitions]
    return start.term.reference, start.low, start.high


def test_a_lateral_distance_is_the_whole_lanes_it_spans_to_that_side_and_another_is_a_located_error():
    # internally lane 0 is the leftmost: a lane to the left of b's has the smaller number
    assert lateral("3.5m, side_of: b, side: right") == ("b", 1, 1)
    assert lateral("3.5m, side_of: b") == ("b", -1, -1)  # side: left, as for lane(side_of: b)
    assert lateral("7.2m, right_of: b") == ("b", 2, 2)
    assert lateral("[3m..7m], left_of: b") == ("b", -2, -1)
    assert lateral("0m, side_of: b") == ("b", 0, 0)  # beside b is b's lane
    text = "scenario s:\n  a: car\n  b: car\n  do serial:\n    a.drive()\n    a.drive() with:\n      lateral(1.5m, side_of: b)\n"
    checked = check_text(text, "d.osc")
    with pytest.raises(OscError) as caught:
        build_automaton(checked.scenarios[0])
    assert "d.osc:7:15: error: a lateral distance of 1.5 m is no whole number of lanes (3.5 m)" in str(caught.value)


def test_a_lateral_distance_measured_between_sides_is_read_between_centres_of_two_cars_1_8_m_wide():
    # 1.7 m between a's right side and b's left side: centres 3.5 m apart, the next lane left
    assert lateral("1.7m, side_of: b, side: left, measure_by: right_to_left") == ("b", -1, -1)
    # the free space between the two boxes, to the right: the same
    assert lateral("1.7m, right_of: b, measure_by: closest") == ("b", 1, 1)
    # a's left side 1.7 m right of b's right side is a's right side 3.5 m from it: one lane right
    assert lateral("1.7m, right_of: b, measure_by: left_to_right") == ("b", 1, 1)
    # same sides measured: the distance between centres
    assert lateral("7m, left_of: b, measure_by: left_to_left") == ("b", -2, -2)
    assert lateral("3.5m, left_of: b, measure_by: center_to_center") == ("b", -1, -1)


def test_a_lateral_distance_without_a_reference_is_a_place_in_the_own_lane_read_with_a_warning_or_refused():
    def checked(arguments: str):
        text = f"scenario s:\n  a: car\n  do a.drive() with:\n    lateral({arguments}, at: start)\n"
        return check_text(text, "d.osc")

    # the standard's Euro NCAP example: 1 m from the left marking to the car's left side
    fits = checked("distance: 1m, measure_by: left_to_left")
    assert not fits.errors
    assert [w.message for w in fits.warnings] == [
        "lateral(1 m, measure_by: left_to_left) is read but not simulated: vehicles drive on their lane's centre line"
    ]
    out = checked("distance: 2m, measure_by: left_to_left")
    assert [(e.location.line, e.location.column, e.message) for e in out.errors] == [
        (
            4,
            23,
            "lateral(2 m, measure_by: left_to_left) puts the vehicle across its lane's marking "
            "(1.8 m wide, in a lane of 3.5 m: at most 0.85 m off its centre)",
        )
    ]
    assert not checked("0.5m, measure_by: closest").errors
    assert checked("1m, measure_by: closest").errors  # no side of a centred car is 1 m from a marking
    # the plan is as without it: no lane bound, and the car asked for no lane (least action)
    a = build_automaton(fits.scenarios[0])
    assert not any("l(a)" in str(t.guard) for t in a.transitions)
    assert all(not location.asks for location in a.locations)


def test_follow_lane_with_an_offset_inside_the_lane_is_read_with_a_warning_and_across_a_marking_refused():
    def checked(offset: str):
        return check_text(f"scenario s:\n  a: car\n  do a.follow_lane(offset: {offset})\n", "d.osc")

    assert not checked("0.375m").errors and len(checked("0.375m").warnings) == 1
    assert "puts the vehicle across its lane's marking" in checked("-1m").errors[0].message


def test_a_modifier_without_at_is_an_invariant_of_its_phase_and_holds_at_both_ends():
    text = "scenario s:\n  a: car\n  do a.drive() with:\n    lane(1)\n    speed([10..20]mps, at: end)\n"
    a = build_automaton(check_text(text).scenarios[0])
    phase = [loc for loc in a.locations if loc.name == "a.drive"][0]
    assert str(phase.invariant) == "l(a) = 2"
    start, end = [t.guard for t in a.transitions]
    assert str(start) == "l(a) = 2"
    assert str(end) == "10 <= v(a) <= 20 and l(a) = 2"


def test_keep_lane_is_a_choice_of_the_lane_held_throughout():
    text = "scenario s:\n  a: car\n  do a.drive() with:\n    keep_lane()\n"
    a = build_automaton(check_text(text).scenarios[0])
    phases = [loc for loc in a.locations if loc.name.startswith("a.drive")]
    assert sorted(str(loc.invariant) for loc in phases) == ["l(a) = 0", "l(a) = 1", "l(a) = 2"]


def test_change_lane_ends_num_of_lanes_to_the_side_of_the_starting_lane():
    text = "scenario s:\n  a: car\n  do a.change_lane(1, left)\n"
    a = build_automaton(check_text(text).scenarios[0])
    pairs = sorted(
        (str(a.outgoing(a.initial)[i].guard), str(a.outgoing(t.target)[0].guard))
        for i, t in enumerate(a.outgoing(a.initial))
    )
    assert pairs == [("l(a) = 1", "l(a) = 0"), ("l(a) = 2", "l(a) = 1")]


def test_change_speed_reaches_its_target_at_the_end():
    text = "scenario s:\n  a: car\n  do a.change_speed(target: 72kph)\n"
    a = build_automaton(check_text(text).scenarios[0])
    assert str(a.transitions[-1].guard) == "19.5 <= v(a) <= 20.5"


def test_remain_stationary_holds_speed_at_zero_and_is_not_a_driving_phase():
    text = "scenario s:\n  o: stationary_object\n  do o.remain_stationary()\n"
    a = build_automaton(check_text(text).scenarios[0])
    phase = [loc for loc in a.locations if loc.name == "o.remain_stationary"][0]
    assert str(phase.invariant) == "-0.1 <= v(o) <= 0.1"
    assert phase.drivers == frozenset()
    assert a.stationary == frozenset({"o"})


def test_a_parameter_left_open_keeps_its_range_and_a_sampled_value_fixes_it():
    text = "scenario s:\n  a: car\n  b: car\n  gap: length with:\n    keep(it in [10..20]m)\n  do a.drive() with:\n    position(gap, behind: b, at: start)\n"
    checked = check_text(text)
    scenario = checked.scenarios[0]
    assert str(build_automaton(scenario).transitions[0].guard) == "10 <= p(b) - p(a) <= 20"
    assert str(build_automaton(scenario, values={"gap": 12.5}).transitions[0].guard) == "11.5 <= p(b) - p(a) <= 13.5"


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


def test_roadlogic_automaton_writes_valid_dot_with_the_papers_guards(tmp_path):
    import pydot

    from pytest_roadlogic.cli import main

    out = tmp_path / "overtake.dot"
    assert main(["automaton", str(OVERTAKE), "--out", str(out)]) == 0
    graph = pydot.graph_from_dot_data(out.read_text())[0]
    labels = {e.get_label().strip('"') for e in graph.get_edges() if e.get_label()}
    assert "l(v1) = l(v2) and 10 <= p(v2) - p(v1) <= 20" in labels
    assert "l(v1) - l(v2) = -1" in labels
    assert len(graph.get_nodes()) >= 5


def test_roadlogic_automaton_of_a_bad_file_is_a_located_error_and_exit_2(tmp_path, capsys):
    from pytest_roadlogic.cli import main

    bad = tmp_path / "bad.osc"
    bad.write_text("scenario s:\n  a: car\n  do a.fly()\n")
    assert main(["automaton", str(bad), "--out", str(tmp_path / "x.dot")]) == 2
    assert f"{bad}:3:6: error: unknown action 'fly'" in capsys.readouterr().err


def test_keep_speed_is_one_bound_over_its_phase_against_the_speed_it_starts_with():
    text = "scenario s:\n  a: car\n  do a.keep_speed()\n"
    a = build_automaton(check_text(text).scenarios[0])
    assert len(a.outgoing(a.initial)) == 1, "one phase, not a choice of starting speeds"
    (timing,) = a.timings.values()
    assert [(type(r).__name__, r.actor, r.low, r.high) for r in timing.rates] == [("HeldSpeed", "a", -math.inf, 1.5)]
    assert "keep_speed() of a over a.keep_speed: its speed within 1.5 m/s of the phase's first" in a.describe()


def test_durations_and_waits_become_timed_phases():
    text = (
        "scenario s:\n  a: car\n  do serial(duration: [8..12]s):\n    a.drive(duration: 3s)\n"
        "    wait elapsed([1..2]s)\n    a.drive()\n"
    )
    a = build_automaton(check_text(text).scenarios[0])
    assert sorted(str(t) for t in a.timings.values()) == [
        "a.drive lasts 2.5..3.5 s",
        "serial lasts 8..12 s",
        "wait lasts 1..2 s",
    ]
    serial = next(p for p, t in a.timings.items() if t.name == "serial")
    assert [t.id for t in a.transitions if serial in t.starts] == [a.outgoing(a.initial)[0].id]
    assert all(serial in t.ends for t in a.transitions if t.target == a.final)


def _phase_ends(text: str) -> list[tuple[str, ...]]:
    """The phases each transition of the scenario's automaton ends, in the order they can happen."""
    automaton = build_automaton(check_text(text).scenarios[0])
    return sorted({tuple(sorted(e for e in t.events if e.endswith(" end"))) for t in automaton.transitions} - {()})


def test_a_parallels_members_start_together_and_one_with_its_own_duration_ends_when_it_ends():
    text = "scenario s:\n  a: car\n  b: car\n  do parallel:\n    a.drive(duration: 3s)\n    b.drive(duration: 5s)\n"
    # the standard's default overlap (start), as CARLA's runner executes it: either may end first
    assert _phase_ends(text) == [("a.drive end",), ("a.drive end", "b.drive end"), ("b.drive end",)]


def test_with_overlap_equal_a_parallels_members_end_together():
    text = "scenario s:\n  a: car\n  b: car\n  do parallel(overlap: equal):\n    a.drive(duration: 3s)\n    b.drive(duration: 5s)\n"
    assert _phase_ends(text) == [("a.drive end", "b.drive end")]


def test_a_member_with_nothing_to_end_it_lasts_as_long_as_the_members_that_end_of_themselves():
    text = "scenario s:\n  a: car\n  b: car\n  do parallel:\n    a.drive(duration: 3s)\n    b.drive()\n"
    # b's drive never goes on alone after a's has ended: it ends with it
    assert _phase_ends(text) == [("a.drive end", "b.drive end")]
    alone = "scenario s:\n  a: car\n  b: car\n  do parallel:\n    a.drive()\n    b.drive()\n"
    assert _phase_ends(alone) == [("a.drive end", "b.drive end")]


def test_in_a_parallel_with_its_own_duration_a_member_with_nothing_to_end_it_lasts_until_that_is_over():
    text = "scenario s:\n  a: car\n  b: car\n  do parallel(duration: 6s):\n    a.drive(duration: 3s)\n    b.drive()\n"
    assert ("a.drive end",) in _phase_ends(text)  # b drives on after a's 3 s
    plan = "scenario s:\n  a: car\n  b: car\n  do parallel(duration: 6s):\n    a.drive(duration: 3s)\n    b.drive()\n"
    from pytest_roadlogic.planning import ContinuousPlanner

    first = next(ContinuousPlanner(build_automaton(check_text(plan).scenarios[0])).plans(limit=1))
    assert first.horizon == 6


def test_with_overlap_end_a_parallels_members_end_together_and_one_with_its_own_duration_may_start_late():
    text = "scenario s:\n  a: car\n  b: car\n  do parallel(overlap: end):\n    a.drive(duration: 3s)\n    b.drive(duration: 5s)\n"
    assert _phase_ends(text) == [("a.drive end", "b.drive end")]
    automaton = build_automaton(check_text(text).scenarios[0])
    starts = {tuple(sorted(e for e in t.events if e.endswith(" start"))) for t in automaton.transitions}
    assert {("a.drive start",), ("b.drive start",), ("a.drive start", "b.drive start")} <= starts


def _orders_of_starts_and_ends(automaton) -> set[tuple[frozenset[str], ...]]:
    """Every run's starts and ends of ``a.drive`` and ``b.drive``, as the sets of them that happen
    at one instant, in order."""
    runs: set[tuple[frozenset[str], ...]] = set()

    def walk(location, so_far):
        if location == automaton.final:
            runs.add(so_far)
        for t in automaton.outgoing(location):
            marks = frozenset(e for e in t.events if e.startswith(("a.drive", "b.drive")))
            walk(t.target, so_far + ((marks,) if marks else ()))

    walk(automaton.initial, ())
    return runs


def _orders_the_standard_accepts(kind: str) -> set[tuple[frozenset[str], ...]]:
    """The orders of a's and b's starts and ends (a the primary) that the standard's definition of
    parallel (7.6.2.1.4) accepts for ``overlap: kind``, found by trying every order of the four."""
    marks = ("a.drive start", "a.drive end", "b.drive start", "b.drive end")
    accepted = set()
    for ranks in itertools.product(range(4), repeat=4):
        if set(ranks) != set(range(max(ranks) + 1)):
            continue  # instants are numbered without gaps
        s0, e0, s1, e1 = ranks
        first, last = min(ranks), max(ranks)
        holds = {
            "equal": s0 == s1 == first and e0 == e1 == last,
            "start": s0 == s1 == first,
            "end": e0 == e1 == last,
            "inside": s0 <= s1 and e0 >= e1,
            "full": s0 >= s1 and e0 <= e1,
            "initial": s1 <= s0 <= e1,
            "final": s1 <= e0 <= e1,
            "any": max(s0, s1) <= min(e0, e1),
        }[kind]
        if s0 < e0 and s1 < e1 and holds:
            accepted.add(tuple(frozenset(m for m, r in zip(marks, ranks) if r == i) for i in range(last + 1)))
    return accepted


@pytest.mark.parametrize("kind", ["equal", "start", "end", "inside", "full", "initial", "final", "any"])
def test_each_overlap_kind_orders_two_timed_members_exactly_as_the_standards_definition_of_parallel(kind):
    text = (
        f"scenario s:\n  a: car\n  b: car\n  do parallel(overlap: {kind}):\n"
        "    a.drive(duration: [2..6]s)\n    b.drive(duration: [2..6]s)\n"
    )
    automaton = build_automaton(check_text(text).scenarios[0])
    assert _orders_of_starts_and_ends(automaton) == _orders_the_standard_accepts(kind)


def test_a_member_with_nothing_to_end_it_spans_the_parallel_whatever_the_overlap():
    for kind in ("inside", "initial", "final", "any"):
        text = f"scenario s:\n  a: car\n  b: car\n  do parallel(overlap: {kind}):\n    a.drive()\n    b.drive(duration: 3s)\n"
        orders = _orders_of_starts_and_ends(build_automaton(check_text(text).scenarios[0]))
        assert all("a.drive start" in run[0] and "a.drive end" in run[-1] for run in orders), kind


def test_overlap_inside_with_a_secondary_longer_than_the_primary_has_no_plan_and_says_which_durations():
    from pytest_roadlogic.planning import ContinuousPlanner, UnsatisfiableScenario

    text = "scenario s:\n  a: car\n  b: car\n  do parallel(overlap: inside):\n    a.drive(duration: 3s)\n    b.drive(duration: 5s)\n"
    with pytest.raises(UnsatisfiableScenario, match=r"a\.drive lasts 2\.5\.\.3\.5 s .* b\.drive lasts 4\.5\.\.5\.5 s"):
        next(ContinuousPlanner(build_automaton(check_text(text).scenarios[0])).plans(limit=1))


def _accepts_timed(automaton, instants: list[tuple[float, frozenset[str]]]) -> bool:
    """Whether some run of ``automaton`` takes its transitions at ``instants`` (time, the starts
    and ends of a.drive and b.drive then), every timed phase lasting within its range."""
    timings = automaton.timings

    def walk(location, i, started) -> bool:
        if i == len(instants):
            return location == automaton.final
        time, marks = instants[i]
        for t in automaton.outgoing(location):
            if frozenset(e for e in t.events if e.startswith(("a.drive", "b.drive"))) != marks:
                continue
            opened = {**started, **dict.fromkeys(t.starts, time)}
            if all(timings[p].admits(time - opened.pop(p)) for p in t.ends if p in timings) and walk(
                t.target, i + 1, opened
            ):
                return True
        return False

    return walk(automaton.initial, 0, {})


OFFSET_CASES = [
    ("any", "start_to_start: 2s", (1.5, 2.5), None),
    ("any", "start_to_start: [-2s..1s]", (-2, 1), None),
    ("end", "start_to_start: -1s", (-1.5, -0.5), None),
    ("inside", "start_to_start: [0s..3s]", (0, 3), None),
    ("any", "end_to_end: -1s", None, (-1.5, -0.5)),
    ("start", "end_to_end: [1s..2s]", None, (1, 2)),
    ("final", "start_to_start: [-3s..0s], end_to_end: [0s..2s]", (-3, 0), (0, 2)),
]


@pytest.mark.parametrize("kind, offsets, starts, ends", OFFSET_CASES)
def test_start_to_start_and_end_to_end_place_two_members_exactly_as_the_standards_definition_of_parallel(
    kind, offsets, starts, ends
):
    # every placement of two members' starts and ends on whole seconds 0..6, judged by the
    # standard's formulas (7.6.2.1.4: the overlap kind, the offsets from the primary's start and
    # end, the members' durations) and by the automaton's runs with their timed phases
    text = (
        f"scenario s:\n  a: car\n  b: car\n  do parallel(overlap: {kind}, {offsets}):\n"
        "    a.drive(duration: [1..6]s)\n    b.drive(duration: [1..6]s)\n"
    )
    automaton = build_automaton(check_text(text).scenarios[0])
    within = {
        "any": lambda s0, e0, s1, e1: max(s0, s1) <= min(e0, e1),
        "end": lambda s0, e0, s1, e1: e0 == e1,
        "start": lambda s0, e0, s1, e1: s0 == s1,
        "inside": lambda s0, e0, s1, e1: s0 <= s1 and e0 >= e1,
        "final": lambda s0, e0, s1, e1: s1 <= e0 <= e1,
    }[kind]
    checked = 0
    for s0, e0, s1, e1 in itertools.product(range(7), repeat=4):
        if min(s0, s1) != 0 or not (1 <= e0 - s0 <= 6 and 1 <= e1 - s1 <= 6):
            continue
        standard = (
            within(s0, e0, s1, e1)
            and (starts is None or starts[0] <= s1 - s0 <= starts[1])
            and (ends is None or ends[0] <= e1 - e0 <= ends[1])
        )
        at = {}
        for time, mark in ((s0, "a.drive start"), (e0, "a.drive end"), (s1, "b.drive start"), (e1, "b.drive end")):
            at.setdefault(time, set()).add(mark)
        instants = [(float(time), frozenset(marks)) for time, marks in sorted(at.items())]
        assert _accepts_timed(automaton, instants) == standard, (s0, e0, s1, e1)
        checked += standard
    assert checked, "some placement meets the offsets"


def test_an_offset_gives_a_member_with_nothing_to_end_it_its_start_and_its_end():
    text = (
        "scenario s:\n  a: car\n  b: car\n  do parallel(overlap: any, start_to_start: 2s, end_to_end: 1s):\n"
        "    a.drive(duration: 5s)\n    b.drive()\n"
    )
    automaton = build_automaton(check_text(text).scenarios[0])
    placed = [(0.0, {"a.drive start"}), (2.0, {"b.drive start"}), (5.0, {"a.drive end"}), (6.0, {"b.drive end"})]
    assert _accepts_timed(automaton, [(t, frozenset(m)) for t, m in placed])
    together = [(0.0, {"a.drive start", "b.drive start"}), (5.0, {"a.drive end", "b.drive end"})]
    assert not _accepts_timed(automaton, [(t, frozenset(m)) for t, m in together])


def test_a_start_to_start_that_the_overlap_kind_forbids_is_refused_at_its_argument():
    text = "scenario s:\n  a: car\n  b: car\n  do parallel(start_to_start: 2s):\n    a.drive(duration: 5s)\n    b.drive()\n"
    with pytest.raises(OscError, match=r"overlap: start starts every member with the primary, so a start_to_start"):
        build_automaton(check_text(text).scenarios[0])
