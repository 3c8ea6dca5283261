"""Files others publish, read as written: one test per cause that kept public files from checking
(the language decisions in docs/language.md: a file's own declarations win, every dimension is
read, the standard's methods, the spellings other grammars accept)."""

from __future__ import annotations

import math
import random
from pathlib import Path

import pytest

from pytest_roadlogic.frontend import check_file, check_text
from pytest_roadlogic.frontend.semantics.values import Interval

LIBRARY = """type speed is SI(m: 1, s: -1)
unit mph of speed is SI(m: 1, s: -1, factor: 0.447038889)
unit kph of speed is SI(m: 1, s: -1, factor: 0.277777778)
type temperature is SI(K: 1)
unit celsius of temperature is SI(K: 1, factor: 1, offset: 273.15)
actor Path
modifier Path.set_map
modifier Path.path_min_driving_lanes
"""


def _lines(checked, severity: str = "error") -> list[str]:
    return [
        f"{Path(d.location.path).name}:{d.location.line}:{d.location.column}: {d.message}"
        for d in checked.diagnostics
        if d.severity == severity
    ]


def _checked(tmp_path, body: str, dialect: str | None = None):
    (tmp_path / "basic.osc").write_text(LIBRARY)
    (tmp_path / "s.osc").write_text("import basic.osc\n" + body)
    return check_file(tmp_path / "s.osc", dialect=dialect)


def _value(checked, parameter: str) -> Interval:
    return checked.scenarios[0].space.domains[parameter].interval


def test_a_files_own_mph_is_read_with_its_own_factor_and_a_warning_naming_both(tmp_path):
    checked = _checked(
        tmp_path, "scenario s:\n    ego: car\n    v: speed = 50mph\n    do ego.drive() with:\n        speed(v)\n"
    )
    assert not checked.errors, checked.report()
    assert _value(checked, "v").low == pytest.approx(50 * 0.447038889, rel=1e-12)
    (warning,) = [w for w in _lines(checked, "warning") if "mph" in w]
    assert warning.startswith("basic.osc:2:6: unit 'mph' is declared as 0.447038889 SI speed units")
    assert "the standard's mph is 0.44704" in warning


def test_a_declared_unit_within_rounding_of_the_standards_is_read_without_a_warning(tmp_path):
    checked = _checked(tmp_path, "scenario s:\n    ego: car\n    do ego.drive() with:\n        speed(90kph)\n")
    assert not [w for w in _lines(checked, "warning") if "kph" in w]


@pytest.mark.parametrize(
    "declaration, value",
    [
        ("heading: angle = 30deg", 30 * math.pi / 180),
        ("heading: angle = 2degree", 2 * math.pi / 180),
        ("heading: angle = 0.5rad", 0.5),
        ("turn: angular_rate = 0.1radps", 0.1),
        ("outside: temperature = 20celsius", 293.15),
    ],
)
def test_angles_rates_and_temperatures_with_an_offset_are_read_in_declarations(tmp_path, declaration, value):
    checked = _checked(tmp_path, f"scenario s:\n    ego: car\n    {declaration}\n    do ego.drive(duration: 3s)\n")
    assert not checked.errors, checked.report()
    name = declaration.split(":")[0]
    assert _value(checked, name).low == pytest.approx(value)


def test_a_value_of_a_dimension_the_tool_does_not_plan_is_refused_where_it_would_be_planned():
    checked = check_text("scenario s:\n    ego: car\n    do ego.drive() with:\n        speed(90deg)\n", "s.osc")
    assert _lines(checked) == ["s.osc:4:15: speed() expects a speed for speed, got an angle"]


@pytest.mark.parametrize("spelling", ["20 kph", "20kph", "1.5e1 mps"])
def test_a_space_between_number_and_unit_is_read_as_one_literal(spelling):
    checked = check_text(f"scenario s:\n    ego: car\n    do ego.drive() with:\n        speed({spelling})\n", "s.osc")
    assert not checked.errors, checked.report()


@pytest.mark.parametrize("unit, seconds", [("minutes", 120), ("minute", 120), ("min", 120), ("h", 7200)])
def test_minutes_and_hours_are_units_of_time(unit, seconds):
    checked = check_text(f"scenario s:\n    ego: car\n    t: time = 2{unit}\n    do ego.drive(duration: t)\n", "s.osc")
    assert not checked.errors, checked.report()
    assert _value(checked, "t").low == seconds


