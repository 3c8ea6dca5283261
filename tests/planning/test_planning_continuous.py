"""The continuous-dynamics encoding (asp/continuous/): its plans obey the vehicle limits, exact
constant-acceleration kinematics, the lane rules, the gaps and the scenario's guards and durations,
checked here independently of the encoding."""

import dataclasses
from pathlib import Path

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.logic.automaton import MeanAcceleration
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings, UnsatisfiableScenario
from pytest_roadlogic.planning.encodings.continuous.instance import stopping
from tests.planning.test_planning import check_run

ROOT = Path(__file__).resolve().parents[2]
SETTINGS = ContinuousSettings()


def behind_in_lane(plan, v, k) -> bool:
    """Whether ``v`` has another vehicle ahead of it in its lane at step ``k``."""
    me = plan.states[v][k]
    return any(
        plan.states[w][k].lane == me.lane and plan.states[w][k].position > me.position for w in plan.vehicles if w != v
    )


def check_continuous_plan(plan, automaton, settings=SETTINGS):
    dt = plan.dt
    may_stop = stopping(automaton, settings)
    # a vehicle asked an acceleration changes it as fast as a car's brakes act
    brisk = {r.actor for timing in automaton.timings.values() for r in timing.rates if isinstance(r, MeanAcceleration)}
    for v in plan.vehicles:
        states = plan.states[v]
        jerk = (settings.brisk_jerk if v in brisk else settings.max_jerk) * dt
        changes = [k for k in range(1, len(states)) if states[k].lane != states[k - 1].lane]
        least = 0.0 if v in may_stop or v in plan.stationary else settings.min_speed
        if v not in plan.stationary and len(states) > 1:
            first = (states[1].speed - states[0].speed) / dt
            assert abs(first) <= jerk + 1e-6, f"{v} starts with acceleration {first}: the simulation starts without one"
        for k, s in enumerate(states):
            # below the driving floor only queued: behind a vehicle in its lane, braking
            queued = k and s.speed <= states[k - 1].speed + 1e-6 and behind_in_lane(plan, v, k)
            floor = 0.0 if queued else least
            assert floor - 1e-6 <= s.speed <= settings.max_speed + 1e-6, f"{v} speed {s.speed} at {k}"
            assert 0 <= s.lane < automaton.lanes
            if k:
                p = states[k - 1]
                acceleration = (s.speed - p.speed) / dt
                assert settings.min_acceleration - 1e-6 <= acceleration <= settings.max_acceleration + 1e-6, (
                    f"{v} acceleration {acceleration} at {k}"
                )
                assert s.position == pytest.approx(p.position + (p.speed + s.speed) / 2 * dt, abs=1e-6), (
                    f"{v} kinematics at {k}"
                )
            if k >= 2:
                change = (s.speed - 2 * states[k - 1].speed + states[k - 2].speed) / dt
                assert abs(change) <= jerk + 1e-6, f"{v} acceleration jumps by {change} at {k}"
                assert abs(s.lane - p.lane) <= 1
        for a, b in zip(changes, changes[1:]):
            assert b - a >= settings.lane_change_gap
        for k in changes:
            assert k >= 2, f"{v} changes lane in the first step, before the simulation could start the move"
            assert min(states[k - 1].speed, states[k].speed) >= settings.lane_change_speed - 1e-6, (
                f"{v} changes lane at a crawl at {k}"
            )

    vehicles = plan.vehicles
    for i, a in enumerate(vehicles):
        for b in vehicles[i + 1 :]:
            for k in range(plan.horizon + 1):
                lanes_a = {plan.at(a, k).lane} | ({plan.at(a, k - 1).lane} if k else set())
                lanes_b = {plan.at(b, k).lane} | ({plan.at(b, k - 1).lane} if k else set())
                if lanes_a & lanes_b:
                    front, back = sorted((a, b), key=lambda v: -plan.at(v, k).position)
                    gap = plan.at(front, k).position - plan.at(back, k).position
                    closing = plan.at(back, k).speed - plan.at(front, k).speed
                    assert gap >= settings.min_gap - 1e-6, f"{a} and {b} too close at {k}"
                    assert gap >= settings.min_gap + settings.closing_time * closing - 1e-6, (
                        f"{back} closes in on {front} too fast at {k}"
                    )
    # a vehicle changing into a lane at step k leans into it before k (the simulation's lane change
    # is a 3 s move): at k-1 it keeps the gap to the vehicles of that lane and to those entering it
    # at k too, on the side it is at k
    for a in vehicles:
        for k in range(1, plan.horizon + 1):
            if plan.at(a, k).lane == plan.at(a, k - 1).lane:
                continue
            for b in vehicles:
                entering_too = plan.at(b, k).lane == plan.at(a, k).lane != plan.at(b, k - 1).lane
                if b == a or (plan.at(b, k - 1).lane != plan.at(a, k).lane and not entering_too):
                    continue
                ahead = plan.at(a, k).position > plan.at(b, k).position
                front, back = (a, b) if ahead else (b, a)
                gap = plan.at(front, k - 1).position - plan.at(back, k - 1).position
                assert gap >= settings.min_gap - 1e-6, (
                    f"{a} enters the lane of {b} at {k} without the gap at {k - 1} ({gap:.1f} m)"
                )
    check_run(plan, automaton)


