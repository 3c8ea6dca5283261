"""Plans become frenetix-driven simulations from standstill that follow the waypoints."""

import numpy as np
import pytest

from pytest_roadlogic.planning import Planner
from pytest_roadlogic.simulation import Road, references, simulate
from pytest_roadlogic.simulation.commonroad_export import write_commonroad_xml


@pytest.fixture(scope="module")
def simulation(overtake_automaton):
    plan = Planner(overtake_automaton, seed=1).first()
    return plan, simulate(plan)


def test_every_vehicle_starts_from_standstill_in_its_planned_lane(simulation):
    plan, sim = simulation
    for v in plan.vehicles:
        assert sim.trace.actors[v]["speed"][0] == 0.0
        assert sim.trace.actors[v]["lane"][0] == plan.at(v, 0).lane


def test_the_trace_is_sampled_every_tenth_of_a_second(simulation):
    _, sim = simulation
    assert np.allclose(np.diff(sim.trace.times), 0.1)


def test_vehicles_reach_their_waypoints_closely_and_without_incidents(simulation):
    plan, sim = simulation
    assert sim.trace.incidents == []
    for v in plan.vehicles:
        for waypoint in sim.references[v].waypoints:
            k = int(round(waypoint.time / sim.dt))
            assert abs(sim.trace.actors[v]["x"][k] - waypoint.position) < 4.0, f"{v} misses {waypoint}"


@pytest.mark.parametrize("seed", range(1, 6))
def test_run_up_from_standstill_keeps_vehicles_in_one_lane_apart(overtake_automaton, seed):
    plan = Planner(overtake_automaton, seed=seed).first()
    refs = references(plan, Road())
    times = np.linspace(0, plan.runup, 200)
    for reference in refs.values():
        assert reference.v(0.0) == 0.0
        assert reference.s(plan.runup) == pytest.approx(reference.waypoints[0].position)
    if plan.at("v1", 0).lane == plan.at("v2", 0).lane:
        gaps = np.abs(refs["v2"].s(times) - refs["v1"].s(times))
        assert gaps.min() >= 8.0 - 1e-6


def test_the_commonroad_file_reads_back(simulation, tmp_path):
    from commonroad.common.file_reader import CommonRoadFileReader

    _, sim = simulation
    path = write_commonroad_xml(sim, tmp_path / "scenario.xml")
    scenario, problems = CommonRoadFileReader(str(path)).open()
    assert len(scenario.dynamic_obstacles) == 2
    assert len(scenario.lanelet_network.lanelets) == 3
    assert len(problems.planning_problem_dict) == 2
