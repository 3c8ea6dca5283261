"""Events and conditions: what `emit`, `wait @e`, `until @e`, `until c` mean in the automaton.

The semantics (construction.py's docstring): an emit marks the instant between its serial
neighbours; a phase that waits for an event ends exactly at an instant where a member emits it,
and at its first emission (a waiting member cannot stay put while the event is emitted). A
condition is a comparison of an observable (constructs/conditions.py) with a value.
"""

import math

import pytest

from pytest_roadlogic.automaton import POSITION, Bound, Term, build_automaton
from pytest_roadlogic.frontend import OscError, check_text

TWO_THREADS = """\
scenario s:
    a: car
    b: car
    event go
    do parallel(overlap: equal):
        serial:
            a.drive(duration: [2s..4s])
            emit go
            a.drive(duration: [3s..5s])
        serial:
            b.drive() with:
                until @go
            b.change_lane(num_of_lanes: 1, side: left)
"""


def automaton(text: str, path: str = "e.osc"):
    checked = check_text(text, path)
    assert not checked.errors, checked.report()
    return build_automaton(checked.scenarios[0])


def test_a_wait_for_an_event_ends_at_the_instant_another_member_emits_it():
    a = automaton(TWO_THREADS)
    emitting = [t for t in a.transitions if "go emitted" in t.events]
    assert emitting, a.describe()
    for t in emitting:
        assert "b.drive end" in t.events, f"go is emitted while b keeps waiting: {t.events}"
    # b's drive never ends at another instant
    for t in a.transitions:
        if "b.drive end" in t.events:
            assert "go emitted" in t.events


def test_an_emit_with_no_member_waiting_for_it_still_marks_its_instant():
    text = "scenario s:\n  a: car\n  event e\n  do serial:\n    a.drive()\n    emit e\n    a.drive()\n"
    a = automaton(text)
    junction = [t for t in a.transitions if "e emitted" in t.events]
    assert len(junction) == 1 and {"a.drive end", "a.drive start"} <= set(junction[0].events)


def test_a_wait_for_an_event_emitted_before_it_began_never_ends_and_the_error_says_why():
    text = "scenario s:\n  a: car\n  event e\n  do serial:\n    a.drive()\n    emit e\n    wait @e\n"
    with pytest.raises(OscError) as caught:
        automaton(text)
    message = str(caught.value)
    assert "can never finish" in message and "@e" in message and "emit before the wait began is missed" in message


def test_an_event_nobody_emits_is_a_checker_error_at_the_wait():
    checked = check_text("scenario s:\n  a: car\n  event e\n  do serial:\n    a.drive()\n    wait @e\n", "n.osc")
    assert "n.osc:6:10: error: nothing emits the event 'e'" in checked.report()


def test_emit_in_a_parallel_is_emitted_at_the_parallels_start():
    text = "scenario s:\n  a: car\n  event e\n  do parallel:\n    a.drive(duration: 3s)\n    emit e\n"
    built = automaton(text, "p.osc")
    starts = [t for t in built.transitions if t.source == built.initial]
    assert starts and all("e emitted" in t.events for t in starts)
    assert not any("e emitted" in t.events for t in built.transitions if t.source != built.initial)


def test_emit_in_a_one_of_or_alone_in_a_parallel_is_a_located_error():
    text = "scenario s:\n  a: car\n  event e\n  do one_of:\n    a.drive()\n    emit e\n"
    with pytest.raises(OscError) as caught:
        automaton(text, "p.osc")
    assert "p.osc:6:5: error: emit is a member of a serial or a parallel" in str(caught.value)
    alone = "scenario s:\n  a: car\n  event e\n  do serial:\n    a.drive()\n    parallel:\n      emit e\n"
    with pytest.raises(OscError) as caught:
        automaton(alone, "p.osc")
    assert "a parallel of only emit has no instant to emit at" in str(caught.value)


def test_until_a_condition_ends_the_phase_where_the_condition_holds():
    text = (
        "scenario s:\n  ego: car\n  lead: car\n  do parallel:\n    lead.drive()\n"
        "    ego.drive() with:\n      until ego.space_headway(reference: lead) < -5m\n"
    )
    a = automaton(text)
    (end,) = [t for t in a.transitions if t.target == a.final]
    # space_headway is front to front, negative when the caller leads: p(lead) - p(ego) <= -5
    assert Bound(Term(POSITION, "lead", "ego"), -math.inf, -5.0) in [replace_source(b) for b in end.guard.atoms()]


def test_until_a_condition_is_its_rising_edge_it_does_not_hold_when_the_phase_starts():
    text = "scenario s:\n  a: car\n  do a.drive() with:\n    until a.speed > 20mps\n"
    a = automaton(text)
    (start,) = a.outgoing(a.initial)
    (end,) = [t for t in a.transitions if t.target == a.final]
    assert str(start.guard) == "not v(a) >= 20" and str(end.guard) == "v(a) >= 20"


def replace_source(bound: Bound) -> Bound:
    return Bound(bound.term, bound.low, bound.high)


@pytest.mark.parametrize(
    "condition, expected",
    [
        ("a.speed >= 20mps", "v(a) >= 20"),
        ("a.time_headway(reference: b) < 2s", "h(b, a) <= 2"),
        ("a.relative_speed(reference: b) > 1mps", "v(a) - v(b) >= 1"),
        ("a.speed >= 20mps and not a.speed > 30mps", "v(a) >= 20 and not v(a) >= 30"),
        ("a.speed < 5mps or b.speed < 5mps", "v(a) <= 5 or v(b) <= 5"),
        ("10m < a.space_headway(reference: b)", "p(b) - p(a) >= 10"),
    ],
)
def test_conditions_become_guards_of_the_shared_algebra(condition, expected):
    text = f"scenario s:\n  a: car\n  b: car\n  do parallel:\n    b.drive()\n    serial:\n      a.drive()\n      wait {condition}\n"
    a = automaton(text)
    assert any(expected in str(t.guard) for t in a.transitions), a.describe()


