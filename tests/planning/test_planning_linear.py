"""The lazy linear theory (planning/encodings/continuous/linear.py): clingo chooses which linear constraints hold, HiGHS
checks them together. What must hold, from its meaning rather than its code: a model's values meet
every constraint its true atoms switch on; a conflict is returned as exactly the choices whose
constraints cannot hold together (a Farkas certificate, never an innocent bystander); constraints
grounded in later steps of a multi-shot solve join those of earlier ones; preferences shape the
values and never decide whether there is a model."""

import re
from pathlib import Path

import clingo
import pytest

from pytest_roadlogic.planning.encodings.continuous.linear import (
    LazyLinearTheory,
    LinearProgram,
    Row,
    check_rows,
    theory_program,
)


def solve(program: str, parts=(("base", []),)) -> tuple[list[list[str]], dict[str, float]]:
    """All models' shown atoms, and the values of the last one."""
    control = clingo.Control(["--models=0", "--warn=none"])
    theory = LazyLinearTheory()
    theory.register(control)
    control.add("base", [], theory_program() + program)
    control.ground(list(parts))
    models, values = [], {}
    with control.solve(yield_=True) as handle:
        for model in handle:
            models.append(sorted(str(s) for s in model.symbols(shown=True)))
            values = {str(k): v for k, v in theory.assignment(model.thread_id)}
    return models, values


def test_a_model_meets_every_constraint_its_atoms_switch_on():
    models, values = solve("""
        { fast }.
        &sum{ x } >= "1".
        &sum{ x } <= "2" :- not fast.
        &sum{ x } >= "10" :- fast.
        &sum{ y; -1*x } = "3".
        #show fast/0.
    """)
    assert sorted(models) == [[], ["fast"]], "both choices have a solution"
    assert values["y"] == pytest.approx(values["x"] + 3)


def test_choices_whose_constraints_clash_are_never_a_model():
    models, _ = solve("""
        { a; b; c }.
        &sum{ x } >= "5" :- a.
        &sum{ x } <= "4" :- b.
        &sum{ z } >= "0" :- c.
        #show a/0. #show b/0. #show c/0.
    """)
    assert ["a", "b"] not in models and ["a", "b", "c"] not in models
    assert ["a", "c"] in models and ["b", "c"] in models, "c is innocent: it is never excluded with them"


def test_a_conflict_names_exactly_the_clashing_choices():
    program = LinearProgram()
    x, y = program.variable(clingo.Function("x")), program.variable(clingo.Function("y"))
    program.always.append(Row({x: 1.0, y: -1.0}, 0.0, equal=True))  # x = y always
    program.switched[2].append(Row({x: -1.0}, -5.0))  # literal 2: x >= 5
    program.switched[3].append(Row({y: 1.0}, 4.0))  # literal 3: y <= 4
    program.switched[4].append(Row({y: 1.0}, 100.0))  # literal 4: y <= 100, harmless
    conflict, solution = check_rows(program, [2, 3, 4])
    assert solution is None and conflict == [2, 3]
    conflict, solution = check_rows(program, [2, 4])
    assert conflict is None and 5.0 - 1e-7 <= solution.values[x] <= 100 + 1e-7


def test_constraints_of_later_steps_join_those_of_earlier_ones():
    # a multi-shot solve: clingo reports only the theory atoms grounded since the last solve
    control = clingo.Control(["--warn=none"])
    theory = LazyLinearTheory()
    theory.register(control)
    control.add("base", [], theory_program() + '&sum{ p(0) } = "0".')
    control.add("step", ["t"], '&sum{ p(t); -1*p(S) } = "2" :- S = t-1.\n&sum{ p(t) } <= "3".')
    control.ground([("base", [])])
    for t in (1, 2):
        control.ground([("step", [clingo.Number(t)])])
        result = control.solve()
        if t == 1:
            assert result.satisfiable, "p(1) = 2 <= 3"
    assert not result.satisfiable, "p(2) = 4 breaks a bound of step 2 only with step 1's equation"


def test_preferences_shape_the_values_but_never_decide_feasibility():
    models, values = solve("""
        &sum{ v } >= "0". &sum{ v } <= "30".
        &prefer{ v } >= "40".
        &nudge{ w } = "7".
        &sum{ w } >= "0".
    """)
    assert models == [[]], "a preference that cannot be met leaves the model in place"
    assert values["v"] == pytest.approx(30), "as close to the preference as the constraints allow"
    assert values["w"] == pytest.approx(7)


def test_a_theory_atom_read_from_its_printed_form_is_the_atom_its_terms_give(monkeypatch):
    """The fast reader of ``str(atom)`` and the walk over the theory terms agree on every atom
    the continuous encoding grounds for a scenario with lane changes, gaps and preferences."""
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.pipeline import load_scenario
    from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings
    from pytest_roadlogic.planning.encodings.continuous import linear

    compared = []
    walk = LinearProgram()

    def row(atom, program, text):
        printed = linear._printed_row(text, program)
        coefficients = {}
        for element in atom.elements:
            for term in element.terms:
                variable, coefficient = linear._element(term, walk)
                key = str(walk.symbols[variable])
                coefficients[key] = coefficients.get(key, 0.0) + coefficient
        operator, right = atom.guard
        assert printed is not None, f"{text} is not read from its printed form"
        read, read_operator, bound = printed
        assert {str(program.symbols[v]): c for v, c in read.items()} == coefficients, text
        assert (read_operator, bound) == (operator, linear._number(right)), text
        compared.append(text)
        return original(atom, program, text)

    original = linear._row
    monkeypatch.setattr(linear, "_row", row)
    root = Path(__file__).resolve().parents[2]
    for path in (root / "scenarios" / "overtake_third_actor.osc", root / "tests" / "corpus" / "46_time_headway.osc"):
        ContinuousPlanner(build_automaton(load_scenario(path)), ContinuousSettings(random_start=True), 1).first()
    assert any(re.search(r"\*v\(ego,[0-9]+\)", text) and "p(lead" in text for text in compared), (
        "a time headway's row was read"
    )
    assert len(compared) > 100
    assert any("&prefer" in text or "&nudge" in text for text in compared)


def test_every_check_of_a_planning_run_agrees_with_a_program_built_afresh(monkeypatch):
    """The switched-row program kept across checks (warm-started, rows switched by their bounds)
    answers as an elastic program built from nothing would: the same feasibility at every check,
    and every conflict it returns is infeasible on its own (a nogood that forbids a feasible
    choice would lose plans silently)."""
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.pipeline import load_scenario
    from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings
    from pytest_roadlogic.planning.encodings.continuous import linear

    checks, conflicts = [], []
    original = linear.check_rows

    def check(program, on, preferring=None):
        conflict, solution = original(program, on, preferring)
        afresh = linear._elastic_conflict(program, on)
        checks.append((conflict is None, afresh is None))
        if conflict is not None:
            conflicts.append(linear._elastic_conflict(program, conflict) is not None)
        return conflict, solution

    monkeypatch.setattr(linear, "check_rows", check)
    automaton = build_automaton(
        load_scenario(Path(__file__).resolve().parents[2] / "scenarios" / "overtake_third_actor.osc")
    )
    ContinuousPlanner(automaton, ContinuousSettings(), 1).first()
    assert len(conflicts) >= 5, "the run should meet some infeasible choices to compare"
    assert all(kept == afresh for kept, afresh in checks), "a check disagreed with the program built afresh"
    assert all(conflicts), "a returned conflict was feasible on its own"