@pytest.mark.parametrize(
    "path",
    [
        ROOT / "scenarios" / "overtake.osc",
        ROOT / "scenarios" / "overtake_third_actor.osc",
        ROOT / "scenarios" / "realistic" / "cut_in.osc",
    ],
    ids=lambda p: p.stem,
)
@pytest.mark.parametrize("seed", [1, 2])
def test_a_continuous_plan_obeys_the_limits_the_kinematics_and_the_guards(path, seed):
    automaton = build_automaton(load_scenario(path))
    plan = ContinuousPlanner(automaton, SETTINGS, seed).first()
    check_continuous_plan(plan, automaton)


def test_speeds_are_not_on_a_grid():
    # cut_in asks for speeds in kph: whole m/s would be a coincidence, not a rule
    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "realistic" / "cut_in.osc"))
    plan = ContinuousPlanner(automaton, SETTINGS, 1).first()
    assert any(not float(s.speed).is_integer() for states in plan.states.values() for s in states)


def test_no_horizon_shorter_than_the_durations_allow_is_searched():
    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "realistic" / "follow_then_overtake.osc"))
    import time

    assert ContinuousPlanner(automaton, SETTINGS, 1).earliest_horizon(time.monotonic() + 30) == 24, (
        "10 + 3 + 8 + 3 s at least"
    )


def test_a_plan_without_a_run_up_is_simulated_from_its_first_state_and_can_be_accepted():
    from pytest_roadlogic.monitor import monitor
    from pytest_roadlogic.simulation import simulate

    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "change_lane.osc"))
    plan = ContinuousPlanner(automaton, SETTINGS, 1).first()
    assert plan.runup == 0
    simulation = simulate(plan)
    trace = simulation.trace
    for vehicle, states in plan.states.items():
        assert trace.actors[vehicle]["x"][0] == pytest.approx(states[0].position)
        assert trace.actors[vehicle]["speed"][0] == pytest.approx(states[0].speed), (
            "no standstill start: the scenario's first instant is the simulation's"
        )
    assert monitor(automaton, trace).accepted


def scenario_file(tmp_path, text):
    path = tmp_path / "scenario.osc"
    path.write_text("import osc.standard\n\n" + text)
    return build_automaton(load_scenario(path))


def test_further_plans_differ_in_their_timing_or_lanes_and_each_obeys_every_rule():
    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "overtake.osc"))
    plans = list(ContinuousPlanner(automaton, SETTINGS, 1).plans(limit=4))
    assert len(plans) == 4 and [p.index for p in plans] == [0, 1, 2, 3]
    choices = [(tuple(p.transitions), tuple(s.lane for states in p.states.values() for s in states)) for p in plans]
    assert len(set(choices)) == 4, "no plan repeats the transition times and lanes of one before it"
    for plan in plans:
        check_continuous_plan(plan, automaton)


def test_a_vehicle_stops_when_the_scenario_asks_and_only_that_one(tmp_path):
    automaton = scenario_file(
        tmp_path,
        """scenario stop:
    ego: vehicle
    lead: vehicle

    do serial:
        cruise: parallel(duration: [4s..6s]):
            lead.drive() with:
                lane(1)
                speed([50kph..60kph])
            ego.drive() with:
                lane(same_as: lead)
                position(distance: [30m..40m], behind: lead, at: start)
        halt: parallel(duration: [5s..9s]):
            lead.drive()
            ego.change_speed(target: 0kph)
""",
    )
    assert stopping(automaton, SETTINGS) == {"ego"}
    plan = ContinuousPlanner(automaton, SETTINGS, 1).first()
    check_continuous_plan(plan, automaton)
    assert plan.states["ego"][-1].speed < 1.0, "braked to (nearly) a standstill"
    assert min(s.speed for s in plan.states["lead"]) >= SETTINGS.min_speed, "the lead keeps moving"


