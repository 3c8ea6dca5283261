"""Reactive execution: the rest of a scenario planned again from observed states, checked on the
plan's own terms (what is pinned is pinned, the run so far is kept, a constraint relative to the
vehicle under test follows where it really is) and end to end (the scenario happens around a
vehicle under test that does not drive as planned)."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.dut import UnderTest
from pytest_roadlogic.dut.reference_drivers import AdaptiveCruiseControl
from pytest_roadlogic.pipeline import load_scenario, run_instances
from pytest_roadlogic.planning import settings_for
from pytest_roadlogic.planning.fallbacks import planned
from pytest_roadlogic.planning.plan import PlanState
from pytest_roadlogic.problem import problem_for
from pytest_roadlogic.reactive import ReactiveExecution, Replanner
from pytest_roadlogic.reactive.replanner import Replan
from pytest_roadlogic.settings import RunSettings

ROOT = Path(__file__).resolve().parents[2]
CUT_IN = ROOT / "scenarios" / "dut" / "cut_in.osc"
VALUES = {
    "approach.duration": 3.0,
    "brake.duration": 4.2,
    "cut_in.duration": 3.5,
    "cut_in_gap": 23.7,
    "dut_speed": 28.9,
    "npc.change_speed.target": 18.4,
    "npc.drive.position.distance": 20.0,
    "npc.drive.speed.speed": 4.3,
}


def _problem(scenario, values, settings):
    """The guide, settings and seed a sample of ``scenario`` is planned with (``problem.problem_for``)."""
    problem = problem_for(scenario, values, settings, 1)
    return problem.guide, problem.settings, problem.seed


@pytest.fixture(scope="module")
def first_plan():
    scenario = load_scenario(CUT_IN)
    guide, settings, seed = _problem(scenario, VALUES, settings_for(RunSettings()))
    return guide, settings, seed, next(planned(guide, settings, seed, 1))


@pytest.fixture
def planning(first_plan):
    """A replanner of its own (it remembers what failed from which step) and the plan it replans."""
    guide, settings, seed, plan = first_plan
    return Replanner(guide(settings), settings, seed, "dut.car"), plan


def observed_at(plan, step, **moved):
    """Every vehicle where ``plan`` has it at ``step``; ``moved``: vehicle -> (metres, m/s) added."""
    states = {}
    for vehicle, trajectory in plan.states.items():
        state = trajectory[step]
        dx, dv = moved.get(vehicle.replace(".", "_"), (0.0, 0.0))
        states[vehicle] = PlanState(state.position + dx, state.lane, state.speed + dv)
    return states


def test_a_replan_pins_every_vehicle_where_it_was_observed_and_keeps_the_run_so_far(planning):
    replanner, plan = planning
    step = 4
    observed = observed_at(plan, step, dut_car=(-6.0, -3.0))
    replan = replanner.replan(plan, step, observed)
    assert replan.plan is not None, replan.why
    for vehicle, state in observed.items():
        now = replan.plan.states[vehicle][step]
        assert now.position == pytest.approx(state.position, abs=1e-3)
        assert now.speed == pytest.approx(state.speed, abs=1e-3)
        assert now.lane == state.lane
    assert [t for t in replan.plan.transitions if t[0] < step] == [t for t in plan.transitions if t[0] < step]
    assert replan.plan.horizon > step


def test_the_vehicle_under_test_is_predicted_at_its_observed_speed_and_the_npc_meets_its_gap_to_where_it_really_is(
    planning,
):
    replanner, plan = planning
    step = 3
    replan = replanner.replan(plan, step, observed_at(plan, step, dut_car=(-10.0, -2.0)))
    assert replan.predicted, "a plan exists with the vehicle under test at its observed speed"
    dut = replan.plan.states["dut.car"]
    assert all(s.speed == pytest.approx(dut[step].speed, abs=1e-3) for s in dut[step:])
    # the cut-in ends cut_in_gap ahead of the vehicle under test (within the planning cell), in its lane
    cut_in_ends = plan.transitions[2][1]  # start, approach -> cut-in, cut-in -> brake, end
    end = next(at for at, transition in replan.plan.transitions if transition == cut_in_ends)
    npc = replan.plan.states["npc"][end]
    assert npc.lane == dut[end].lane
    assert npc.position - dut[end].position == pytest.approx(VALUES["cut_in_gap"], abs=1.5)


def test_no_vehicle_limit_binds_the_past_so_a_vehicle_under_test_that_braked_harder_than_a_plan_may_still_replans(
    planning,
):
    replanner, plan = planning
    # 6 m/s slower than a second before: beyond the plan's jerk limit, which binds only the future
    assert plan.states["dut.car"][1].speed - (plan.states["dut.car"][2].speed - 7.0) > 6.0
    replan = replanner.replan(plan, 2, observed_at(plan, 2, dut_car=(-3.0, -7.0)))
    assert replan.plan is not None, replan.why


def test_a_replan_that_finds_no_plan_says_why_and_keeps_nothing(planning):
    replanner, plan = planning
    # the npc observed 80 m behind and slower: no cut-in 23.7 m ahead of the vehicle under test can come
    replan = replanner.replan(plan, 5, observed_at(plan, 5, npc=(-80.0, -10.0)))
    assert replan.plan is None
    assert "cannot go on" in replan.why and "t=5 s" in replan.why


def seen_until(plan, step, **changed):
    """The plan's states at the steps before ``step``, as a simulation would have seen them;
    ``changed``: vehicle -> step -> lane seen there instead."""
    seen = {}
    for k in range(step):
        seen[k] = {}
        for vehicle, trajectory in plan.states.items():
            state = trajectory[k]
            lane = changed.get(vehicle.replace(".", "_"), {}).get(k, state.lane)
            seen[k][vehicle] = PlanState(state.position, lane, state.speed)
    return seen


def test_a_replan_through_what_was_seen_at_the_steps_pins_the_past_and_takes_a_run_of_the_automaton_through_it(
    planning,
):
    replanner, plan = planning
    step = 5
    seen = seen_until(plan, step)
    replan = replanner.replan(plan, step, observed_at(plan, step), seen)
    assert replan.plan is not None and replan.seen, replan.why
    for k, states in seen.items():
        for vehicle, state in states.items():
            assert replan.plan.states[vehicle][k].position == pytest.approx(state.position, abs=1e-3)
            assert replan.plan.states[vehicle][k].lane == state.lane


def test_a_cut_in_seen_not_to_have_happened_when_planned_is_replanned_to_end_later_within_its_duration():
    # the cut-in's duration left to its range, [3s..5s]: a cut-in that has not happened by the
    # step its plan ended it may still end later
    values = {k: v for k, v in VALUES.items() if k != "cut_in.duration"}
    scenario = load_scenario(CUT_IN)
    guide, settings, seed = _problem(scenario, values, settings_for(RunSettings()))
    plan = next(planned(guide, settings, seed, 1))
    replanner = Replanner(guide(settings), settings, seed, "dut.car")
    end, cut_in_ends = plan.transitions[2]  # start, approach -> cut-in, cut-in -> brake, end
    npc = plan.states["npc"]
    before = npc[0].lane
    assert npc[end].lane != before, "the plan's npc is in the lane of the vehicle under test when its cut-in ends"
    # observed at that step: the npc seen in its first lane throughout, and still there, lagging
    # its plan as a simulated car does (8 m back, 4 m/s faster than the vehicle under test, not
    # the 11 m/s its plan had reached: from there no car could still end the cut-in at its gap)
    seen = seen_until(plan, end, npc={k: before for k in range(end)})
    observed = observed_at(plan, end)
    observed["npc"] = PlanState(observed["npc"].position - 8.0, before, observed["dut.car"].speed + 4.0)
    replan = replanner.replan(plan, end, observed, seen)
    assert replan.plan is not None and replan.seen, replan.why
    ended = [at for at, t in replan.plan.transitions if t == cut_in_ends]
    assert ended and ended[0] > end, replan.plan.transitions
    assert replan.plan.states["npc"][ended[0]].lane == replan.plan.states["dut.car"][ended[0]].lane


class CautiousAcc(AdaptiveCruiseControl):
    """A reference driver set 15% below the speed it starts at: it slows down where its plan holds
    its speed (the plan's vehicle under test holds what it is asked at the start)."""

    def start(self, vehicle, reference, road, dt):
        super().start(vehicle, reference, road, dt)
        self.set_speed *= 0.85


def cautious(name: str):
    return CautiousAcc() if name == "dut.car" else None


def test_with_replanning_the_cut_in_happens_around_a_vehicle_under_test_that_does_not_drive_as_planned():
    scenario = load_scenario(CUT_IN)
    reactive = next(run_instances(scenario, 1, values=VALUES, drivers=cautious, under_test=UnderTest(), max_tries=1))
    scripted = next(
        run_instances(scenario, 1, values=VALUES, drivers=cautious, under_test=UnderTest(replan_period=0), max_tries=1)
    )
    assert reactive.verdict.accepted and not reactive.dut.failed, reactive.verdict.explain()
    assert reactive.simulation.replans and all(r.plan is not None for r in reactive.simulation.replans)
    assert not scripted.verdict.accepted and not scripted.simulation.replans


class RecordingReplanner:
    """Records the replans asked of it and finds none."""

    dut = "dut.car"

    def __init__(self):
        self.asked = []

    def replan(self, plan, step, observed, seen, at):
        self.asked.append((round(at, 6), step, sorted(seen), observed))
        return Replan(at, 0.0, None, False, "recorded")


def test_replans_come_every_period_several_times_a_second_each_from_the_next_planning_step_with_every_step_before_seen():
    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.simulation.driver import VehicleState

    replanner = RecordingReplanner()
    plan = SimpleNamespace(dt=1.0, horizon=3, vehicles=("dut.car",), stationary=())
    execution = ReactiveExecution(replanner, plan, 0.25)
    road = Road(3)
    for k in range(40):  # the lockstep asks at every simulation step of 0.1 s
        state = VehicleState(10.0 * k * 0.1, road.center_y(1), 0.0, 10.0, 0.0)
        assert execution(round(k * 0.1, 6), {"dut.car": state}, road, {}, {"dut.car": road}) is None
    # every 0.25 s, at the first simulation step not before it; none once the plan has ended (t >= 2)
    assert [at for at, *_ in replanner.asked] == [0.3, 0.5, 0.8, 1.0, 1.3, 1.5, 1.8, 2.0]
    assert [step for _, step, *_ in replanner.asked] == [1, 1, 1, 1, 2, 2, 2, 2]
    assert all(set(range(step)) <= set(seen) for _, step, seen, _ in replanner.asked)
    # a replan between steps pins where the vehicle will be at the next one
    at, step, _, observed = replanner.asked[0]
    assert observed["dut.car"].position == pytest.approx(10.0 * step)
    assert len(execution.replans) == 8


def test_a_state_predicted_to_the_next_step_stops_rather_than_reverses_and_crosses_into_the_lane_it_is_heading_for():
    import math

    from pytest_roadlogic.reactive.execution import _observed
    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.simulation.driver import VehicleState

    road = Road(3)
    braking = VehicleState(0.0, road.center_y(1), 0.0, 10.0, -20.0)
    assert _observed({"car": braking}, {"car": road}, 0.9)["car"] == PlanState(pytest.approx(2.5), 1, 0.0)
    # 0.3 m short of the line to lane 0 (left: larger y), drifting left at 1 m/s
    line = road.center_y(1) + road.lane_width / 2
    heading = math.asin(1.0 / 20.0)
    drifting = VehicleState(0.0, line - 0.3, heading, 20.0, 0.0)
    assert _observed({"car": drifting}, {"car": road}, 0.0)["car"].lane == 1
    assert _observed({"car": drifting}, {"car": road}, 0.5)["car"].lane == 0


def test_an_observed_state_is_held_to_the_scenario_as_written_not_to_the_plans_margin_inside_it():
    # ccr_braking_close's car ahead holds 50 km/h (13.9 m/s, within 0.5 m/s) until it brakes at 2 s;
    # its plan keeps 0.25 m/s inside that band, for the tracking error still to come. Observed at
    # 14.3 m/s when braking is due (inside the band, outside the plan's part of it), the rest of
    # the scenario is still planned: it had timed out, and the case ended not exercised
    scenario = load_scenario(ROOT / "scenarios" / "dut" / "ccr_braking_close.osc")
    settings = settings_for(RunSettings()).with_self_driven("dut.car")
    guide, settings, seed = _problem(scenario, {}, settings)
    plan = next(planned(guide, settings, seed, 1))
    observed = observed_at(plan, 2)
    observed["target"] = PlanState(observed["target"].position, observed["target"].lane, 14.3)
    replan = Replanner(guide(settings), settings, seed, "dut.car").replan(plan, 2, observed)
    assert replan.plan is not None, replan.why
    assert replan.plan.states["target"][2].speed == pytest.approx(14.3, abs=1e-3)
    assert replan.predicted, "found with the vehicle under test predicted, the first way a replan tries"


def test_at_a_junction_a_replan_comes_only_once_the_vehicle_under_test_has_left_its_planned_course():
    from pytest_roadlogic.planning.plan import PlanState
    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.simulation.driver import VehicleState

    replanner = RecordingReplanner()
    # planned at 10 m/s for 3 s
    states = {"dut.car": [PlanState(10.0 * k, 1, 10.0) for k in range(4)]}
    plan = SimpleNamespace(
        dt=1.0, horizon=3, vehicles=("dut.car",), stationary=(), states=states, at=lambda v, k: states[v][k]
    )
    execution = ReactiveExecution(replanner, plan, 0.25, on_course_only=True)
    road = Road(3)
    for k in range(15):  # on course, 0.1 m and 0.1 m/s off at most
        state = VehicleState(10.0 * k * 0.1 + 0.1, road.center_y(1), 0.0, 10.1, 0.0)
        execution(round(k * 0.1, 6), {"dut.car": state}, road, {}, {"dut.car": road})
    assert replanner.asked == []
    # it brakes: 1 m/s slower than planned, and the next period replans
    for k in range(15, 20):
        state = VehicleState(10.0 * k * 0.1 - 0.2, road.center_y(1), 0.0, 9.0, -2.0)
        execution(round(k * 0.1, 6), {"dut.car": state}, road, {}, {"dut.car": road})
    assert [at for at, *_ in replanner.asked] == [1.5, 1.8]


def _modes_with_plans():
    """Every set of replanning modes that could have plans: with a mode, every mode that asks less
    of the same run so far (the vehicle under test free rather than predicted, any length rather
    than the old one's) has one too."""
    import itertools

    from pytest_roadlogic.reactive.replanner import MODES

    def asks_less(wider, narrower):
        return (
            wider.seen == narrower.seen
            and (not wider.predicted or narrower.predicted)
            and (not wider.full_length or narrower.full_length)
        )

    for chosen in itertools.product((False, True), repeat=len(MODES)):
        having = {m for m, c in zip(MODES, chosen) if c}
        if all(w in having for m in having for w in MODES if asks_less(w, m)):
            yield having


@pytest.mark.parametrize("having", list(_modes_with_plans()), ids=lambda h: f"{len(h)} modes")
def test_a_replan_after_one_without_a_plan_takes_the_plan_it_would_have_taken_and_proves_none_with_two_searches(
    monkeypatch, having
):
    import pytest_roadlogic.planning as planning
    from pytest_roadlogic.planning import NoPlanError
    from pytest_roadlogic.reactive.replanner import MODES

    tried = []

    class Planner:
        def replan(self, past, shortest):
            mode = next(
                m
                for m in MODES
                if m.seen == (past.seen is not None)
                and m.predicted == past.predicted
                and m.full_length == (shortest == plan.horizon)
            )
            tried.append(mode)
            if mode not in having:
                raise NoPlanError("none")
            return SimpleNamespace(mode=mode)

    monkeypatch.setattr(planning, "planner_for", lambda automaton, settings, seed: Planner())
    plan = SimpleNamespace(dt=1.0, horizon=6, transitions=[])
    seen = {k: {} for k in range(3)}
    settings = SimpleNamespace(time_limit=10.0)
    monkeypatch.setattr("dataclasses.replace", lambda obj, **changes: obj)
    taken = {}
    for stuck in (False, True):
        replanner = Replanner(None, settings, 1, "dut.car")
        replanner.stuck = stuck
        tried.clear()
        found = replanner.replan(plan, 3, {}, seen)
        taken[stuck] = found.plan.mode if found.plan is not None else None
        if not having and stuck:
            assert len(tried) == 2  # the two widest modes prove that none has a plan
    assert taken[True] == taken[False]
    assert (taken[False] is None) == (not having)


def test_only_the_constraints_a_run_may_still_meet_name_a_vehicle_as_ahead_of_it():
    scenario = load_scenario(ROOT / "scenarios" / "junctions" / "yield_left_turn_across_oncoming.osc")
    automaton = build_automaton(scenario)
    # the oncoming car is placed relative to the vehicle under test at the start, and is held to
    # its own speed all along; nothing after the start names the vehicle under test
    ahead = {loc.name: automaton.names_ahead(loc.id, "dut.car") for loc in automaton.locations}
    assert ahead == {
        "init": True,
        "dut.car.drive | oncoming.drive": False,
        "dut.car.drive | oncoming.drive#2": False,
        "fin": False,
    }
    assert [automaton.names_ahead(loc.id, "oncoming") for loc in automaton.locations] == [True, True, True, False]


def test_at_a_junction_replans_stop_once_a_car_whose_way_crosses_the_vehicle_under_tests_has_passed_the_crossing():
    import dataclasses

    from pytest_roadlogic.roads.asks import TurnAsk
    from pytest_roadlogic.roads.conflicts import meetings_of
    from pytest_roadlogic.roads.opendrive_in import read_map
    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.roads.ways import choose_ways
    from pytest_roadlogic.simulation.driver import VehicleState

    road_map = read_map(ROOT / "scenarios" / "junctions" / "maps" / "crossing.xodr")
    asks = (TurnAsk("left", junction="j", in_road="r"), TurnAsk("straight", junction="j", out_road="r"))
    turn, oncoming = choose_ways(road_map, 1, 200.0, asks, (frozenset({"dut.car"}), frozenset({"oncoming"}))).routes()
    (crossing,) = meetings_of(0, turn, 1, oncoming)
    roads = {
        "dut.car": dataclasses.replace(Road(1), route=turn),
        "oncoming": dataclasses.replace(Road(1), route=oncoming),
    }
    replanner = RecordingReplanner()
    replanner.automaton = build_automaton(
        load_scenario(ROOT / "scenarios" / "junctions" / "yield_left_turn_across_oncoming.osc")
    )
    # planned at 10 m/s; the vehicle under test waits before the crossing (off its course)
    states = {"dut.car": [PlanState(10.0 * k, 1, 10.0) for k in range(30)]}
    plan = SimpleNamespace(
        dt=1.0,
        horizon=29,
        vehicles=("dut.car", "oncoming"),
        stationary=(),
        states=states,
        at=lambda v, k: states[v][k],
        transitions=[(0, 0)],
    )
    execution = ReactiveExecution(replanner, plan, 1.0, on_course_only=True)
    waiting = VehicleState(crossing.first_span[0] - 10.0, 0.0, 0.0, 0.0, 0.0)

    def asked_with_the_oncoming_car_at(metres: float, k: int) -> bool:
        before = len(replanner.asked)
        state = VehicleState(metres, 0.0, 0.0, 8.0, 0.0)
        execution(float(k), {"dut.car": waiting, "oncoming": state}, Road(1), {}, roads)
        return len(replanner.asked) > before

    assert asked_with_the_oncoming_car_at(crossing.second_span[0] - 5.0, 1)  # still to come
    assert asked_with_the_oncoming_car_at(crossing.second_span[1], 2)  # in it
    assert not asked_with_the_oncoming_car_at(crossing.second_span[1] + 3.0, 3)  # past it: the plan stands
