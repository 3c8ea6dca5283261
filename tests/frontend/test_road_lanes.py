"""How many lanes the road has: from the scenario, unless an option fixes it.

A scenario says what road it needs (``path.path_min_driving_lanes(n)``, ``path.path_max_lanes(n)``,
and implicitly every lane number and lane change it writes); the checker resolves the count once
and every later stage (automaton, plan, simulation, CommonRoad file) uses that same number.
"""

import subprocess
import sys

import pytest

from pytest_roadlogic.artifacts.commonroad import commonroad_scenario
from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import check_file, check_text
from pytest_roadlogic.pipeline import run_scenario

PAIR = "scenario s:\n    a: car\n    b: car\n"


def lanes_of(text: str, lanes: int | None = None) -> int:
    checked = check_text(text, "t.osc", lanes=lanes)
    assert not checked.errors, checked.report()
    return checked.scenarios[0].lanes


def errors_of(text: str, lanes: int | None = None) -> list[str]:
    return [
        f"{d.location.line}:{d.location.column}: {d.message}" for d in check_text(text, "t.osc", lanes=lanes).errors
    ]


def side_by_side(a_lane: str, b_lane: str = "lane(1, at: all)", head: str = PAIR) -> str:
    return (
        head
        + f"    do parallel(duration: 3s):\n        a.drive() with:\n            {a_lane}\n        b.drive() with:\n            {b_lane}\n"
    )


@pytest.mark.parametrize(
    "text, expected",
    [
        pytest.param(side_by_side("lane(same_as: b, at: all)", "keep_lane()"), 3, id="no lane number: the default 3"),
        pytest.param(side_by_side("lane(2, at: all)"), 3, id="lanes within the default"),
        pytest.param(side_by_side("lane(5, at: all)"), 5, id="the highest lane number"),
        pytest.param(side_by_side("lane(4, from: left, at: all)"), 4, id="counted from the left"),
        pytest.param(
            PAIR
            + "    k: int with:\n        keep(it in [2..4])\n"
            + "    do parallel(duration: 3s):\n        a.drive() with:\n            lane(k, at: all)\n        b.drive()\n",
            4,
            id="a lane parameter's range",
        ),
        pytest.param(
            PAIR + "    do serial:\n        a.change_lane(3, left)\n        b.drive()\n", 4, id="a change of 3 lanes"
        ),
        pytest.param(side_by_side("change_lane(4, right)"), 5, id="a change_lane modifier"),
        pytest.param(
            side_by_side("lane(2, at: all)", head=PAIR + "    road: Path\n    road.path_min_driving_lanes(5)\n"),
            5,
            id="path_min_driving_lanes",
        ),
        pytest.param(
            side_by_side("lane(2, at: all)", head=PAIR + "    road: Path\n    road.path_max_lanes(2)\n"),
            2,
            id="path_max_lanes below the default",
        ),
        pytest.param(
            side_by_side("lane(2, at: all)", head=PAIR + "    path_min_driving_lanes(4)\n"),
            4,
            id="the bare form without a Path field",
        ),
        pytest.param(
            side_by_side("lane(2, at: all)", head=PAIR + "    map: map\n    map.number_of_lanes(map, 5)\n"),
            5,
            id="the standard's number_of_lanes above the default",
        ),
        pytest.param(
            side_by_side(
                "lane(1, at: all)",
                head=PAIR + "    map: map\n    map.number_of_lanes(map, 2, driving, directionality: uni_direction)\n",
            ),
            2,
            id="number_of_lanes below the default, counting driving lanes one way",
        ),
    ],
)
def test_the_road_is_as_wide_as_the_scenario_needs(text, expected):
    assert lanes_of(text) == expected


def test_the_lanes_option_wins_over_the_inferred_count():
    assert lanes_of(side_by_side("lane(2, at: all)"), lanes=6) == 6
    assert errors_of(side_by_side("lane(5, at: all)"), lanes=4) == [
        "6:18: lane 5 is outside the road's 4 lanes (set by the lanes option)"
    ]