@pytest.mark.parametrize("actor", ["dut", "ego", "npc"])
def test_dut_ego_and_npc_are_vehicles_without_a_declaration_as_carlas_runner_reads_them(tmp_path, actor):
    body = f"scenario s:\n    path: Path\n    do {actor}.drive(path, duration: 3s) with:\n        speed(50kph)\n"
    checked = _checked(tmp_path, body, dialect="carla")
    assert not checked.errors, checked.report()
    assert [a.name for a in checked.scenarios[0].scenario.actors] == [actor]
    warned = [w for w in _lines(checked, "warning") if "not declared" in w]
    assert warned == (
        []
        if actor == "dut"
        else [f"s.osc:4:8: '{actor}' is not declared: read as a vehicle, as CARLA's scenario runner does"]
    )


def test_set_map_and_an_anchor_read_a_global_string_as_its_value(tmp_path):
    body = (
        'global my_map: string = "Town04"\nglobal anchor: string = "start"\n'
        "scenario s:\n    path: Path\n    path.set_map(my_map)\n    ego, npc: car\n"
        "    do parallel(duration: 3s):\n        ego.drive()\n        npc.drive() with:\n"
        "            position(20m, ahead_of: ego, at: anchor)\n"
    )
    checked = _checked(tmp_path, body)
    assert not checked.errors, checked.report()
    from pytest_roadlogic.automaton import build_automaton

    automaton = build_automaton(checked.scenarios[0])
    start = [t for t in automaton.transitions if t.source == automaton.initial]
    assert all("p(npc) - p(ego)" in str(t.guard) for t in start), "the position holds at the start"


def test_cover_and_record_inside_a_fields_with_are_items_of_that_field():
    text = (
        "scenario s:\n    ego: car\n    v: speed with:\n        keep(it in [20mps..30mps])\n"
        "        cover(v_band, expression: it, unit: kph, every: 9)\n        record(v)\n    do ego.drive() with:\n        speed(v)\n"
    )
    checked = check_text(text, "s.osc")
    assert not checked.errors, checked.report()
    assert _lines(checked, "warning") == []
    items = {item.name: item for item in checked.scenarios[0].coverage}
    assert {name: item.parameter for name, item in items.items()} == {"v_band": "v", "v": "v"}
    assert [b.label for b in items["v_band"].buckets] == [
        "[72..81) kph",
        "[81..90) kph",
        "[90..99) kph",
        "[99..108] kph",
    ]


def test_a_cast_of_an_actor_reads_the_actor():
    text = (
        "scenario s:\n    ego, lead: car\n    do serial:\n        ego.drive(duration: 2s)\n"
        "        wait ego.as(vehicle).speed >= 10mps\n"
    )
    checked = check_text(text, "s.osc")
    assert not checked.errors, checked.report()


def test_a_positional_argument_after_a_named_one_binds_the_first_parameter_not_named():
    from pytest_roadlogic.automaton import build_automaton

    text = (
        "scenario s:\n    a, b: car\n    do parallel(duration: 3s):\n        a.drive()\n"
        "        b.drive() with:\n            position(behind: a, 10m, at: start)\n"
    )
    checked = check_text(text, "s.osc")
    assert not checked.errors, checked.report()
    guards = " ".join(str(t.guard) for t in build_automaton(checked.scenarios[0]).transitions)
    assert "9 <= p(a) - p(b) <= 11" in guards  # 10 m, read with its tolerance


def test_a_range_bounded_by_parameters_bounds_its_parameter_and_every_sample_meets_it():
    text = (
        "scenario s:\n    a, b: car\n    near: length with:\n        keep(it in [10m..20m])\n    far: length = 30m\n"
        "    gap: length with:\n        keep(it in [near..far])\n"
        "    do parallel(duration: 3s):\n        a.drive()\n        b.drive() with:\n"
        "            position(gap, behind: a, at: start)\n"
    )
    checked = check_text(text, "s.osc")
    assert not checked.errors, checked.report()
    space = checked.scenarios[0].space
    assert space.domains["gap"].interval == Interval(10.0, 30.0, "length")
    point = Interval
    assert space.accepts(
        {"near": point(15, 15, "length"), "far": point(30, 30, "length"), "gap": point(16, 16, "length")}
    )
    assert not space.accepts(
        {"near": point(15, 15, "length"), "far": point(30, 30, "length"), "gap": point(12, 12, "length")}
    )


def test_a_range_whose_bounds_are_reversed_is_an_error_at_the_range():
    text = (
        "scenario s:\n    a: car\n    lo: length = 30m\n    hi: length = 10m\n    gap: length with:\n"
        "        keep(it in [lo..hi])\n    do a.drive() with:\n        position(gap, ahead_of: a, at: start)\n"
    )
    assert any("empty range" in line for line in _lines(check_text(text, "s.osc")))


