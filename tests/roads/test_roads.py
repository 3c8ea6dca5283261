"""Roads beyond one straight road: OpenDRIVE read as data (geometry checked against closed forms),
a route picked or refused with reasons, set_map and the map option, and a run on a curve."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pytest_roadlogic.roads.choice import describe, pick_route
from pytest_roadlogic.roads.opendrive_in import MapError, read_map
from pytest_roadlogic.roads.reference_line import Geometry, ReferenceLine
from pytest_roadlogic.roads.route import curve_speed
from tests.roads.map_files import MAPS, one_road_map, recipe, write

pytest_plugins = ["pytester"]

ROOT = Path(__file__).resolve().parents[2]


def test_the_committed_maps_are_what_their_recipe_writes(tmp_path):
    for written in recipe(MAPS).write(tmp_path):
        assert same_document(written, MAPS / written.name), written.name


def same_document(one: Path, other: Path, tolerance: float = 1e-9) -> bool:
    """Whether two XML files hold the same elements, attributes and text, numbers equal within
    ``tolerance`` (absolute, or relative to the larger): the last digits of a float differ between
    machines (``b="-3.039e-17"`` here, ``-3.553e-17`` there), so a byte comparison failed on one."""
    import xml.etree.ElementTree as ET

    def same_text(a: str | None, b: str | None) -> bool:
        a, b = (a or "").strip(), (b or "").strip()
        if a == b:
            return True
        try:
            x, y = float(a), float(b)
        except ValueError:
            return False
        return math.isclose(x, y, rel_tol=tolerance, abs_tol=tolerance)

    def same(a: ET.Element, b: ET.Element) -> bool:
        return (
            a.tag == b.tag
            and a.attrib.keys() == b.attrib.keys()
            and all(same_text(a.attrib[k], b.attrib[k]) for k in a.attrib)
            and same_text(a.text, b.text)
            and len(a) == len(b)
            and all(same(x, y) for x, y in zip(a, b))
        )

    return same(ET.parse(one).getroot(), ET.parse(other).getroot())


def test_two_documents_differing_in_a_floats_last_digits_are_the_same_and_in_a_value_are_not(tmp_path):
    one, two, three = tmp_path / "1.xml", tmp_path / "2.xml", tmp_path / "3.xml"
    one.write_text('<r><w a="0" b="-3.039235529911366e-17">1.0</w></r>')
    two.write_text('<r><w a="0" b="-3.552713678800501e-17">1.0</w></r>')
    three.write_text('<r><w a="0" b="-3.5e-3">1.0</w></r>')
    assert same_document(one, two) and not same_document(one, three)


def test_an_arc_keeps_its_radius_and_turns_by_its_length_over_the_radius():
    radius = 500.0
    line = ReferenceLine((Geometry(0.0, 10.0, -5.0, 0.3, 400.0, "arc", curvature=1 / radius),))
    s = np.linspace(0.0, 400.0, 81)
    x, y, heading = line.pose(s)
    centre = (10.0 - math.sin(0.3) * radius, -5.0 + math.cos(0.3) * radius)
    assert np.hypot(x - centre[0], y - centre[1]) == pytest.approx(np.full_like(s, radius), abs=1e-3)
    assert heading == pytest.approx(0.3 + s / radius)
    # a point 3.5 m left of the line is 3.5 m nearer the centre of a left curve
    xl, yl, _ = line.pose(s, 3.5)
    assert np.hypot(xl - centre[0], yl - centre[1]) == pytest.approx(np.full_like(s, radius - 3.5), abs=1e-3)


def test_a_clothoid_from_a_straight_follows_the_fresnel_integrals():
    from scipy.special import fresnel

    length, end = 100.0, 1 / 500.0
    line = ReferenceLine((Geometry(0.0, 0.0, 0.0, 0.0, length, "spiral", curvature_start=0.0, curvature_end=end),))
    s = np.linspace(0.0, length, 21)
    x, y, heading = line.pose(s)
    # heading = a s^2 / 2 with a = end / length; x + i y = integral of exp(i a u^2 / 2)
    a = end / length
    scale = math.sqrt(math.pi / a)
    fresnel_s, fresnel_c = fresnel(s / scale)
    assert x == pytest.approx(scale * fresnel_c, abs=1e-3)
    assert y == pytest.approx(scale * fresnel_s, abs=1e-3)
    assert heading == pytest.approx(a * s**2 / 2, abs=1e-9)
    assert line.curvature(s) == pytest.approx(a * s)


def test_the_test_maps_read_as_their_recipe_describes():
    curved = read_map(MAPS / "curved_highway.xodr").roads["1"]
    s, _, _, heading, curvature = curved.reference_line.sampled()
    assert curved.length == pytest.approx(1250.0)
    assert heading[-1] == pytest.approx(0.1 + 700 / 500 + 0.1, abs=1e-6)  # two clothoids and the arc
    assert np.abs(curvature).max() == pytest.approx(1 / 500)
    assert curve_speed(pick_route(read_map(MAPS / "curved_highway.xodr"), 3)) == pytest.approx(math.sqrt(2.0 * 500))
    ramp = read_map(MAPS / "on_ramp.xodr").roads["1"]
    assert [len(section.right) for section in ramp.sections] == [3, 4, 4, 4, 3]
    opening = ramp.sections[1]
    assert float(opening.right[3].width(0.0)) == pytest.approx(0.0, abs=1e-9)
    assert float(opening.right[3].width(opening.end - opening.s)) == pytest.approx(3.5, abs=1e-6)
    drop = read_map(MAPS / "lane_drop.xodr").roads["1"]
    assert [len(section.right) for section in drop.sections] == [3, 3, 2]


def test_a_map_with_a_document_type_is_refused_at_it_and_no_entity_is_read(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("TOKEN-123")
    hostile = write(
        tmp_path / "hostile.xodr",
        f"""
        <?xml version="1.0"?>
        <!DOCTYPE OpenDRIVE [<!ENTITY leak SYSTEM "file://{secret}">]>
        <OpenDRIVE><header name="&leak;"/></OpenDRIVE>
        """,
    )
    with pytest.raises(MapError) as caught:
        read_map(hostile)
    assert caught.value.line == 2 and "document type" in caught.value.message
    assert "TOKEN" not in str(caught.value)


@pytest.mark.parametrize(
    "body, line, words",
    [
        ("<OpenDRIVE><road length='10'>", 1, "not well-formed"),
        ("<html/>", 1, "not an OpenDRIVE file"),
        ("<OpenDRIVE>\n<road id='1' length='x'/></OpenDRIVE>", 2, "is not a number"),
        (
            "<OpenDRIVE><road id='1' length='10'><planView>\n<geometry s='0' x='0' y='0' hdg='0' length='10'>"
            "<clothoid/></geometry></planView></road></OpenDRIVE>",
            2,
            "unknown plan view geometry",
        ),
        (
            "<OpenDRIVE><road id='1' length='10'><planView><geometry s='0' x='0' y='0' hdg='0' length='10'>"
            "<line/></geometry></planView><lanes>\n<laneOffset s='0' a='1e6' b='0' c='0' d='0'/>"
            "<laneSection s='0'/></lanes></road></OpenDRIVE>",
            2,
            "a lane offset that moves the lanes 1e+06 m off the reference line",
        ),
        (
            "<OpenDRIVE>\n<road id='1' length='1e12'><planView><geometry s='0' x='0' y='0' hdg='0' length='1e12'>"
            "<line/></geometry></planView></road></OpenDRIVE>",
            2,
            "a road 1e+12 m long",
        ),
    ],
)
def test_a_map_that_cannot_be_read_is_refused_naming_its_line(tmp_path, body, line, words):
    with pytest.raises(MapError) as caught:
        read_map(write(tmp_path / "bad.xodr", body))
    assert caught.value.line == line and words in caught.value.message, str(caught.value)


def test_no_route_on_a_map_without_enough_lanes_says_road_by_road_why():
    with pytest.raises(MapError) as caught:
        pick_route(read_map(MAPS / "lane_drop.xodr"), 4)
    message = caught.value.message
    assert "no road of the map has 4 driving lanes" in message
    assert "road 1: 2 driving lanes over 900 m, 3 in parts" in message


def test_a_road_inside_a_junction_is_never_a_route_and_is_named_so(tmp_path):
    text = (MAPS / "s_curve.xodr").read_text().replace('junction="-1"', 'junction="7"')
    with pytest.raises(MapError) as caught:
        pick_route(read_map(write(tmp_path / "junction.xodr", text)), 3)
    assert (
        "road 1: inside junction 7 (a route goes through a junction straight on, never begins in one)"
        in caught.value.message
    )


SCENARIO = """
import osc.standard

