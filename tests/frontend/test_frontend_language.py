"""What each construct of tiers 1 and 2 means once read: the model and the parameter domains.

The corpus test (test_corpus.py) shows that realistic files are accepted; this file pins down
what the front end makes of each construct, one at a time.
"""

import math

import pytest

from pytest_roadlogic.frontend import OscError, check_text, model, parse_text


def checked(text: str):
    result = check_text(text, "t.osc")
    assert not result.errors, result.report()
    return result


def domains(text: str) -> dict[str, str]:
    result = checked(text)
    return {name: d.describe() for name, d in result.scenarios[0].space.domains.items()}


PAIR = "scenario s:\n    a: car\n    b: car\n"


def uses(*names: str) -> str:
    """A behavior that uses the given length parameters, so that none is reported unused."""
    lines = "".join(f"            position({n}, behind: b, at: start)\n" for n in names)
    return "    do parallel:\n        b.drive()\n        a.drive() with:\n" + lines


# ---------------------------------------------------------------- lexical structure


def test_tabs_indent_to_eight_column_stops():
    scenario = checked("scenario s:\n\ta: car\n\tdo a.drive()\n").scenarios[0].scenario
    assert [a.name for a in scenario.actors] == ["a"]


def test_a_backslash_joins_lines():
    scenario = (
        checked(
            PAIR
            + "    do parallel:\n        b.drive()\n        a.drive() with:\n            lane(same_as: b, \\\n at: start)\n"
        )
        .scenarios[0]
        .scenario
    )
    modifier = scenario.behavior.children[1].modifiers[0]
    assert [arg.name for arg in modifier.arguments] == ["same_as", "at"]


def test_comments_and_blank_lines_anywhere_are_ignored():
    checked(
        "# head\n\nscenario s:  # trailing\n\n    a: car\n# column zero inside a block\n        # deeper\n    do a.drive()\n"
    )


def test_a_byte_order_mark_is_ignored():
    checked("\ufeffscenario s:\n    a: car\n    do a.drive()\n")


@pytest.mark.parametrize(
    "literal, value",
    [
        ("42", 42.0),
        ("0x1F", 31.0),
        ("1.5", 1.5),
        ("2e3", 2000.0),
        ("-4", -4.0),
        ("inf", math.inf),
        (".5", 0.5),
        (".1e+7", 1e6),
    ],
)
def test_number_literals(literal, value):
    osc = parse_text(f"scenario s:\n    x: float = {literal}\n")
    assert osc.scenarios[0].fields[0].default.value == value


@pytest.mark.parametrize(
    "literal, value, dimension",
    [
        ("10m", 10.0, "length"),
        ("2km", 2000.0, "length"),
        ("50cm", 0.5, "length"),
        ("3.6kph", 1.0, "speed"),
        ("1mph", 0.44704, "speed"),
        ("2mpsps", 2.0, "acceleration"),
        ("1500ms", 1.5, "time"),
        ("2min", 120.0, "time"),
        ("1e2m", 100.0, "length"),
    ],
)
def test_physical_literals_are_converted_to_si(literal, value, dimension):
    default = parse_text(f"scenario s:\n    x: length = {literal}\n").scenarios[0].fields[0].default
    assert default.value == pytest.approx(value) and default.dimension == dimension


@pytest.mark.parametrize("spelling", ["[10..20]m", "[10m..20m]", "range(10m, 20m)"])
def test_both_range_spellings_and_range_call(spelling):
    default = parse_text(f"scenario s:\n    x: length = {spelling}\n").scenarios[0].fields[0].default
    assert isinstance(default, model.Range)
    assert (default.low.value, default.high.value) == (10.0, 20.0)


def test_a_range_written_high_to_low_is_an_error_not_silently_swapped():
    """Issue 20: [20m..10m] holds no value; swapping it would guess which bound the author meant."""
    with pytest.raises(OscError, match="an empty range: its first bound is above its second"):
        parse_text("scenario s:\n    x: length = [20m..10m]\n")


@pytest.mark.parametrize(
    "literal, value",
    [('"two words"', "two words"), ("'single'", "single"), ('"""triple"""', "triple"), ('"esc\\"aped"', 'esc"aped')],
)
def test_string_literals(literal, value):
    assert parse_text(f"scenario s:\n    x: string = {literal}\n").scenarios[0].fields[0].default.value == value


def test_bool_enum_and_list_literals():
    fields = (
        parse_text("scenario s:\n    p: bool = false\n    q: side = side!left\n    r: float = [1, 2]\n")
        .scenarios[0]
        .fields
    )
    assert fields[0].default.value is False
    assert (fields[1].default.name, fields[1].default.enum) == ("left", "side")
    assert isinstance(fields[2].default, model.ListValue) and len(fields[2].default.items) == 2


