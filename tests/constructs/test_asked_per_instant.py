"""What a vehicle is asked, per vehicle and per instant (docs/language.md, "What a vehicle is asked
to do"), read on the first plan of files written as public files are written: a value asked
`at: start` is met at the first instant and then kept, a relative lane is the adjacent lane, a
vehicle placed relative to itself is refused at check, and what the simulation does not model is
read with a warning."""

from __future__ import annotations

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.evaluation.fidelity import unasked_changes
from pytest_roadlogic.frontend import OscError, check_text
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings
from tests.planning.test_planning_continuous import check_continuous_plan

SETTINGS = ContinuousSettings(time_limit=30.0)  # guards a hang only


def automaton_of(tmp_path, text: str, dialect: str | None = None):
    """The automaton of a scenario written as ``text`` in a file, read in ``dialect``."""
    path = tmp_path / "scenario.osc"
    path.write_text(text)
    return build_automaton(load_scenario(path, dialect=dialect))


def planned(tmp_path, text: str, dialect: str | None = None, seed: int = 1):
    """The first plan of a scenario written as ``text``, its automaton and its planner (its stats)."""
    automaton = automaton_of(tmp_path, text, dialect)
    planner = ContinuousPlanner(automaton, SETTINGS, seed)
    return planner.first(), automaton, planner


def first_plan(tmp_path, text: str):
    plan, _, planner = planned(tmp_path, text)
    assert planner.stats["least_action"] == 1.0, "planned with only asked changes"
    return plan


OVERTAKE_AND_RETURN = """scenario overtake_and_return:
    ego: car
    npc: car
    do serial:
        pull_out: parallel(duration: 4s):
            npc.drive() with:
                lane(1, at: start)
                speed(20mps, at: start)
            ego.drive() with:
                lane(same_as: npc, at: start)
                position(20m, behind: npc, at: start)
                lane(left_of: npc, at: end)
        pass_by: parallel(duration: [4s..8s]):
            npc.drive()
            ego.drive() with:
                position(10m, ahead_of: npc, at: end)
                lane(same_as: npc, at: end)
"""


def test_a_lane_asked_at_start_is_asked_at_that_instant_and_one_asked_at_end_within_the_phase(tmp_path):
    automaton = automaton_of(tmp_path, OVERTAKE_AND_RETURN)
    init, pull_out, pass_by, _ = automaton.locations  # named after their invocations, in this order
    # the npc's lane(1, at: start) asks for its lane at the first instant only: within the phase
    # it keeps its lane (it had licensed the npc to move into the ego's lane)
    assert not pull_out.asked("npc", "lane") and not pass_by.asked("npc", "lane")
    assert init.asked("npc", "lane"), "reached before the phase (where the scenario starts: no change)"
    # the ego's lane(left_of: npc, at: end) asks for a lane change within the phase, and so does
    # the return; the reference vehicle of a relation is never asked
    assert pull_out.asked("ego", "lane") and pass_by.asked("ego", "lane")
    # so is a speed asked at start: met at the first instant, then held
    assert init.asked("npc", "speed") and not pull_out.asked("npc", "speed")


def test_the_car_being_overtaken_keeps_its_lane_in_the_first_plan(tmp_path):
    plan = first_plan(tmp_path, OVERTAKE_AND_RETURN)
    assert len({state.lane for state in plan.states["npc"]}) == 1, "the npc changed lane unasked"
    lanes = [state.lane for state in plan.states["ego"]]
    assert lanes[0] == lanes[-1] == plan.states["npc"][0].lane and len(set(lanes)) == 2, lanes


@pytest.mark.parametrize("side, offset", [("right_of", 1), ("left_of", -1)])
def test_a_lane_beside_another_car_is_the_adjacent_lane(tmp_path, side, offset):
    plan = first_plan(
        tmp_path,
        "scenario beside:\n    ego: car\n    npc: car\n    path: Path\n    path.path_min_driving_lanes(4)\n"
        "    do parallel(duration: 3s):\n        ego.drive() with:\n            lane(2, at: start)\n"
        f"        npc.drive() with:\n            lane({side}: ego, at: start)\n",
    )
    # internally lane 0 is the leftmost: the lane right of ego's has the next number
    assert plan.states["npc"][0].lane - plan.states["ego"][0].lane == offset


def test_a_lane_count_beside_another_car_counts_the_lanes_to_that_side(tmp_path):
    plan = first_plan(
        tmp_path,
        "scenario two_over:\n    ego: car\n    npc: car\n    path: Path\n    path.path_min_driving_lanes(4)\n"
        "    do parallel(duration: 3s):\n        ego.drive() with:\n            lane(1, at: start)\n"
        "        npc.drive() with:\n            lane(2, left_of: ego, at: start)\n",
    )
    assert plan.states["ego"][0].lane - plan.states["npc"][0].lane == 2


