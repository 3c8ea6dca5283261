"""A vehicle under test at a junction, from the definitions: a driver sees the cars of other ways
as they come to where the ways meet; the reference driver gives way by its gap-acceptance rule
(a car that would be in the crossing within 2 s of its leaving it makes it stop short of the
crossing, unless it can no longer stop there), the non-yielding one never does; the
post-encroachment time is the least time between the two cars being where their boxes overlap;
and the junction suite's three scenarios for a vehicle under test tell the two drivers apart."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pytest_roadlogic.dimensions import CAR_LENGTH, CAR_WIDTH
from pytest_roadlogic.dut.reference_drivers import AdaptiveCruiseControl, NonYieldingAcc
from pytest_roadlogic.roads.road import Road
from pytest_roadlogic.simulation.driver import CrossTraffic, VehicleState
from pytest_roadlogic.simulation.reference import Reference, Waypoint

ROOT = Path(__file__).resolve().parents[2]
JUNCTIONS = ROOT / "scenarios" / "junctions"
YIELD = sorted(JUNCTIONS.glob("yield_*.osc"))


def _started(driver_class, speed: float = 8.0):
    driver = driver_class()
    road = Road(lanes=1, x_start=-100.0, x_end=300.0)
    driver.start("dut.car", Reference("dut.car", 0.0, 0.0, [Waypoint(0.0, 0.0, 0, speed)], road), road, 0.1)
    return driver


def _acceleration(driver, state: VehicleState, traffic: tuple[CrossTraffic, ...]) -> float:
    driver.see(traffic)
    return float(driver.plan(0.0, state, {}).acceleration[0])


def _crossing_ahead(start: float, distance: float, speed: float = 10.0) -> CrossTraffic:
    """A car of another way, ``distance`` m short of a 10 m crossing that begins at x = ``start``."""
    return CrossTraffic("npc", "crossing", start, start + 10.0, distance, 10.0, speed, 0.0)


def test_a_car_coming_to_the_crossing_while_it_would_be_there_makes_the_reference_driver_stop_short_of_it():
    state = VehicleState(0.0, 1.75, 0.0, 8.0, 0.0)
    # it reaches the crossing 30 m ahead in about 3.5 s; the other car, 40 m short of it at 10 m/s, in 4 s
    too_soon = (_crossing_ahead(30.0, 40.0),)
    braking = _acceleration(_started(AdaptiveCruiseControl), state, too_soon)
    # stopping a metre short of the crossing from 8 m/s: v^2 / 2d
    room = 30.0 - CAR_LENGTH / 2 - 1.0
    assert braking == pytest.approx(-(8.0**2) / (2 * room), abs=0.05)
    # the defective driver drives on at its speed
    assert _acceleration(_started(NonYieldingAcc), state, too_soon) >= 0.0
    # a car that has 2 s more to go than the gap asks for is no reason to wait: 150 m at 10 m/s
    assert _acceleration(_started(AdaptiveCruiseControl), state, (_crossing_ahead(30.0, 150.0),)) >= 0.0
    # nor one that has passed the crossing already
    passed = CrossTraffic("npc", "crossing", 30.0, 40.0, -20.0, 10.0, 10.0, 0.0)
    assert _acceleration(_started(AdaptiveCruiseControl), state, (passed,)) >= 0.0


def test_the_reference_driver_waits_at_the_crossing_and_goes_on_once_it_could_no_longer_stop_short():
    waiting = VehicleState(30.0 - CAR_LENGTH / 2 - 1.0, 1.75, 0.0, 0.0, 0.0)
    assert _acceleration(_started(AdaptiveCruiseControl), waiting, (_crossing_ahead(30.0, 20.0),)) == 0.0
    # 2 m short of the crossing at 8 m/s: stopping would take 16 m/s^2, so it goes on
    late = VehicleState(30.0 - CAR_LENGTH / 2 - 2.0, 1.75, 0.0, 8.0, 0.0)
    assert _acceleration(_started(AdaptiveCruiseControl), late, (_crossing_ahead(30.0, 20.0),)) >= 0.0


def test_a_car_that_has_joined_its_lane_ahead_of_it_is_followed_like_any_car_ahead():
    state = VehicleState(0.0, 1.75, 0.0, 8.0, 0.0)
    # joined 15 m past the join at x = 20: 35 m ahead of it, standing
    joined = CrossTraffic("npc", "shared", 20.0, 200.0, -15.0, 180.0, 0.0, 0.0)
    driver = _started(AdaptiveCruiseControl)
    alone = _started(AdaptiveCruiseControl)
    assert _acceleration(driver, state, (joined,)) < -1.0 < _acceleration(alone, state, ())


def _crossing_trace(offset: float, speed: float = 10.0):
    """Two cars at right angles through the map's origin, ``b`` passing it ``offset`` s after ``a``."""
    from pytest_roadlogic.simulation.trace import Trace

    times = np.round(np.arange(0.0, 10.0 + 1e-9, 0.01), 6)
    a_x, b_y = speed * (times - 5.0), speed * (times - 5.0 - offset)
    zeros = np.zeros_like(times)

    def columns(x, y, heading):
        return {
            "x": x, "y": y, "heading": zeros, "speed": zeros + speed, "acceleration": zeros, "lane": zeros,
            "world_x": x, "world_y": y, "world_heading": zeros + heading,
        }  # fmt: skip

    return Trace(times, {"a": columns(a_x, zeros, 0.0), "b": columns(zeros, b_y, math.pi / 2)}, [])


