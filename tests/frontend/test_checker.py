"""Every error (and warning) the front end reports, each from a small bad file.

Each case names the construct, gives the file, and states the exact ``line:col: severity: message``
a user sees. When one of these fails, the message or its place changed: check that the new one
still points at the offending token and still says what to do.
"""

import pytest

from pytest_roadlogic.frontend import OscError, check_file, check_text

HEAD = "scenario s:\n    a: car\n    b: car\n"
# The same scenario on a road of at most three lanes: two lines more, so errors move down by two.
ROAD3 = "scenario s:\n    road: Path\n    road.path_max_lanes(3)\n    a: car\n    b: car\n"


def drive(modifiers: list[str], head: str = HEAD) -> str:
    """Scenario s where b drives and a drives with the given modifier lines."""
    body = "".join(f"            {m}\n" for m in modifiers)
    return head + "    do parallel:\n        b.drive()\n        a.drive() with:\n" + body


def diagnostics(text: str):
    try:
        return check_text(text, "t.osc").diagnostics
    except OscError as error:
        return error.diagnostics


CASES = [
    ("missing_colon", "scenario s\n    a: car\n", "2:5: error: unexpected indented block"),
    (
        "bad_dedent",
        "scenario s:\n    a: car\n  b: car\n",
        "3:3: error: this line is dedented to a column that no enclosing block uses",
    ),
    ("unknown_unit", drive(["position(3furlongs, behind: b, at: start)"]), "7:22: error: unknown unit 'furlongs'"),
    (
        "unit_twice",
        drive(["position([1m..2m]m, behind: b, at: start)"]),
        "7:30: error: a unit after the range, but a bound already has one",
    ),
    (
        "range_kinds",
        drive(["position([1m..2s], behind: b, at: start)"]),
        "7:22: error: the range's bounds differ in kind (length and time)",
    ),
    (
        "range_bound_name",
        drive(["position([b..2]m, behind: b, at: start)"]),
        "7:23: error: a range bound must be a number, with its unit",
    ),
    ("on", HEAD + "    on @x:\n        emit y\n", "4:5: error: not supported: on"),
    ("call", HEAD + "    do call log()\n", "4:8: error: not supported: call"),
    (
        "cover",
        HEAD + "    cover(a)\n",
        "4:11: warning: cover(a): a is no logical parameter of the scenario (a value it leaves open, sampled per case); the item is not collected",
    ),
    (
        "record",
        HEAD + "    record(a, expression: a.heading_to(b))\n",
        "4:27: warning: not supported yet: record() of this value of the run; the tool collects the scenario's "
        "logical parameters, and vehicles' speeds, accelerations, positions and gaps (a.space_gap(b)) at an event; "
        "the item is not collected",
    ),
    (
        "cover_in_actor_declaration",
        "actor robot inherits car:\n    cover(speed)\n" + HEAD,
        "2:5: warning: cover() in a type declaration is read and ignored",
    ),
    ("export", "export s\n" + HEAD, "1:1: error: not supported: export"),
    ("export_namespace_wildcard", "export mine::*\n" + HEAD, "1:1: error: not supported: export"),
    (
        "namespace_qualifier_type",
        HEAD + "    c: osc::car\n",
        "4:8: error: not supported: the namespace qualifier in 'osc::car'",
    ),
    (
        "global_namespace_qualifier",
        HEAD + "    c: ::car\n",
        "4:8: error: not supported: the namespace qualifier in '::car'",
    ),
    ("var", HEAD + "    var x: length = 1m\n", "4:5: error: not supported: var"),
    (
        "external",
        HEAD + "    def f() -> length is external cpp.f()\n",
        "4:9: warning: an external method is read and ignored",
    ),
    (
        "external_call",
        HEAD + "    def f() -> length is external cpp.f()\n    g: length = f()\n",
        "5:17: error: not supported: a call of the external method 'f'",
    ),
    (
        "modifier_decl",
        "modifier my_mod of car:\n    x: length\n" + HEAD,
        "1:1: error: not supported: modifier declarations",
    ),
    ("rise", HEAD + "    do serial:\n        wait rise(a.speed > 10mps)\n", "5:14: error: not supported: rise()"),
    ("action_decl", "action car.my_action:\n    x: length\n", "1:12: error: not supported: action declarations"),
    (
        "inherits_unknown",
        "scenario base:\n    a: car\nscenario s inherits basis:\n    b: car\n",
        "3:10: error: scenario 's' inherits an unknown scenario 'basis'",
    ),
    (
        "scenario_modifier",
        HEAD + "    a.speed(10mps)\n",
        "4:7: error: not supported: a modifier applied to the whole scenario",
    ),
    ("import_late", HEAD + "import osc.standard\n", "4:8: error: an import after a declaration"),
    ("unknown_library", "import foo.bar\n" + HEAD, "1:8: error: unknown library 'foo.bar'"),
    ("missing_import", 'import "nowhere.osc"\n' + HEAD, "1:8: error: cannot find the imported file 'nowhere.osc'"),
    (
        "duplicate_scenario",
        HEAD + "scenario s:\n    c: car\n",
        "4:10: error: scenario 's' is already declared on line 1",
    ),
    ("duplicate_field", HEAD + "    a: truck\n", "4:5: error: 'a' is already declared on line 2"),
    (
        "duplicate_label",
        HEAD + "    do serial:\n        x: a.drive()\n        x: b.drive()\n",
        "6:12: error: label 'x' is already used on line 5",
    ),
    ("duplicate_enum_member", "enum e: [p, q, p]\n" + HEAD, "1:6: error: enum 'e' lists 'p' twice"),
    ("duplicate_type", "enum side: [l, r]\n" + HEAD, "1:6: error: type 'side' is already declared"),
    ("unknown_type", HEAD + "    c: spaceship\n", "4:8: error: unknown type 'spaceship'"),
    ("person", HEAD + "    p: person\n", "4:8: error: not supported: actor type 'person' (the road is a highway)"),
    (
        "actor_no_base",
        "actor robot\n" + HEAD + "    r: robot\n",
        "5:8: warning: actor type 'robot' does not derive from a road user: it is driven as a vehicle",
    ),
    (
        "struct_param",
        "struct st:\n    x: length\n" + HEAD + "    p: st\n",
        "6:8: warning: a parameter of struct type 'st' is read but not used: its fields are not parameters of the scenario",
    ),
    ("list_param", HEAD + "    p: list of length\n", "4:8: error: not supported: list parameters"),
    (
        "actor_constraint",
        HEAD.replace("    a: car\n", "    a: car with:\n        keep(it.color == red)\n"),
        "3:9: warning: a constraint on the fields of a is read but not enforced: vehicles are simulated with the tool's own dimensions",
    ),
    ("two_dos", HEAD + "    do a.drive()\n    do b.drive()\n", "5:8: error: a scenario has at most one `do`"),
    ("unknown_actor_invocation", HEAD + "    do c.drive()\n", "4:8: error: unknown actor 'c'"),
    (
        "unknown_actor_argument",
        drive(["position([1..2]m, behind: ghost, at: start)"]),
        "7:39: error: unknown actor 'ghost'",
    ),
    ("no_actor", HEAD + "    do drive()\n", "4:8: error: drive() needs an actor"),
    ("unknown_action", HEAD + "    do a.fly()\n", "4:8: error: unknown action 'fly'"),
    ("unknown_modifier", drive(["colour(red)"]), "7:13: error: unknown modifier 'colour'"),
    (
        "unknown_argument",
        drive(["position([1..2]m, before: b, at: start)"]),
        "7:31: error: unknown argument 'before' of position()",
    ),
    (
        "too_many_positional",
        drive(["position(1m, 2m, behind: b, at: start)"]),
        "7:26: error: too many positional arguments to position()",
    ),
    (
        "argument_twice",
        drive(["position(1m, distance: 2m, behind: b, at: start)"]),
        "7:26: error: position() is given 'distance' twice",
    ),
    (
        "unsupported_argument",
        HEAD + "    do a.change_lane(side: left, rate_profile: smooth)\n",
        "4:34: error: not supported: argument 'rate_profile' of change_lane()",
    ),
    (
        "exclusive",
        drive(["position(1m, behind: b, ahead_of: b, at: start)"]),
        "7:26: error: position() takes only one of ahead_of, behind",
    ),
    ("required", drive(["position(1m, at: start)"]), "7:13: error: position() needs ahead_of: or behind:"),
    (
        "speed_for_length",
        drive(["position(3mps, behind: b, at: start)"]),
        "7:22: error: position() expects a length for distance, got a speed",
    ),
    (
        "number_for_length",
        drive(["position(3, behind: b, at: start)"]),
        "7:22: error: position() expects a length for distance, got a plain number",
    ),
    (
        "unit_for_number",
        drive(["lane(2m, at: start)"]),
        "7:18: error: lane() expects a plain number for lane, got a length",
    ),
    ("bad_enum", drive(["lane(same_as: b, at: middle)"]), "7:34: error: at: takes start, end or all"),
    ("bad_enum_qualified", drive(["lane(same_as: b, at: side!left)"]), "7:34: error: at: takes start, end or all"),
    (
        "negative_uint",
        HEAD + "    do a.change_lane(-1, left)\n",
        "4:22: error: num_of_lanes: takes a whole number from 0 up",
    ),
    (
        "lane_outside",
        drive(["lane(4, at: start)"], head=ROAD3),
        "9:18: error: lane 4 is outside the road's 3 lanes (path_max_lanes(3) on line 3)",
    ),
    ("lane_zero", drive(["lane(0, at: start)"]), "7:18: error: lane 0 is outside the road's 3 lanes"),
    (
        "lane_change_too_far",
        ROAD3 + "    do a.change_lane(3, left)\n",
        "6:22: error: a change of 3 lanes is impossible on a road of 3 lanes (path_max_lanes(3) on line 3)",
    ),
    (
        "road_map",
        HEAD + '    road: Path\n    road.set_map("Town04")\n',
        "5:10: warning: the map is not available: the scenario runs on one straight road",
    ),
    (
        "road_map_not_a_string",
        HEAD + "    road: Path\n    road.set_map(4)\n",
        '5:18: error: map: takes a string, e.g. "Town04"',
    ),
    ("drive_path_not_a_road", HEAD + "    do a.drive(b)\n", "4:16: error: path: takes the scenario's road"),
    (
        "declared_modifier_unknown",
        "modifier Path.set_weather\n" + HEAD,
        "1:15: error: not supported: the declared modifier 'set_weather'",
    ),
    (
        "unit_contradicts_builtin",
        "type velocity is SI(m: 1, s: -1)\nunit kph of velocity is SI(m: 1, s: -1, factor: 0.3)\n" + HEAD,
        "2:6: warning: unit 'kph' is declared as 0.3 SI speed units; the standard's kph is 0.277777778 (8.0e-02 relative); this file's values are read with its own",
    ),
    (
        "unit_of_unknown_type",
        "unit foot of distance is SI(m: 1, factor: 0.3048)\n" + HEAD,
        "1:6: error: unit 'foot' is of an unknown type 'distance'",
    ),
    (
        "unit_exponents_differ",
        "type len is SI(m: 1)\nunit foot of len is SI(s: 1, factor: 0.3048)\n" + HEAD,
        "2:6: error: unit 'foot' has other SI exponents than its type 'len'",
    ),
    (
        "type_contradicts_builtin",
        "type speed is SI(m: 1)\n" + HEAD,
        "1:6: error: type 'speed' is a length here but a speed in the standard library (osc.physical)",
    ),
    (
        "road_bounds_contradict",
        HEAD + "    road: Path\n    road.path_max_lanes(2)\n    road.path_min_driving_lanes(4)\n",
        "5:10: error: at most 2 lanes contradicts at least 4 (line 6)",
    ),
    (
        "road_lanes_not_whole",
        HEAD + "    road: Path\n    road.path_min_driving_lanes(2.5)\n",
        "5:33: error: lanes: takes a whole number from 0 up",
    ),
    (
        "road_lanes_zero",
        HEAD + "    road: Path\n    road.path_max_lanes(0)\n",
        "5:25: error: path_max_lanes() takes one whole number of lanes from 1 up, e.g. path_max_lanes(3)",
    ),
    (
        "road_lanes_unit",
        HEAD + "    road: Path\n    road.path_max_lanes(3m)\n",
        "5:25: error: path_max_lanes() expects a plain number for lanes, got a length",
    ),
    ("road_unknown", HEAD + "    lanes.path_max_lanes(3)\n", "4:11: error: unknown road 'lanes'"),
    (
        "road_with_value",
        HEAD + "    road: Path = 3\n",
        "4:11: error: a road takes no value",
    ),
    (
        "road_with_a_keep_of_no_lanes",
        HEAD + "    road: Path with:\n        keep(it == 3)\n",
        "5:9: error: not supported: this keep() of a road",
    ),
    (
        "from_with_relative",
        drive(["lane(same_as: b, from: left, at: start)"]),
        "7:30: error: from: goes with a lane number, not with a relative lane",
    ),
    (
        "stationary_drives",
        "scenario s:\n    o: stationary_object\n    do o.drive()\n",
        "3:8: error: 'o' is a stationary_object: it can only remain_stationary() or keep_position()",
    ),
    (
        "modifier_other_actor",
        drive(["b.lane(1, at: start)"]),
        "7:15: error: this modifier names 'b' but the invocation is for 'a'",
    ),
    ("unknown_name", drive(["position(gap, behind: b, at: start)"]), "7:22: error: unknown name 'gap'"),
    (
        "unbounded_parameter",
        HEAD
        + "    gap: length\n    do parallel:\n        b.drive()\n        a.drive() with:\n            position(gap, behind: b, at: start)\n",
        "4:5: error: parameter 'gap' has no range or value",
    ),
    (
        "empty_range",
        HEAD + "    gap: length with:\n        keep(it >= 20m)\n        keep(it <= 10m)\n",
        "6:9: error: parameter 'gap' is constrained to an empty range",
    ),
    (
        "default_outside",
        HEAD + "    gap: length = 50m with:\n        keep(it <= 10m)\n        keep(it >= 1m)\n",
        "4:19: warning: the default of 'gap' (50m) lies outside its range [1..10]m; it is ignored",
    ),
    ("default_wrong_kind", HEAD + "    gap: length = 5s\n", "4:19: error: 'gap' is a length but this is a time"),
    (
        "keep_wrong_kind",
        HEAD + "    gap: length with:\n        keep(it in [1..2]s)\n",
        "5:20: error: 'gap' is a length but this is a time",
    ),
    ("keep_unknown_name", HEAD + "    keep(gap > 1m)\n", "4:10: error: unknown name 'gap' in a constraint"),
    (
        "enum_default_not_member",
        "enum e: [p, q]\n" + HEAD + "    x: e = r\n",
        "5:12: error: the default of 'x' is not one of its values (p, q)",
    ),
    (
        "add_speed_length",
        drive(["position(1m + 2mps, behind: b, at: start)"]),
        "7:25: error: '+' between a length and a speed",
    ),
    (
        "emit_undeclared",
        HEAD + "    do serial:\n        a.drive()\n        emit boom\n",
        "6:9: error: emit names an undeclared event 'boom'",
    ),
    (
        "wait_unknown_event",
        HEAD + "    do serial:\n        a.drive()\n        wait @boom\n",
        "6:14: error: unknown event 'boom'",
    ),
    (
        "elapsed_length",
        HEAD + "    do serial:\n        a.drive()\n        wait elapsed(3m)\n",
        "6:22: error: elapsed() expects a time, got a length",
    ),
    (
        "unknown_function",
        HEAD + "    do serial:\n        a.drive()\n        wait later(3s)\n",
        "6:14: error: unknown function 'later'",
    ),
    (
        "start_to_start_length",
        HEAD + "    do parallel(overlap: any, start_to_start: 2m):\n        a.drive()\n        b.drive()\n",
        "4:47: error: parallel expects a time for start_to_start, got a length",
    ),
    (
        "duration_length",
        HEAD + "    do serial(duration: 5m):\n        a.drive()\n        b.drive()\n",
        "4:25: error: serial expects a time for duration, got a length",
    ),
    (
        "unused_parameter",
        HEAD + "    gap: length = 5m\n    do parallel:\n        a.drive()\n        b.drive()\n",
        "4:5: warning: parameter 'gap' is never used",
    ),
    ("idle_actor", HEAD + "    do a.drive()\n", "3:5: warning: actor 'b' takes no part in the behavior"),
    (
        "extend_unknown",
        "extend nothing:\n    x: length = 1m\n" + HEAD,
        "1:1: error: extend names an unknown scenario 'nothing'",
    ),
    (
        "method_argument_unknown",
        HEAD + "    def f(x: length) -> length is x\n    g: length = f(y: 2m)\n",
        "5:19: error: method 'f' has no parameter 'y'",
    ),
    (
        "composition_argument",
        HEAD + "    do serial(speed: 5mps):\n        a.drive()\n        b.drive()\n",
        "4:15: error: unknown argument 'speed' of serial",
    ),
    (
        "function_in_argument",
        drive(["position(f(1m), behind: b, at: start)"]),
        "7:22: error: a function call is not allowed in distance:",
    ),
    (
        "invocation_keep",
        HEAD + "    do a.drive() with:\n        keep(it.duration <= 5m)\n",
        "5:26: error: '<=' between a time and a length",
    ),
]