scenario curve:
    npc: car
    path: Path
    path.set_map("{map}")
    do serial:
        follow: parallel(duration: [4s..5s]):
            ego.drive() with:
                lane({ego_lane}, at: start)
                speed([22mps..25mps], at: start)
            npc.drive() with:
                lane(1, at: start)
                position(distance: [20m..30m], behind: ego, at: start)
        pass: parallel(duration: [5s..8s]):
            ego.drive()
            npc.change_lane(num_of_lanes: 1, side: left)
"""


def scenario_file(folder: Path, map_name: str, ego_lane: int = 1) -> Path:
    return write(folder / "curve.osc", SCENARIO.format(map=map_name, ego_lane=ego_lane))


def test_set_map_runs_a_scenario_on_the_route_of_its_map_and_the_trace_carries_world_poses(tmp_path):
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "curved.xodr").write_bytes((MAPS / "curved_highway.xodr").read_bytes())
    scenario = load_scenario(scenario_file(tmp_path, "maps/curved.xodr"))
    assert scenario.route is not None and scenario.lanes == 3
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    trace, road = outcome.simulation.trace, outcome.simulation.road
    assert trace.on_map
    for name, columns in trace.actors.items():
        # the world pose is the road pose mapped onto the map: same point, recomputed independently
        wx, wy, wh = scenario.route.reference_line.pose(columns["x"] + road.route_shift, columns["y"] - road.width)
        assert columns["world_x"] == pytest.approx(wx) and columns["world_y"] == pytest.approx(wy)
        # the cars follow the curve: they turn with it (the route turns 0.5 rad over the run's 300 m)
        assert columns["world_heading"][-1] - columns["world_heading"][0] > 0.2, name
    ego = trace.actors["ego"]
    assert np.abs(ego["y"] - road.center_y(2)).max() < 0.6, "the ego keeps its lane through the curve"


def offset_map(path: Path) -> Path:
    """A straight 600 m road along +x whose lanes move off the reference line, as published maps'
    do: a lane offset rising from 0 to 3 m over its first 100 m (a cubic), then a 2 m median
    border, then three 3.5 m driving lanes."""
    lane = "<lane id='{id}' type='{type}'><width sOffset='0' a='{width}' b='0' c='0' d='0'/></lane>"
    lanes = "".join(
        lane.format(id=i, type=t, width=w)
        for i, t, w in ((-1, "border", 2.0), (-2, "driving", 3.5), (-3, "driving", 3.5), (-4, "driving", 3.5))
    )
    return one_road_map(
        path,
        600,
        '<geometry s="0" x="0" y="0" hdg="0" length="600"><line/></geometry>',
        '<laneOffset s="0" a="0" b="0" c="0.0009" d="-0.000006"/><laneOffset s="100" a="3" b="0" c="0" d="0"/>'
        '<laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>'
        f"<right>{lanes}</right></laneSection>",
    )


def test_a_lane_offset_and_a_median_move_a_routes_lanes_off_the_reference_line(tmp_path):
    route = pick_route(read_map(offset_map(tmp_path / "offset.xodr")), 3)
    assert route.lanes == 3 and route.lane_width == 3.5
    # the lanes begin at the offset less the 2 m border: -2 m at the start, 1 m from 100 m on
    assert route.inner_edge([0.0, 50.0, 100.0, 400.0]) == pytest.approx([-2.0, -0.5, 1.0, 1.0])
    # the centre of lane 0 (y = 8.75 m left of the right edge of 10.5 m of lanes) lies 1.75 m inside them
    _, y, _ = route.pose([400.0], [route.width - 1.75])
    assert y == pytest.approx([1.0 - 1.75])


def left_hand_map(path: Path) -> Path:
    """A straight 600 m road along +x of left-hand traffic: a 2 m median border beside the centre
    line, then three 3.5 m driving lanes on the left (those going along +x), and one lane on the
    right (the other way)."""
    lane = "<lane id='{id}' type='{type}'><width sOffset='0' a='{width}' b='0' c='0' d='0'/></lane>"
    left = "".join(
        lane.format(id=i, type=t, width=w)
        for i, t, w in ((4, "driving", 3.5), (3, "driving", 3.5), (2, "driving", 3.5), (1, "border", 2.0))
    )
    text = one_road_map(
        path,
        600,
        '<geometry s="0" x="0" y="0" hdg="0" length="600"><line/></geometry>',
        f'<laneSection s="0"><left>{left}</left><right>{lane.format(id=-1, type="driving", width=3.5)}</right></laneSection>',
    ).read_text()
    return write(path, text.replace('junction="-1"', 'junction="-1" rule="LHT"'))


def test_a_left_hand_traffic_road_is_driven_on_its_left_lanes_with_left_and_right_as_a_driver_there_sees_them(tmp_path):
    """Nothing is mirrored: along +x the road's left lanes carry the traffic; the leftmost of the
    route's lanes (lane 0) is by the road's edge, the rightmost beside the median."""
    road_map = read_map(left_hand_map(tmp_path / "lht.xodr"))
    route = pick_route(road_map, 3)
    assert route.lanes == 3 and route.lane_width == 3.5 and route.road.left_hand
    assert not route.reference_line.against  # driven along its line: +x
    centres = [route.width - (lane + 0.5) * route.lane_width for lane in range(3)]
    _, y, heading = route.pose([300.0] * 3, centres)
    assert y == pytest.approx([2.0 + 8.75, 2.0 + 5.25, 2.0 + 1.75])  # left of the line, lane 2 by the median
    assert heading == pytest.approx([0.0] * 3)
    # the other way, against the line, is the right side's one lane
    assert "road 1 (left-hand traffic): 3 driving lanes over 600 m, 1 the other way" in describe(road_map.roads["1"])


def overtake_on(tmp_path: Path, make_map, name: str):
    """The paper's overtake run at seed 1 on the map ``make_map`` writes (as maps/NAME in
    ``tmp_path``), accepted; its outcome."""
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    (tmp_path / "maps").mkdir()
    road_map = make_map(tmp_path / "maps" / name)
    text = (ROOT / "scenarios" / "overtake.osc").read_text()
    scenario = load_scenario(write(tmp_path / "overtake.osc", text), road_map=road_map)
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    return outcome


def test_an_overtake_on_a_left_hand_traffic_road_passes_on_the_left_as_written(tmp_path):
    trace = overtake_on(tmp_path, left_hand_map, "lht.xodr").simulation.trace
    passer, passed = trace.actors["v1"], trace.actors["v2"]
    widest = int(np.argmax(passer["world_y"] - passed["world_y"]))
    # lane(left_of: v2): v1 passes further from the centre line, on the world's left of v2
    assert passer["world_y"][widest] - passed["world_y"][widest] > 2.5
    assert (passer["world_y"] > 0).all() and (passed["world_y"] > 0).all()  # on the road's left side


def with_outer_lane(path: Path, kind: str, width: float) -> str:
    """``offset_map``'s text with its outermost lane (-4) of ``kind`` and ``width``."""
    return (
        offset_map(path)
        .read_text()
        .replace(
            "<lane id='-4' type='driving'><width sOffset='0' a='3.5'",
            f"<lane id='-4' type='{kind}'><width sOffset='0' a='{width:g}'",
        )
    )


