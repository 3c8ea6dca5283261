"""The front end reads the paper's Listing 1 verbatim and reports bad input with file:line:col."""

import pytest

from pytest_roadlogic.frontend import Composition, Invocation, OscError, Range, parse_text


def test_listing_1_parses_into_the_scenario_model(overtake):
    assert overtake.name == "overtake"
    overtake = overtake.scenario
    assert overtake.actor_type == "traffic"
    assert [(a.name, a.type) for a in overtake.actors] == [("v1", "car"), ("v2", "car")]
    top = overtake.behavior
    assert isinstance(top, Composition) and top.operator == "parallel"
    v2_drive, serial = top.children
    assert isinstance(v2_drive, Invocation) and (v2_drive.actor, v2_drive.action) == ("v2", "drive")
    assert serial.operator == "serial"
    assert [phase.label for phase in serial.children] == ["A", "B", "C"]


def test_paper_range_spelling_puts_the_unit_on_both_bounds(overtake):
    phase_a = overtake.scenario.behavior.children[1].children[0]
    position = [m for m in phase_a.modifiers if m.name == "position"][0]
    distance = position.arguments[0].value
    assert isinstance(distance, Range)
    assert (distance.low.value, distance.high.value, distance.dimension) == (10.0, 20.0, "length")


def test_standard_range_spelling_and_units_convert_to_si():
    text = "scenario s:\n  a: car\n  do a.drive() with:\n    speed([36kph..72kph], at: start)\n"
    speed = parse_text(text).scenarios[0].behavior.modifiers[0].arguments[0].value
    assert speed.low.value == pytest.approx(10.0) and speed.high.value == pytest.approx(20.0)


def test_nodes_keep_their_source_location(overtake):
    phase_b = overtake.scenario.behavior.children[1].children[1]
    assert (phase_b.location.line, phase_b.location.column) == (13, 10)
    assert phase_b.modifiers[0].location.line == 14


def test_line_breaks_inside_brackets_and_crlf_and_no_final_newline_are_fine():
    text = "scenario s:\r\n  a: car\r\n  b: car\r\n  do a.drive() with:\r\n    position([5..10]m,\r\n             behind: b, at: end)"
    scenario = parse_text(text).scenarios[0]
    assert scenario.behavior.modifiers[0].name == "position"


def test_a_syntax_error_names_file_line_and_column_and_shows_the_line():
    text = "scenario s:\n  a: car\n  do a.drive() with\n    speed(1mps, at: end)\n"
    with pytest.raises(OscError) as caught:
        parse_text(text, "bad.osc")
    report = str(caught.value)
    assert report.startswith("bad.osc:3:")
    assert "error:" in report and "do a.drive() with" in report and "^" in report


def test_an_unknown_unit_is_reported_with_the_known_ones():
    with pytest.raises(OscError) as caught:
        parse_text("scenario s:\n  a: car\n  do a.drive() with:\n    speed(3furlongs, at: end)\n", "u.osc")
    assert "u.osc:4:11: error: unknown unit 'furlongs'" in str(caught.value)
    assert "mps" in str(caught.value)
