"""Files come out as their author meant: every vehicle does only what its own constructs ask
(docs/language.md, "What a vehicle is asked to do"), read from each first plan by
``evaluation.fidelity`` (written from that definition, not from the encoding), and what a reader
of a file expects (who changes lane, whose speed is held, where a vehicle starts) checked on the
plan and on the simulated trace."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.evaluation.fidelity import SPEED_CHANGE, unasked_changes
from pytest_roadlogic.frontend import check_file
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "corpus"
# files meant to have no plan, and corpus files that check but do not build an automaton (a
# construct the automaton does not translate yet; test_corpus says which)
NO_FIRST_PLAN = {"infeasible_gain.osc", "infeasible_order.osc"}
FILES = [
    *sorted((ROOT / "scenarios").glob("*.osc")),
    *sorted((ROOT / "scenarios" / "realistic").glob("*.osc")),
    *sorted((ROOT / "scenarios" / "realistic" / "carla_dialect").glob("*.osc")),
    *sorted(CORPUS.glob("*.osc")),
]


def _dialect(path: Path) -> str | None:
    """CARLA's dialect for the files written in it (named so, or in its folder)."""
    return "carla" if "carla" in path.name or path.parent.name == "carla_dialect" else None


def _first_plans(path: Path):
    checked = check_file(path, dialect=_dialect(path))
    assert not checked.errors, checked.report()
    for scenario in checked.scenarios:
        try:
            automaton = build_automaton(scenario)
        except Exception:  # the automaton's refusals are test_corpus's and test_automaton's matter
            continue
        planner = ContinuousPlanner(automaton, ContinuousSettings(time_limit=30), seed=1)
        yield scenario.scenario.name, automaton, planner.first(), planner


# files whose first plan is known to make a change nothing asks, and why (strict: fixed, it fails)
KNOWN_UNFAITHFUL: dict[str, str] = {}


@pytest.mark.parametrize(
    "path",
    [
        pytest.param(p, marks=pytest.mark.xfail(strict=True, reason=KNOWN_UNFAITHFUL[p.name]))
        if p.name in KNOWN_UNFAITHFUL
        else p
        for p in FILES
        if p.name not in NO_FIRST_PLAN
    ],
    ids=lambda p: p.relative_to(ROOT).as_posix(),
)
def test_no_first_plan_has_a_lane_or_speed_change_that_no_construct_of_its_vehicle_asks_for(path):
    for name, automaton, plan, planner in _first_plans(path):
        assert planner.stats["least_action"] == 1.0, f"{name}: planned without least action"
        changes = unasked_changes(plan, automaton)
        assert not changes, f"{name}: " + "; ".join(map(str, changes))


# file -> (vehicles that change lane, vehicles whose speed is held throughout, {vehicle: start
# speed in m/s}) as a reader of the file expects them
EXPECTED = {
    "scenarios/overtake.osc": ({"v1"}, {"v2"}, {}),
    "scenarios/realistic/follow_then_overtake.osc": ({"ego"}, set(), {}),
    "scenarios/realistic/cut_in.osc": ({"npc"}, set(), {}),
    "tests/corpus/109_runner_mph_library.osc": (set(), set(), {"dut": 50 * 0.447038889}),
    "tests/corpus/111_global_map_and_anchor.osc": ({"ego_vehicle"}, set(), {"ego_vehicle": 25.0}),
    "tests/corpus/112_overtake_ego_returns.osc": ({"ego"}, {"npc"}, {}),
    "tests/corpus/113_carla_targets_in_sequence.osc": (set(), set(), {"ego_vehicle": 10 / 3.6}),
    "scenarios/realistic/carla_dialect/slow_cut_in.osc": ({"van"}, set(), {"hero": 60 / 3.6}),
}


def _trace_lanes(columns) -> set[int]:
    """The lanes a vehicle's centre is in over the trace, a lane counted when it stays 1 s."""
    lanes = np.asarray(columns["lane"], dtype=int)
    held = set()
    run_start = 0
    for k in range(1, len(lanes) + 1):
        if k == len(lanes) or lanes[k] != lanes[run_start]:
            if k - run_start >= 10:  # samples of 0.1 s
                held.add(int(lanes[run_start]))
            run_start = k
    return held


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_a_files_vehicles_change_lane_hold_speed_and_start_as_its_reader_expects_in_plan_and_trace(name):
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    changers, holders, starts = EXPECTED[name]
    path = ROOT / name
    outcome = run_scenario(load_scenario(path, dialect=_dialect(path)), seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    plan, trace = outcome.plan, outcome.simulation.trace
    assert unasked_changes(plan, outcome.automaton) == []
    for vehicle, states in plan.states.items():
        lanes = {s.lane for s in states}
        assert (len(lanes) > 1) == (vehicle in changers), f"plan: {vehicle} in lanes {sorted(lanes)}"
        traced = _trace_lanes(trace.actors[vehicle])
        assert (len(traced) > 1) == (vehicle in changers), f"trace: {vehicle} in lanes {sorted(traced)}"
    for vehicle in holders:
        speeds = [s.speed for s in plan.states[vehicle]]
        assert max(speeds) - min(speeds) <= SPEED_CHANGE * plan.dt, f"plan: {vehicle}'s speeds {speeds}"
        traced = trace.actors[vehicle]["speed"]
        assert float(np.ptp(traced)) <= 1.0, f"trace: {vehicle}'s speed ranges over {np.ptp(traced):.2f} m/s"
    for vehicle, speed in starts.items():
        assert plan.states[vehicle][0].speed == pytest.approx(speed, abs=0.5), f"plan: {vehicle} starts elsewhere"
        assert float(trace.actors[vehicle]["speed"][0]) == pytest.approx(speed, abs=0.5)


def test_an_unasked_change_is_said_in_the_files_lane_numbers_and_in_kph():
    import functools

    from pytest_roadlogic.constructs import STANDARD
    from pytest_roadlogic.evaluation.fidelity import UnaskedChange

    lane_number = functools.partial(STANDARD.lane_number, lanes=3)
    # the planner's index 1 -> 0 is the standard's lane 2 -> 3 (counted from the right)
    lane = UnaskedChange("lead", 4, "lane", 1, 0)
    assert lane.described(lane_number) == "lead changes from lane 2 to 3 at step 4, unasked"
    speed = UnaskedChange("lead", 5, "speed", 19.4, 5.6)
    assert speed.described(lane_number) == (
        "lead changes speed from 19.4 m/s (70 kph) to 5.6 m/s (20 kph) at step 5, unasked"
    )