def test_a_lanes_option_that_contradicts_the_scenario_names_the_declaration():
    text = side_by_side("lane(2, at: all)", head=PAIR + "    road: Path\n    road.path_min_driving_lanes(5)\n")
    assert errors_of(text, lanes=3) == ["5:10: the scenario asks for at least 5 lanes, but the lanes option sets 3"]


def test_a_lane_beyond_path_max_lanes_names_the_bound():
    text = side_by_side("lane(3, at: all)", head=PAIR + "    road: Path\n    road.path_max_lanes(2)\n")
    assert errors_of(text) == ["8:18: lane 3 is outside the road's 2 lanes (path_max_lanes(2) on line 5)"]


@pytest.mark.parametrize(
    "road, message",
    [
        ("map.number_of_lanes(map, 2)", "8:18: lane 3 is outside the road's 2 lanes (number_of_lanes(2) on line 5)"),
        (
            "map.number_of_lanes(map, 3, pedestrian)",
            "5:33: not supported: lane_type pedestrian: the tool counts a road's driving lanes one way",
        ),
        (
            "map.number_of_lanes(map, 3, directionality: bi_direction)",
            "5:49: not supported: directionality bi_direction: the tool counts a road's driving lanes one way",
        ),
        (
            "map.number_of_lanes(map, 3)\n    map.path_max_lanes(4)",
            "6:9: path_max_lanes() is already given on line 5",
        ),
    ],
    ids=["a lane beyond it", "another lane type", "both directions", "a second bound"],
)
def test_number_of_lanes_fixes_the_roads_lanes_and_a_count_the_tool_cannot_make_is_refused_at_its_argument(
    road, message
):
    text = side_by_side("lane(3, at: all)", head=PAIR + f"    map: map\n    {road}\n")
    assert errors_of(text) == [message]


def test_each_scenario_of_a_file_has_its_own_road():
    text = side_by_side("lane(4, at: all)") + side_by_side("lane(1, at: all)").replace("scenario s:", "scenario t:")
    checked = check_text(text, "t.osc")
    assert not checked.errors, checked.report()
    assert [s.lanes for s in checked.scenarios] == [4, 3]


def test_the_scenarios_road_reaches_the_automaton_the_plan_and_the_simulation():
    # a on the leftmost of four lanes, b on the rightmost: only a four-lane road can hold this
    text = side_by_side("lane(4, at: all)", "lane(1, at: all)")
    scenario = check_text(text, "t.osc").scenarios[0]
    automaton = build_automaton(scenario)
    assert automaton.lanes == 4
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    assert outcome.plan.lanes == 4
    assert {s.lane for s in outcome.plan.states["a"]} == {0}, (
        "lane(4) counted from the right is internal lane 0, the leftmost"
    )
    assert {s.lane for s in outcome.plan.states["b"]} == {3}
    assert outcome.simulation.road.lanes == 4
    commonroad, _problems = commonroad_scenario(outcome.simulation)
    assert len(commonroad.lanelet_network.lanelets) == 4


def test_roadlogic_check_takes_the_road_from_the_file_and_the_option_overrides_it(tmp_path):
    path = tmp_path / "wide.osc"
    path.write_text(side_by_side("lane(5, at: all)"))

    def check(*extra):
        return subprocess.run(
            [sys.executable, "-m", "pytest_roadlogic.cli", "check", str(path), *extra], capture_output=True, text=True
        )

    assert check().returncode == 0, check().stdout
    narrow = check("--lanes", "3")
    assert narrow.returncode == 1
    assert f"{path}:6:18: error: lane 5 is outside the road's 3 lanes (set by the lanes option)" in narrow.stdout


def test_the_plugin_takes_the_road_from_the_file_unless_the_lanes_option_is_given(tmp_path):
    (tmp_path / "wide.osc").write_text(side_by_side("lane(5, at: all)"))

    def collect(*extra):
        return subprocess.run(
            [
                sys.executable,
                "-m",
                "pytest",
                "--collect-only",
                "-q",
                "-p",
                "no:cacheprovider",
                "--rootdir",
                str(tmp_path),
                str(tmp_path),
                *extra,
            ],
            capture_output=True,
            text=True,
            cwd=tmp_path,
        )

    wide = collect()
    assert wide.returncode == 0, wide.stdout
    assert "wide.osc::s" in wide.stdout
    narrow = collect("--roadlogic-lanes", "3")
    assert narrow.returncode != 0
    assert "lane 5 is outside the road's 3 lanes (set by the lanes option)" in narrow.stdout


