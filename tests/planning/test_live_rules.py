"""The rules of an encoding that cannot fire for an instance are left out of its program
(planning/live_rules.py), and the plans are the same without them."""

from __future__ import annotations

import json
from pathlib import Path

import clingo
import pytest
from clingo.ast import parse_string

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings
from pytest_roadlogic.planning.encodings.continuous import planner as continuous_planner
from pytest_roadlogic.planning.live_rules import Annotated, live_statements, names_in

ROOT = Path(__file__).resolve().parents[2]


def annotated(text: str) -> Annotated:
    statements: list = []
    parse_string(text, statements.append)
    return Annotated.of(statements)


def kept(text: str, instance: str) -> list[str]:
    return [str(statement) for statement in live_statements(annotated(text), names_in(instance))]


def test_a_rule_whose_body_needs_what_nothing_gives_is_left_out_and_so_are_the_rules_that_needed_its_head():
    rules = "a(X) :- shaped(X). b(X) :- a(X). c(X) :- d(X). e(X) :- d(X), not shaped(X)."
    assert kept(rules, "d(1).") == ["#program base.", "c(X) :- d(X).", "e(X) :- d(X); not shaped(X)."]


def test_a_name_the_instance_writes_or_a_kept_rule_or_an_external_gives_keeps_the_rules_that_need_it():
    rules = "#external on. a(X) :- shaped(X). b(X) :- a(X). f :- on. &sum{ x } <= 1 :- b(1)."
    assert len(kept(rules, "shaped(1).")) == 6
    assert kept(rules, "") == ["#program base.", "#external on. [false]", "f :- on."]


def test_the_ground_program_is_the_same_without_the_rules_that_cannot_fire():
    rules = "{ d(1..3) }. a(X) :- shaped(X). c(X) :- d(X), not a(X). :- c(2), c(3). #show c/1."
    models = []
    for statements in (annotated(rules).statements, live_statements(annotated(rules), names_in(""))):
        control = clingo.Control(["0"])
        with clingo.ast.ProgramBuilder(control) as builder:
            for statement in statements:
                builder.add(statement)
        control.ground([("base", [])])
        found: list = []
        control.solve(on_model=lambda model, found=found: found.append(sorted(map(str, model.symbols(shown=True)))))
        models.append(sorted(found))
    assert models[0] == models[1] and len(models[0]) == 6


def plan_text(plan) -> str:
    data = plan.to_dict()
    data.pop("stats")
    return json.dumps(data, sort_keys=True)


@pytest.mark.parametrize(
    "name", ["scenarios/overtake.osc", "scenarios/realistic/lead_brake.osc", "benchmarks/scenarios/follow_close.osc"]
)
def test_plans_are_the_same_with_and_without_the_rules_that_cannot_fire(name, monkeypatch):
    automaton = build_automaton(load_scenario(ROOT / name))
    settings = ContinuousSettings(time_limit=30.0, random_start=True)
    pruned = [plan_text(plan) for plan in ContinuousPlanner(automaton, settings, 3).plans(limit=2)]
    monkeypatch.setattr(continuous_planner, "live_statements", lambda encoding, given: list(encoding.statements))
    whole = [plan_text(plan) for plan in ContinuousPlanner(automaton, settings, 3).plans(limit=2)]
    assert pruned == whole
