"""The standard library shipped as .osc files (pytest_roadlogic/stdlib/osc/): what they declare is
what the tool reads, and every construct the tool executes is declared there with the same
parameters, so the library a user reads is the one the checker applies."""

import math
from pathlib import Path

import pytest

from pytest_roadlogic.constructs import CARLA, STANDARD, carla, conditions
from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.frontend.semantics import library
from pytest_roadlogic.frontend.syntax.standard_library import UNITS, part_file, part_names, standard_library


def declared_kind(type_name: str) -> str:
    """A declared parameter type as the signatures name its kind."""
    lib = standard_library()
    if type_name == library.ROAD_TYPE:
        return "road"
    if type_name in lib.enums:
        return f"enum:{type_name}"
    if type_name in lib.actors:
        return "actor"
    return type_name


@pytest.mark.parametrize("registry", [STANDARD, CARLA], ids=["standard", "carla"])
def test_every_construct_the_tool_executes_is_declared_with_the_same_parameters(registry):
    lib = standard_library()
    for kind, provided, declared in (
        ("action", registry.actions, lib.actions),
        ("modifier", registry.modifiers, lib.modifiers),
    ):
        for name, construct in provided.items():
            if construct in carla.CARLA_OWN:
                continue  # CARLA's own, as CARLA's runner reads it (not the standard's declaration)
            assert name in declared, f"the {kind} {name} is provided but stdlib/osc/movement.osc does not declare it"
            written = {p: declared_kind(t) for p, t in declared[name].parameters}
            # the standard's common movement-modifier parameters are declared once (library.MOVEMENT_OPTIONS)
            common = construct.kind == "modifier" and set(library.MOVEMENT_OPTIONS)
            signature = {p.name: p.kind for p in construct.signature.parameters if not common or p not in common}
            assert written == signature, f"{kind} {name}: declared {written}, the tool reads {signature}"


def test_carlas_own_constructs_are_in_carlas_dialect_only():
    for construct in carla.CARLA_OWN:
        assert construct.signature.description.endswith("(CARLA)")
        standard = (STANDARD.actions if construct.kind == "action" else STANDARD.modifiers).get(construct.name)
        assert standard is None or standard.signature != construct.signature


def test_every_observable_a_condition_reads_is_a_declared_method_with_its_type():
    methods = standard_library().methods
    for name, observable in conditions.OBSERVABLES.items():
        assert name in methods, f"conditions read {name}, which stdlib/osc/methods.osc does not declare"
        assert methods[name].returns == (observable.dimension or "int"), (
            "a plain number is declared as an int (a count of lanes)"
        )
        assert [p for p, _ in methods[name].parameters] == (
            list(observable.parameters) if observable.needs_reference else []
        )


def test_the_unit_table_is_the_one_the_physical_part_declares():
    lib = standard_library()
    assert dict(UNITS) == lib.units
    assert UNITS["kph"] == ("speed", pytest.approx(1 / 3.6)) and UNITS["km"] == ("length", 1000.0)
    assert UNITS["mph"][1] == 0.44704 and UNITS["min"] == ("time", 60.0)
    # every dimension is read; the four the pipeline plans are the physical types of the same name
    assert UNITS["deg"] == ("angle", pytest.approx(math.pi / 180)) and lib.types["angle"] == "angle"
    assert UNITS["celsius"] == ("temperature", 1.0, 273.15)
    assert {name: library.PHYSICAL_TYPES[name] for name in ("length", "time", "speed", "acceleration")} == {
        "length": "length",
        "time": "time",
        "speed": "speed",
        "acceleration": "acceleration",
    }
    assert all(math.isfinite(unit[1]) and unit[1] > 0 for unit in UNITS.values())


def test_the_tools_actor_types_are_the_libraries_road_users():
    lib = standard_library()
    for name in (*library.ACTOR_TYPES, *library.SCENARIO_OWNERS, *library.UNSUPPORTED_ACTOR_TYPES):
        assert name in lib.actors, f"{name} is not declared in stdlib/osc/actors.osc"
    assert lib.ancestors("car")[:3] == ["car", "vehicle", "movable_object"]
    assert "vehicle" in lib.ancestors("truck")


def test_osc_standard_imports_every_part_and_each_part_imports_alone():
    assert set(part_names()) >= {
        "osc.standard",
        "osc.physical",
        "osc.types",
        "osc.actors",
        "osc.movement",
        "osc.methods",
    }
    standard = part_file("osc.standard").read_text()
    for part in part_names():
        if part != "osc.standard":
            assert f"import {part}" in standard
    for part in part_names():
        checked = check_text(
            f"import {part}\n\nscenario s:\n    a: car\n    do a.drive(duration: 3s) with:\n        speed(20kph)\n"
        )
        assert not checked.diagnostics, (part, [d.message for d in checked.diagnostics])


