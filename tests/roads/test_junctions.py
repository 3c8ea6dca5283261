"""Turns at junctions, from their definitions: a junction's turns read from the map's geometry and
named as the standard's ``roads_follow_in_junction`` names them, the route of a turn, the speed its
bend allows, a turn the map lacks refused with the turns it has, and the junction suite run."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pytest_roadlogic.roads.asks import TurnAsk
from pytest_roadlogic.roads.junctions import direction, turns
from pytest_roadlogic.roads.opendrive_in import MapError, read_map
from pytest_roadlogic.roads.route import MAX_LATERAL_ACCELERATION
from pytest_roadlogic.roads.ways import choose_ways
from tests.roads.map_files import recipe, write
from tests.roads.test_roads import same_document

ROOT = Path(__file__).resolve().parents[2]
SUITE = ROOT / "scenarios" / "junctions"
MAPS = SUITE / "maps"


def the_turn(road_map, lanes, length, direction, roads):
    """The route of the first turn of the kind asked, as a scenario with one path runs it."""
    return choose_ways(road_map, lanes, length, (TurnAsk(direction, roads),), (frozenset(),)).routes()[0]


def test_the_committed_junction_maps_are_what_their_recipe_writes(tmp_path):
    for written in recipe(MAPS).write(tmp_path):
        assert same_document(written, MAPS / written.name), written.name


@pytest.mark.parametrize(
    "degrees, name",
    [
        (0, "straight"),
        (29, "straight"),
        (-29, "straight"),
        (31, "left"),
        (90, "left"),
        (-90, "right"),
        (150, "uturn"),
        (-179, "uturn"),
    ],
)
def test_a_turns_direction_is_named_by_how_far_its_heading_turns(degrees, name):
    assert direction(math.radians(degrees)) == name


def test_a_four_way_crossing_offers_every_turn_from_every_arm_each_turning_as_its_name_says():
    road_map = read_map(MAPS / "crossing.xodr")
    offered = turns(road_map)
    assert len(offered) == 12  # four arms, three ways out of each
    for name, angle in (("left", 90.0), ("right", -90.0), ("straight", 0.0)):
        named = [t for t in offered if t.direction == name]
        assert len(named) == 4, name
        assert {t.into.id for t in named} == {"1", "2", "3", "4"}
        for turn in named:
            # the heading's change, read from the world poses where the turn's route enters and leaves
            _, _, heading_in = turn.into.reference_line.pose(np.array([turn.into.length]))
            _, _, heading_out = turn.out_of.reference_line.pose(np.array([0.0]))
            turned = (float(heading_out[0] - heading_in[0]) + math.pi) % (2 * math.pi) - math.pi
            assert math.degrees(turned) == pytest.approx(angle, abs=1.0)


def test_a_turns_route_runs_on_without_a_gap_through_the_junction_in_its_lane():
    route = the_turn(read_map(MAPS / "crossing.xodr"), 1, 0.0, "left", 4)
    first, last = route.junction_span
    s = np.arange(0.0, route.length, 0.5)
    x, y, _ = route.pose(s, np.full(len(s), route.width / 2))  # the lane's centre
    steps = np.hypot(np.diff(x), np.diff(y))
    # half a metre along the reference line is more along the outer lane of a left turn, never a jump
    assert steps.max() < 0.65 and steps.min() > 0.4
    assert 190.0 < first < last < 250.0 and route.lanes == 1 and route.lane_width == pytest.approx(3.5)


def test_a_turn_is_driven_no_faster_than_its_lane_lets_a_car_hold_and_only_there():
    road_map = read_map(MAPS / "crossing.xodr")
    for name in ("left", "right"):
        route = the_turn(road_map, 1, 0.0, name, 4)
        ((first, last, speed),) = route.slow_stretches
        begin, end = route.junction_span
        assert first <= begin + 1.0 and last >= end - 1.0  # the bend is the junction's
        # the lane's centre is 1.75 m right of the connecting road's reference line: a left turn's
        # lane bends less sharply than the line, a right turn's more (k / (1 - k t))
        k = route.greatest_curvature(begin, end)
        lane_radius = 1 / k + (1.75 if name == "left" else -1.75)
        assert speed == pytest.approx(math.sqrt(MAX_LATERAL_ACCELERATION * lane_radius), rel=0.02)
        assert route.gentle_curvature() == 0.0  # the streets are straight: no limit elsewhere


def test_a_turn_the_map_lacks_is_refused_with_the_junctions_and_their_turns():
    road_map = read_map(MAPS / "t_junction.xodr")
    with pytest.raises(MapError) as refused:
        the_turn(road_map, 1, 0.0, "left", 4)
    message = refused.value.message
    assert message.startswith("no left turn at a junction of 4 roads in the map: junction 100 ('t-junction'), 3 roads:")
    assert "right from road 1 into road 2" in message and "straight from road 3 into road 1" in message
    with pytest.raises(MapError, match="no U-turn at a junction"):
        the_turn(road_map, 1, 0.0, "uturn", None)


SCENARIO = """\
    scenario turn:
        path: Path
        path.set_map("maps/t_junction.xodr")
        path.roads_follow_in_junction({ask})
        ego: car
        do parallel(duration: [10s..15s]):
            ego.drive() with:
                along(path)