def test_a_start_speed_the_scenario_asks_for_is_never_refused_for_a_default(tmp_path):
    # the default start speeds (8-40 m/s) are a preference: 200 kph at the start is 55.6 m/s
    automaton = scenario_file(
        tmp_path,
        """scenario fast:
    ego: vehicle

    do ego.drive(duration: 5s) with:
        speed(200kph, at: start)
""",
    )
    plan = ContinuousPlanner(automaton, SETTINGS, 1).first()
    assert plan.states["ego"][0].speed == pytest.approx(200 / 3.6, abs=1.0)


def test_an_infeasible_timed_scenario_is_refuted_only_over_the_lengths_its_durations_allow():
    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "realistic" / "infeasible_gain.osc"))
    with pytest.raises(UnsatisfiableScenario) as caught:
        ContinuousPlanner(automaton, SETTINGS, 1).first()
    message = str(caught.value)
    assert "any length its durations allow (3 s)" in message, "3 s +- the tolerance: 3 steps of 1 s, no other"
    for line in (13, 16, 17, 18, 10):
        assert f"infeasible_gain.osc:{line}:" in message, f"line {line}'s constraint clashes too: {message}"


def test_farthest_is_the_value_of_a_band_farthest_from_every_earlier_one():
    from pytest_roadlogic.planning.encodings.continuous.preferences import farthest

    assert farthest([0.0], 0.0, 1.0) == 1.0
    assert farthest([0.0, 1.0], 0.0, 1.0) == 0.5
    assert farthest([0.0, 1.0, 0.5], 0.0, 1.0) == 0.25, "the lowest of ties"
    assert farthest([], 8.0, 40.0) == 8.0


def test_each_next_plan_is_steered_to_start_elsewhere_in_the_start_band_and_only_that_plan():
    # the base strategy's plans: without steering, all ten of overtake's started at the band's low end
    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "overtake.osc"))
    plans = list(ContinuousPlanner(automaton, SETTINGS, 1).plans(limit=4))
    # the steered start: the faster of the two cars' (steering moves the start band of the plan,
    # not one named car's speed); the first plan starts at the band's low end
    starts = [max(plan.states[v][0].speed for v in ("v1", "v2")) for plan in plans]
    low, high = SETTINGS.road_speed
    # steered to the band's high end, its middle, its lower quarter (as far as the overtake lets
    # the cars go: v2 holds its speed, and v1 must pass it): a nudge of an earlier plan left on
    # would pull each towards the high end instead
    assert min(plans[0].states[v][0].speed for v in ("v1", "v2")) == pytest.approx(low, abs=0.5)
    # (the lower quarter, 25.7 m/s, is where the first plan's faster car starts already: its slower
    # car, which holds its speed, at the band's low end and 3.5 m/s slower)
    assert starts[1] > starts[2] > starts[3] >= starts[0], f"start speeds {starts}"
    assert starts[2] == pytest.approx(low + 0.5 * (high - low), abs=2.0), f"start speeds {starts}"
    assert all(low - 0.5 <= speed <= high + 0.5 for speed in starts), f"start speeds {starts}"
    for plan in plans:
        check_continuous_plan(plan, automaton)


def test_a_random_start_draws_different_plans_from_different_seeds():
    import dataclasses

    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "overtake.osc"))
    settings = dataclasses.replace(SETTINGS, random_start=True)
    starts = {
        tuple(
            round(states[0].speed, 3) for states in ContinuousPlanner(automaton, settings, seed).first().states.values()
        )
        for seed in range(1, 6)
    }
    assert len(starts) >= 4
    again = ContinuousPlanner(automaton, settings, 3).first()
    assert again.states == ContinuousPlanner(automaton, settings, 3).first().states, "one seed, one plan"


