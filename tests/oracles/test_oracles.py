"""The oracles and the reference vehicles under test, checked against their definitions.

The measures are recomputed here sample by sample, from the definitions in docs/vehicle-under-test.md
(bumper-to-bumper gap, time to collision as the gap over the closing speed, a vehicle in the path when
clear ahead and overlapping across), independently of the package's vectorised code."""

from __future__ import annotations

import math
import random

import numpy as np
import pytest

from pytest_roadlogic.dimensions import CAR_LENGTH, CAR_WIDTH
from pytest_roadlogic.dut import AUTO, NONE, NoSuchVehicle, UnderTest
from pytest_roadlogic.dut.reference_drivers import AdaptiveCruiseControl, LateAcc, SlowAcquisitionAcc, WeakBrakingAcc
from pytest_roadlogic.oracles import Thresholds, judge
from pytest_roadlogic.simulation.driver import Trajectory, VehicleState
from pytest_roadlogic.simulation.trace import Incident, Trace

DT = 0.1


def trace_of(columns: dict[str, dict[str, list[float]]], incidents=()) -> Trace:
    n = len(next(iter(columns.values()))["x"])
    actors = {}
    for name, c in columns.items():
        actors[name] = {
            "x": np.array(c["x"], float),
            "y": np.array(c.get("y", [0.0] * n), float),
            "heading": np.zeros(n),
            "speed": np.array(c.get("speed", [0.0] * n), float),
            "acceleration": np.array(c.get("acceleration", [0.0] * n), float),
            "lane": np.zeros(n, int),
        }
    return Trace(np.round(np.arange(n) * DT, 6), actors, list(incidents))


def brute_force(trace: Trace, me: str, reaction: float):
    """(least gap, least time to collision, least time headway) by the definitions, one sample and
    one vehicle at a time."""
    gaps, ttcs, headways = [math.inf], [math.inf], [math.inf]
    for other in trace.names:
        if other == me:
            continue
        entered = None
        for k, t in enumerate(trace.times):
            a, b = trace.actors[me], trace.actors[other]
            dx, dy = b["x"][k] - a["x"][k], b["y"][k] - a["y"][k]
            if not (dx >= CAR_LENGTH and abs(dy) < CAR_WIDTH):
                entered = None
                continue
            entered = t if entered is None else entered
            if t - entered < reaction - 1e-9:
                continue
            gap = dx - CAR_LENGTH
            gaps.append(gap)
            closing = a["speed"][k] - b["speed"][k]
            if closing > 1e-6:
                ttcs.append(gap / closing)
                headways.append(gap / a["speed"][k])  # judged while it closes in
    return min(gaps), min(ttcs), min(headways)


@pytest.mark.parametrize("seed", range(30))
def test_gap_time_to_collision_and_time_headway_are_those_of_the_definition_on_random_traffic(seed):
    draw = random.Random(seed)
    n = 60
    columns = {}
    for name in ("dut", "a", "b"):
        x0, v, y = draw.uniform(0, 60), draw.uniform(5, 30), draw.choice([1.75, 5.25, 3.5 + draw.uniform(-1, 1)])
        a = draw.uniform(-3, 2)
        speed = [max(0.0, v + a * k * DT) for k in range(n)]
        x = list(np.cumsum([x0] + [s * DT for s in speed[:-1]]))
        columns[name] = {"x": x, "y": [y] * n, "speed": speed}
    trace = trace_of(columns)
    report = judge(trace, "dut", Thresholds())
    gap, ttc, headway = brute_force(trace, "dut", Thresholds().reaction_time)
    assert (
        report.measured["gap"].value == pytest.approx(gap)
        if math.isfinite(gap)
        else report.measured["gap"].value == math.inf
    )
    assert (
        report.measured["time_to_collision"].value == pytest.approx(ttc)
        if math.isfinite(ttc)
        else not math.isfinite(report.measured["time_to_collision"].value)
    )
    least_headway = report.measured["time_headway"].value
    assert least_headway == pytest.approx(headway) if math.isfinite(headway) else least_headway == math.inf