def test_a_driving_lane_no_car_fits_in_is_no_lane_there(tmp_path):
    # OpenDRIVE writes a lane that exists in other sections as 0 m wide in this one (esmini's tunnels)
    zero = write(tmp_path / "zero.xodr", with_outer_lane(tmp_path / "zero.xodr", "driving", 0.0))
    assert pick_route(read_map(zero), 2).lanes == 2


def test_a_wide_verge_is_read_where_a_driving_lane_as_wide_is_refused(tmp_path):
    verge = write(tmp_path / "verge.xodr", with_outer_lane(tmp_path / "verge.xodr", "none", 30.0))
    assert pick_route(read_map(verge), 2).lanes == 2
    with pytest.raises(MapError, match="width runs outside 0..20 m"):
        read_map(write(tmp_path / "wide.xodr", with_outer_lane(tmp_path / "wide.xodr", "driving", 30.0)))


def test_a_scenario_runs_in_the_lanes_of_a_map_whose_lanes_are_off_the_reference_line(tmp_path):
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    (tmp_path / "maps").mkdir()
    offset_map(tmp_path / "maps" / "offset.xodr")
    scenario = load_scenario(scenario_file(tmp_path, "maps/offset.xodr"))
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    trace, road = outcome.simulation.trace, outcome.simulation.road
    for name, columns in trace.actors.items():
        # on this straight map the world's y is the lateral position: every car inside the three
        # driving lanes, which begin at the lane offset less the border
        inner = scenario.route.inner_edge(columns["x"] + road.route_shift)
        assert np.all(columns["world_y"] <= inner - 0.8) and np.all(columns["world_y"] >= inner - 10.5 + 0.8), name
    ego = trace.actors["ego"]
    assert np.abs(ego["y"] - road.center_y(2)).max() < 0.6, "the ego keeps its lane where the lanes move"