def test_a_random_start_keeps_each_free_vehicles_drawn_acceleration_within_the_drift_speeds(tmp_path):
    """The refined strategy's vehicles asked for a speed range do not all cruise at their start
    speed: each accelerates at its drawn -2, 0 or +2 m/s^2 (as the grid planner's do) until it
    reaches the drift's speeds. (A vehicle asked for no speed holds its speed: least action.)"""
    automaton = scenario_file(
        tmp_path,
        """scenario free:
    ego: vehicle

    do ego.drive(duration: 12s) with:
        speed([1mps..60mps])
""",
    )
    settings = dataclasses.replace(SETTINGS, random_start=True)
    slow, fast = settings.drift_speeds
    seen = set()
    for seed in range(1, 10):
        planner = ContinuousPlanner(automaton, settings, seed)
        plan = planner.first()
        check_continuous_plan(plan, automaton)
        (aim,) = [
            float(line.split(",")[1].rstrip(").").strip('"'))
            for line in planner.preferences.splitlines()
            if line.startswith("drift(")
        ]
        seen.add(aim)
        speeds = [state.speed for state in plan.states["ego"]]
        start, steps = speeds[0], len(speeds) - 1
        expected = min(max(start + aim * steps, slow), fast) if aim else start
        assert speeds[-1] == pytest.approx(expected, abs=0.6), (
            f"seed {seed}, drawn {aim:+g} m/s^2: speeds {[round(v, 1) for v in speeds]}"
        )
        assert all(min(slow, start) - 1e-6 <= v <= max(fast, start) + 1e-6 for v in speeds), (
            f"seed {seed}: left the drift's speeds {speeds}"
        )
    assert seen == {-settings.drift, 0.0, settings.drift}, "each of the three accelerations drawn in nine seeds"


def test_a_random_start_meets_a_guard_that_pins_a_vehicle_to_a_place_as_early_as_it_can():
    """dodge_obstacle's end pins the ego 5-20 m past a parked car. Tried late, as every free guard
    is, it was met at the last step of a plan stretched to its drawn length, and the ego crawled
    towards the car all the way; a random start meets it at the first step it can, as the
    shortest plan does, and the ego drives on for the rest of the plan. Guards between two driving
    vehicles (follow's end gap) pin nobody and keep the solver's order."""
    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "dodge_obstacle.osc"))
    earliest = ContinuousPlanner(automaton, SETTINGS, 1).first().transitions[-1][0]
    settings = dataclasses.replace(SETTINGS, random_start=True)
    stretched = 0
    for seed in range(1, 7):
        plan = ContinuousPlanner(automaton, settings, seed).first()
        check_continuous_plan(plan, automaton)
        assert plan.transitions[-1][0] == earliest, (
            f"seed {seed}: the dodge ended at step {plan.transitions[-1][0]}, not at the earliest, {earliest}"
        )
        stretched += plan.horizon > earliest
    assert stretched, "some of the plans last longer than the dodge (the ego drives on after it)"
    follow = build_automaton(load_scenario(ROOT / "scenarios" / "follow.osc"))
    assert "fire(" not in ContinuousPlanner(follow, settings, 1).preferences


@pytest.mark.slow  # clingo-lpx, kept to compare, searches for minutes on two busy cores
def test_the_clingo_lpx_theory_plans_a_random_start_too():
    # kept selectable to compare: it has no preferences, so a random start's nudges must not reach it
    import dataclasses

    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "overtake.osc"))
    # its search takes 33 s alone on this machine (the same at 77dc271): a limit of 60 s ran out when
    # two test workers and another run shared the two cores; what is tested is that it plans at all
    lpx = dataclasses.replace(SETTINGS, theory="lpx", random_start=True, time_limit=max(SETTINGS.time_limit, 300.0))
    plan = ContinuousPlanner(automaton, lpx, 1).first()
    check_continuous_plan(plan, automaton)


@pytest.mark.parametrize("encoding", ["continuous", "grid"])
def test_the_time_a_caller_spends_with_a_plan_is_not_the_next_plans_planning_time(encoding, monkeypatch):
    """Between two plans the caller simulates the first; the next plan still has the whole time
    limit (five_vehicle_minute's second plan once timed out after its first plan's simulation).
    The caller's time is a jump of the clock past the limit, not a sleep against a tight limit: on
    a loaded machine a 1 s limit ran out in the planning itself. The limit, 30 s, guards a hang."""
    import time

    from pytest_roadlogic.planning import GridPlanner, GridSettings

    automaton = build_automaton(load_scenario(ROOT / "scenarios" / "overtake.osc"))
    planner = (
        ContinuousPlanner(automaton, ContinuousSettings(time_limit=30.0), 1)
        if encoding == "continuous"
        else GridPlanner(automaton, GridSettings(time_limit=30.0), 1)
    )
    plans = planner.plans()
    first = next(plans)
    clock = time.monotonic
    monkeypatch.setattr(time, "monotonic", lambda: clock() + 31.0)  # the caller simulated for 31 s
    second = next(plans)
    assert (second.transitions, second.states) != (first.transitions, first.states)


