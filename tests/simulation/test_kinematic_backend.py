"""The kinematic backend (simulation/kinematic/): a bicycle model tracking each plan, behind the
same seam as frenetix, judged by the same monitor."""

from __future__ import annotations

import numpy as np
import pytest

from pytest_roadlogic.pipeline import load_scenario, run_scenario
from pytest_roadlogic.simulation.backends import available, simulator
from tests.conftest import ROOT

PAPER = sorted((ROOT / "scenarios").glob("*.osc"))


def test_the_kinematic_backend_is_built_in_and_frenetix_stays_the_default():
    assert available()[:2] == ["frenetix", "kinematic"]
    assert simulator().name == "frenetix" and simulator("kinematic").name == "kinematic"


@pytest.mark.parametrize("path", PAPER, ids=[p.stem for p in PAPER])
def test_both_backends_accept_the_papers_seven(path):
    for name in ("kinematic", "frenetix"):
        outcome = run_scenario(load_scenario(path), seed=1, simulator=simulator(name))
        assert outcome.verdict.accepted, (name, outcome.verdict.explain())


def test_the_kinematic_vehicles_follow_the_plan_within_half_a_metre_and_a_lane_change_takes_seconds():
    outcome = run_scenario(load_scenario(ROOT / "scenarios" / "overtake.osc"), seed=1, simulator=simulator("kinematic"))
    plan, trace = outcome.plan, outcome.simulation.trace
    for vehicle, states in plan.states.items():
        reference = outcome.simulation.references[vehicle]
        times = np.array([reference.waypoints[0].time + k * plan.dt for k in range(len(states))])
        sampled = np.interp(times, trace.times, trace.actors[vehicle]["x"])
        assert np.max(np.abs(sampled - reference.s(times))) < 0.5, vehicle
        lanes = trace.actors[vehicle]["lane"]
        changes = np.flatnonzero(lanes[1:] != lanes[:-1])
        assert len(changes) == sum(a.lane != b.lane for a, b in zip(states, states[1:])), vehicle
    heading = trace.actors["v1"]["heading"] if "v1" in trace.actors else next(iter(trace.actors.values()))["heading"]
    assert np.max(np.abs(heading)) < 0.2, "a lane change is a gentle swerve, not a jump"