def test_a_vehicle_placed_relative_to_itself_is_refused_at_check():
    text = "scenario s:\n    ego: car\n    do ego.drive(duration: 3s) with:\n        lane(right_of: ego)\n"
    with pytest.raises(OscError) as refused:
        check_text(text, "s.osc").raise_for_errors()
    assert "s.osc:4:14: error: lane() places 'ego' relative to itself (right_of: ego)" in str(refused.value)


@pytest.mark.parametrize("modifier", ["yaw(0rad, at: start)", "orientation(yaw: 0rad)", 'physical_movement("simple")'])
def test_a_modifier_the_simulation_does_not_model_is_read_with_one_located_warning(modifier):
    text = (
        f"scenario s:\n    ego: car\n    do ego.drive(duration: 3s) with:\n        speed(20kph)\n        {modifier}\n"
    )
    checked = check_text(text, "s.osc")
    checked.raise_for_errors()
    warnings = [d for d in checked.diagnostics if d.severity == "warning"]
    assert len(warnings) == 1 and warnings[0].location.line == 5
    assert "is read but not simulated" in warnings[0].message
    build_automaton(checked.scenarios[0])


def test_a_namespace_statement_is_read_as_the_runs_one_namespace():
    text = "namespace demo use std\nscenario s:\n    ego: car\n    do ego.drive(duration: 3s)\n"
    check_text(text, "s.osc").raise_for_errors()


def test_a_run_whose_plan_needs_an_unasked_change_says_which_vehicle_did_what_in_the_files_lanes(tmp_path, capsys):
    from pytest_roadlogic import cli

    (tmp_path / "s.osc").write_text(
        "scenario join:\n    ego: car\n    npc: car\n    do parallel(duration: 6s):\n"
        "        ego.drive() with:\n            lane(1, at: start)\n            keep_lane()\n"
        "            lane(same_as: npc, at: end)\n"
        "        npc.drive() with:\n            lane(2, at: start)\n            position(40m, ahead_of: ego, at: start)\n"
    )
    cli.main(["run", str(tmp_path / "s.osc"), "--seed", "1", "--out", str(tmp_path / "out")])
    said = capsys.readouterr().out
    assert (
        "no plan has every vehicle do only what it is asked; this one has the fewest changes nothing asks for:" in said
    )
    assert "npc changes from lane 2 to 1 at step" in said, said


FOLLOW_THEN_OVERTAKE_EXACT = """scenario follow_then_overtake_exact:
    ego: car
    slow: car
    do serial:
        follow: parallel(duration: 12s):
            slow.drive() with:
                lane(1)
                speed(70kph)
            ego.drive() with:
                lane(same_as: slow)
                position(distance: 30m, behind: slow, at: start)
                speed(72kph)
        pull_out: parallel(duration: 4s):
            slow.drive() with:
                keep_lane()
            ego.change_lane(num_of_lanes: 1, side: left)
        pass_by: parallel(duration: 12s):
            slow.drive() with:
                keep_lane()
            ego.drive() with:
                keep_lane()
                speed(95kph)
                position(distance: 20m, ahead_of: slow, at: end)
        cut_back: parallel(duration: 4s):
            slow.drive()
            ego.change_lane(num_of_lanes: 1, side: right)
"""


@pytest.mark.parametrize("seed", [1, 6])
def test_when_no_plan_keeps_to_what_is_asked_one_vehicle_makes_the_fewest_and_smallest_changes(tmp_path, seed):
    # exact values no natural plan meets: held at 95 kph for 12 s the ego ends about 60 m ahead,
    # not 20 m, so someone must do what nothing asks. Dropping least action altogether, the slow
    # car had sped up unasked for 8 steps, to 128 kph
    plan, automaton, planner = planned(tmp_path, FOLLOW_THEN_OVERTAKE_EXACT, seed=seed)
    assert planner.stats["least_action"] == 0.0
    changes = unasked_changes(plan, automaton)  # measured independently of the encoding
    assert changes and {change.vehicle for change in changes} == {"slow"}, changes
    assert all(change.kind == "speed" for change in changes), changes
    assert len(changes) <= 3, changes
    assert max(abs(c.after - c.before) for c in changes) <= 2.5, changes  # a comfortable rate, m/s per 1 s step
    assert max(state.speed for state in plan.states["slow"]) < 90 / 3.6, "kept smallest"


