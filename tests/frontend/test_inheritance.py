"""Scenario inheritance: a child has every member of its parent (fields, keeps, events, the do)
and adds its own; a keep of the child narrows the parent's parameter. What cannot be read
(an unknown parent, a cycle, a second do, conditional inheritance) is an error at its place."""

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.planning import ContinuousPlanner
from tests.planning.test_planning_continuous import check_continuous_plan

PARENT = """scenario vehicle.follow_base:
    ego: car
    lead: car
    gap: length with:
        keep(it in [15m..40m])
    do follow: parallel(duration: [3s..5s]):
        ego.drive() with:
            speed([20mps..25mps])
            lane(1)
        lead.drive() with:
            lane(1)
            position(gap, ahead_of: ego, at: start)
"""


def errors_of(text: str) -> list[str]:
    return [f"{d.location.line}: {d.message}" for d in check_text(text, "c.osc").errors]


def test_a_child_runs_its_parents_do_with_its_own_keep_narrowing_the_parents_parameter():
    result = check_text(
        PARENT + "\nscenario vehicle.close_follow inherits follow_base:\n    keep(gap <= 20m)\n", "c.osc"
    )
    assert not result.errors, result.report()
    child = next(s for s in result.scenarios if s.scenario.name == "close_follow")
    assert child.space.domains["gap"].describe() == "[15..20]m"
    assert [a.name for a in child.scenario.actors] == ["ego", "lead"]
    automaton = build_automaton(child, values={"gap": 18.0})
    check_continuous_plan(ContinuousPlanner(automaton, seed=1).first(), automaton)


def test_the_parent_stays_a_scenario_of_its_own_with_its_own_range():
    result = check_text(
        PARENT + "\nscenario vehicle.close_follow inherits follow_base:\n    keep(gap <= 20m)\n", "c.osc"
    )
    parent = next(s for s in result.scenarios if s.scenario.name == "follow_base")
    assert parent.space.domains["gap"].describe() == "[15..40]m"


def test_a_child_without_a_do_of_its_parent_declares_it_and_a_grandchild_inherits_both():
    text = """scenario vehicle.actors_only:
    ego: car
    lead: car
    gap: length with:
        keep(it in [20m..30m])
scenario vehicle.with_do inherits actors_only:
    do parallel(duration: 3s):
        ego.drive() with:
            lane(1)
        lead.drive() with:
            lane(1)
            position(gap, ahead_of: ego, at: start)
scenario vehicle.narrowed inherits with_do:
    keep(gap >= 25m)
"""
    result = check_text(text, "c.osc")
    assert not result.errors, result.report()
    assert [a.name for a in result.scenarios[-1].scenario.actors] == ["ego", "lead"]
    assert result.scenarios[-1].scenario.behavior is not None
    assert result.scenarios[-1].space.domains["gap"].describe() == "[25..30]m"


@pytest.mark.parametrize(
    "child, expected",
    [
        (
            "scenario vehicle.c inherits nowhere:\n    keep(gap > 1m)\n",
            "scenario 'c' inherits an unknown scenario 'nowhere'",
        ),
        (
            "scenario vehicle.a inherits b:\n    keep(gap > 1m)\nscenario vehicle.b inherits a:\n    keep(gap > 1m)\n",
            "the inherits of scenario 'a' form a cycle (a -> b -> a)",
        ),
        (
            "scenario vehicle.c inherits follow_base:\n    do ego.drive()\n",
            "scenario 'c' declares a do and inherits one from 'follow_base' (line 6); a scenario has one do",
        ),
        ("scenario vehicle.c inherits follow_base:\n    lead: truck\n", "'lead' is already declared on line 3"),
        (
            "scenario vehicle.c inherits follow_base(gap == 20m):\n    keep(gap > 1m)\n",
            "not supported: conditional inheritance",
        ),
    ],
    ids=["unknown-parent", "cycle", "second-do", "field-declared-again", "conditional"],
)
def test_what_inheritance_cannot_mean_is_an_error_at_the_childs_line(child, expected):
    errors = errors_of(PARENT + child)
    assert any(expected in e for e in errors), errors
    assert all(int(e.split(":")[0]) > 12 or "already declared" in e for e in errors), errors
