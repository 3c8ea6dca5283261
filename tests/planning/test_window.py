"""Which horizons planning searches (planning/window.py): the floor read off the automaton's graph
never passes the first horizon at which a run can end, and the window's answers do not depend on
how many steps it happens to have grounded."""

import time
from pathlib import Path

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.evaluation.bench import conftest_dialect
from pytest_roadlogic.frontend import check_file
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings
from pytest_roadlogic.planning.window import shortest_run

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted(
    path
    for path in [
        *ROOT.glob("scenarios/*.osc"),
        *ROOT.glob("scenarios/realistic/**/*.osc"),
        *ROOT.glob("tests/scenarios/*.osc"),
    ]
    if path.name != "lib.osc"
)


def automaton_of(path: Path):
    checked = check_file(path, dialect=conftest_dialect(path, [ROOT / "scenarios"]))  # as pytest would read it
    assert not checked.errors, checked.report()
    return build_automaton(checked.scenario_to_run())


def window_without_floor(automaton, dt: float):
    planner = ContinuousPlanner(automaton, ContinuousSettings(dt=dt), 1)
    return planner.window(time.monotonic() + 60, planner.instance)  # a program of its own: no floor


@pytest.mark.parametrize("path", FILES, ids=lambda path: path.stem)
@pytest.mark.parametrize("dt", [1.0, 0.5])
def test_no_run_of_the_automaton_ends_before_its_floor(path, dt):
    automaton = automaton_of(path)
    earliest = window_without_floor(automaton, dt).earliest(480)
    floor = shortest_run(automaton, dt)
    assert earliest is None or floor <= earliest, (
        f"the floor {floor} passes the first step a run ends at, {earliest}: planning would miss plans"
    )


@pytest.mark.parametrize(
    "name", ["realistic/five_vehicle_minute", "realistic/follow_then_overtake", "realistic/one_of_reaction", "overtake"]
)
def test_the_floor_of_phases_in_series_is_where_a_run_ends(name):
    # why planning starts there without asking the window (planning/encodings/continuous/planner.py): one solve less
    automaton = automaton_of(ROOT / "scenarios" / f"{name}.osc")
    assert shortest_run(automaton, 1.0) == window_without_floor(automaton, 1.0).earliest(480)


@pytest.mark.parametrize("name", ["realistic/infeasible_gain", "realistic/cut_in", "close_in"])
def test_the_window_says_the_same_however_far_it_has_grounded(name):
    path = ROOT / "tests" / "scenarios" / f"{name}.osc" if name == "close_in" else ROOT / "scenarios" / f"{name}.osc"
    automaton = automaton_of(path)
    for dt in (1.0, 0.5):
        far = window_without_floor(automaton, dt)
        far._ground_to(80)
        last = far.last_open(80)
        for step in range(last + 3):
            near = window_without_floor(automaton, dt)  # grounds only what the question needs
            assert near.open_at(step) == far.open_at(step), (
                f"under way at step {step} (dt {dt}): a window grounded to the step answered otherwise"
            )


def test_a_plan_may_need_one_step_after_the_last_end_and_no_more():
    automaton = automaton_of(ROOT / "scenarios" / "realistic" / "infeasible_gain.osc")  # one phase of 3 steps
    window = window_without_floor(automaton, 1.0)
    assert window.last_open(120) == 2, "under way at step 2, ended at 3"
    assert window.last_horizon(120) == 4, "the last end, and one step for the checks of a plan's last state"
    assert [window.past_end(h) for h in range(2, 7)] == [False, False, False, True, True]


@pytest.mark.parametrize("path", [p for p in FILES if not automaton_of(p).timings], ids=lambda path: path.stem)
def test_a_window_without_timed_phases_answers_as_its_solver_would(path):
    # the scenario's own window of an automaton without durations answers without a solver
    automaton = automaton_of(path)
    planner = ContinuousPlanner(automaton, ContinuousSettings(), 1)
    own = planner.window(time.monotonic() + 60)
    assert own.untimed
    solved = window_without_floor(automaton, 1.0)
    for horizon in range(0, 30):
        assert own.ends_by(horizon) == solved.ends_by(horizon), f"ends by step {horizon}"
        assert own.open_at(horizon) == solved.open_at(horizon), f"under way at step {horizon}"