@pytest.mark.parametrize("text, expected", [pytest.param(t, e, id=n) for n, t, e in CASES])
def test_the_checker_reports_the_problem_at_its_place(text, expected):
    lines = [f"{d.location.line}:{d.location.column}: {d.severity}: {d.message}" for d in diagnostics(text)]
    assert expected in lines, "\n".join(lines)
    severity = expected.split(": ")[1]
    first_of_kind = [line for line in lines if f": {severity}: " in line][0]
    assert first_of_kind == expected, "the expected problem should be the first of its kind reported"


def test_every_report_has_the_offending_line_and_a_caret():
    for name, text, _ in CASES:
        for diagnostic in diagnostics(text):
            formatted = diagnostic.format(text).splitlines()
            assert formatted[0].startswith(f"t.osc:{diagnostic.location.line}:{diagnostic.location.column}: "), name
            assert formatted[2].strip() == "^", name


LIBRARY = """\
type distance is SI(m: 1)
unit furlong of distance is SI(m: 1, factor: 201.168)
type velocity is SI(m: 1, s: -1)
unit kph of velocity is SI(m: 1, s: -1, factor: 0.277777778)
type angle is SI(rad: 1)
unit deg of angle is SI(rad: 1, factor: 0.017453293)
actor Sedan
modifier Path.set_map
"""


