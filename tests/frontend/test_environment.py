"""The environment actor (docs/language.md, "What is read"): the weather a scenario asks for is read,
its arguments checked as the standard library declares them, each use warned about once where it
is written, and the vehicles planned as if it were not written."""

from __future__ import annotations

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import OscError, check_text
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings

DRIVES = (
    "        ego.drive() with:\n"
    "            speed(50kph)\n"
    "            lane(2)\n"
    "        npc.drive() with:\n"
    "            speed([40kph..60kph])\n"
    "            lane(right_of: ego)\n"
    "            position([15m..25m], ahead_of: ego, at: start)\n"
)


def scenario(weather: str, field: str = "    env: environment\n") -> str:
    return f"scenario cruise:\n    ego: car\n    npc: car\n{field}    do parallel(duration: 8s):\n{weather}{DRIVES}"


def planned(tmp_path, text: str):
    """The automaton of ``text`` written to a file, and its first plan at seed 1."""
    path = tmp_path / "scenario.osc"
    path.write_text(text)
    automaton = build_automaton(load_scenario(path))
    return automaton, ContinuousPlanner(automaton, ContinuousSettings(time_limit=30.0), 1).first()


def first_plan(tmp_path, text: str):
    return planned(tmp_path, text)[1]


def refusal(text: str, name: str = "cruise.osc") -> str:
    """The report of ``text``'s errors (checked as file ``name``)."""
    with pytest.raises(OscError) as refused:
        check_text(text, name).raise_for_errors()
    return str(refused.value)


def warnings_of(text: str):
    checked = check_text(text, "cruise.osc")
    checked.raise_for_errors()
    return [d for d in checked.diagnostics if d.severity == "warning"]


def test_each_environment_action_is_read_with_one_warning_where_it_is_written():
    text = scenario(
        "        env.air(15celsius, 1013hPa, 0.6)\n"
        "        env.rain(intensity: 5kph)\n"
        "        env.wind(speed: 8mps, direction: 90deg)\n"
        "        env.fog(visual_range: 150m)\n"
    )
    warnings = warnings_of(text)
    assert [w.location.line for w in warnings] == [6, 7, 8, 9]
    assert all("is read but not simulated" in w.message for w in warnings)


def test_the_environment_the_standards_examples_name_without_declaring_it_is_the_scenarios():
    warnings = warnings_of(scenario("        environment.snow(intensity: 2kph)\n", field=""))
    assert [(w.location.line, w.location.column) for w in warnings] == [(5, 9)]
    assert warnings[0].message.startswith("environment.snow() is read but not simulated")


def test_the_vehicles_are_planned_as_if_the_weather_were_not_written(tmp_path):
    with_weather = first_plan(tmp_path, scenario("        env.rain(intensity: 5kph)\n        env.fog(150m)\n"))
    without = first_plan(tmp_path, scenario(""))
    assert with_weather.states == without.states
    assert with_weather.transitions == without.transitions


def test_an_environment_action_in_a_serial_takes_no_time(tmp_path):
    text = (
        "scenario s:\n    ego: car\n    env: environment\n    do serial:\n"
        "        env.rain(intensity: 5kph)\n        ego.drive(duration: 4s) with:\n            speed(30kph)\n"
    )
    automaton, plan = planned(tmp_path, text)
    assert plan.horizon * plan.dt == pytest.approx(4.0, abs=0.5)


@pytest.mark.parametrize(
    "weather, place, message",
    [
        ("env.rain(intensity: 5m)", (6, 29), "env.rain() expects a speed for intensity, got a length"),
        ("env.fog(visual_range: 100m, depth: 3m)", (6, 37), "unknown argument 'depth' of env.fog()"),
        ("env.air(15celsius, 1000hpa, 0.5, 3)", (6, 42), "too many positional arguments to env.air()"),
    ],
)
def test_an_environment_actions_arguments_are_checked_as_the_library_declares_them(weather, place, message):
    assert f"cruise.osc:{place[0]}:{place[1]}: error: {message}" in refusal(scenario(f"        {weather}\n"))