def test_quoted_identifiers_name_anything():
    scenario = checked("scenario |my scenario|:\n    |the car|: car\n    do |the car|.drive()\n").scenarios[0].scenario
    assert scenario.name == "my scenario" and scenario.actors[0].name == "the car"


def test_operator_precedence():
    keep = parse_text("scenario s:\n    keep(x + 2 * y > 3 and not z or w => v)\n").scenarios[0].constraints[0]
    top = keep.expression
    assert top.operator == "=>"
    assert top.left.operator == "or" and top.left.left.operator == "and"
    comparison = top.left.left.left
    assert comparison.operator == ">" and comparison.left.operator == "+" and comparison.left.right.operator == "*"


# ---------------------------------------------------------------- declarations


def test_actor_fields_declared_together_and_their_types():
    scenario = (
        checked(
            "scenario s:\n    a, b: vehicle\n    t: truck\n    o: stationary_object\n    do parallel:\n        a.drive()\n        b.drive()\n        t.drive()\n        o.remain_stationary()\n"
        )
        .scenarios[0]
        .scenario
    )
    assert [(a.name, a.type) for a in scenario.actors] == [
        ("a", "vehicle"),
        ("b", "vehicle"),
        ("t", "truck"),
        ("o", "stationary_object"),
    ]
    assert scenario.actor("o").stationary


def test_a_declared_actor_type_derives_from_a_built_in_one():
    scenario = (
        checked("actor police inherits car:\n    siren: bool = false\nscenario s:\n    p: police\n    do p.drive()\n")
        .scenarios[0]
        .scenario
    )
    assert (scenario.actors[0].type, scenario.actors[0].base) == ("police", "car")


def test_the_device_under_test_needs_no_declaration():
    scenario = checked("scenario dut.s:\n    do dut.car.drive()\n").scenarios[0].scenario
    assert [a.name for a in scenario.actors] == ["dut.car"]


def test_a_parameter_range_from_keep_in():
    assert domains(PAIR + "    gap: length with:\n        keep(it in [10..20]m)\n" + uses("gap")) == {
        "gap": "[10..20]m"
    }


def test_bounds_from_several_keeps_intersect():
    text = PAIR + "    gap: length\n    keep(gap >= 5m)\n    keep(hard gap < 30m and gap > 10m)\n" + uses("gap")
    assert domains(text) == {"gap": "[10..30]m"}


def test_a_default_fixes_the_value():
    assert domains(PAIR + "    gap: length = 12m\n" + uses("gap")) == {"gap": "12m"}


def test_a_hard_in_overrides_the_default():
    assert domains(PAIR + "    gap: length = 12m\n    keep(gap in [20m..30m])\n" + uses("gap")) == {"gap": "[20..30]m"}


def test_a_default_keep_is_soft_and_a_later_default_replaces_it():
    text = (
        PAIR
        + "    gap: length with:\n        keep(default it == 12m)\n        keep(default it == 14m)\n        keep(it <= 40m)\n        keep(it >= 0m)\n"
        + uses("gap")
    )
    assert domains(text) == {"gap": "14m"}


def test_remove_default_restores_the_range():
    text = (
        PAIR + "    gap: length = 12m with:\n        keep(it in [5..15]m)\n        remove_default(it)\n" + uses("gap")
    )
    assert domains(text) == {"gap": "[5..15]m"}


def test_a_value_naming_another_parameter_follows_it_unless_a_hard_keep_of_its_own_overrides_it():
    text = PAIR + "    near: length with:\n        keep(it in [5..8]m)\n    far: length = near + 10m\n" + uses("far")
    result = checked(text)
    assert {n: d.describe() for n, d in result.scenarios[0].space.domains.items()} == {
        "near": "[5..8]m",
        "far": "[15..18]m",
    }
    assert len(result.scenarios[0].space.relations) == 1, "each sample meets far == near + 10m"
    overridden = text.replace("far: length = near + 10m\n", "far: length = near + 10m with:\n        keep(it == 30m)\n")
    assert domains(overridden) == {"near": "[5..8]m", "far": "30m"}


def test_a_default_range():
    text = PAIR + "    gap: length with:\n        keep(default it in [5..8]m)\n" + uses("gap")
    assert domains(text) == {"gap": "[5..8]m"}


def test_globals_are_parameters_of_every_scenario():
    text = "global gap: length with:\n    keep(it in [1..2]m)\n" + PAIR + uses("gap")
    assert domains(text) == {"gap": "[1..2]m"}