@pytest.mark.parametrize(
    "condition, message",
    [
        ("a.speed > 5m", "speed is a speed, compared here with a length"),
        ("a.gap(reference: b) < 5m", "not supported in a condition: gap()"),
        ("a.space_headway() < 5m", "space_headway() needs reference: <actor>"),
        ("c.speed > 5mps", "a condition compares an actor's observable with a value"),
        ("rise(a.speed > 5mps)", "not supported: rise()"),
    ],
)
def test_a_condition_the_tool_cannot_read_is_a_checker_error_at_its_place(condition, message):
    text = f"scenario s:\n  a: car\n  b: car\n  do serial:\n    a.drive()\n    wait {condition}\n"
    report = check_text(text, "c.osc").report()
    assert "c.osc:6:" in report and message in report, report


def test_an_event_defined_as_elapsed_time_makes_the_waiting_phase_a_timed_one():
    text = "scenario s:\n  a: car\n  event later is elapsed([2s..3s])\n  do a.drive() with:\n    until @later\n"
    a = automaton(text)
    assert [str(t) for t in a.timings.values()] == ["a.drive lasts 2..3 s"]


TWICE = """\
scenario s:
    a: car
    b: car
    event go
    do parallel(overlap: equal):
        serial:
            first: a.drive()
            emit go
            second: a.drive()
            emit go
            third: a.drive()
        serial:
            b.drive() with:
                until @go
            b.change_lane(num_of_lanes: 1, side: left)
"""


def b_ends_with(a) -> set[str]:
    """The phases of a whose end can coincide with the end of b's wait."""
    return {
        ev.split()[0]
        for t in a.transitions
        if "b.drive end" in t.events
        for ev in t.events
        if ev.endswith(" end") and not ev.startswith("b.")
    }


def test_a_wait_ends_at_the_first_emission_of_its_event():
    assert b_ends_with(automaton(TWICE)) == {"first"}


def test_a_wait_with_a_condition_may_let_an_emission_pass_when_the_condition_does_not_hold():
    a = automaton(TWICE.replace("until @go", "until @go if b.speed > 10mps"))
    assert b_ends_with(a) == {"first", "second"}
    conditioned = [t for t in a.transitions if "b.drive end" in t.events]
    assert all("v(b) >= 10" in str(t.guard) for t in conditioned)


def test_the_realistic_event_scenarios_check_and_build():
    from pathlib import Path

    from pytest_roadlogic.frontend import check_file

    for name in ("emit_wait_brake", "merge_into_gap"):
        checked = check_file(Path(__file__).resolve().parents[2] / "scenarios" / "realistic" / f"{name}.osc")
        assert not checked.errors, checked.report()
        build_automaton(checked.scenarios[0])


BUILTIN = """\
scenario s:
    a: car
    b: car
    do parallel:
        serial:
            pass_b: a.change_lane(side: left, duration: [3s..4s])
            a.drive(duration: [2s..3s])
        serial:
            b.drive() with:
                until @pass_b.{edge}
            b.drive(duration: [{after}])
"""


def test_a_wait_for_a_phases_built_in_end_event_ends_at_the_instant_that_phase_ends():
    a = automaton(BUILTIN.format(edge="end", after="2s..3s"))
    ending = [t for t in a.transitions if "pass_b end" in t.events]
    assert ending, a.describe()
    for t in ending:
        assert {"pass_b.end emitted", "b.drive end"} <= set(t.events), t.events
    assert all("pass_b end" in t.events for t in a.transitions if "pass_b.end emitted" in t.events)


def test_a_wait_for_a_phases_built_in_start_event_ends_at_the_instant_that_phase_starts():
    text = BUILTIN.replace(
        "            pass_b: a.change_lane(side: left, duration: [3s..4s])\n            a.drive(duration: [2s..3s])\n",
        "            a.drive(duration: [2s..3s])\n            pass_b: a.change_lane(side: left, duration: [3s..4s])\n",
    )
    a = automaton(text.format(edge="start", after="3s..4s"))
    starting = [t for t in a.transitions if "pass_b.start emitted" in t.events]
    assert starting and all({"pass_b start", "b.drive end"} <= set(t.events) for t in starting), a.describe()


def test_a_built_in_event_of_a_label_no_phase_has_is_an_error_that_lists_the_labels():
    checked = check_text(BUILTIN.format(edge="end", after="2s..3s").replace("@pass_b.end", "@pass.end"), "e.osc")
    (error,) = checked.errors
    assert (error.location.line, error.message) == (
        10,
        "@pass.end is the end of the phase labelled 'pass', and no phase has that label",
    )
    assert "labels here: pass_b" in error.hint


def test_a_called_scenarios_built_in_event_refers_to_its_own_label_which_the_call_renames():
    callee = (
        BUILTIN.format(edge="end", after="2s..3s")
        .replace("scenario s:\n    a: car\n    b: car\n", "scenario a.pass_then_go:\n    b: car\n")
        .replace("a.change_lane", "change_lane")
        .replace("a.drive", "drive")
    )
    a = automaton(callee + "scenario top:\n    a: car\n    b: car\n    do a.pass_then_go()\n")
    ending = [t for t in a.transitions if "pass_then_go.pass_b end" in t.events]
    assert ending and all({"pass_b.end emitted", "b.drive end"} <= set(t.events) for t in ending), a.describe()