"""


def test_check_refuses_a_turn_the_map_lacks_at_the_line_asking_for_it_naming_what_it_has(tmp_path):
    from pytest_roadlogic.frontend import OscError
    from pytest_roadlogic.pipeline import load_scenario

    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "t_junction.xodr").write_bytes((MAPS / "t_junction.xodr").read_bytes())
    path = write(tmp_path / "turn.osc", SCENARIO.format(ask="direction: uturn"))
    with pytest.raises(OscError) as refused:
        load_scenario(path)
    text = str(refused.value)
    # at the line that asks for the turn (the map itself is read at set_map, line 3)
    assert (
        "turn.osc:4:10: error: the map" in text
        and "no U-turn at a junction" in text
        and "left from road 2 into road 1" in text
    )


def test_a_turn_without_a_map_and_a_junction_too_small_are_errors_at_their_lines(tmp_path):
    from pytest_roadlogic.frontend import OscError
    from pytest_roadlogic.pipeline import load_scenario

    lines = SCENARIO.format(ask="direction: left").splitlines(keepends=True)
    text = "".join(line for line in lines if "set_map" not in line)
    with pytest.raises(OscError, match=r"turn.osc:3:\d+: error: roads_follow_in_junction\(\) asks for a junction"):
        load_scenario(write(tmp_path / "turn.osc", text))
    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "t_junction.xodr").write_bytes((MAPS / "t_junction.xodr").read_bytes())
    with pytest.raises(OscError, match="number_of_roads takes one whole number from 3 up"):
        load_scenario(write(tmp_path / "turn.osc", SCENARIO.format(ask="number_of_roads: 2")))


def test_every_vehicle_driving_along_the_turn_goes_through_the_junction_no_faster_than_its_bend_allows():
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.pipeline import load_scenario
    from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings

    scenario = load_scenario(SUITE / "left_turn_behind_lead.osc")
    assert scenario.route.crossers == {"ego", "lead"}
    settings = ContinuousSettings(time_limit=30.0).on_route(scenario.route)
    planner = ContinuousPlanner(build_automaton(scenario), settings, 1)
    plan = planner.first()
    assert planner.stats["least_action"] == 1.0
    begin, end = scenario.route.junction_span
    ((first, last, speed),) = scenario.route.slow_stretches
    for name, states in plan.states.items():
        along = [state.position + plan.origin for state in states]
        assert along[0] <= begin and along[-1] >= end, name
        for step in range(1, len(states)):
            # a step that ends in the bend, or leaves a place short of it for one beyond its entry
            # (1 mm: the linear program's values at the bend's ends are its ends)
            if first + 1e-3 < along[step] < last - 1e-3 or (
                along[step - 1] < first - 1e-3 and along[step] > first + 1e-3
            ):
                assert states[step].speed <= speed + 1e-6, (name, step)
                assert states[step - 1].speed <= speed + 1e-6, (name, step)


@pytest.mark.parametrize("name", ["left_turn_behind_lead", "right_turn_at_t_junction", "straight_across"])
def test_the_junction_suite_runs_conformant_each_car_in_its_lane_through_the_turn(name):
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    scenario = load_scenario(SUITE / f"{name}.osc")
    outcome = run_scenario(scenario, seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()
    assert not outcome.simulation.trace.incidents
    for vehicle, columns in outcome.simulation.trace.actors.items():
        # within half a metre of its lane's centre all along, the turn included
        assert np.abs(np.asarray(columns["y"]) - scenario.route.lane_width / 2).max() < 0.5, vehicle


def test_the_plot_of_a_turn_draws_every_road_of_its_junction():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from pytest_roadlogic.artifacts.plot import _junction_roads

    route = the_turn(read_map(MAPS / "crossing.xodr"), 1, 0.0, "right", 4)
    figure, axes = plt.subplots()
    try:
        _junction_roads(axes, route)
        # four arms and six connecting roads, each its two outer edges
        assert len(axes.lines) == 20
    finally:
        plt.close(figure)


def test_a_car_where_the_simulators_frame_has_no_projection_stands_as_a_fallback_not_a_traceback():
    from pytest_roadlogic.pipeline import load_scenario, run_scenario
    from pytest_roadlogic.simulation.driver import VehicleState
    from pytest_roadlogic.simulation.frenetix import FrenetixDriver

    answers = []

    class Astray:
        """frenetix, asked once for a car 1 km off the route (a town corner tighter than a lane's
        distance from the reference line puts a car so: fabriksgatan's)."""

        def __init__(self):
            self.inner = FrenetixDriver()

        def start(self, vehicle, reference, road, dt):
            self.inner.start(vehicle, reference, road, dt)

        def plan(self, time, state, others):
            if not answers and time > 1.0:
                astray = VehicleState(state.x, state.y + 1000.0, state.heading, state.speed, 0.0)
                answers.append((self.inner.plan(time, astray, others), self.inner.fallbacks))
            return self.inner.plan(time, state, others)

    scenario = load_scenario(SUITE / "straight_across.osc")
    run_scenario(scenario, seed=1, max_tries=1, drivers=lambda v: Astray() if v == "ego" else None)
    ((trajectory, fallbacks),) = answers
    # it holds its place (the standing trajectory), counted as a fallback
    assert fallbacks == 1 and float(np.ptp(trajectory.x)) == 0.0 and float(trajectory.y[0]) > 900.0


def test_a_turn_the_map_has_but_too_short_for_the_scenario_is_refused_saying_how_long_it_is():
    with pytest.raises(MapError) as refused:
        the_turn(read_map(MAPS / "crossing.xodr"), 1, 1000.0, "left", 4)
    message = refused.value.message
    assert message.startswith("of the map's 4 turns of the kind path asks (left from road 2 into road 1,")
    assert "4 have 1 driving lane in and out, none 1000 m of road in all (at most 433 m)" in message


def test_a_turn_whose_road_in_is_short_is_approached_from_the_road_before_it_straight_through_the_last_junction():
    """with_room: the roads a car comes from are added before the road in (through the town's
    other junction straight on), the turn itself stays the same, and the junction lies as far
    along the longer route as the roads before it add. A turn with room enough is left as it is."""
    from pytest_roadlogic.roads.choice import MIN_APPROACH, MIN_ROUTE_LENGTH, roomy
    from pytest_roadlogic.roads.junctions import junction_span, turn_route, with_room

    town = read_map(MAPS / "town.xodr")
    turn = next(t for t in turns(town) if t.describe() == "straight from road 3 into road 1")
    longer = with_room(town, turn, turn.into.length + 20.0, 0.0)
    assert [road.id for road in longer.before] == ["6", "201"] and longer.after == ()
    assert longer.roads == turn.roads and longer.describe() == turn.describe()
    added = sum(road.length for road in longer.before)
    assert longer.approach == pytest.approx(turn.into.length + added)
    assert junction_span(longer) == pytest.approx((turn.approach + added, turn.approach + added + turn.inside.length))
    # the route starts where road 6 is driven from, and reaches the junction where the turn's own does
    route, own = turn_route(longer), turn_route(turn)
    x, y, _ = route.reference_line.pose(np.array([added]))
    x0, y0, _ = own.reference_line.pose(np.array([0.0]))
    assert (float(x[0]), float(y[0])) == pytest.approx((float(x0[0]), float(y0[0])), abs=0.05)
    assert with_room(town, turn, MIN_APPROACH, MIN_ROUTE_LENGTH) == turn  # 200 m in and out: room enough
    assert roomy(town, turn) == turn


def _crossing_with_a_corner(folder: Path, straight: float) -> Path:
    """The recipe's four-way crossing, its west arm (road 1) coming round a town's corner: 100 m,
    a 90-degree bend of 20 m radius, then ``straight`` metres into the junction."""
    from scenariogeneration import xodr

    module = recipe(MAPS)
    arms = {number: module._arm(number) for number in (2, 3, 4)}
    bent = xodr.create_road(
        [xodr.Line(100.0), xodr.Arc(1 / 20.0, angle=math.pi / 2), xodr.Line(straight)],
        id=1,
        left_lanes=1,
        right_lanes=1,
        lane_width=module.LANE_WIDTH,
    )
    bent.add_elevation(0.0, 0.0, 0.0, 0.0, 0.0)
    bent.add_type(xodr.RoadType.town, 0, speed=50, speed_unit="km/h")
    arms[1] = bent
    angles = {1: 0.0, 2: math.pi / 2, 3: math.pi, 4: 3 * math.pi / 2}
    creator = module._creator(100, "crossing", {n: (road, angles[n], "successor") for n, road in arms.items()})
    opendrive = module._opendrive("corner", [arms[n] for n in sorted(arms)], [creator])
    path = folder / "corner.xodr"
    opendrive.write_xml(str(path))
    return path


def test_a_turns_room_ends_at_a_corner_before_it_and_no_car_is_planned_round_that_corner(tmp_path):
    """A town's corner on the road in is a turn of its own: the route's room (``Turn.room``,
    ``Route.within``) ends there, the planner keeps every car ROUTE_MARGIN short of it, and a
    scenario's cars never slow down for a bend nobody asked for."""
    from pytest_roadlogic.planning.encodings.continuous.settings import RouteFacts
    from pytest_roadlogic.roads.choice import MIN_APPROACH, fitting_turns, roomy, turn_as_route
    from pytest_roadlogic.roads.route import ROUTE_MARGIN

    road_map = read_map(_crossing_with_a_corner(tmp_path, 80.0))
    turn = roomy(road_map, next(t for t in turns(road_map) if t.describe() == "straight from road 1 into road 3"))
    arc = math.pi / 2 * 20.0
    assert turn.approach == pytest.approx(100.0 + arc + 80.0, abs=0.5)
    assert turn.clear_before == pytest.approx(80.0, abs=1.0)  # back to the bend's end
    assert turn.clear_after == pytest.approx(turn.leave)  # road 3 is straight
    route = turn_as_route(road_map, turn)
    first, last = route.within
    assert first == pytest.approx(turn.approach - turn.clear_before) and last == pytest.approx(route.length)
    facts = RouteFacts.of(route)
    assert facts.route_span == pytest.approx((first + ROUTE_MARGIN, last - ROUTE_MARGIN))
    # the corner is a slow stretch of the route, and every car stays past it
    assert any(end <= facts.route_span[0] for _, end, _ in route.slow_stretches[:1])
    # with the corner 40 m before the junction, road 1 leaves too little room to approach on
    short = read_map(_crossing_with_a_corner(tmp_path, 40.0))
    bent = roomy(short, next(t for t in turns(short) if t.describe() == "straight from road 1 into road 3"))
    assert bent.clear_before < MIN_APPROACH
    offered = [t.describe() for t in fitting_turns(short, 1, 0.0, TurnAsk("straight", 4))]
    assert "straight from road 1 into road 3" not in offered and "straight from road 3 into road 1" not in offered
    assert "straight from road 2 into road 4" in offered


def test_on_a_crossing_of_left_hand_traffic_the_right_turn_crosses_the_oncoming_way_and_the_left_does_not(tmp_path):
    """The recipe's crossing with every road of left-hand traffic: cars drive on the left, nothing
    is mirrored. A left turn is the short turn there and never meets the oncoming car going
    straight on (the scenario written for right-hand traffic is said to have ways that never
    meet); the right turn crosses its way."""
    from scenariogeneration import xodr

    opendrive = recipe(MAPS).maps()["crossing.xodr"]
    for road in opendrive.roads.values():
        road.rule = xodr.TrafficRule.LHT
    path = tmp_path / "crossing_lht.xodr"
    opendrive.write_xml(str(path))
    road_map = read_map(path)

    def ways(direction: str):
        asks = (
            TurnAsk(direction, junction="j", in_road="approach", path="turn"),
            TurnAsk("straight", junction="j", out_road="approach", path="oncoming"),
        )
        return choose_ways(road_map, 1, 0.0, asks, (frozenset({"ego"}), frozenset({"npc"})))

    assert not ways("left").meet and ways("right").meet
    # the left turn's route keeps to the left of its roads' reference lines: cars drive on the left
    route = ways("left").routes()[0]
    s = np.array([20.0, route.length - 20.0])
    _, _, heading = route.reference_line.pose(s)
    x, y, _ = route.pose(s, np.full(2, route.width / 2))
    x0, y0, _ = route.reference_line.pose(s)
    left_of_line = -np.sin(heading) * (x - x0) + np.cos(heading) * (y - y0)
    assert (left_of_line > 1.0).all()


def test_a_car_sweeping_wide_of_its_lane_round_a_turn_is_on_the_road_and_one_beyond_every_lane_is_off_it():
    from types import SimpleNamespace

    from pytest_roadlogic.roads.road import Road
    from pytest_roadlogic.simulation.geometry import corners

    route = the_turn(read_map(MAPS / "crossing.xodr"), 1, 0.0, "right", 4)
    road = Road(lanes=route.lanes, lane_width=route.lane_width, route=route)
    begin, end = route.junction_span
    middle = (begin + end) / 2

    def car(y: float) -> tuple[bool, bool]:
        """Whether a car ``y`` metres left of its lane's right edge, midway round the turn, heading
        along the lane, is on its lane (road coordinates) and on the junction (world)."""
        state = SimpleNamespace(x=middle, y=y, heading=0.0)
        wx, wy, wh = road.world(middle, y)
        world = SimpleNamespace(x=float(wx), y=float(wy), heading=float(wh))
        return road.on_road(corners(state)), road.on_junction(corners(world))

    assert car(1.75) == (True, True)  # the lane's centre
    # a metre out of its lane on the outside of the right turn: over the junction's other lanes
    assert car(1.75 + 2.6) == (False, True)
    # beyond the crossing's lanes on the inside of the turn: the kerb
    assert car(-6.0) == (False, False)
    # a route that turns at no junction has no junction to be on
    straight = Road(lanes=1)
    assert not straight.on_junction(corners(SimpleNamespace(x=0.0, y=1.75, heading=0.0)))