def test_a_speed_range_a_phase_holds_is_reached_a_step_before_the_phase_and_kept_a_step_after(tmp_path):
    """The motion planner rounds off the plan's changes of speed (late in, early out), so the plan
    prefers each speed bound to hold one step either side of the steps it must hold at, where the
    hard constraints let it."""
    automaton = scenario_file(
        tmp_path,
        """scenario speed_up:
    ego: vehicle

    do serial:
        slow: ego.drive(duration: 4s) with:
            speed([40kph..45kph])
        free: ego.drive(duration: 6s)
        fast: ego.drive(duration: 4s) with:
            speed([80kph..85kph])
""",
    )
    plan = ContinuousPlanner(automaton, SETTINGS, 1).first()
    check_continuous_plan(plan, automaton)
    fast_starts = max(step for step, _ in plan.transitions[:-1])  # the last transition ends the scenario
    slow_ends = sorted(step for step, _ in plan.transitions)[1]
    speeds = [s.speed for s in plan.states["ego"]]
    assert 80 / 3.6 - 0.01 <= speeds[fast_starts - 1] <= 85 / 3.6 + 0.01, (
        f"fast's range already at the step before it ({speeds})"
    )
    assert 40 / 3.6 - 0.01 <= speeds[slow_ends] <= 45 / 3.6 + 0.01, (
        f"slow's range still at the step after it ({speeds})"
    )


def test_a_time_headway_is_planned_as_a_gap_over_the_followers_speed():
    """position(time: [1.5s..2.5s], behind: lead) held throughout cruise, and 1 s (+- 0.2 s) at the
    end of close_in: at every step of the plan the gap over the follower's speed is in range."""
    automaton = build_automaton(load_scenario(ROOT / "tests" / "corpus" / "46_time_headway.osc"))
    for seed in (1, 2):
        plan = ContinuousPlanner(automaton, SETTINGS, seed).first()
        check_continuous_plan(plan, automaton)
        cruise_ends, close_in_ends = sorted(step for step, _ in plan.transitions)[1:3]
        lead, ego = plan.states["lead"], plan.states["ego"]
        headways = [(lead[k].position - ego[k].position) / ego[k].speed for k in range(len(ego))]
        assert all(1.5 - 1e-6 <= h <= 2.5 + 1e-6 for h in headways[:cruise_ends]), headways
        assert 0.8 - 1e-6 <= headways[close_in_ends] <= 1.2 + 1e-6, headways


def test_the_grid_encoding_refuses_a_time_headway_at_its_place():
    from pytest_roadlogic.frontend import OscError
    from pytest_roadlogic.planning import GridPlanner, GridSettings

    automaton = build_automaton(load_scenario(ROOT / "tests" / "corpus" / "46_time_headway.osc"))
    with pytest.raises(OscError) as raised:
        GridPlanner(automaton, GridSettings(), 1).first()
    report = raised.value.report()
    assert "46_time_headway.osc:15:" in report and "continuous" in report, report


# 3 s and 4 s one after the other beside 9 s, all ending together: the durations clash whatever
# the speed bound (line 8)
CLASHING_DURATIONS = (
    "scenario s:\n  a: car\n  b: car\n  do parallel(overlap: equal):\n"
    "    serial:\n      a.drive(duration: 3s)\n      a.drive(duration: 4s) with:\n        speed([10mps..20mps])\n"
    "    b.drive(duration: 9s)\n"
)


def test_durations_that_clash_at_every_length_are_not_blamed_on_the_horizon_limit():
    from pytest_roadlogic.frontend import check_text
    from pytest_roadlogic.planning import HorizonTooShort, NoPlanError

    automaton = build_automaton(check_text(CLASHING_DURATIONS).scenarios[0])
    settings = dataclasses.replace(SETTINGS, explain_unsatisfiable=False)
    with pytest.raises(NoPlanError) as caught:
        next(ContinuousPlanner(automaton, settings, 1).plans())
    assert not isinstance(caught.value, HorizonTooShort), str(caught.value)
    assert "durations cannot all hold at any length" in str(caught.value)