def test_a_run_on_a_loop_keeps_to_its_lap(tmp_path):
    """A road that ends where it starts (esmini's velodrome): the cars were projected a lap on, from
    30 m to 2,030 m in the first tenth of a second, and no run was conformant."""
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    radius = 400.0
    lanes = "".join(
        f"<lane id='{i}' type='driving'><width sOffset='0' a='3.5' b='0' c='0' d='0'/></lane>" for i in (-1, -2, -3)
    )
    (tmp_path / "maps").mkdir()
    write(
        tmp_path / "maps" / "loop.xodr",
        f"""
        <?xml version="1.0"?>
        <OpenDRIVE><header/>
        <road id="1" length="{2 * math.pi * radius}" junction="-1"><link>
        <predecessor elementType="road" elementId="1" contactPoint="end"/>
        <successor elementType="road" elementId="1" contactPoint="start"/></link><planView>
        <geometry s="0" x="0" y="0" hdg="0" length="{2 * math.pi * radius}"><arc curvature="{1 / radius}"/></geometry>
        </planView><lanes><laneSection s="0"><right>{lanes}</right></laneSection></lanes></road>
        </OpenDRIVE>
        """,
    )
    scenario = load_scenario(scenario_file(tmp_path, "maps/loop.xodr"))
    assert scenario.route.closed
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    for name, columns in outcome.simulation.trace.actors.items():
        assert np.abs(np.diff(columns["x"])).max() < 5.0, name


def test_a_map_with_too_few_lanes_is_refused_at_set_map_with_the_maps_reason(tmp_path):
    from pytest_roadlogic.frontend import check_file

    (tmp_path / "drop.xodr").write_bytes((MAPS / "lane_drop.xodr").read_bytes())
    checked = check_file(scenario_file(tmp_path, "drop.xodr", ego_lane=4))
    errors = [d for d in checked.diagnostics if d.severity == "error"]
    assert errors and errors[0].location.line == 6, checked.report()
    assert "no road of the map has 4 driving lanes" in errors[0].message


def test_a_map_outside_the_folders_the_tool_reads_is_refused_unread(tmp_path):
    from pytest_roadlogic.confinement import ReadRoots
    from pytest_roadlogic.frontend import check_file

    inside = tmp_path / "project"
    inside.mkdir()
    checked = check_file(scenario_file(inside, str(MAPS / "curved_highway.xodr")), roots=ReadRoots.of(inside))
    errors = [d for d in checked.diagnostics if d.severity == "error"]
    assert errors and "outside the folders the tool reads" in errors[0].message


def test_a_town_name_still_runs_on_the_straight_road_with_a_warning(tmp_path):
    from pytest_roadlogic.frontend import check_file

    checked = check_file(scenario_file(tmp_path, "Town04"))
    assert not checked.errors and checked.scenarios[0].route is None
    assert any("straight road" in d.message for d in checked.diagnostics)


def test_the_map_option_runs_every_scenario_on_its_map_and_a_bad_value_is_a_usage_error(pytester):
    plain = SCENARIO.replace('    path.set_map("{map}")\n', "")
    pytester.makefile(".osc", plain=plain.format(ego_lane=1), wide=plain.format(ego_lane=4).replace("curve:", "wide:"))
    (pytester.path / "curved.xodr").write_bytes((MAPS / "curved_highway.xodr").read_bytes())
    result = pytester.runpytest_subprocess(
        "--roadlogic-map", "curved.xodr", "--roadlogic-examples", "2", "-p", "no:cacheprovider"
    )
    # the plain file runs on the map's three lanes; the one that needs a fourth is refused by it
    result.assert_outcomes(passed=1, errors=1)
    assert "the map (the map option)" in result.stdout.str() and "no road of the map has 4 driving lanes" in (
        result.stdout.str()
    )
    bad = pytester.runpytest_subprocess("--roadlogic-map", "curved.txt", "-p", "no:cacheprovider")
    assert bad.ret != 0 and "--roadlogic-map" in bad.stderr.str() + bad.stdout.str()
    assert "Traceback" not in bad.stderr.str() + bad.stdout.str()


def test_the_merge_from_the_ramp_runs_conformant_and_leaves_the_acceleration_lane_before_it_ends():
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    scenario = load_scenario(ROOT / "scenarios" / "roads" / "merge_from_ramp.osc")
    assert scenario.lanes == 4  # the highway's three and the acceleration lane
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    first, last = scenario.route.spans()[3]
    road = outcome.simulation.road
    for name, states in outcome.plan.states.items():
        for state in states:
            along = state.position + outcome.plan.origin
            assert 30.0 <= along <= scenario.route.length - 30.0
            if state.lane == 3:
                assert first <= along <= last, (name, along)
    npc = outcome.simulation.trace.actors["npc"]
    on_ramp = npc["lane"] == 3
    assert on_ramp[0] and not on_ramp[-1], "the npc starts on the acceleration lane and leaves it"
    assert (npc["x"][on_ramp] + road.route_shift).max() <= scenario.route.spans()[3][1] + 10.0
    assert not outcome.simulation.trace.incidents