@pytest.mark.parametrize("offset", [1.0, 1.5, 3.0])
def test_the_post_encroachment_time_of_two_cars_crossing_at_right_angles_is_their_offset_less_the_time_to_pass_once_it_can_act(
    offset,
):
    from pytest_roadlogic.oracles.measures import CONFLICT_MARGIN, Seen, least_post_encroachment_time

    trace = _crossing_trace(offset)
    # the boxes, grown by the margin, overlap while each centre is within this of the crossing point
    reach = (CAR_LENGTH + CAR_WIDTH) / 2 + 2 * CONFLICT_MARGIN
    closest = least_post_encroachment_time(Seen(trace, "a", {}, None, frozenset({"b"})))
    assert closest.value == pytest.approx(offset - 2 * reach / 10.0, abs=0.02)
    assert closest.other == "b"
    # a car of its own route is never judged so (its gap and headway are)
    assert least_post_encroachment_time(Seen(trace, "a", {}, None, frozenset())).value == math.inf
    # one over before the vehicle under test could act (the cars meet about 5 s in) is the start
    # the scenario gave it, not its driving
    assert least_post_encroachment_time(Seen(trace, "a", {}, None, frozenset({"b"}), 1.0)) == closest
    assert least_post_encroachment_time(Seen(trace, "a", {}, None, frozenset({"b"}), 9.0)).value == math.inf


@pytest.mark.parametrize("path", YIELD, ids=lambda p: p.stem)
def test_the_junction_suite_tells_the_yielding_reference_driver_from_the_one_that_never_gives_way(path):
    from pytest_roadlogic.dut import AUTO, UnderTest
    from pytest_roadlogic.oracles.thresholds import Thresholds
    from pytest_roadlogic.pipeline import load_scenario, run_instances

    scenario = load_scenario(path)
    outcome = {}
    for driver in ("acc", "non-yielding-acc"):
        under_test = UnderTest(AUTO, driver, Thresholds.given())
        instance = next(run_instances(scenario, count=1, seed=1, under_test=under_test))
        assert instance.dut is not None
        outcome[driver] = (instance.verdict.accepted, instance.dut.failures)
    assert outcome["acc"] == (True, [])
    assert any("post-encroachment time" in failure for failure in outcome["non-yielding-acc"][1]), outcome