def test_a_car_that_cuts_in_close_is_judged_only_after_the_reaction_time():
    # the npc enters the dut's lane 3 m ahead at t=1 s, and drives away: no failure of the dut
    n = 40
    x_dut = [20.0 * k * DT for k in range(n)]
    x_npc = [x + CAR_LENGTH + 3.0 + 0.5 * k * DT for k, x in enumerate(x_dut)]
    y_npc = [3.5 if k < 10 else 0.0 for k in range(n)]
    trace = trace_of({"dut": {"x": x_dut, "speed": [20.0] * n}, "npc": {"x": x_npc, "y": y_npc, "speed": [20.5] * n}})
    report = judge(trace, "dut")
    assert report.measured["gap"].value == pytest.approx(3.0 + 0.5 * 2.0)  # from t = 2 s, a second after it cut in
    assert not report.failed


def test_running_into_the_car_ahead_is_the_vehicle_under_tests_failure_and_being_hit_from_behind_is_not():
    n = 20
    ahead = trace_of({"dut": {"x": [0.0] * n}, "npc": {"x": [4.0] * n}}, [Incident(1.0, "collision", ("dut", "npc"))])
    behind = trace_of({"dut": {"x": [4.0] * n}, "npc": {"x": [0.0] * n}}, [Incident(1.0, "collision", ("npc", "dut"))])
    rammed = judge(ahead, "dut")
    assert rammed.failed and rammed.collisions[0].caused and "dut ran into npc ahead" in rammed.failures[0]
    hit = judge(behind, "dut")
    assert not hit.failed and hit.hit_by_others and "npc ran into dut from behind" in hit.collisions[0].how


def test_a_side_collision_is_caused_by_the_one_that_moved_across():
    n = 20
    npc_moves = trace_of(
        {"dut": {"x": [0.0] * n, "y": [0.0] * n}, "npc": {"x": [1.0] * n, "y": [3.5 - 0.15 * k for k in range(n)]}},
        [Incident(1.2, "collision", ("dut", "npc"))],  # first contact: 1.7 m apart across, 1 m along
    )
    report = judge(npc_moves, "dut")
    assert not report.collisions[0].caused and "npc moved into dut from its left" == report.collisions[0].how


def test_braking_harder_than_the_threshold_fails_and_the_margin_says_how_close_each_oracle_was():
    n = 10
    hard = trace_of({"dut": {"x": list(range(n)), "acceleration": [0, 0, -7.5, -7.5, 0, 0, 0, 0, 0, 0]}})
    report = judge(hard, "dut", Thresholds.given(deceleration=7.0))
    assert report.failed and "braked at 7.50 m/s^2" in report.failures[0]
    assert report.margin() == pytest.approx((7.0 - 7.5) / 7.0)
    gentle = judge(hard, "dut", Thresholds.given(deceleration=10.0))
    assert not gentle.failed and gentle.margin() == pytest.approx(0.25)


def test_the_vehicle_under_test_is_the_scenarios_dut_unless_an_option_names_another_or_none():
    assert UnderTest(AUTO).vehicle(("npc", "dut.car")) == "dut.car"
    assert UnderTest(AUTO).vehicle(("ego", "npc")) is None
    assert UnderTest(NONE).vehicle(("npc", "dut.car")) is None
    assert UnderTest("ego").vehicle(("ego", "npc")) == "ego"
    with pytest.raises(NoSuchVehicle, match="'hero' is not a vehicle of the scenario .*ego, npc"):
        UnderTest("hero").vehicle(("ego", "npc"))