def test_the_fewest_unasked_changes_found_beside_the_search_for_asked_ones_are_those_it_finds_alone(tmp_path):
    # the search with only asked changes asks, at each horizon, whether the one that allows
    # unasked changes has a plan there, and that one then steps over the horizons known empty:
    # its first plan is at the horizon a search of its own finds, with the same changes in count
    # and vehicle, and the plans after it differ from it
    automaton = automaton_of(tmp_path, FOLLOW_THEN_OVERTAKE_EXACT)
    planner = ContinuousPlanner(automaton, SETTINGS, 1)
    plans = list(planner.plans(limit=3))
    assert planner.stats["least_action"] == 0.0
    alone = ContinuousPlanner(automaton, SETTINGS, 1)
    alone.least_action, alone.least_change = True, True
    first_alone = next(alone._search(limit=1))
    assert plans[0].horizon == first_alone.horizon
    changes, changes_alone = unasked_changes(plans[0], automaton), unasked_changes(first_alone, automaton)
    assert {c.vehicle for c in changes} == {c.vehicle for c in changes_alone} == {"slow"}
    assert len(changes) == len(changes_alone), (changes, changes_alone)
    assert len(plans) == 3
    runs = {(tuple(plan.transitions), tuple(s.lane for v in plan.vehicles for s in plan.states[v])) for plan in plans}
    assert len(runs) == 3, "a plan came twice"
    for plan in plans:
        check_continuous_plan(plan, automaton)
        assert unasked_changes(plan, automaton), "a later plan with only asked changes: the first search missed it"


# the same follow-then-overtake with exact values, its pass 6 s at 90 kph: short of the gain
SHORT_OF_THE_GAIN = (
    FOLLOW_THEN_OVERTAKE_EXACT.replace("follow: parallel(duration: 12s)", "follow: parallel(duration: 10s)")
    .replace("speed(72kph)", "speed(70kph)")
    .replace("pass_by: parallel(duration: 12s)", "pass_by: parallel(duration: 6s)")
    .replace("speed(95kph)", "speed(90kph)")
)


def test_an_overtaker_short_of_the_gain_speeds_up_in_its_pull_out_and_the_slow_car_does_nothing_unasked(tmp_path):
    # exact values: 6 s at 20 kph faster gain 33 m of the 50 needed, the rest is the ego's to
    # gain while it pulls out (the pass asks its speed from its first instant, so the speed-up
    # there is asked), not the slow car braking from 70 to 20 kph and changing lane
    assert SHORT_OF_THE_GAIN.count("duration: 6s") == 1 and "speed(90kph)" in SHORT_OF_THE_GAIN
    plan, automaton, planner = planned(tmp_path, SHORT_OF_THE_GAIN)
    assert planner.stats["least_action"] == 1.0, "planned with only asked changes"
    assert unasked_changes(plan, automaton) == []
    slow = plan.states["slow"]
    assert len({state.lane for state in slow}) == 1
    assert max(s.speed for s in slow) - min(s.speed for s in slow) < 0.5, [round(s.speed, 1) for s in slow]
    pull_out = [state.speed for state in plan.states["ego"][10:15]]
    assert pull_out[-1] - pull_out[0] > 5.0, "the ego speeds up while it pulls out"


def test_a_parallel_members_start_is_asked_once_not_again_at_every_junction_of_another_member(tmp_path):
    # written as CARLA's overtake example is: the npc's lane(2, at: start) had been asked again
    # before each of the ego's later phases, and the npc left its lane so that the ego had not to
    text = (
        "scenario overtake_in_parallel:\n    ego: car\n    npc: car\n"
        "    do parallel(duration: 18s):\n"
        "        npc.drive() with:\n            speed(30kph)\n            lane(2, at: start)\n"
        "        serial:\n"
        "            get_ahead: parallel(duration: 3s):\n"
        "                ego.drive() with:\n                    speed(30kph)\n"
        "                    lane(same_as: npc, at: start)\n"
        "                    position([10m..20m], behind: npc, at: start)\n"
        "            change_lane1: parallel(duration: 5s):\n"
        "                ego.drive() with:\n                    lane(left_of: npc, at: end)\n"
        "            accelerate: parallel(duration: 5s):\n"
        "                ego.drive() with:\n                    speed(45kph)\n"
        "            change_lane2: parallel(duration: 5s):\n"
        "                ego.drive() with:\n                    lane(same_as: npc, at: end)\n"
    )
    plan, automaton, planner = planned(tmp_path, text)
    assert [loc.asked("npc", "lane") for loc in automaton.locations] == [True] + [False] * (
        len(automaton.locations) - 1
    )
    assert planner.stats["least_action"] == 1.0, "planned with only asked changes"
    assert len({state.lane for state in plan.states["npc"]}) == 1, "the npc left its lane"
    assert len({state.lane for state in plan.states["ego"]}) == 2