def test_a_car_asked_to_stay_in_a_lane_past_its_end_has_no_plan(tmp_path):
    from pytest_roadlogic.pipeline import load_scenario, run_scenario
    from pytest_roadlogic.planning import NoPlanError

    (tmp_path / "drop.xodr").write_bytes((MAPS / "lane_drop.xodr").read_bytes())
    stay = write(
        tmp_path / "stay.osc",
        """
        import osc.standard

        scenario stay:
            path: Path
            path.set_map("drop.xodr")
            do serial:
                cruise: parallel(duration: [25s..30s]):
                    ego.drive() with:
                        lane(1)
                        speed([80kph..90kph])
        """,
    )
    # 25 s at 80 kph or more is 555 m: more than the 440 m the ending lane takes a car
    with pytest.raises(NoPlanError):
        run_scenario(load_scenario(stay), seed=1)


def test_the_lane_drop_runs_conformant_and_no_car_is_in_the_ending_lane_past_its_end():
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    scenario = load_scenario(ROOT / "scenarios" / "roads" / "lane_drop.osc")
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    road = outcome.simulation.road
    last = scenario.route.spans()[2][1]
    for name, columns in outcome.simulation.trace.actors.items():
        along = columns["x"] + road.route_shift
        assert not ((columns["lane"] == 2) & (along > last + 10.0)).any(), name
    # both drive on past the end of the lane: the drop is on the scenario's way
    assert (outcome.simulation.trace.actors["ego"]["x"][-1] + road.route_shift) > last


def test_on_a_map_the_planner_knows_the_curve_speed_the_speed_limit_and_where_each_lane_is(tmp_path):
    from pytest_roadlogic.pipeline import load_scenario
    from pytest_roadlogic.planning import settings_for
    from pytest_roadlogic.problem import problem_for
    from pytest_roadlogic.roads.route import MAX_LATERAL_ACCELERATION
    from pytest_roadlogic.settings import RunSettings

    (tmp_path / "s.xodr").write_bytes((MAPS / "s_curve.xodr").read_bytes())
    scenario = load_scenario(scenario_file(tmp_path, "s.xodr"))
    settings = problem_for(scenario, None, settings_for(RunSettings()), 1).settings
    assert settings.max_speed == pytest.approx(math.sqrt(MAX_LATERAL_ACCELERATION * 400.0))
    # a message naming the top speed says where it comes from
    assert dict(settings.limit_reasons)["max_speed"].startswith("the sharpest curve of road 1 of s.xodr, radius 400 m")
    assert settings.road_speed[1] == pytest.approx(100 / 3.6)  # the map's limit, 100 km/h
    assert settings.route_span == (30.0, 970.0) and settings.lane_spans == ()
    ramp = load_scenario(ROOT / "scenarios" / "roads" / "merge_from_ramp.osc")
    settings = problem_for(ramp, None, settings_for(RunSettings()), 1).settings
    ((lane, first, last),) = settings.lane_spans
    assert lane == 3 and 180.0 < first < 200.0 and 395.0 < last < 410.0


@pytest.mark.parametrize(
    "asks, fits",
    [
        ("path.path_curve(min_radius: 300m, max_radius: 450m, side: right)", True),
        ("path.path_curve(min_radius: 300m, max_radius: 350m)", False),
        ("path.path_length(min_length: 900m)", True),
        ("path.path_length(min_length: 1200m)", False),
    ],
)
def test_path_curve_and_path_length_narrow_the_route_and_a_map_without_one_says_what_its_roads_have(
    tmp_path, asks, fits
):
    from pytest_roadlogic.frontend import check_file

    (tmp_path / "s.xodr").write_bytes((MAPS / "s_curve.xodr").read_bytes())
    text = SCENARIO.format(map="s.xodr", ego_lane=1).replace(
        '    path.set_map("s.xodr")\n', f'    path.set_map("s.xodr")\n    {asks}\n'
    )
    checked = check_file(write(tmp_path / "asks.osc", text))
    errors = [d for d in checked.diagnostics if d.severity == "error"]
    if fits:
        assert not errors and checked.scenarios[0].route is not None, checked.report()
    else:
        assert errors and errors[0].location.line == 6, checked.report()
        assert "curves of radius down to left 400 m and right 400 m" in errors[0].message


def test_path_curve_without_a_map_is_an_error_at_it(tmp_path):
    from pytest_roadlogic.frontend import check_file

    text = SCENARIO.format(map="Town04", ego_lane=1).replace(
        '    path.set_map("Town04")\n', "    path.path_curve(min_radius: 300m, max_radius: 450m)\n"
    )
    checked = check_file(write(tmp_path / "curve.osc", text))
    errors = [d for d in checked.diagnostics if d.severity == "error"]
    assert errors and errors[0].location.line == 6 and "straight road" in errors[0].message