@pytest.mark.parametrize("lanes, error", [(3, None), (2, "has 3 driving lanes, more than number_of_lanes(2)")])
def test_number_of_lanes_on_a_map_takes_a_road_with_as_many_lanes_or_says_the_map_has_none(tmp_path, lanes, error):
    from pathlib import Path

    maps = Path(__file__).resolve().parents[2] / "scenarios" / "roads" / "maps"
    (tmp_path / "curved_highway.xodr").write_bytes((maps / "curved_highway.xodr").read_bytes())
    text = (
        'scenario s:\n    map: map\n    map.set_map("curved_highway.xodr")\n'
        f"    map.number_of_lanes(map, {lanes})\n    ego: car\n    do ego.drive(duration: 5s)\n"
    )
    (tmp_path / "t.osc").write_text(text)
    checked = check_file(tmp_path / "t.osc")
    if error is None:
        assert not checked.errors, checked.report()
        assert checked.scenarios[0].lanes == lanes
    else:
        assert [d.message for d in checked.errors] == [f"the route on road 1 of curved_highway.xodr {error}"]


@pytest.mark.parametrize(
    "kept, lanes",
    [
        ("keep(it.min_lanes == 2)", 2),
        ("keep(it.min_lanes >= 4)", 4),
        ("keep(it.min_lanes > 4)", 5),
        ("keep(it.max_lanes <= 2)", 2),
        ("keep(2 == it.max_lanes)", 2),
    ],
)
def test_a_route_or_road_with_its_lanes_kept_is_the_scenarios_road_as_the_standards_examples_write_it(kept, lanes):
    for declared in ("route", "road"):
        text = (
            PAIR
            + f"    r: {declared} with:\n        {kept}\n"
            + "    do parallel(duration: 3s):\n        a.drive() with:\n            along(r)\n"
            + "        b.drive() with:\n            along(route: r)\n"
        )
        assert lanes_of(text) == lanes, (declared, kept)


def test_a_lane_beyond_a_kept_lane_count_names_the_keep_and_a_second_bound_is_refused():
    head = PAIR + "    r: route with:\n        keep(it.min_lanes == 2)\n"
    assert errors_of(side_by_side("lane(3, at: all)", head=head)) == [
        "8:18: lane 3 is outside the road's 2 lanes (keep(it.min_lanes == 2) on line 5)"
    ]
    twice = PAIR + "    r: route with:\n        keep(it.min_lanes >= 2)\n        keep(it.min_lanes >= 3)\n"
    assert errors_of(side_by_side("lane(1, at: all)", head=twice)) == [
        "6:9: keep(it.min_lanes >= 3) bounds the road's lanes again: keep(it.min_lanes >= 2) on line 5"
    ]


def test_the_maps_inner_side_is_the_left_and_its_outer_side_the_right_in_right_hand_traffic():
    head = PAIR + "    map: map\n"
    for side, expected in (("inner_side", 0), ("outer_side", 2)):
        text = side_by_side(f"lane(side_of: b, side: map.{side}(), at: all)", head=head)
        checked = check_text(text, "t.osc")
        assert not checked.errors, checked.report()
        guard = next(t.guard for t in build_automaton(checked.scenarios[0]).transitions if "l(a" in str(t.guard))
        assert f"l(a) - l(b) = {expected - 1}" in str(guard)


def test_a_road_driven_along_and_named_by_no_map_modifier_is_the_scenarios_road():
    text = side_by_side("along(my_road)", head=PAIR + "    my_road: road\n")
    checked = check_text(text, "t.osc")
    assert not checked.errors, checked.report()
    assert checked.scenarios[0].lanes == 3