def test_a_modifier_on_an_environment_action_is_an_error_at_the_modifier():
    text = scenario("        env.fog(visual_range: 100m) with:\n            speed(3kph)\n")
    message = "cruise.osc:7:13: error: speed() on env.fog(): an environment action takes no modifiers"
    assert message in refusal(text)


def test_an_environment_action_the_tool_does_not_know_is_read_with_a_warning_naming_the_ones_it_knows():
    (warning,) = warnings_of(scenario("        env.clouds(density: 3)\n"))
    assert "this tool does not know that environment action" in warning.message
    assert "air, rain, snow, wind, fog" in warning.hint


def test_a_behavior_that_only_sets_the_environment_is_an_error():
    text = "scenario s:\n    ego: car\n    env: environment\n    do env.rain(intensity: 5kph)\n"
    assert "the behavior only sets the environment: no vehicle is driven" in refusal(text, "s.osc")


def test_a_vehicles_action_on_the_environment_and_the_environments_on_a_vehicle_are_errors():
    report = refusal(scenario("        env.drive()\n        ego.rain(intensity: 3kph)\n"))
    assert (
        "cruise.osc:6:9: error: env.drive(): drive() is an action of a vehicle, and 'env' is the environment" in report
    )
    assert "cruise.osc:7:9: error: rain() is an action of the environment, not of a vehicle" in report


def test_a_labelled_environment_action_is_an_instant_whose_end_others_can_wait_for(tmp_path):
    text = (
        "scenario s:\n    ego: car\n    npc: car\n    env: environment\n    do parallel:\n        serial:\n"
        "            ego.drive(duration: 3s) with:\n                speed(30kph)\n"
        "            wet: env.rain(intensity: 3kph)\n            ego.drive(duration: 3s) with:\n"
        "                speed(30kph)\n        serial:\n            wait @wet.end\n"
        "            npc.drive(duration: 3s) with:\n                speed(30kph)\n"
    )
    automaton, plan = planned(tmp_path, text)
    assert any("wet.end emitted" in t.label for t in automaton.transitions)
    labels = {t.id: t.label for t in automaton.transitions}
    (step,) = [k for k, t in plan.transitions if "wet.end emitted" in labels[t]]
    assert step * plan.dt == pytest.approx(3.0, abs=0.5), "the rain's instant is the first drive's end"


def test_an_environment_action_given_a_duration_takes_that_time(tmp_path):
    text = (
        "scenario s:\n    ego: car\n    env: environment\n    do parallel:\n        serial:\n"
        "            env.rain(intensity: 3kph, duration: 4s)\n            env.fog(200m)\n"
        "        ego.drive(duration: 4s) with:\n            speed(30kph)\n"
    )
    automaton, plan = planned(tmp_path, text)
    assert plan.horizon * plan.dt == pytest.approx(4.0, abs=0.5)
    waits = [t.label for t in automaton.transitions if "wait" in t.label]
    assert waits, "the rain's 4 s are a phase of the run"


def test_a_keep_or_an_until_on_an_environment_action_is_refused_with_the_duration_argument_as_the_way():
    text = scenario("        env.rain(intensity: 3kph) with:\n            keep(it.duration == 2s)\n")
    assert "cruise.osc:7:13: error: not supported: keep() on env.rain()" in refusal(text)


def test_a_one_of_member_that_only_sets_the_environment_is_an_error_at_the_member():
    text = (
        "scenario s:\n    ego: car\n    env: environment\n    do serial:\n        one_of:\n"
        "            env.fog(100m)\n            env.rain(intensity: 1kph, duration: 2s)\n"
        "            ego.drive(duration: 3s)\n        ego.drive(duration: 3s)\n"
    )
    report = refusal(text, "s.osc")
    assert "s.osc:6:13: error: this one_of member only sets the environment" in report
    assert "s.osc:7:" not in report, "a member given a duration takes that time"