def test_enum_bool_and_string_parameters_have_choices():
    text = (
        "enum mood: [calm, hasty]\n"
        + PAIR
        + '    m: mood\n    flag: bool\n    name: string = "x"\n    do parallel:\n        a.drive()\n        b.drive()\n'
    )
    result = domains(text)
    assert result == {"m": "calm | hasty", "flag": "false | true", "name": "x"}


def test_a_relation_between_parameters_is_checked_on_samples():
    text = (
        PAIR
        + "    g1: length with:\n        keep(it in [0..10]m)\n    g2: length with:\n        keep(it in [0..10]m)\n    keep(g1 + g2 <= 12m)\n"
        + uses("g1", "g2")
    )
    result = checked(text)
    space = result.scenario("s").space
    assert space.accepts({"g1": 5.0, "g2": 6.0}) and not space.accepts({"g1": 7.0, "g2": 6.0})


def test_arithmetic_in_an_argument_is_evaluated_over_the_range():
    from pytest_roadlogic.frontend.semantics.values import evaluate

    result = checked(PAIR + "    gap: length with:\n        keep(it in [10..20]m)\n" + uses("gap"))
    argument = result.scenarios[0].scenario.behavior.children[1].modifiers[0].arguments[0].value
    doubled = model.Binary("*", model.Quantity(2.0, None, argument.location), argument, argument.location)
    value = evaluate(doubled, result.scenario("s").space.environment())
    assert (value.low, value.high, value.dimension) == (20.0, 40.0, "length")
    assert evaluate(doubled, result.scenario("s").space.environment({"gap": 12.5})).low == 25.0


# ---------------------------------------------------------------- behavior


def test_compositions_with_arguments_and_labels():
    text = (
        PAIR
        + "    do top: serial(duration: [10..20]s):\n        p: parallel(overlap: equal, duration: 5s):\n            a.drive()\n            b.drive()\n        o: one_of:\n            a.drive()\n            b.drive()\n"
    )
    behavior = checked(text).scenarios[0].scenario.behavior
    assert (behavior.label, behavior.operator) == ("top", "serial")
    duration = behavior.argument("duration").value
    assert (duration.low.value, duration.high.value) == (10.0, 20.0)
    assert [(c.label, c.operator) for c in behavior.children] == [("p", "parallel"), ("o", "one_of")]


def test_an_invocation_with_arguments_modifiers_keep_and_until():
    text = (
        PAIR
        + "    event go\n    do serial:\n        a.change_lane(1, left) with:\n            speed([20..30]mps)\n            keep(it.duration <= 5s)\n            until @go\n        emit go\n        b.drive()\n"
    )
    invocation = checked(text).scenarios[0].scenario.behavior.children[0]
    assert (invocation.actor, invocation.action) == ("a", "change_lane")
    assert [a.name for a in invocation.arguments] == [None, None]
    assert invocation.modifiers[0].name == "speed"
    assert invocation.constraints[0].expression.operator == "<="
    assert invocation.until.name == "go"


def test_waits_take_a_time_an_event_or_a_condition():
    text = (
        PAIR
        + "    event e\n    do serial:\n        wait elapsed([1..2]s)\n        a.drive()\n        wait a.speed > 10mps\n        emit e\n        wait @e\n        b.drive()\n"
    )
    waits = [c for c in checked(text).scenarios[0].scenario.behavior.children if isinstance(c, model.Wait)]
    assert isinstance(waits[0].condition, model.Call) and waits[0].condition.function == "elapsed"
    assert isinstance(waits[1].condition, model.Binary)
    assert isinstance(waits[2].condition, model.EventReference)


def test_extend_adds_members_to_a_scenario():
    text = PAIR + "extend s:\n    gap: length = 5m\n" + uses("gap")
    scenario = checked(text).scenarios[0].scenario
    assert scenario.parameter("gap") is not None and scenario.behavior is not None


def test_extend_adds_members_to_an_enum_in_either_spelling():
    text = (
        "enum color: [red]\nextend color: [green, blue]\nextend color:\n    white\n    black = 9\n"
        + PAIR
        + "    tint: color\n    do parallel:\n        a.drive()\n        b.drive()\n"
    )
    assert domains(text)["tint"] == "red | green | blue | white | black"


def test_extending_an_unknown_enum_is_a_located_error():
    result = check_text("extend colour: [green]\n" + PAIR + "    do a.drive()\n", "t.osc")
    assert "t.osc:1:8: error: extend of an unknown enum 'colour'" in result.report()