def test_a_constraint_on_an_actors_own_field_is_read_with_a_warning_not_refused():
    text = "scenario s:\n    ego: car\n    keep(ego.length == 4.5m)\n    do ego.drive(duration: 3s)\n"
    checked = check_text(text, "s.osc")
    assert not checked.errors, checked.report()
    assert _lines(checked, "warning") == [
        "s.osc:3:5: a constraint on the fields of ego is read but not enforced: vehicles are simulated with the tool's own dimensions"
    ]


def _gap_guard(direction: str, operator: str, value: str):
    from pytest_roadlogic.automaton import build_automaton

    text = (
        "scenario s:\n    a, b: car\n    do serial:\n        parallel(duration: 2s):\n            a.drive()\n"
        f"            b.drive()\n        wait a.space_gap(b, {direction}) {operator} {value}\n"
    )
    checked = check_text(text, "s.osc", lanes=4)
    assert not checked.errors, checked.report()
    automaton = build_automaton(checked.scenarios[0])
    (guard,) = [t.guard for t in automaton.transitions if "wait end" in t.label]
    return guard


def _space_gap(a, b, direction: str) -> float:
    """The standard's definition, written out: the distance one box travels to touch the other."""
    from pytest_roadlogic.dimensions import CAR_LENGTH, CAR_WIDTH, LANE_WIDTH

    if direction == "longitudinal":
        d, extent = a.position - b.position, CAR_LENGTH
    else:
        d, extent = (b.lane - a.lane) * LANE_WIDTH, CAR_WIDTH  # lanes from the left: a left of b is positive
    return math.copysign(max(0.0, abs(d) - extent), d)


@pytest.mark.parametrize("direction", ["longitudinal", "lateral"])
@pytest.mark.parametrize("operator, value", [("<=", "15m"), (">=", "3m"), (">=", "-2m"), ("<=", "0m"), ("<=", "-6m")])
def test_space_gap_in_a_condition_holds_exactly_where_the_standards_definition_does(direction, operator, value):
    from pytest_roadlogic.simulation.trace import ActorSnapshot

    guard = _gap_guard(direction, operator, value)
    limit = float(value.rstrip("m"))
    draw = random.Random(7)
    for _ in range(2000):
        a = ActorSnapshot(draw.uniform(-40, 40), draw.randrange(4), 20.0)
        b = ActorSnapshot(draw.uniform(-40, 40), draw.randrange(4), 20.0)
        gap = _space_gap(a, b, direction)
        if abs(gap - limit) < 1e-6:
            continue  # on the edge: either reading is right
        expected = gap <= limit if operator == "<=" else gap >= limit
        assert guard.holds({"a": a, "b": b}) == expected, f"gap {gap:.2f} {operator} {limit}: a={a} b={b}"


def _time_gap(a, b) -> float:
    """The standard's definition: the space gap over the speed of the car behind."""
    gap = _space_gap(a, b, "longitudinal")
    behind = b if a.position > b.position else a
    return gap / max(behind.speed, 0.1)


@pytest.mark.parametrize(
    "operator, value", [("<=", "1.5s"), (">=", "0.8s"), (">=", "-1s"), ("<=", "-0.5s"), ("<=", "0s")]
)
def test_time_gap_in_a_condition_holds_exactly_where_the_standards_definition_does(operator, value):
    from pytest_roadlogic.simulation.trace import ActorSnapshot

    text = (
        "scenario s:\n    a, b: car\n    do serial:\n        parallel(duration: 2s):\n            a.drive()\n"
        f"            b.drive()\n        wait a.time_gap(b, longitudinal) {operator} {value}\n"
    )
    from pytest_roadlogic.automaton import build_automaton

    checked = check_text(text, "s.osc")
    assert not checked.errors, checked.report()
    (guard,) = [t.guard for t in build_automaton(checked.scenarios[0]).transitions if "wait end" in t.label]
    limit = float(value.rstrip("s"))
    draw = random.Random(11)
    for _ in range(3000):
        a = ActorSnapshot(draw.uniform(-60, 60), 1, draw.uniform(1, 35))
        b = ActorSnapshot(draw.uniform(-60, 60), 1, draw.uniform(1, 35))
        gap = _time_gap(a, b)
        if abs(gap - limit) < 1e-6:
            continue
        expected = gap <= limit if operator == "<=" else gap >= limit
        assert guard.holds({"a": a, "b": b}) == expected, f"time gap {gap:.3f} {operator} {limit}: a={a} b={b}"