def test_a_unit_declared_in_an_unquoted_import_is_read_with_its_factor(tmp_path):
    (tmp_path / "lib.osc").write_text(LIBRARY)
    (tmp_path / "s.osc").write_text(
        "import lib.osc\nscenario s:\n    a: Sedan\n    b: Sedan\n    limit: velocity = 72kph\n"
        "    do a.drive() with:\n        position(1furlong, behind: b, at: start)\n        speed(limit)\n"
    )
    checked = check_file(tmp_path / "s.osc")
    assert not checked.errors, checked.report()
    position = checked.scenarios[0].scenario.behavior.modifiers[0].arguments[0].value
    assert position.value == pytest.approx(201.168) and position.dimension == "length"
    # a declared alias of speed is a speed parameter
    assert checked.scenarios[0].space.domains["limit"].interval.dimension == "speed"


def test_a_unit_of_a_dimension_the_tool_does_not_model_is_refused_where_it_is_used(tmp_path):
    (tmp_path / "lib.osc").write_text(LIBRARY)
    (tmp_path / "s.osc").write_text(
        "import lib.osc\nscenario s:\n    a: Sedan\n    do a.drive() with:\n        speed(90deg)\n"
    )
    lines = [f"{d.location.line}:{d.location.column}: {d.message}" for d in check_file(tmp_path / "s.osc").errors]
    assert "5:15: speed() expects a speed for speed, got an angle" in lines