# The standard's syntax that the tool reads and does not execute: each parses, and the checker
# refuses it by name at its place (never a syntax error).
STANDARD_SYNTAX_REFUSED = [
    ("    var seen: speed\n", "not supported: var", 4),
    ("    var at_start: speed = 3mps\n", "not supported: var", 4),
    ("    on @go as g if a.speed > 3mps:\n        emit go\n    event go\n", "not supported: on", 4),
    (
        "    def f(x: speed) -> speed is only external lib.f(x)\n    y: speed = f(x: 3mps)\n",
        "not supported: a call of the external method 'f'",
        5,
    ),
    ("    x: float = .1e+7\n    keep(x > 0 ? 1 : 2)\n", "not supported: a conditional expression", 5),
]


@pytest.mark.parametrize(
    "members, message, line", STANDARD_SYNTAX_REFUSED, ids=[m for _, m, _ in STANDARD_SYNTAX_REFUSED]
)
def test_the_standards_syntax_parses_and_what_the_tool_does_not_execute_is_refused_by_name(members, message, line):
    result = check_text(PAIR + members + "    do parallel:\n        a.drive()\n        b.drive()\n", "t.osc")
    report = result.report()
    assert "syntax error" not in report and f"t.osc:{line}:" in report and message in report, report


def test_a_type_test_in_a_wait_is_refused_by_name():
    result = check_text(PAIR + "    do serial:\n        a.drive(duration: 2s)\n        wait a.is(car)\n", "t.osc")
    assert "t.osc:6:" in result.report() and "not supported: a type test x.is(T)" in result.report(), result.report()


def test_keywords_name_fields_where_the_standard_allows_it():
    checked(
        "struct origin:\n    namespace: string\n    sample: int\n    expression: float\n"
        + PAIR
        + "    do parallel:\n        a.drive()\n        b.drive()\n"
    )


def test_a_method_is_an_expression_with_or_without_the_keyword():
    osc = parse_text(
        "scenario s:\n    def twice() -> length is expression 2 * 3m\n    def once() -> length is only 3m\n"
    )
    assert [m.body.value if hasattr(m.body, "value") else m.body.operator for m in osc.scenarios[0].methods] == [
        "*",
        3.0,
    ]


# ---------------------------------------------------------------- several errors, imports


def test_every_error_of_a_file_is_reported_not_just_the_first():
    text = (
        PAIR
        + "    do parallel:\n        ghost.drive()\n        a.fly()\n        b.drive() with:\n            lane(0, at: start)\n"
    )
    result = check_text(text, "t.osc")
    messages = [f"{d.location.line}: {d.message}" for d in result.errors]
    assert messages == [
        "5: unknown actor 'ghost'",
        "6: unknown action 'fly'",
        "8: lane 0 is outside the road's 3 lanes",
    ]


def test_an_import_loads_declarations_relative_to_the_importing_file(tmp_path):
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "types.osc").write_text("actor taxi inherits car\nglobal g: length = 3m\n")
    (tmp_path / "main.osc").write_text('import "lib/types.osc"\nscenario s:\n    a: taxi\n    b: car\n' + uses("g"))
    from pytest_roadlogic.frontend import check_file

    result = check_file(tmp_path / "main.osc")
    assert not result.errors, result.report()
    assert result.scenarios[0].scenario.actor("a").base == "car"
    assert [s.name for s in result.scenarios] == ["s"], "an imported file's scenarios are not the importer's"


def test_errors_in_an_imported_file_are_reported_with_its_own_path(tmp_path):
    (tmp_path / "lib.osc").write_text("scenario broken\n    a: car\n")
    (tmp_path / "main.osc").write_text('import "lib.osc"\nscenario s:\n    a: car\n    do a.drive()\n')
    from pytest_roadlogic.frontend import check_file

    report = check_file(tmp_path / "main.osc").report()
    assert f"{tmp_path / 'main.osc'}:1:8: error: the imported file 'lib.osc' has errors" in report
    assert f"{tmp_path / 'lib.osc'}:2:5: error: unexpected indented block" in report
    assert "scenario broken" not in report.split("lib.osc:2:5")[0].splitlines()[-1]


def test_a_circular_import_is_an_error_not_a_hang(tmp_path):
    (tmp_path / "a.osc").write_text('import "b.osc"\nscenario s:\n    a: car\n    do a.drive()\n')
    (tmp_path / "b.osc").write_text('import "a.osc"\n')
    from pytest_roadlogic.frontend import check_file

    errors = check_file(tmp_path / "a.osc").errors
    assert any("imports itself" in e.message and e.location.path.endswith("b.osc") for e in errors)


def test_parse_errors_raise_the_project_error_type():
    with pytest.raises(OscError):
        check_text("scenario s:\n", "t.osc")