@pytest.mark.parametrize("method", ["time_to_collision(b)", "time_gap(b, lateral)"])
def test_the_standards_methods_not_read_yet_are_refused_where_used_naming_what_to_write(method):
    text = (
        "scenario s:\n    a, b: car\n    do serial:\n        parallel(duration: 2s):\n            a.drive()\n"
        f"            b.drive()\n        wait a.{method} <= 2s\n"
    )
    (line,) = _lines(check_text(text, "s.osc"))
    assert line.startswith("s.osc:7:") and "not supported" in line


@pytest.mark.parametrize(
    "text, band",
    [
        ("80..130kph", (80 / 3.6, 130 / 3.6)),
        ("20..35mps", (20.0, 35.0)),
        ("50mph..70mph", (50 * 0.44704, 70 * 0.44704)),
    ],
)
def test_the_road_speed_option_reads_a_band_with_its_unit(text, band):
    from pytest_roadlogic.settings import speed_band

    assert speed_band(text) == pytest.approx(band)


def test_a_vehicle_the_scenario_names_no_speed_for_starts_in_the_road_speed_band_and_a_case_replays_it(tmp_path):
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.case import Case
    from pytest_roadlogic.planning import planner_for, settings_for
    from pytest_roadlogic.settings import RunSettings, speed_band

    checked = check_text("scenario s:\n    ego: car\n    do ego.drive(duration: 4s)\n", "s.osc")
    run = RunSettings(road_speed=speed_band("100..120kph"))
    plan = planner_for(build_automaton(checked.scenarios[0]), settings_for(run), 1).first()
    assert 100 / 3.6 - 1e-6 <= plan.states["ego"][0].speed <= 120 / 3.6 + 1e-6
    case = Case.of("s.osc", "s", run)
    assert Case.load(case.save(tmp_path / "case.json")).settings.road_speed == run.road_speed


@pytest.mark.parametrize(
    "declaration, base",
    [
        ("actor car inherits vehicle(vehicle_category == vehicle_category!car)", "car"),
        ("actor lorry inherits vehicle(vehicle_category == vehicle_category!truck)", "truck"),
        ("actor sedan inherits vehicle(vehicle_category == car)", "car"),
    ],
)
def test_a_vehicle_of_a_category_is_that_built_in_type_as_the_standards_examples_declare_a_car(declaration, base):
    kind = declaration.split()[1]
    checked = check_text(f"{declaration}\nscenario s:\n    a: {kind}\n    do a.drive(duration: 3s)\n", "t.osc")
    assert not checked.errors, checked.report()
    assert checked.scenarios[0].scenario.actors[0].base == base


def test_another_condition_on_inheritance_is_refused_at_the_condition():
    text = "actor fast inherits vehicle(is_electric == true)\nscenario s:\n    a: fast\n    do a.drive(duration: 3s)\n"
    assert _lines(check_text(text, "t.osc"))[:1] == ["t.osc:1:29: not supported: conditional inheritance"]


def test_a_negative_distance_is_the_other_side_and_a_range_spanning_zero_puts_the_vehicle_beside_the_other():
    def position(distance: str):
        text = (
            "scenario s:\n    a: car\n    b: car\n    do parallel(duration: 3s):\n        b.drive()\n"
            f"        a.drive() with:\n            lane(left_of: b)\n            position({distance}, ahead_of: b)\n"
        )
        return check_text(text, "t.osc")

    from pytest_roadlogic.automaton import build_automaton

    beside = position("[-1m..1m]")
    assert not beside.errors, beside.report()
    guards = " and ".join(str(t.guard) for t in build_automaton(beside.scenarios[0]).transitions)
    assert "-1 <= p(a) - p(b) <= 1" in guards
    # a negative distance is the other side, as the standard reads it
    behind = " and ".join(str(t.guard) for t in build_automaton(position("-5m").scenarios[0]).transitions)
    assert "-6 <= p(a) - p(b) <= -4" in behind


def test_a_parameter_bounded_on_one_side_only_says_which_bound_is_missing():
    text = "scenario s:\n    a: car\n    t: time\n    keep(t >= 5min)\n    do a.drive(duration: t)\n"
    assert _lines(check_text(text, "t.osc")) == [
        "t.osc:3:5: parameter 't' is at least 300 s but has no upper bound: a sample needs both ends"
    ]


def test_the_standards_common_movement_modifier_parameters_are_read_and_projected_tracking_warned():
    def checked(arguments: str):
        text = (
            "scenario s:\n    a: car\n    b: car\n    do parallel(duration: 3s):\n        a.drive()\n"
            f"        b.drive() with:\n            position(10m, ahead_of: a, {arguments})\n"
        )
        return check_text(text, "t.osc")

    quiet = checked("movement_mode: monotonous, track: actual")
    assert not quiet.errors and not quiet.warnings, quiet.report()
    projected = checked("track: projected")
    assert [w.message.split(":")[0] for w in projected.warnings] == ["track"]
    assert [e.message for e in checked("shape: s").errors] == ["not supported: argument 'shape' of position()"]
    assert checked("movement_mode: wobbly").errors


