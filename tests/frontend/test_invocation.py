"""Scenario invocation: a user scenario called in ``do`` is expanded in place, its parameters bound
by the call's arguments (or kept as the caller's parameters, named after the call), its actors
matched by argument or by name, and its labels kept apart per call."""

from pathlib import Path

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings
from tests.planning.test_planning_continuous import check_continuous_plan

ROOT = Path(__file__).resolve().parents[2]

CALLEE = """scenario dut.follow_at:
    lead: car
    gap: length with:
        keep(it in [20m..40m])
    lead_speed: speed
    do follow: parallel(duration: [3s..4s]):
        dut.drive() with:
            lane(1)
            position(gap, behind: lead, at: start)
        lead.drive() with:
            lane(1)
            speed(lead_speed)
"""


def checked(text: str):
    result = check_text(text, "c.osc")
    assert not result.errors, result.report()
    return result


def test_a_call_binds_its_argument_and_keeps_the_other_parameter_as_the_callers_named_after_the_call():
    result = checked(
        CALLEE + "scenario top:\n    dut: car\n    lead: car\n    do dut.follow_at(lead_speed: [20mps..25mps])\n"
    )
    assert [s.scenario.name for s in result.scenarios] == ["top"], "the called scenario runs only as part of its caller"
    top = result.scenarios[0]
    assert {n: d.describe() for n, d in top.space.domains.items()} == {"follow_at.gap": "[20..40]m"}
    assert [a.name for a in top.scenario.actors] == ["dut", "lead"]
    assert "20 <= v(lead) <= 25" in build_automaton(top).describe()


def test_positional_arguments_bind_parameters_in_declaration_order_and_an_actor_argument_renames_the_actor():
    result = checked(
        CALLEE + "scenario top:\n    dut: car\n    front: car\n    do dut.follow_at(30m, 22mps, lead: front)\n"
    )
    top = result.scenarios[0]
    assert top.space.domains == {}
    described = build_automaton(top).describe()
    assert "v(front)" in described and "lead" not in [a.name for a in top.scenario.actors]


def test_an_actor_the_caller_does_not_declare_becomes_its_actor():
    top = checked(CALLEE + "scenario top:\n    dut: car\n    do dut.follow_at(lead_speed: 20mps)\n").scenarios[0]
    assert sorted(a.name for a in top.scenario.actors) == ["dut", "lead"]


def test_a_scenario_called_twice_has_its_phases_labelled_per_call():
    text = (
        CALLEE
        + "scenario top:\n    dut: car\n    lead: car\n    do serial:\n        first: dut.follow_at(lead_speed: 20mps)\n        second: dut.follow_at(lead_speed: 25mps)\n"
    )
    top = checked(text).scenarios[0]
    labels = [c.label for c in top.scenario.behavior.children]
    assert labels == ["first", "second"]
    assert set(top.space.domains) == {"first.gap", "second.gap"}


@pytest.mark.parametrize(
    "call, message",
    [
        ("dut.follow_at(speed_of_lead: 20mps)", "scenario 'follow_at' has no field 'speed_of_lead'"),
        (
            "dut.follow_at(lead: 3m, lead_speed: 20mps)",
            "'lead' is an actor: pass the name of one of the caller's actors",
        ),
        (
            "dut.follow_at(lead_speed: 20mps) with:\n        lane(1)",
            "not supported: modifiers on a call of scenario 'follow_at'",
        ),
    ],
)
def test_a_wrong_call_is_a_located_error(call, message):
    result = check_text(CALLEE + f"scenario top:\n    dut: car\n    lead: car\n    do {call}\n", "c.osc")
    assert "c.osc:16:" in result.report() and message in result.report(), result.report()


def test_a_scenario_that_calls_itself_is_a_located_error():
    result = check_text(
        "scenario loop:\n    dut: car\n    do serial:\n        dut.drive(duration: 2s)\n        dut.loop()\nscenario top:\n    dut: car\n    do dut.loop()\n",
        "c.osc",
    )
    assert "calls itself" in result.report(), result.report()


def test_the_corpus_call_plans_with_the_callees_constraints():
    automaton = build_automaton(load_scenario(ROOT / "tests" / "corpus" / "51_scenario_call.osc"))
    plan = ContinuousPlanner(automaton, ContinuousSettings(), 1).first()
    check_continuous_plan(plan, automaton)
    assert 28 - 1e-6 <= plan.states["npc"][0].speed <= 32 + 1e-6
