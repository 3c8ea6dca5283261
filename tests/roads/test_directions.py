"""Both directions of a road: its left lanes driven against its reference line, and a road of one
lane each way whose oncoming lane an overtake passes in (docs/roads.md, "The route")."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from pytest_roadlogic.roads.choice import pick_route
from pytest_roadlogic.roads.cubic_records import LaneWidth, piecewise_cubic, reversed_records, summed
from pytest_roadlogic.roads.directions import against, with_oncoming
from pytest_roadlogic.roads.opendrive_in import MapError, read_map
from tests.roads.map_files import MAPS, one_road_map, write


def lane(lane_id: int, kind: str = "driving", widths: str = "<width sOffset='0' a='3.5' b='0' c='0' d='0'/>") -> str:
    return f"<lane id='{lane_id}' type='{kind}'>{widths}</lane>"


def two_way_map(path: Path, left: str, right: str, length: float = 700.0) -> Path:
    """A road of ``length`` m along a clothoid from a 600 m left bend to a 500 m right one, with a
    lane offset that moves its lanes 0.5 m left over the first 200 m, and two sections: ``left``
    and ``right`` lanes in the first, and from 400 m on a further left lane that opens (0 to 3.5 m
    over 100 m) beside them."""
    opening = (
        "<width sOffset='0' a='0' b='0' c='0.00105' d='-0.000007'/><width sOffset='100' a='3.5' b='0' c='0' d='0'/>"
    )
    return one_road_map(
        path,
        length,
        f'<geometry s="0" x="10" y="-20" hdg="0.3" length="{length}">'
        '<spiral curvStart="0.0016667" curvEnd="-0.002"/></geometry>',
        '<laneOffset s="0" a="0" b="0" c="0.0000375" d="-0.000000125"/><laneOffset s="200" a="0.5" b="0" c="0" d="0"/>'
        f'<laneSection s="0"><left>{left}</left><right>{right}</right></laneSection>'
        f'<laneSection s="400"><left>{left}{lane(len(left.split("<lane ")), widths=opening)}</left>'
        f"<right>{right}</right></laneSection>",
    )


def test_cubic_records_read_backwards_and_added_up_give_the_same_values():
    records = (
        LaneWidth(0.0, 1.0, 0.1, -0.002, 0.00001),
        LaneWidth(30.0, 2.0, 0.0, 0.001, 0.0),
        LaneWidth(70.0, 3.0, 0, 0, 0),
    )
    u = np.linspace(0.0, 99.999, 401)
    back = reversed_records(records, 100.0, sign=-1.0)
    assert piecewise_cubic(back, 100.0 - u) == pytest.approx(-piecewise_cubic(records, u), abs=1e-9)
    late = (LaneWidth(20.0, 1.5, 0.01, 0, 0),)  # 0 before 20 m, and so read backwards past 80 m
    assert piecewise_cubic(reversed_records(late, 100.0), 100.0 - u) == pytest.approx(
        piecewise_cubic(late, u), abs=1e-9
    )
    other = (LaneWidth(0.0, 0.5, 0.02, 0.0, -0.00001),)
    total = summed([(0.0, 100.0, records), (40.0, 90.0, other)], 100.0)
    inside = (u >= 40.0) & (u < 90.0)
    want = piecewise_cubic(records, u) + np.where(inside, piecewise_cubic(other, u - 40.0), 0.0)
    assert piecewise_cubic(total, u) == pytest.approx(want, abs=1e-9)


def test_a_road_read_against_its_reference_line_is_the_same_road_from_its_other_end(tmp_path):
    left = lane(1) + lane(2, widths="<width sOffset='0' a='3.2' b='0.001' c='0' d='0'/>")
    road = read_map(two_way_map(tmp_path / "two_way.xodr", left, lane(-1) + lane(-2))).roads["1"]
    back = against(road)
    length = road.length
    s = np.linspace(0.0, length, 57)
    for t in (-4.0, 0.0, 2.5):
        x, y, heading = road.reference_line.pose(s, t)
        bx, by, bheading = back.reference_line.pose(length - s, -t)
        assert bx == pytest.approx(x, abs=1e-6) and by == pytest.approx(y, abs=1e-6)
        turned = (bheading - heading - np.pi + np.pi) % (2 * np.pi) - np.pi
        assert turned == pytest.approx(0.0, abs=1e-6)
    assert back.reference_line.curvature(length - s) == pytest.approx(-road.reference_line.curvature(s), abs=1e-9)
    assert back.offset(length - s[1:-1]) == pytest.approx(-road.offset(s[1:-1]), abs=1e-9)
    # its right lanes are the road's left ones, read from the other end, section by section
    assert [len(section.right) for section in back.sections] == [3, 2]
    for section, mirrored in zip(road.sections, reversed(back.sections)):
        ds = np.linspace(0.0, section.end - section.s - 1e-6, 9)
        for original, read in zip(section.left, mirrored.right):
            assert read.id == -original.id
            assert read.width(section.end - section.s - ds) == pytest.approx(original.width(ds), abs=1e-9)
    assert back.label == "road 1 against its reference line" and against(back).sections == road.sections


def test_a_road_whose_driving_lanes_run_against_its_reference_line_is_a_route_that_way(tmp_path):
    sidewalk = lane(-1, "sidewalk", "<width sOffset='0' a='2' b='0' c='0' d='0'/>")
    road_map = read_map(two_way_map(tmp_path / "one_way.xodr", lane(1) + lane(2), sidewalk))
    route = pick_route(road_map, 2)
    assert route.road.against and route.road.oncoming == 0 and route.lanes == 3  # the third opens on it
    original = road_map.roads["1"]
    x = np.array([50.0, 250.0, 600.0])
    # its lane 0 (next to the reference line) is the road's left lane 1: 1.75 m left of the lane
    # offset, on the left of the road's reference line as the map draws it
    wx, wy, heading = route.pose(x, route.width - 1.75)
    ox, oy, oheading = original.reference_line.pose(original.length - x, original.offset(original.length - x) + 1.75)
    assert wx == pytest.approx(ox, abs=1e-6) and wy == pytest.approx(oy, abs=1e-6)
    assert np.cos(heading - oheading) == pytest.approx(-1.0)


def test_a_road_of_one_lane_each_way_joins_its_oncoming_lane_only_for_a_scenario_that_needs_two():
    road_map = read_map(MAPS / "rural_road.xodr")
    own = pick_route(road_map, 1)
    assert own.lanes == 1 and own.road.oncoming == 0 and not own.road.against
    joined = pick_route(road_map, 2)
    assert joined.lanes == 2 and joined.road.oncoming == 1 and joined.lane_width == 3.25
    # lane 0 (the scenario's lane 2) is the oncoming lane, left of the reference line; lane 1 the own
    x = np.array([10.0, 450.0, 900.0])
    line = road_map.roads["1"].reference_line
    for y, t in ((joined.width - 1.625, 1.625), (1.625, -1.625)):
        wx, wy, _ = joined.pose(x, y)
        ox, oy, _ = line.pose(x, t)
        assert wx == pytest.approx(ox, abs=1e-6) and wy == pytest.approx(oy, abs=1e-6)


def test_a_median_keeps_the_oncoming_lanes_apart_and_a_map_without_a_fit_says_what_each_way_has(tmp_path):
    median = lane(1, "border", "<width sOffset='0' a='1' b='0' c='0' d='0'/>") + lane(2)
    road_map = read_map(two_way_map(tmp_path / "divided.xodr", median, lane(-1)))
    assert with_oncoming(road_map.roads["1"]) is None
    with pytest.raises(MapError) as caught:
        pick_route(road_map, 3)
    assert "road 1: 1 driving lane over 700 m, 1 (2 in parts) the other way" in caught.value.message


def test_the_rural_overtake_passes_in_the_oncoming_lane_and_only_to_pass():
    from pytest_roadlogic.frontend import check_file
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    path = MAPS.parent / "overtake_rural.osc"
    warnings = check_file(path).warnings
    assert any("lane 2 the oncoming lane" in w.message for w in warnings), warnings
    scenario = load_scenario(path)
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    trace, road = outcome.simulation.trace, outcome.simulation.road
    slow, ego = trace.actors["slow"], trace.actors["ego"]
    assert set(slow["lane"]) == {1}, "the slow car keeps to its own lane"
    # the ego is in the oncoming lane (lane 0: left of the reference line, as the map has it) in
    # one stretch, from its pull-out to its pull-in, and passes the slow car there
    oncoming = np.flatnonzero(ego["lane"] == 0)
    assert len(oncoming) and np.all(np.diff(oncoming) == 1)
    lateral = road.route.lateral(ego["x"][oncoming] + road.route_shift, ego["y"][oncoming])
    assert np.all(lateral > 0.0)
    assert ego["x"][oncoming[0]] < slow["x"][oncoming[0]] and ego["x"][oncoming[-1]] > slow["x"][oncoming[-1]]
    # on 3.25 m lanes a car keeps its lane's centre: the slow car 1.625 m right of the centre line
    slow_lateral = road.route.lateral(slow["x"] + road.route_shift, slow["y"])
    assert np.abs(slow_lateral + 1.625).max() < 0.15


def test_a_road_heading_west_is_driven(tmp_path):
    """frenetix's yaw-rate check differences headings without wrapping them: on a road whose heading
    crossed pi every car stood still there (esmini's jolengatan). This one heads west and bends
    right (clockwise) so that its heading crosses pi 120 m along it, where the cars drive."""
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    lanes = lane(-1) + lane(-2)
    write(
        tmp_path / "west.xodr",
        f"""
        <?xml version="1.0"?>
        <OpenDRIVE><header/>
        <road id="1" length="260" junction="-1"><planView>
        <geometry s="0" x="0" y="0" hdg="{np.pi - 0.06}" length="260"><arc curvature="0.0005"/></geometry>
        </planView><lanes><laneSection s="0"><right>{lanes}</right></laneSection></lanes></road>
        </OpenDRIVE>
        """,
    )
    osc = (MAPS.parents[1] / "change_lane.osc").read_text()
    osc = "import osc.standard\n" + osc.replace("  v2: car\n", '  v2: car\n  path: Path\n  path.set_map("west.xodr")\n')
    outcome = run_scenario(load_scenario(write(tmp_path / "west.osc", osc)), seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    for name, columns in outcome.simulation.trace.actors.items():
        heading = columns["world_heading"]
        # the trace's heading is within -pi..pi: on both sides of pi, it is near both ends
        assert (heading > 3.0).any() and (heading < -3.0).any(), f"{name} drove where the heading crosses pi"
        assert np.diff(columns["x"]).min() > 1.0, f"{name} never stands still"


def linked_map(path: Path, second_contact: str = "start", shift: float = 0.0) -> Path:
    """Two 150 m roads along +x with two lanes each way and a 20 m connecting road of junction 9
    between them (straight on), plus one turning left out of the junction into road 5 (a quarter
    circle of 15 m radius). ``second_contact``: the end of road 2 the junction meets (its
    reference line then runs back toward it); ``shift``: metres road 2's lanes lie left of the line."""
    both = lane(1) + lane(2), lane(-1) + lane(-2)
    sections = f"<laneSection s='0'><left>{both[0]}</left><right>{both[1]}</right></laneSection>"
    if second_contact == "start":
        second = f"<geometry s='0' x='170' y='{shift}' hdg='0' length='150'><line/></geometry>"
    else:
        second = f"<geometry s='0' x='320' y='{-shift}' hdg='{np.pi}' length='150'><line/></geometry>"
    link2 = (
        "<predecessor elementType='junction' elementId='9'/>"
        if second_contact == "start"
        else "<successor elementType='junction' elementId='9'/>"
    )
    return write(
        path,
        f"""
        <?xml version="1.0"?>
        <OpenDRIVE><header/>
        <road id="1" length="150" junction="-1"><link><successor elementType="junction" elementId="9"/></link>
        <planView><geometry s="0" x="0" y="0" hdg="0" length="150"><line/></geometry></planView>
        <lanes>{sections}</lanes></road>
        <road id="3" length="20" junction="9"><link><predecessor elementType="road" elementId="1" contactPoint="end"/>
        <successor elementType="road" elementId="2" contactPoint="{second_contact}"/></link>
        <planView><geometry s="0" x="150" y="0" hdg="0" length="20"><line/></geometry></planView>
        <lanes>{sections}</lanes></road>
        <road id="4" length="{np.pi / 2 * 15}" junction="9"><link><predecessor elementType="road" elementId="1" contactPoint="end"/>
        <successor elementType="road" elementId="5" contactPoint="start"/></link>
        <planView><geometry s="0" x="150" y="0" hdg="0" length="{np.pi / 2 * 15}"><arc curvature="{1 / 15}"/></geometry></planView>
        <lanes>{sections}</lanes></road>
        <road id="2" length="150" junction="-1"><link>{link2}</link>
        <planView>{second}</planView><lanes>{sections}</lanes></road>
        <road id="5" length="100" junction="-1"><link><predecessor elementType="junction" elementId="9"/></link>
        <planView><geometry s="0" x="165" y="15" hdg="{np.pi / 2}" length="100"><line/></geometry></planView>
        <lanes>{sections}</lanes></road>
        <junction id="9" name="crossing">
        <connection id="0" incomingRoad="1" connectingRoad="3" contactPoint="start"/>
        <connection id="1" incomingRoad="1" connectingRoad="4" contactPoint="start"/>
        </junction>
        </OpenDRIVE>
        """,
    )


@pytest.mark.parametrize("contact", ["start", "end"])
def test_a_route_goes_on_straight_through_a_junction_into_the_road_that_continues_its_lanes(tmp_path, contact):
    route = pick_route(read_map(linked_map(tmp_path / "linked.xodr", contact)), 2)
    assert route.length == pytest.approx(320.0) and route.lanes == 2
    assert route.road.id == "1+3+2"
    assert route.road.label.endswith("road 2" + ("" if contact == "start" else " against its reference line"))
    # one straight line along +x: the right lane's centre 1.75 m right of it all along
    x = np.linspace(0.0, 320.0, 33)
    wx, wy, heading = route.pose(x, 1.75)
    assert wx == pytest.approx(x, abs=1e-6) and wy == pytest.approx(-5.25, abs=1e-6)
    assert heading == pytest.approx(0.0, abs=1e-6)


def test_a_route_does_not_turn_at_a_junction_nor_go_on_where_the_lanes_do_not_meet(tmp_path):
    # lanes 1 m apart where the roads meet: each road alone (150 m) is too short for 200 m
    with pytest.raises(MapError) as caught:
        pick_route(read_map(linked_map(tmp_path / "apart.xodr", shift=1.0)), 2)
    assert "no road of the map has 2 driving lanes over 200 m" in caught.value.message
    # the quarter circle inside the junction is never part of a route: road 1 goes on into 3 and 2 only
    route = pick_route(read_map(linked_map(tmp_path / "linked.xodr")), 2, length=300.0)
    assert "4" not in route.road.id.split("+") and "5" not in route.road.id.split("+")


def one_way_junction_map(path: Path) -> Path:
    """``linked_map`` with its junction's roads one way each, as CARLA's towns have them: road 3
    east from road 1 into road 2 with only its right lanes, and in place of the left turn, road 4
    west from road 2 into road 1 along the same 20 m, its right lanes only."""
    text = linked_map(path).read_text()
    right_only = "<laneSection s='0'><right>" + lane(-1) + lane(-2) + "</right></laneSection>"
    road_3 = re.search(r'<road id="3".*?</road>', text, re.S).group(0)
    road_4 = re.search(r'<road id="4".*?</road>', text, re.S).group(0)
    west = (
        '<road id="4" length="20" junction="9"><link><predecessor elementType="road" elementId="2" '
        'contactPoint="start"/><successor elementType="road" elementId="1" contactPoint="end"/></link>'
        f'<planView><geometry s="0" x="170" y="0" hdg="{np.pi}" length="20"><line/></geometry></planView>'
        f"<lanes>{right_only}</lanes></road>"
    )
    text = text.replace(road_3, re.sub(r"<lanes>.*</lanes>", f"<lanes>{right_only}</lanes>", road_3, flags=re.S))
    text = text.replace(road_4, west).replace(
        'incomingRoad="1" connectingRoad="4"', 'incomingRoad="2" connectingRoad="4"'
    )
    return write(path, text)


def test_the_roads_before_a_road_through_a_junction_of_one_way_connecting_roads_are_its_own_directions(tmp_path):
    """Each way through the junction is found on the connecting road that carries it: before road 2
    eastward lie road 1 and road 3 (not road 4 driven the wrong way, which has no lane that way),
    and before road 1 westward road 2 and road 4."""
    from pytest_roadlogic.roads.chains import next_ways, previous_ways, way
    from pytest_roadlogic.roads.route import through_lanes

    road_map = read_map(one_way_junction_map(tmp_path / "one_way.xodr"))

    def named(steps):
        return [[(road.id, road.against) for road in step] for step in steps]

    east, west = way(road_map, "2", "start"), way(road_map, "1", "end")
    assert named(previous_ways(road_map, east)) == [[("1", False), ("3", False)]]
    assert named(previous_ways(road_map, west)) == [[("2", True), ("4", False)]]
    for step in (*previous_ways(road_map, east), *previous_ways(road_map, west)):
        assert all(through_lanes(road)[0] == 2 for road in step)
    # the same ways forward: from road 1 eastward through road 3 into road 2
    assert named(next_ways(road_map, way(road_map, "1", "start"))) == [[("3", False), ("2", False)]]


def kinked_map(path: Path, turn_degrees: float = 15.0) -> Path:
    """``linked_map`` with the connecting road a 20 m arc that turns ``turn_degrees`` to the
    left, road 2 going on from its end, and no turn out of the junction: straight on for a
    route, but sharper than a highway's curves (about 76 m of radius at 15 degrees)."""
    turn = np.radians(turn_degrees)
    curvature = turn / 20.0
    x, y = 150.0 + np.sin(turn) / curvature, (1.0 - np.cos(turn)) / curvature
    text = linked_map(path).read_text()
    text = text.replace(
        '<geometry s="0" x="150" y="0" hdg="0" length="20"><line/></geometry>',
        f'<geometry s="0" x="150" y="0" hdg="0" length="20"><arc curvature="{curvature}"/></geometry>',
    )
    text = text.replace(
        "<geometry s='0' x='170' y='0.0' hdg='0' length='150'><line/></geometry>",
        f"<geometry s='0' x='{x}' y='{y}' hdg='{turn}' length='150'><line/></geometry>",
    )
    turning = text.index('<road id="4"')
    text = text[:turning] + text[text.index('<road id="2"') :]
    text = text.replace('<connection id="1" incomingRoad="1" connectingRoad="4" contactPoint="start"/>', "")
    return write(path, text)


def test_where_no_route_keeps_to_a_highways_curves_one_goes_through_a_sharper_bend_and_keeps_its_curve(tmp_path):
    road_map = read_map(kinked_map(tmp_path / "kinked.xodr"))
    route = pick_route(road_map, 2)
    assert route.road.id == "1+3+2" and route.lanes == 2
    assert route.road.reference_line.sharpest() == pytest.approx(np.radians(15.0) / 20.0, rel=0.01)
    # a road of its own long enough is still preferred to the bend
    assert pick_route(road_map, 2, length=120.0).road.id in ("1", "2")