@pytest.mark.parametrize(
    "modifier, parameters",
    [
        ("position(distance_range: [10m..20m], behind: a, at: start)", []),
        ("position(distance: [10m..20m], behind: a, at: start)", ["b.drive.position.distance"]),
        ("position(time_range: [1s..2s], behind: a, at: end)", []),
        ("speed(speed_range: [10kph..20kph], at: end)", []),
        ("lateral(distance_range: [3m..4m], side_of: a)", []),
    ],
)
def test_a_range_typed_argument_of_the_standard_2_2_is_an_interval_the_plan_keeps_never_a_value_sampled(
    modifier, parameters
):
    text = (
        "scenario s:\n    a: car\n    b: car\n    do parallel(duration: 3s):\n        a.drive()\n"
        f"        b.drive() with:\n            {modifier}\n"
    )
    checked = check_text(text, "t.osc")
    assert not checked.errors, checked.report()
    assert [p.name for p in checked.scenarios[0].parameters] == parameters


def test_a_value_and_its_range_typed_counterpart_together_are_refused():
    text = (
        "scenario s:\n    a: car\n    do a.drive(duration: 3s) with:\n"
        "        speed(speed: 10kph, speed_range: [1kph..2kph])\n"
    )
    assert _lines(check_text(text, "t.osc")) == ["t.osc:4:29: speed() takes one of speed and speed_range"]


def test_change_lane_takes_its_count_as_lane_as_the_standard_2_2_names_it():
    from pytest_roadlogic.automaton import build_automaton

    def ends(arguments: str):
        text = f"scenario s:\n    a: car\n    do a.drive(duration: 6s) with:\n        change_lane({arguments})\n"
        checked = check_text(text, "t.osc")
        assert not checked.errors, checked.report()
        automaton = build_automaton(checked.scenarios[0])
        return sorted(str(t.guard) for t in automaton.transitions if t.target == automaton.final)

    assert ends("lane: 2, side: left") == ends("num_of_lanes: 2, side: left") == ends("2, left")


def test_a_scenario_of_a_vehicle_drives_that_vehicle_where_an_invocation_names_no_actor():
    # the standard's semantics chapter: scenario vehicle.two_phases, its phases drive() of "the
    # parent actor of this scenario"
    text = (
        "scenario vehicle.two_phases:\n    do serial(duration: [10s..30s]):\n"
        "        phase1: drive() with:\n            speed(speed: 0kph, at: start)\n"
        "            speed(speed: 10kph, at: end)\n"
        "        phase2: drive() with:\n            speed(speed: [10kph..15kph])\n"
    )
    checked = check_text(text, "t.osc")
    assert not checked.errors, checked.report()
    assert [(a.name, a.base) for a in checked.scenarios[0].scenario.actors] == [("vehicle", "vehicle")]


def test_a_behavior_may_be_named_after_a_composition_keyword_as_the_standards_example_names_one_of():
    text = "scenario vehicle.one_of:\n    do drive(duration: 3s)\n"
    checked = check_text(text, "t.osc")
    assert not checked.errors, checked.report()
    assert checked.scenarios[0].scenario.name == "one_of"


def test_a_parameter_without_a_range_is_one_error_not_also_a_negative_speed():
    text = "scenario vehicle.accelerate:\n    v: speed\n    do drive(duration: [2s..4s]) with:\n        speed(speed: v, at: end)\n"
    assert _lines(check_text(text, "t.osc")) == ["t.osc:2:5: parameter 'v' has no range or value"]


def test_the_standards_dut_vehicle_and_labelled_modifiers_are_read_as_its_domain_model_writes_them():
    # the domain model's "track" example: dut.vehicle undeclared, each modifier named (l1: lane(...))
    text = (
        "scenario dut.cut_in_late:\n    vehicle1: vehicle\n    do parallel(duration: [1.5s..3s]):\n"
        "        d3: dut.vehicle.drive()\n        d4: vehicle1.drive() with:\n"
        "            l1: lane(side_of: dut.vehicle, at: start)\n"
        "            p2: position(time: [1.5s..2s], ahead_of: dut.vehicle, at: end)\n"
    )
    checked = check_text(text, "t.osc")
    assert not checked.errors, checked.report()
    assert sorted(a.name for a in checked.scenarios[0].scenario.actors) == ["dut.vehicle", "vehicle1"]