def test_the_animation_of_a_run_on_a_curve_draws_the_road_bending(tmp_path):
    from PIL import Image

    from pytest_roadlogic.artifacts.animation import LINE, PALETTE, animate_simulation
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    (tmp_path / "curved.xodr").write_bytes((MAPS / "curved_highway.xodr").read_bytes())
    outcome = run_scenario(load_scenario(scenario_file(tmp_path, "curved.xodr")), seed=1)
    gif = animate_simulation(outcome.simulation, outcome.verdict, tmp_path / "run.gif")
    image = Image.open(gif)
    image.seek(image.n_frames // 2)
    grey = (np.array(image.convert("RGB")) == PALETTE[LINE]).all(axis=2)
    # the road's left edge, the first line's row by column: in a left curve turned level at the
    # centre, it rises toward both ends of the view
    top = [int(np.argmax(grey[:, column])) for column in (5, grey.shape[1] // 2, grey.shape[1] - 5)]
    assert all(grey[row, column] for row, column in zip(top, (5, grey.shape[1] // 2, grey.shape[1] - 5)))
    assert top[0] < top[1] - 3 and top[2] < top[1] - 3, top


def test_past_the_ends_of_a_route_the_road_runs_on_straight_with_its_end_lanes():
    route = pick_route(read_map(MAPS / "curved_highway.xodr"), 3)
    x, y, heading = route.reference_line.pose(np.array([route.length, route.length + 50.0]))
    assert heading[1] == pytest.approx(heading[0])
    assert math.hypot(x[1] - x[0], y[1] - y[0]) == pytest.approx(50.0)
    assert route.right_edge([-20.0, route.length + 80.0]) == pytest.approx([0.0, 0.0])
    drop = pick_route(read_map(MAPS / "lane_drop.xodr"), 3)
    assert drop.right_edge([drop.length + 80.0]) == pytest.approx([3.5])  # two lanes on past the drop


def test_a_scenario_that_asks_for_a_curve_starts_in_it(tmp_path):
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    (tmp_path / "s.xodr").write_bytes((MAPS / "s_curve.xodr").read_bytes())
    asks = "path.path_curve(min_radius: 300m, max_radius: 450m, side: right)"
    text = SCENARIO.format(map="s.xodr", ego_lane=1).replace(
        '    path.set_map("s.xodr")\n', f'    path.set_map("s.xodr")\n    {asks}\n'
    )
    scenario = load_scenario(write(tmp_path / "right.osc", text))
    first, last = scenario.route.start_within
    assert first == pytest.approx(400.0, abs=1.0) and last == pytest.approx(650.0, abs=1.0)  # the right-hand arc
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    assert first - 1e-6 <= outcome.plan.origin <= last + 1e-6


def test_a_broken_map_is_a_located_collection_error_and_the_other_files_still_run(pytester):
    (pytester.path / "bad.xodr").write_text("<OpenDRIVE>\n<road id='1' length='oops'/></OpenDRIVE>\n")
    plain = SCENARIO.replace('    path.set_map("{map}")\n', "").format(ego_lane=1)
    pytester.makefile(
        ".osc", good=plain, broken=SCENARIO.format(map="bad.xodr", ego_lane=1).replace("curve:", "broken:")
    )
    result = pytester.runpytest_subprocess("--roadlogic-examples", "2", "-p", "no:cacheprovider")
    result.assert_outcomes(passed=1, errors=1)
    out = result.stdout.str()
    assert "broken.osc:6:" in out and "bad.xodr:2:" in out and "is not a number" in out
    assert "Traceback" not in out + result.stderr.str()


def test_the_artifacts_of_a_run_on_a_map_are_on_it(tmp_path):
    import json

    from pytest_roadlogic.artifacts.writer import write_artifacts
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    outcome = run_scenario(load_scenario(ROOT / "scenarios" / "roads" / "merge_from_ramp.osc"), seed=1)
    write_artifacts(outcome, tmp_path / "out", animation=False)
    out = tmp_path / "out"
    assert (out / "road.xodr").read_bytes() == (MAPS / "on_ramp.xodr").read_bytes()
    verdict = json.loads((out / "verdict.json").read_text())
    assert verdict["map"]["road"] == "1" and verdict["map"]["origin_m"] == pytest.approx(outcome.plan.origin)
    assert (out / "trace.csv").read_text().splitlines()[0].endswith("world_x,world_y,world_heading")
    # CommonRoad: the lanelets run along the route, in the map's coordinates
    xml = (out / "scenario.xml").read_text()
    assert xml.count("<lanelet ") == outcome.simulation.road.lanes
    plan = json.loads((out / "plan.json").read_text())
    assert plan["origin"] == pytest.approx(outcome.plan.origin)


def test_on_a_curve_a_car_the_plan_holds_still_stays_still_and_a_vehicle_under_test_is_replanned_in_place():
    from pytest_roadlogic.dut import UnderTest
    from pytest_roadlogic.pipeline import load_scenario, run_instances

    scenario = load_scenario(ROOT / "scenarios" / "dut" / "cut_out.osc", road_map=MAPS / "curved_highway.xodr")
    outcome = next(run_instances(scenario, 1, seed=1, under_test=UnderTest(), max_tries=1))
    assert outcome.verdict.accepted and not outcome.dut.failed, outcome.verdict.explain()
    wreck = outcome.simulation.trace.actors["wreck"]
    # (its planned start speed, 0.05 m/s, is its first sample's; held, it stands from then on)
    assert float(np.abs(wreck["speed"][1:]).max()) == 0.0 and float(np.ptp(wreck["x"])) == 0.0
    replans = outcome.simulation.replans
    assert replans and all(r.plan is not None for r in replans)
    # every replan keeps the scenario where the simulation has it on the route
    assert {r.plan.origin for r in replans} == {outcome.plan.origin}


def test_the_grid_encoding_on_a_map_has_no_plan_and_says_why_rather_than_plan_a_straight_road():
    from pytest_roadlogic.pipeline import load_scenario, run_scenario
    from pytest_roadlogic.planning import NoPlanError, settings_for
    from pytest_roadlogic.settings import RunSettings

    scenario = load_scenario(ROOT / "scenarios" / "roads" / "merge_from_ramp.osc")
    with pytest.raises(NoPlanError) as caught:
        run_scenario(scenario, seed=1, settings=settings_for(RunSettings(encoding="grid")))
    assert "needs the continuous encoding" in str(caught.value)


def stepped_map(path: Path) -> Path:
    """Two straight roads along +x, 300 m each, one lane each way, the second's reference line
    1.75 m right of the first's end, its lanes moved back by a lane offset of 1.75 m: their lanes
    continue one another while their lines step sideways (as esmini's fabriksgatan's roads into
    its junction do)."""
    lanes = (
        '<laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>'
        '</left><right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection>'
    )
    return write(
        path,
        f"""
        <?xml version="1.0"?>
        <OpenDRIVE><header/>
        <road id="1" length="300" junction="-1"><link><successor elementType="road" elementId="2" contactPoint="start"/></link>
        <planView><geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry></planView>
        <lanes>{lanes}</lanes></road>
        <road id="2" length="300" junction="-1"><link><predecessor elementType="road" elementId="1" contactPoint="end"/></link>
        <planView><geometry s="0" x="300" y="-1.75" hdg="0" length="300"><line/></geometry></planView>
        <lanes><laneOffset s="0" a="1.75" b="0" c="0" d="0"/>{lanes}</lanes></road>
        </OpenDRIVE>
        """,
    )


def test_a_route_over_roads_whose_lines_step_sideways_where_their_lanes_meet_runs_in_the_lanes(tmp_path):
    """Just past the step the route's line is the second road's, not a line drawn across the step
    from the first road's end (the lanes' edge was put 0.7 m out there, a kink no car followed:
    the cars stopped at fabriksgatan's junction), and a scenario runs through it in its lane."""
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    (tmp_path / "maps").mkdir()
    route = pick_route(read_map(stepped_map(tmp_path / "maps" / "stepped.xodr")), 1)
    assert route.length == pytest.approx(600.0)
    along = np.array([299.0, 300.2, 300.4, 301.0])
    _, line_y, _ = route.reference_line.pose(along)
    assert line_y == pytest.approx([0.0, -1.75, -1.75, -1.75])
    # the lanes' right edge (y = 0 in road coordinates) lies 3.5 m right of the first road's line all along
    _, edge_y, _ = route.pose(along, np.zeros_like(along))
    assert edge_y == pytest.approx([-3.5] * 4)
    scenario = load_scenario(
        write(
            tmp_path / "stepped.osc",
            """
            import osc.standard

            scenario stepped:
                ego: car
                npc: car
                path: Path
                path.set_map("maps/stepped.xodr")
                do parallel(duration: [20s..22s]):
                    ego.drive() with:
                        speed([18mps..20mps])
                    npc.drive() with:
                        position(distance: [20m..30m], ahead_of: ego, at: start)
                        speed([18mps..20mps])
            """,
        )
    )
    outcome = run_scenario(scenario, seed=1)
    assert outcome.simulation.road.route_shift < 300.0 < outcome.simulation.road.route_shift + 360.0  # over the step
    assert outcome.verdict.accepted, outcome.verdict.explain()
    for name, columns in outcome.simulation.trace.actors.items():
        assert np.all(np.abs(np.asarray(columns["world_y"]) + 1.75) < 0.6), name  # the lane's centre


def two_plus_one_map(path: Path) -> Path:
    """A straight 600 m road along +x of one lane each way, with a passing lane for its own
    direction from 200 m to 400 m: it opens on the inside (left of the lane that runs on) over the
    50 m before, as the lane offset moves the road's centre over by a lane, and closes over the 50 m
    after (a 2+1 road: ids are counted from the centre, so the lane that runs on is -1 at the ends
    and -2 along the passing stretch)."""
    step_c, step_d = 3 * 3.5 / 50**2, -2 * 3.5 / 50**3  # a smooth step of 3.5 m over 50 m

    def lane(number: int, *widths: tuple[float, float, float, float, float]) -> str:
        records = "".join(f'<width sOffset="{o}" a="{a}" b="{b}" c="{c}" d="{d}"/>' for o, a, b, c, d in widths)
        return f'<lane id="{number}" type="driving">{records}</lane>'

    full = (0, 3.5, 0, 0, 0)
    oncoming = f"<left>{lane(1, full)}</left>"
    sections = [
        (0, f"<right>{lane(-1, full)}</right>"),
        (150, f"<right>{lane(-1, (0, 0, 0, step_c, step_d))}{lane(-2, full)}</right>"),
        (200, f"<right>{lane(-1, full)}{lane(-2, full)}</right>"),
        (400, f"<right>{lane(-1, (0, 3.5, 0, -step_c, -step_d))}{lane(-2, full)}</right>"),
        (450, f"<right>{lane(-1, full)}</right>"),
    ]
    offsets = (
        f'<laneOffset s="0" a="0" b="0" c="0" d="0"/><laneOffset s="150" a="0" b="0" c="{step_c}" d="{step_d}"/>'
        f'<laneOffset s="200" a="3.5" b="0" c="0" d="0"/><laneOffset s="400" a="3.5" b="0" c="{-step_c}" d="{-step_d}"/>'
        '<laneOffset s="450" a="0" b="0" c="0" d="0"/>'
    )
    return one_road_map(
        path,
        600,
        '<geometry s="0" x="0" y="0" hdg="0" length="600"><line/></geometry>',
        offsets + "".join(f'<laneSection s="{s}">{oncoming}{right}</laneSection>' for s, right in sections),
    )


def test_a_passing_lane_that_opens_on_the_inside_is_lane_2_and_the_lane_that_runs_on_keeps_its_place(tmp_path):
    """On a 2+1 road the lane that runs the whole way is the right one, also where it is the road's
    only lane: the passing lane exists only along its stretch, and the lanes' right edge stays where
    the road's is."""
    route = pick_route(read_map(two_plus_one_map(tmp_path / "two_plus_one.xodr")), 2)
    assert route.lanes == 2
    spans = route.spans()
    # lane 0, the passing lane: where it is a car's width wide (2.8 m, 35 m into its 50 m opening),
    # less half a car
    assert set(spans) == {0} and spans[0] == pytest.approx((188.0, 412.0), abs=1.5)
    along = np.array([50.0, 175.0, 300.0, 425.0, 550.0])
    _, right, _ = route.pose(along, np.zeros_like(along))
    assert right == pytest.approx([-3.5] * 5)  # the right edge: where the road's is, all along
    assert route.left_edge(along) == pytest.approx([3.5, 5.25, 7.0, 5.25, 3.5])
    assert route.lane_width_at(1, along) == pytest.approx([3.5] * 5)


def test_an_overtake_on_a_2_plus_1_road_passes_in_the_passing_lane(tmp_path):
    outcome = overtake_on(tmp_path, two_plus_one_map, "two_plus_one.xodr")
    trace, road = outcome.simulation.trace, outcome.simulation.road
    passing = road.center_y(0)
    for name, columns in trace.actors.items():
        in_passing_lane = np.abs(columns["y"] - passing) < 1.0
        # a car is in the passing lane only where the road has it
        assert (columns["x"][in_passing_lane] + road.route_shift > 150.0).all(), name
        assert (columns["x"][in_passing_lane] + road.route_shift < 450.0).all(), name
    assert (np.abs(trace.actors["v1"]["y"] - passing) < 1.0).any(), "v1 passes in the passing lane"


def test_a_route_of_left_hand_traffic_goes_on_over_the_next_road_on_its_left_lanes(tmp_path):
    """The stepped map's two roads with rule LHT: driven along +x on their left lanes, which
    continue one another where the roads meet (the second's line 1.75 m to the right, its lanes
    moved back by its lane offset), the route is both roads; its lane lies left of the first
    road's line all along."""
    text = stepped_map(tmp_path / "stepped.xodr").read_text().replace('junction="-1"', 'junction="-1" rule="LHT"')
    route = pick_route(read_map(write(tmp_path / "lht_stepped.xodr", text)), 1)
    assert route.length == pytest.approx(600.0) and route.road.left_hand
    along = np.array([100.0, 299.0, 301.0, 500.0])
    x, y, heading = route.pose(along, np.full_like(along, route.width - route.lane_width / 2))
    assert x == pytest.approx(along, abs=0.01) and heading == pytest.approx([0.0] * 4)
    assert y == pytest.approx([1.75] * 4)  # the left lane's centre, on both roads


def pocket_map(path: Path) -> Path:
    """A straight 600 m road along +x of one 3.5 m lane each way; from 300 m on, a lane beside the
    centre line opens on the right (0 to 3.5 m over 100 m: a turn pocket), between the lane that
    runs on and the oncoming one."""
    lane = "<lane id='{id}' type='driving'>{widths}</lane>"
    full = "<width sOffset='0' a='3.5' b='0' c='0' d='0'/>"
    opening = (
        "<width sOffset='0' a='0' b='0' c='0.00105' d='-0.000007'/><width sOffset='100' a='3.5' b='0' c='0' d='0'/>"
    )
    left = lane.format(id=1, widths=full)
    return one_road_map(
        path,
        600,
        '<geometry s="0" x="0" y="0" hdg="0" length="600"><line/></geometry>',
        f"<laneSection s='0'><left>{left}</left><right>{lane.format(id=-1, widths=full)}</right></laneSection>"
        f"<laneSection s='300'><left>{left}</left>"
        f"<right>{lane.format(id=-1, widths=opening)}{lane.format(id=-2, widths=full)}</right></laneSection>",
    )


def test_a_lane_that_opens_between_a_roads_lane_and_the_oncoming_one_is_refused_saying_so(tmp_path):
    """Joined with its oncoming lane, the road's lanes are [oncoming, own] and then [oncoming,
    pocket, own]: the lanes that run on move apart by a lane where the sections meet, and no one
    numbering holds all along. Its own lanes alone number one way (the pocket opens at their left)."""
    from pytest_roadlogic.roads.directions import with_oncoming
    from pytest_roadlogic.roads.route import lane_opens_between

    road_map = read_map(pocket_map(tmp_path / "pocket.xodr"))
    road = road_map.roads["1"]
    assert not lane_opens_between(road) and lane_opens_between(with_oncoming(road))
    with pytest.raises(MapError) as refused:
        pick_route(road_map, 3)
    assert "a lane there opens between two that run on" in refused.value.message
    # where the pocket is wide enough for a car, lane 0 (the leftmost of the two)
    assert pick_route(road_map, 2).spans() == {0: pytest.approx((375.0, 597.0), abs=3.0)}


def bays_map(path: Path) -> Path:
    """A straight 300 m road along +x of one 3.5 m lane each way, and beyond the left one a row of
    parking bays drawn as one driving lane: 0 m wide, then 3.5 m for 40 m, then 0 again, every 60 m
    (as esmini's parking_demo draws them)."""
    bays = "".join(
        f"<width sOffset='{start}' a='0' b='0.7' c='0' d='0'/><width sOffset='{start + 5}' a='3.5' b='0' c='0' d='0'/>"
        f"<width sOffset='{start + 45}' a='3.5' b='-0.7' c='0' d='0'/><width sOffset='{start + 50}' a='0' b='0' c='0' d='0'/>"
        for start in range(0, 300, 60)
    )
    full = "<width sOffset='0' a='3.5' b='0' c='0' d='0'/>"
    left = f"<lane id='2' type='driving'>{bays}</lane><lane id='1' type='driving'>{full}</lane>"
    right = f"<lane id='-1' type='driving'>{full}</lane>"
    return one_road_map(
        path,
        300,
        '<geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry>',
        f"<laneSection s='0'><left>{left}</left><right>{right}</right></laneSection>",
    )


def test_a_row_of_parking_bays_drawn_as_a_driving_lane_is_no_lane_to_overtake_in():
    """A bay beyond the oncoming lane is no lane to pass in (it had been joined as a second
    oncoming lane, a car's width wide 40 m at a time): a scenario of two lanes runs in the road's
    own lane and its oncoming one, as on a road of one lane each way. Driven the other way, the
    bays are the road's own lanes beside its one: two lanes side by side for 40 m at a time are no
    road of two lanes (MIN_SIDE_BY_SIDE)."""
    import tempfile

    from pytest_roadlogic.roads.directions import oncoming_lanes

    with tempfile.TemporaryDirectory() as folder:
        road_map = read_map(bays_map(Path(folder) / "bays.xodr"))
    (section,) = road_map.roads["1"].sections
    assert oncoming_lanes(section) == 1
    route = pick_route(road_map, 2)
    assert route.road.oncoming == 1 and route.lanes == 2 and route.spans() == {}
    assert not route.road.against