def test_durations_that_clash_among_themselves_are_named_at_their_lines():
    # the diagnosis had solved no horizon and named nothing (emit_wait_brake's 6.8 s brake, which
    # must equal its wait plus its lane change, at most 6.5 s)
    from pytest_roadlogic.frontend import check_text

    automaton = build_automaton(check_text(CLASHING_DURATIONS).scenarios[0])
    with pytest.raises(UnsatisfiableScenario) as caught:
        next(ContinuousPlanner(automaton, SETTINGS, 1).plans())
    (group,) = caught.value.conflicts
    assert sorted(member.source.line for member in group) == [6, 7, 9], "the three durations, not the speed bound"


def test_a_gap_in_one_lane_that_the_scenario_asks_closer_than_the_tools_spacing_is_planned_at_once():
    """follow_close ends the tail 5-15 m behind the lead in its lane; the tool keeps 8 m between
    centres. A sample of 6 m had no plan until the fallbacks relaxed the gap, after searches that
    each proved there was none: now the first planner plans it, with the gap the file asks for,
    and a scenario asking for no close gap keeps the tool's (its plans are unchanged)."""
    from pytest_roadlogic.planning import planner_for, settings_for
    from pytest_roadlogic.planning.encodings.continuous.instance import spacing
    from pytest_roadlogic.problem import problem_for
    from pytest_roadlogic.settings import RunSettings

    scenario = load_scenario(Path(__file__).resolve().parents[2] / "benchmarks" / "scenarios" / "follow_close.osc")
    specification = build_automaton(scenario)
    settings = settings_for(RunSettings(), explain_unsatisfiable=False)
    assert spacing(specification, settings) == settings.min_gap, "the range 5-15 m holds gaps of 8 m"
    values = {"start_gap": 20.0, "end_gap": 6.0, "lead_speed": 10.0}
    problem = problem_for(scenario, values, settings, 1)
    guide, guided, seed = problem.guide, problem.settings, problem.seed
    assert 5.0 <= spacing(guide(guided), guided) < settings.min_gap
    plan = next(planner_for(guide(guided), guided, seed).plans(limit=1))
    gap = plan.states["lead"][-1].position - plan.states["tail"][-1].position
    assert 5.0 <= gap < settings.min_gap, gap
    assert plan.states["lead"][-1].lane == plan.states["tail"][-1].lane


def test_a_conflict_with_a_phases_mean_acceleration_is_explained_naming_it_not_a_traceback():
    # lead_brake at a sample whose lead must lose 9.2 m/s in a 4.1 s phase braking at most 6 m/s^2
    # within the planner's jerk: the explanation named every constraint but this one's kind, and
    # raised AttributeError instead (found by benchmarks/roads.py)
    from pytest_roadlogic.pipeline import run_instances
    from pytest_roadlogic.planning import NoPlanError

    scenario = load_scenario(ROOT / "scenarios" / "realistic" / "lead_brake.osc")
    values = {
        "headway": 1.9,
        "initial": 19.9,
        "follow.duration": 8.2,
        "brake.duration": 4.1,
        "lead.change_speed.target": 10.7,
    }
    with pytest.raises(NoPlanError) as caught:
        next(run_instances(scenario, 1, seed=1, values=values, max_tries=1))
    assert "mean acceleration of lead over lead.change_speed in -6..-3 m/s^2" in str(caught.value)


def test_a_planner_grounds_the_encodings_extensions_only_for_a_scenario_that_uses_them(tmp_path):
    from pytest_roadlogic.planning.encodings.continuous.planner import BACKGROUND, REPLAN, ROUTE, TOWARD

    def files(text: str, dialect: str | None = None) -> tuple:
        path = tmp_path / "scenario.osc"
        path.write_text(text)
        return ContinuousPlanner(build_automaton(load_scenario(path, dialect=dialect)), SETTINGS, 1).encoding_files()

    drive = "scenario s:\n    car1: car\n    do car1.drive() with:\n        speed(20kph)\n"
    assert files(drive) == BACKGROUND
    # CARLA's speed(v): a target driven toward from the phase's start
    assert files(drive, "carla") == (*BACKGROUND, TOWARD)
    path = tmp_path / "scenario.osc"
    planner = ContinuousPlanner(build_automaton(load_scenario(path)), SETTINGS, 1)
    planner.past = "now(2)."  # a replan's past
    assert planner.encoding_files() == (*BACKGROUND, REPLAN)
    rural = ROOT / "scenarios" / "roads" / "overtake_rural.osc"
    scenario = load_scenario(rural)
    on_route = SETTINGS.on_route(scenario.route, scenario.routes[1:])
    assert ContinuousPlanner(build_automaton(scenario), on_route, 1).encoding_files() == (*BACKGROUND, ROUTE)