def test_an_unknown_library_is_an_error_and_an_unknown_part_a_warning():
    body = "\n\nscenario s:\n    a: car\n    do a.drive(duration: 3s)\n"
    [error] = check_text("import carla.standard" + body).diagnostics
    assert (error.severity, error.location.line) == ("error", 1) and "unknown library 'carla.standard'" in error.message
    [warning] = check_text("import osc.helpers" + body).diagnostics
    assert (
        warning.severity == "warning" and "no part 'osc.helpers'" in warning.message and "osc.physical" in warning.hint
    )


@pytest.mark.parametrize(
    "use, message",
    [
        (
            "a.drive(duration: 3s) with:\n        along_trajectory(start_offset: 1m)",
            "not supported: the standard's modifier 'along_trajectory'",
        ),
        ("a.follow_trajectory(duration: 3s)", "not supported: the standard's action 'follow_trajectory'"),
        ("a.fly(duration: 3s)", "unknown action 'fly'"),
    ],
)
def test_a_construct_the_library_declares_and_the_tool_does_not_execute_is_refused_by_name(use, message):
    checked = check_text(f"scenario s:\n    a: car\n    do {use}\n")
    errors = [d for d in checked.diagnostics if d.severity == "error"]
    assert errors and errors[0].message == message, [d.message for d in errors]
    assert errors[0].location.line in (3, 4)


def test_an_actor_derived_from_an_abstract_library_actor_is_driven_as_a_vehicle_with_a_warning():
    checked = check_text("actor bus inherits movable_object\n\nscenario s:\n    b: bus\n    do b.drive(duration: 3s)\n")
    [warning] = checked.diagnostics
    assert warning.severity == "warning" and "driven as a vehicle" in warning.message
    assert checked.scenarios[0].scenario.actors[0].base == "vehicle"


def test_a_value_of_a_dimension_the_tool_does_not_plan_is_read_where_it_is_not_executed():
    # an angle in a modifier the simulation does not model (constructs.unsimulated): read, warned
    checked = check_text("scenario s:\n    a: car\n    do a.drive(duration: 3s) with:\n        yaw(10deg)\n", "s.osc")
    assert checked.errors == []
    assert [(d.location.line, d.location.column, d.severity) for d in checked.diagnostics] == [(4, 9, "warning")]


def test_a_file_that_declares_a_library_unit_as_another_dimension_is_told_so_at_the_declaration(tmp_path):
    from pytest_roadlogic.frontend import check_file

    (tmp_path / "lib.osc").write_text("type length is SI(m: 1)\nunit deg of length is SI(m: 1, factor: 0.5)\n")
    (tmp_path / "s.osc").write_text(
        "import lib.osc\nscenario s:\n    a, b: car\n    do b.drive(duration: 3s) with:\n        position(40deg, behind: a, at: start)\n"
    )
    errors = check_file(tmp_path / "s.osc").errors
    report = [f"{Path(d.location.path).name}:{d.location.line}:{d.location.column}: {d.message}" for d in errors]
    assert "lib.osc:2:6: unit 'deg' is declared as a unit of length, but deg is a unit of angle" in report
    assert "s.osc:5:18: position() expects a length for distance, got an angle" in report


def test_the_shipped_declarations_are_the_library_files_read_anew():
    from pytest_roadlogic.frontend.syntax import standard_library as library

    committed = library.DECLARATIONS_FILE.read_text(encoding="utf-8")
    assert committed == library.declarations_text(library.parse_library()), (
        "stdlib/osc/declarations.json is stale: run "
        "python -m pytest_roadlogic.frontend.syntax.regenerate --declarations and commit"
    )
    # read back in the same order (hints list what a file declares in its order)
    assert library.declarations_text(library.standard_library()) == committed
    assert library.standard_library() == library.parse_library()


def test_a_library_file_changed_since_the_declarations_were_written_is_read_from_its_file(tmp_path, monkeypatch):
    from pytest_roadlogic.frontend.syntax import standard_library as library

    stale = tmp_path / "declarations.json"
    stale.write_text(library.DECLARATIONS_FILE.read_text(encoding="utf-8").replace('"digest": "', '"digest": "0'))
    monkeypatch.setattr(library, "DECLARATIONS_FILE", stale)
    assert library._shipped_declarations() is None
    stale.write_text("{not json")
    assert library._shipped_declarations() is None
