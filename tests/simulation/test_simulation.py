"""Plans become frenetix-driven simulations from standstill that follow the waypoints."""

import numpy as np
import pytest

from pytest_roadlogic.artifacts.commonroad import write_commonroad_xml
from pytest_roadlogic.planning import GridPlanner
from pytest_roadlogic.simulation import Road, references, simulate


@pytest.fixture(scope="module")
def simulation(overtake_automaton):
    plan = GridPlanner(overtake_automaton, seed=1).first()
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
    plan = GridPlanner(overtake_automaton, seed=seed).first()
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
    assert len(scenario.dynamic_obstacles) == 2, "one trajectory per moving vehicle"
    assert len(scenario.lanelet_network.lanelets) == 3
    for obstacle in scenario.dynamic_obstacles:
        assert len(obstacle.prediction.trajectory.state_list) == len(sim.trace) - 1
    # one planning problem per waypoint, chained from standstill
    waypoints = {v: r.waypoints for v, r in sim.references.items()}
    assert len(problems.planning_problem_dict) == sum(len(w) for w in waypoints.values())
    first = problems.planning_problem_dict[2000]
    assert first.initial_state.velocity == 0.0
    goal = first.goal.state_list[0]
    assert goal.time_step.start <= round(waypoints["v1"][0].time / sim.dt) <= goal.time_step.end


def test_every_vehicle_reaches_each_goal_in_its_time_window(simulation):
    plan, sim = simulation
    assert set(sim.goals) == set(plan.vehicles)
    for vehicle, records in sim.goals.items():
        assert len(records) == len(plan.states[vehicle])
        for record in records:
            assert record.reached_at is not None, f"{vehicle} missed {record.waypoint}"
            assert record.waypoint.earliest - 1e-9 <= record.reached_at <= record.waypoint.latest + 1e-9


class _Misbehaving:
    """A plug-in driver (the ``Driver`` interface) that drives v2 with frenetix until the plan is
    over, then leaves the road or jumps onto v1: the scenario's guards have all held by then."""

    def __init__(self, incident):
        from pytest_roadlogic.simulation.frenetix import FrenetixDriver

        self.incident = incident
        self.inner = FrenetixDriver()

    def start(self, vehicle, reference, road, dt):
        self.inner.start(vehicle, reference, road, dt)
        self.end = reference.end_time
        self.dt = dt

    def plan(self, time, state, others):
        from pytest_roadlogic.simulation.driver import Trajectory, VehicleState

        if time < self.end + 0.3:
            return self.inner.plan(time, state, others)
        if self.incident == "collision":
            return Trajectory.standing(others["v1"].state(0), 2)
        drifted = VehicleState(state.x + state.speed * self.dt, state.y + 1.0, state.heading, state.speed, 0.0)
        return Trajectory.standing(drifted, 2)


@pytest.mark.parametrize("incident", ["off-road", "collision"])
def test_a_collision_or_leaving_the_road_is_never_accepted_even_when_the_guards_hold(overtake, incident):
    from pytest_roadlogic.pipeline import run_scenario
    from pytest_roadlogic.planning import GridSettings

    # a grid plan whose guards are known to hold at seed 3; the rule under test is the monitor's
    outcome = run_scenario(
        overtake,
        seed=3,
        settings=GridSettings(),
        max_tries=1,
        drivers=lambda v: _Misbehaving(incident) if v == "v2" else None,
    )
    verdict = outcome.verdict
    assert verdict.robustness >= 0, "the guards should hold: the incident comes after the plan's end"
    assert [i.kind for i in verdict.incidents] == [incident]
    assert not verdict.accepted
    assert incident in verdict.explain()


def braking_to_a_stop(brisk: bool):
    """A reference braking from 14 m/s at 6 m/s^2 from t = 1 s, its plan in whole steps: 14, 14, 8,
    2, then standing (the plan's last braking step brakes 2 m/s^2: it stands at its end)."""
    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.simulation.reference import Reference, Waypoint

    speeds = [14.0, 14.0, 8.0, 2.0, 0.0, 0.0, 0.0]
    positions = [0.0]
    for before, after in zip(speeds, speeds[1:]):
        positions.append(positions[-1] + (before + after) / 2)
    waypoints = [Waypoint(float(k), p, 1, v) for k, (p, v) in enumerate(zip(positions, speeds))]
    return Reference("lead", 0.0, 0.0, waypoints, Road(3), brisk=brisk), positions


def test_a_car_braking_briskly_to_a_standstill_brakes_on_at_its_rate_into_it_and_stands_there():
    reference, positions = braking_to_a_stop(brisk=True)
    stop = 3.0 + 2.0 / 6.0
    assert reference.v([3.2])[0] == pytest.approx(2.0 - 6.0 * 0.2, abs=1e-6)
    assert reference.v([stop, 4.0, 6.0]).tolist() == pytest.approx([0.0, 0.0, 0.0])
    stands = positions[3] + 2.0**2 / (2 * 6.0)
    assert reference.s([stop, 5.0, 6.0]).tolist() == pytest.approx([stands] * 3)
    assert stands < positions[4], "short of the planned place, by less than the last step's distance"
    assert reference.next_onset(2.5) == np.inf, "a standstill is no onset the car waits for"


def test_a_car_not_braking_briskly_follows_its_plan_through_the_last_step():
    reference, positions = braking_to_a_stop(brisk=False)
    assert reference.v([3.5])[0] > 0.5, "the plan's gentle last step, as planned"
    assert reference.s([4.0])[0] == pytest.approx(positions[4])


def test_a_run_whose_vehicle_the_simulator_could_not_drive_for_a_quarter_of_it_says_so(simulation):
    import dataclasses

    _, sim = simulation
    steps = len(sim.trace.times)
    assert sim.unfollowed() == ""  # the overtake is driven all along
    quarter = -(-steps // 4)
    held = dataclasses.replace(sim, fallbacks={"ego": quarter, "npc": quarter - 1})
    assert held.unfollowed().startswith(
        f"the simulator found no trajectory of its own for ego in {quarter} of {steps} steps,"
    )
    assert "npc" not in held.unfollowed() and "--roadlogic-simulator kinematic" in held.unfollowed()