def follow(driver, lead_speed, lead_braking, seconds=25.0):
    """The driver behind a lead that starts 40 m ahead at its speed and brakes at ``lead_braking``
    from t = 3 s to a stop; returns (least gap, collided)."""
    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.simulation.reference import Reference, Waypoint

    road = Road(3)
    reference = Reference("dut", 0.0, 0.0, [Waypoint(0.0, 0.0, 1, lead_speed)], road)
    driver.start("dut", reference, road, DT)
    me = VehicleState(0.0, road.center_y(1), 0.0, lead_speed, 0.0)
    lead_x, v = 40.0 + CAR_LENGTH, lead_speed
    least = math.inf
    for k in range(int(seconds / DT)):
        a = -lead_braking if k * DT >= 3.0 and v > 0 else 0.0
        lead = VehicleState(lead_x, road.center_y(1), 0.0, v, a)
        seen = Trajectory(
            *(np.array([value]) for value in (lead.x, lead.y, lead.heading, lead.speed, lead.acceleration))
        )
        me = driver.plan(k * DT, me, {"lead": seen}).state(1)
        v = max(0.0, v + a * DT)
        lead_x += v * DT
        least = min(least, lead_x - me.x - CAR_LENGTH)
    return least, least <= 0


def test_the_reference_acc_stops_behind_a_lead_that_brakes_hard_and_the_defective_ones_do_not():
    gap, collided = follow(AdaptiveCruiseControl(), 30.0, 7.0)
    assert not collided and gap >= 2.0, gap
    assert follow(LateAcc(), 30.0, 7.0)[1], "a driver 1.5 s late runs into a lead braking at 7 m/s^2"
    assert follow(WeakBrakingAcc(), 30.0, 7.0)[1], "a driver braking at most 3 m/s^2 runs into it"


def test_the_reference_acc_cruises_at_its_set_speed_in_its_lane_with_no_one_ahead():
    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.simulation.reference import Reference, Waypoint

    road = Road(3)
    driver = AdaptiveCruiseControl()
    driver.start("dut", Reference("dut", 0.0, 0.0, [Waypoint(0.0, 0.0, 2, 25.0)], road), road, DT)
    me = VehicleState(0.0, road.center_y(2) + 0.8, 0.0, 20.0, 0.0)
    for k in range(300):
        me = driver.plan(k * DT, me, {}).state(1)
    assert me.speed == pytest.approx(25.0, abs=0.3) and me.y == pytest.approx(road.center_y(2), abs=0.01)


def test_closing_in_nearer_in_time_than_the_headway_threshold_fails_and_a_car_drawing_away_is_not_judged():
    n = 40
    # at 25 m/s behind one at 24 m/s, from 12 m to 8 m: a time headway down to 0.32 s while it closes in
    lead = [25.0 * k * DT + CAR_LENGTH + 12.0 - 1.0 * k * DT for k in range(n)]
    closing = trace_of(
        {"dut": {"x": [25.0 * k * DT for k in range(n)], "speed": [25.0] * n}, "lead": {"x": lead, "speed": [24.0] * n}}
    )
    report = judge(closing, "dut", Thresholds.given(time_headway=0.5))
    assert report.measured["time_headway"].value == pytest.approx((12.0 - 3.9) / 25.0)
    assert report.failed and "time headway 0.32 s (threshold 0.5 s) behind lead at t=3.9 s" in report.failures[0]
    assert report.margin() == pytest.approx(((12.0 - 3.9) / 25.0 - 0.5) / 0.5)
    # the same near gap to one that draws away: the scenario's doing, not judged
    away = trace_of(
        {"dut": {"x": [25.0 * k * DT for k in range(n)], "speed": [25.0] * n}, "lead": {"x": lead, "speed": [26.0] * n}}
    )
    assert judge(away, "dut", Thresholds.given(time_headway=0.5)).measured["time_headway"].value == math.inf