def test_beside_a_car_asked_to_drive_slowly_an_open_start_speed_is_held_not_braked_off_all_phase(tmp_path):
    # written as CARLA's cut-in examples are: the ego at 20 kph, the npc asked only where it is at
    # the phase's ends; a start-speed floor of 29 kph (the tool's "no crawl") had made the npc start
    # faster than needed and brake through the whole 30 s phase, a change nothing asks for
    text = (
        "scenario slow_cut_in:\n    ego: car\n    npc: car\n"
        "    do parallel(duration: 30s):\n"
        "        ego.drive() with:\n            speed(20kph)\n            lane(1, at: start)\n"
        "        npc.drive() with:\n"
        "            lane(right_of: ego, at: start)\n"
        "            position(5m, behind: ego, at: start)\n"
        "            position(20m, ahead_of: ego, at: end)\n"
    )
    plan, _, _ = planned(tmp_path, text, dialect="carla")
    speeds = [state.speed * 3.6 for state in plan.states["npc"]]
    assert max(speeds) - min(speeds) < 1.0, [round(s, 1) for s in speeds]  # one speed, about 23 kph
    assert 22.0 < speeds[0] < 25.0, speeds[0]


# a lead braking from 50 kph to a stop 30 m ahead of a car asked nothing in that phase: with no
# vehicle under test to brake for itself, no plan keeps the follower to what it is asked, at any
# horizon
BRAKING_AHEAD_OF_A_CAR_ASKED_NOTHING = """scenario braking_ahead:
    lead: car
    follower: car

    do serial:
        follow: parallel(duration: 2s):
            follower.drive() with:
                lane(2, at: start)
                speed(50kph, at: start)
            lead.drive() with:
                lane(same_as: follower, at: start)
                position(distance: 30m, ahead_of: follower, at: start)
                speed(50kph)
        brake: parallel:
            follower.drive()
            lead.change_speed(target: 0kph, rate_profile: linear, rate_peak: 4mpss)
        stand: parallel(duration: [3s..4s]):
            follower.drive()
            lead.drive() with:
                speed(0kph)
"""


def test_a_car_asked_nothing_brakes_to_a_stop_behind_a_lead_that_stops_and_keeps_its_lane(tmp_path):
    plan, automaton, planner = planned(tmp_path, BRAKING_AHEAD_OF_A_CAR_ASKED_NOTHING)
    assert planner.stats["least_action"] == 1.0, "planned with only asked changes"
    assert unasked_changes(plan, automaton) == []  # measured independently of the encoding
    check_continuous_plan(plan, automaton, SETTINGS)
    follower = plan.states["follower"]
    assert len({state.lane for state in follower}) == 1, "the follower changed lane unasked"
    assert follower[-1].speed < SETTINGS.min_speed, "queued behind the stopped lead"
    speeds = [state.speed for state in follower]
    assert all(later <= earlier + 1e-6 for earlier, later in zip(speeds, speeds[1:])), "it only brakes"


# the follower's speed asked over the first phase: it brakes only once the lead does, too late
# for its gentle braking to stop behind it
BRAKING_HARD_AHEAD_OF_A_CAR_ASKED_NOTHING = (
    BRAKING_AHEAD_OF_A_CAR_ASKED_NOTHING.replace("speed(50kph, at: start)", "speed(50kph)")
    .replace("distance: 30m", "distance: 15m")
    .replace("rate_peak: 4mpss", "rate_peak: 8mpss")
)


def test_a_search_for_only_asked_changes_gives_up_after_its_horizons_and_the_fewest_unasked_changes_are_planned(
    tmp_path,
):
    from pytest_roadlogic.planning import NoPlanError
    from pytest_roadlogic.planning.encodings.continuous.planner import LEAST_ACTION_HORIZONS

    automaton = automaton_of(tmp_path, BRAKING_HARD_AHEAD_OF_A_CAR_ASKED_NOTHING)
    asked_only = ContinuousPlanner(automaton, SETTINGS, 1)
    asked_only.least_action, asked_only.least_change = True, False
    with pytest.raises(NoPlanError, match=f"and {LEAST_ACTION_HORIZONS} horizons"):
        next(asked_only._search(limit=1))
    plan, _, planner = planned(tmp_path, BRAKING_HARD_AHEAD_OF_A_CAR_ASKED_NOTHING)
    assert planner.stats["least_action"] == 0.0
    changes = unasked_changes(plan, automaton)  # measured independently of the encoding
    assert [(change.vehicle, change.kind) for change in changes] == [("follower", "lane")], changes
