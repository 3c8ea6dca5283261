"""What a reader of a file expects, checked on the simulated trace, not only on the plan: who
changes lane and how often, which speeds are held (within 1 kph once reached), where vehicles
start. Files written as public ones are (docs/language.md, "What a vehicle is asked to do"); the
plan-side checks of the same definition are in test_asked_per_instant.py and
test_carla_as_its_runner.py."""

from __future__ import annotations

import numpy as np
import pytest

from pytest_roadlogic.pipeline import load_scenario, run_scenario
from tests.constructs.test_asked_per_instant import OVERTAKE_AND_RETURN
from tests.constructs.test_carla_as_its_runner import CRUISE_THEN_FASTER

KPH = 1 / 3.6
HELD = 1.0 * KPH

FOLLOW_KEEPING_LANE = """scenario follow_keeping_lane:
    ego: car
    lead: car
    do parallel(duration: 15s):
        lead.drive() with:
            lane(2, at: start)
            speed(60kph)
        ego.drive() with:
            lane(same_as: lead, at: start)
            position([25..35]m, behind: lead, at: start)
            speed([70..80]kph, at: start)
            avoid_collisions(true)
"""


def simulated(tmp_path, text: str, dialect: str | None = None):
    path = tmp_path / "scenario.osc"
    path.write_text(text)
    outcome = run_scenario(load_scenario(path, dialect=dialect), seed=1)
    assert outcome.verdict.accepted
    return outcome.plan, outcome.simulation.trace


def lane_changes(trace, vehicle: str) -> int:
    lanes = trace.actors[vehicle]["lane"]
    return int(np.sum(lanes[1:] != lanes[:-1]))


def speeds_between(trace, vehicle: str, start: float, end: float) -> np.ndarray:
    inside = (trace.times >= start - 1e-9) & (trace.times <= end + 1e-9)
    return trace.actors[vehicle]["speed"][inside]


def test_in_an_overtake_only_the_overtaker_changes_lane_out_and_back_and_the_other_holds_its_speed(tmp_path):
    plan, trace = simulated(tmp_path, OVERTAKE_AND_RETURN)
    assert lane_changes(trace, "ego") == 2
    assert lane_changes(trace, "npc") == 0
    npc = trace.actors["npc"]["speed"]
    assert np.max(np.abs(npc - 20.0)) <= HELD, "speed(20mps, at: start) and nothing after it asks a change"
    assert trace.actors["npc"]["x"][0] - trace.actors["ego"]["x"][0] == pytest.approx(20, abs=0.6)


def test_carlas_target_speeds_are_held_in_the_trace_once_reached(tmp_path):
    plan, trace = simulated(tmp_path, CRUISE_THEN_FASTER, dialect="carla")
    faster = plan.transitions[1][0] * plan.dt
    for vehicle, target in (("ego", 40), ("npc", 50)):
        assert lane_changes(trace, vehicle) == 0
        # the tracking controller blends into the next phase in its last half second
        cruise = speeds_between(trace, vehicle, 0.0, faster - 0.5)
        assert np.max(np.abs(cruise - 30 * KPH)) <= HELD, (vehicle, cruise)
        reached = next(k for k, state in enumerate(plan.states[vehicle]) if abs(state.speed - target * KPH) <= HELD)
        held = speeds_between(trace, vehicle, (reached + 1) * plan.dt, trace.times[-1])
        assert np.max(np.abs(held - target * KPH)) <= HELD, (vehicle, held)


def test_a_follow_keeps_its_lane_the_lead_holds_its_speed_and_the_follower_only_brakes(tmp_path):
    plan, trace = simulated(tmp_path, FOLLOW_KEEPING_LANE)
    assert lane_changes(trace, "ego") == 0 and lane_changes(trace, "lead") == 0
    assert np.max(np.abs(trace.actors["lead"]["speed"] - 60 * KPH)) <= HELD
    ego = trace.actors["ego"]["speed"]
    assert 70 * KPH - HELD <= ego[0] <= 80 * KPH + HELD
    assert np.max(np.diff(ego)) <= 0.05, "it never speeds up: nothing asks it to"