def revealed(driver, speed=25.0, reveal_at=3.0, seconds=12.0):
    """The driver 30 m behind a lead at its own speed that changes lane at ``reveal_at`` s, 40 m
    before a stopped car (70 m ahead of the driver then); returns the least gap to the stopped car."""
    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.simulation.reference import Reference, Waypoint

    road = Road(3)
    driver.start("dut", Reference("dut", 0.0, 0.0, [Waypoint(0.0, 0.0, 1, speed)], road), road, DT)
    me = VehicleState(0.0, road.center_y(1), 0.0, speed, 0.0)
    wreck_at = 30.0 + speed * reveal_at + 40.0
    least = math.inf
    for k in range(int(seconds / DT)):
        t = k * DT
        lead = VehicleState(30.0 + speed * t, road.center_y(1 if t < reveal_at else 0), 0.0, speed, 0.0)
        wreck = VehicleState(wreck_at, road.center_y(1), 0.0, 0.0, 0.0)
        others = {
            name: Trajectory(*(np.array([v]) for v in (s.x, s.y, s.heading, s.speed, s.acceleration)))
            for name, s in (("lead", lead), ("wreck", wreck))
        }
        me = driver.plan(t, me, others).state(1)
        least = min(least, wreck_at - me.x - CAR_LENGTH)
    return least


def test_a_driver_slow_to_acquire_a_new_target_comes_closer_to_a_revealed_stopped_car_than_the_gap_oracle_allows():
    assert revealed(AdaptiveCruiseControl()) >= 2.0, "the reference stops 2 m or more behind it"
    assert revealed(SlowAcquisitionAcc()) < 2.0, "2 s blind to the revealed car: it stops too close, or not at all"


def test_a_case_file_written_before_an_oracle_existed_replays_with_that_oracle_off(tmp_path):
    import json

    from pytest_roadlogic.case import Case

    (tmp_path / "case.json").write_text(
        json.dumps({"path": "a.osc", "scenario": "s", "dut": "auto", "min_ttc": 1.5, "min_gap": 2.0, "max_decel": 8.0})
    )
    settings = Case.load(tmp_path / "case.json").settings
    assert settings.min_headway is None and settings.min_gap == 2.0
    n = 40
    close = trace_of(
        {
            "dut": {"x": [25.0 * k * DT for k in range(n)], "speed": [25.0] * n},
            "lead": {"x": [25.0 * k * DT + CAR_LENGTH + 8.0 - 0.5 * k * DT for k in range(n)], "speed": [24.5] * n},
        }
    )
    assert judge(close, "dut", Thresholds.given(time_headway=0.5)).failed, "closing in within 0.32 s"
    off = judge(close, "dut", Thresholds.of(settings))
    assert not off.failed and off.values()["thresholds"]["min_time_headway"] is None


def test_a_car_of_another_route_is_never_in_the_path_by_road_coordinates_and_a_crossing_hit_is_the_dut_not_giving_way():
    # the npc drives another way through a junction: 6 m ahead along its own route, in its lane 0
    # too, yet crossing the dut's way in the world from its right
    n = 20
    columns = {
        "dut": {"x": [10.0 * k * DT for k in range(n)], "speed": [10.0] * n},
        "npc": {"x": [6.0 + 10.0 * k * DT for k in range(n)], "speed": [10.0] * n},
    }
    trace = trace_of(columns, [Incident(1.0, "collision", ("dut", "npc"))])
    for name, (wx, wy, heading) in {"dut": (0.0, 0.0, 0.0), "npc": (1.0, -1.5, math.pi / 2)}.items():
        trace.actors[name]["world_x"] = np.full(n, wx)
        trace.actors[name]["world_y"] = np.full(n, wy)
        trace.actors[name]["world_heading"] = np.full(n, heading)
    same_route = judge(trace, "dut")
    assert same_route.measured["gap"].value == pytest.approx(6.0 - CAR_LENGTH)
    apart = judge(trace, "dut", apart=frozenset({"npc"}))
    assert apart.measured["gap"].value == math.inf
    # at a junction the vehicle under test gives way to a car crossing its way: moving, it did not
    (collision,) = apart.collisions
    assert collision.caused and collision.how == "dut did not give way to npc, which came from its right"
    # standing short of the crossing, waiting, it was run into
    trace.actors["dut"]["speed"] = np.zeros(n)
    (collision,) = judge(trace, "dut", apart=frozenset({"npc"})).collisions
    assert not collision.caused and collision.how == "npc ran into dut standing, from its right"
