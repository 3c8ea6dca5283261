"""The ways a scenario's paths take through its map, from the standard's roads_follow_in_junction():
the solver's answers are exactly the turns that agree on the fields the paths share and whose
ways meet; each path's way is a logical parameter, drawn only among the ways that go with those
drawn before it, shrunk to the first in the map's order, refused with the ways it may take, and
driven by a run as the sample names it."""

from __future__ import annotations

import dataclasses
import itertools
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, find, given, settings
from hypothesis import strategies as st

from pytest_roadlogic.frontend import load_file
from pytest_roadlogic.frontend.semantics.logical import WAY
from pytest_roadlogic.roads.asks import TurnAsk
from pytest_roadlogic.roads.choice import fitting_turns, turn_as_route
from pytest_roadlogic.roads.conflicts import meetings_of
from pytest_roadlogic.roads.opendrive_in import read_map
from pytest_roadlogic.roads.ways import choose_ways
from pytest_roadlogic.runner import Runner, replay
from pytest_roadlogic.sampling import UnknownParameter, on_ways, strategy
from pytest_roadlogic.settings import RunSettings

ROOT = Path(__file__).resolve().parents[2]
TOWN = ROOT / "scenarios" / "junctions" / "maps" / "town.xodr"
TOWN_SCENARIO = ROOT / "scenarios" / "junctions" / "turn_at_a_junction_of_the_town.osc"


@pytest.fixture(scope="module")
def town():
    return load_file(TOWN_SCENARIO).scenario_to_run(None)


def test_the_solver_answers_every_pair_of_turns_at_one_junction_whose_ways_meet_and_no_other():
    road_map = read_map(TOWN)
    asks = (TurnAsk(junction="j", path="a"), TurnAsk(junction="j", path="b"))
    ways = choose_ways(road_map, 1, 200.0, asks, (frozenset(), frozenset()))
    # brute force, from the definition: two different turns of one junction whose routes meet
    offered = fitting_turns(road_map, 1, 200.0, TurnAsk())
    routes = {id(t): turn_as_route(road_map, t) for t in offered}
    expected = {
        (first.describe(), first.junction, second.describe(), second.junction)
        for first, second in itertools.permutations(offered, 2)
        if first.junction == second.junction and meetings_of(0, routes[id(first)], 1, routes[id(second)])
    }
    answered = {
        (ways.turns[a].describe(), ways.turns[a].junction, ways.turns[b].describe(), ways.turns[b].junction)
        for a, b in ways.combinations
    }
    assert answered == expected
    assert {junction for _, junction, _, _ in answered} == {"100", "200"}  # the town's two junctions
    assert list(ways.combinations) == sorted(ways.combinations)  # in the map's order, the first the default


def test_paths_take_ways_of_as_many_lanes_where_the_map_has_them(monkeypatch):
    """A scenario plans one number of lanes, so of the ways that go together the solver answers
    those whose lanes agree, where there are any (in CARLA's Town04 the first answer had a turn
    off a two-lane road beside a one-lane way, and the scenario was refused). Checked against the
    answers without lanes, filtered by the definition."""
    import pytest_roadlogic.roads.ways as ways_module

    road_map = read_map(TOWN)
    asks = (TurnAsk(junction="j", path="a"), TurnAsk(junction="j", path="b"))
    crossers = (frozenset(), frozenset())
    every = choose_ways(road_map, 1, 200.0, asks, crossers)  # the town's roads have one lane each

    def lanes(road):  # roads of odd ids have two lanes one way; a turn keeps its fewer
        return 1, 1 + int(road.id) % 2

    monkeypatch.setattr(ways_module, "through_lanes", lanes)
    agreeing = choose_ways(road_map, 1, 200.0, asks, crossers)

    def of(turn):
        return min(lanes(turn.into)[1], lanes(turn.out_of)[1])

    expected = {
        tuple(every.turns[t].describe() for t in answer)
        for answer in every.combinations
        if of(every.turns[answer[0]]) == of(every.turns[answer[1]])
    }
    answered = {tuple(agreeing.turns[t].describe() for t in answer) for answer in agreeing.combinations}
    first = {of(agreeing.turns[t]) for t in agreeing.combinations[0]}
    assert expected and len(first) == 1
    # of those, the ones with the first answer's lanes (a scenario has one lane count)
    assert answered == {
        answer
        for answer in expected
        if {of(next(t for t in every.turns if t.describe() == d)) for d in answer} == first
    }


def test_a_path_that_may_take_several_ways_is_a_logical_parameter_at_its_roads_follow_in_junction(town):
    ways = {p.name: p for p in town.parameters if p.kind == WAY}
    assert set(ways) == {"ego_way", "other_way"}
    assert ways["ego_way"].location.line == 11 and ways["other_way"].location.line == 12
    assert len(ways["ego_way"].choices) == 18  # every turn of the town's two junctions
    # unsampled, a run takes the first answer
    assert town.route.turn == "left from road 2 into road 1 at junction 100"


@settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_every_sample_takes_ways_that_go_together(town, data):
    values = data.draw(strategy(town))
    chosen = town.ways.chosen({path: values[path] for path in town.ways.paths})
    assert [town.ways.labels[t] for t in chosen] == [values[path] for path in town.ways.paths]


def test_a_failing_way_shrinks_to_the_first_way_of_the_map_that_still_fails(town):
    # "fails at the T-junction": the simplest such sample is its first turn with the first that meets it
    values = find(
        strategy(town),
        lambda v: v["ego_way"].endswith("junction 200"),
        settings=settings(database=None, max_examples=500, suppress_health_check=list(HealthCheck)),
    )
    assert values["ego_way"] == "left from road 5 into road 3 at junction 200"
    assert values["other_way"] == "straight from road 6 into road 3 at junction 200"


def test_a_sample_runs_on_the_routes_of_the_ways_it_names_and_a_way_that_does_not_fit_is_refused(town):
    on_t = on_ways(
        town,
        {
            "ego_way": "straight from road 3 into road 6 at junction 200",
            "other_way": "left from road 6 into road 5 at junction 200",
        },
    )
    assert [r.turn for r in on_t.routes] == [
        "straight from road 3 into road 6 at junction 200",
        "left from road 6 into road 5 at junction 200",
    ]
    assert on_t.routes[0].crossers == frozenset({"ego"}) and on_t.routes[1].crossers == frozenset({"other"})
    # one path named: the other takes the first way that goes with it
    assert on_ways(town, {"ego_way": "right from road 5 into road 6 at junction 200"}).routes[1].turn == (
        "left from road 5 into road 3 at junction 200"
    )
    with pytest.raises(UnknownParameter, match="ego_way = 'a U-turn' is not one of"):
        on_ways(town, {"ego_way": "a U-turn"})
    with pytest.raises(
        UnknownParameter,
        match=r"other_way = 'left from road 2 into road 1 at junction 100' does not go with ego_way = "
        r"'straight from road 3 into road 6 at junction 200'; it may take: left from road 5 into road 3 at junction 200,",
    ):
        on_ways(
            town,
            {
                "ego_way": "straight from road 3 into road 6 at junction 200",
                "other_way": "left from road 2 into road 1 at junction 100",
            },
        )


def test_a_case_on_ways_the_sample_names_is_driven_there_and_replays_exactly(town, tmp_path):
    values = {
        "ego_way": "straight from road 3 into road 6 at junction 200",
        "other_way": "left from road 6 into road 5 at junction 200",
        "parallel.duration": 15.0,
        "other.drive.speed.speed": 7.0,
    }
    runner = Runner(town, RunSettings(seed=1))
    result = runner.run_case(runner.case(strategy="refined", values=values))
    assert result.kind == "accepted"
    road = result.run.simulation.road_of("other")
    assert road.route.turn == "left from road 6 into road 5 at junction 200"
    # each car drove through the junction; one held short of it would not have taken its turn
    simulation = result.run.simulation
    assert simulation.turns_not_taken() == []
    held = {
        **simulation.trace.actors["other"],
        "x": np.full(len(simulation.trace.times), simulation.trace.actors["other"]["x"][0]),
    }
    short = dataclasses.replace(
        simulation, trace=dataclasses.replace(simulation.trace, actors={**simulation.trace.actors, "other": held})
    )
    (missed,) = short.turns_not_taken()
    assert (
        missed.actors == ("other",) and missed.kind == "turn not taken (left from road 6 into road 5 at junction 200)"
    )
    # the way is written into the case file by its label, and read back
    again = replay(type(result.case).load(result.case.save(tmp_path / "case.json")))
    assert again.case.values == values
    first, second = result.run.simulation.trace, again.run.simulation.trace
    assert set(first.actors) == set(second.actors) and np.array_equal(first.times, second.times)
    for actor, signals in first.actors.items():
        assert all(np.array_equal(values, second.actors[actor][name]) for name, values in signals.items())


AS_THE_STANDARD_WRITES_IT = """scenario left_turn_across_oncoming:
    map: map
    crossing: junction
    approach: road
    map.set_map("crossing.xodr")
    ego_turn: map.roads_follow_in_junction(junction: crossing, in_road: approach, direction: left)
    oncoming_way: map.roads_follow_in_junction(junction: crossing, out_road: approach, direction: straight)
    ego: car
    oncoming: car
    do parallel(duration: [14s..20s]):
        ego.drive() with:
            along(ego_turn.resulting_route)
        oncoming.drive() with:
            along(oncoming_way.resulting_route)
            speed([30kph..50kph])
"""


def _standard_file(folder: Path, text: str) -> Path:
    (folder / "crossing.xodr").write_bytes((TOWN.parent / "crossing.xodr").read_bytes())
    path = folder / "turns.osc"
    path.write_text(text)
    return path


def test_a_labelled_roads_follow_in_junction_is_a_way_its_resulting_route_is_driven_along(tmp_path):
    checked = load_file(_standard_file(tmp_path, AS_THE_STANDARD_WRITES_IT)).scenario_to_run(None)
    assert checked.ways.paths == ("ego_turn", "oncoming_way")
    assert [r.crossers for r in checked.routes] == [{"ego"}, {"oncoming"}]
    ego, oncoming = (ways.turns[t] for ways in (checked.ways,) for t in ways.combinations[0])
    # the oncoming way leaves the junction on the road the left turn comes in on, as the fields say
    assert ego.direction == "left" and oncoming.direction == "straight" and oncoming.out_of.id == ego.into.id
    assert {p.name for p in checked.parameters if p.kind == WAY} == {"ego_turn", "oncoming_way"}


@pytest.mark.parametrize(
    "change, message",
    [
        (
            ("    map.set_map", "    lanes_asked: map.path_min_driving_lanes(1)\n    map.set_map"),
            r"turns.osc:5:22: error: not supported: a label on path_min_driving_lanes\(\)",
        ),
        (
            ("along(ego_turn.resulting_route)", "along(ego_turn.junction_route)"),
            r"turns.osc:12:19: error: not supported: ego_turn.junction_route: a vehicle drives along "
            r"ego_turn.resulting_route",
        ),
        (
            ("ego_turn: map.roads", "approach: map.roads"),
            r"turns.osc:6:\d+: error: approach is already a field of the scenario",
        ),
    ],
    ids=[
        "a label on another map modifier",
        "a route the tool does not read",
        "a label that is a field",
    ],
)
def test_a_label_the_tool_cannot_read_is_refused_at_its_line(tmp_path, change, message):
    from pytest_roadlogic.frontend import OscError
    from pytest_roadlogic.pipeline import load_scenario

    text = AS_THE_STANDARD_WRITES_IT.replace(*change)
    with pytest.raises(OscError, match=message):
        load_scenario(_standard_file(tmp_path, text))


def test_a_way_on_which_the_scenario_has_no_plan_is_set_aside_never_blamed(tmp_path):
    # held to 20-40 kph all along, the other car cannot take a turn (its bend holds a car to
    # 18-20 kph): the ways it turns on have no plan, which is the map's, not a defect of the file
    text = TOWN_SCENARIO.read_text().replace("speed([20kph..40kph], at: start)", "speed([20kph..40kph])")
    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "town.xodr").write_bytes(TOWN.read_bytes())
    (tmp_path / "town.osc").write_text(text)
    scenario = load_file(tmp_path / "town.osc").scenario_to_run(None)
    ran, set_aside = [], []
    Runner(scenario, RunSettings(seed=1)).refined(ran.append, count=6, search=False, set_aside=set_aside.append)
    assert set_aside and all(not r.case.values["other_way"].startswith("straight") for r in set_aside)
    assert all(r.culprit is None for r in ran + set_aside)
    assert all(r.outcome == "conformant" for r in ran)


def test_a_value_is_blamed_only_with_no_plan_on_the_samples_ways_nor_on_the_maps_first_others(town):
    """Blame tries a value alone on the sample's own ways and on the map's first answers unlike
    them (WAYS_TRIED in all): the sample's ways may be the map's first, and a value with no plan on
    one junction of a town may have plans on the next."""
    from pytest_roadlogic.blame import WAYS_TRIED, Blame

    ways = town.ways
    first = {path: ways.labels[t] for path, t in zip(ways.paths, ways.combinations[0])}
    second = {path: ways.labels[t] for path, t in zip(ways.paths, ways.combinations[1])}
    tried = Blame(town, RunSettings(seed=1)).ways_to_try(first)
    assert len(tried) == WAYS_TRIED and tried[0] == first and tried[1] == second
    assert len({tuple(sorted(t.items())) for t in tried}) == len(tried)  # each way once
    assert Blame(town, RunSettings(seed=1)).ways_to_try(second)[:2] == [second, first]


MERGING = """scenario right_turn_merging_into_traffic:
    map: map
    map.set_map("crossing.xodr")
    ego_turn: map.roads_follow_in_junction(direction: right)
    traffic_way: map.roads_follow_in_junction(direction: straight)
    map.routes_overlap(route1: ego_turn.resulting_route, route2: traffic_way.resulting_route, overlap_kind: end)
    ego: car
    traffic: car
    do parallel(duration: [14s..20s]):
        ego.drive() with:
            along(ego_turn.resulting_route)
        traffic.drive() with:
            along(traffic_way.resulting_route)
"""


@pytest.mark.parametrize("kind, same", [("end", ("out_of",)), ("start", ("into",)), ("any", ("into", "out_of"))])
def test_routes_overlap_keeps_exactly_the_ways_that_share_the_road_in_or_out(tmp_path, kind, same):
    text = MERGING.replace("overlap_kind: end", f"overlap_kind: {kind}")
    ways = load_file(_standard_file(tmp_path, text)).scenario_to_run(None).ways
    pairs = [(ways.turns[a], ways.turns[b]) for a, b in ways.combinations]
    # brute force: every right turn with every way straight on that shares that road with it
    road_map = read_map(TOWN.parent / "crossing.xodr")
    expected = {
        (r.describe(), s.describe())
        for r in fitting_turns(road_map, 1, 200.0, TurnAsk("right"))
        for s in fitting_turns(road_map, 1, 200.0, TurnAsk("straight"))
        if any(getattr(r, road).id == getattr(s, road).id for road in same)
    }
    assert {(r.describe(), s.describe()) for r, s in pairs} == expected and len(expected) == 4 * len(same)


def _driven(turn) -> set[tuple[str, bool]]:
    """The roads a turn's route drives, each with whether it drives it against its reference line."""
    return {(road.id, road.against) for road in (turn.into, turn.out_of)}


def _town_file(folder: Path, text: str) -> Path:
    (folder / "town.xodr").write_bytes(TOWN.read_bytes())
    path = folder / "turns.osc"
    path.write_text(text)
    return path


OPPOSITE = """scenario left_turn_across_oncoming:
    map: map
    approach: road
    map.set_map("town.xodr")
    ego_turn: map.roads_follow_in_junction(direction: left)
    oncoming_way: map.roads_follow_in_junction(direction: straight)
    map.routes_are_opposite(route1: ego_turn.resulting_route, route2: oncoming_way.resulting_route)
    ego: car
    oncoming: car
    do parallel(duration: [14s..20s]):
        ego.drive() with:
            along(ego_turn.resulting_route)
        oncoming.drive() with:
            along(oncoming_way.resulting_route)
"""


@pytest.mark.parametrize(
    "bound", [None, "approach", "ego_turn.in_road"], ids=["any road", "the ego's road in", "the label's road in"]
)
def test_routes_are_opposite_keeps_exactly_the_ways_that_drive_a_road_in_opposite_directions(tmp_path, bound):
    text = OPPOSITE
    if bound == "approach":  # the road both drive is the one the left turn comes in on: the oncoming car's way out
        text = text.replace("(direction: left)", "(direction: left, in_road: approach)")
    if bound:  # the label's in_road is the road its turn comes in on, as a field bound to it is
        text = text.replace(
            "oncoming_way.resulting_route)\n", f"oncoming_way.resulting_route, containing_road: {bound})\n", 1
        )
    ways = load_file(_town_file(tmp_path, text)).scenario_to_run(None).ways
    answered = {(ways.turns[a].describe(), ways.turns[b].describe()) for a, b in ways.combinations}
    # brute force, from the definition: a road both routes drive, against its reference line in one
    # and along it in the other; of those, the pairs whose ways meet (two paths are there to meet)
    road_map = read_map(TOWN)
    lefts = fitting_turns(road_map, 1, 200.0, TurnAsk("left"))
    straights = fitting_turns(road_map, 1, 200.0, TurnAsk("straight"))
    expected = set()
    for left, straight in itertools.product(lefts, straights):
        shared = {road: against for road, against in _driven(left)} if not bound else {left.into.id: left.into.against}
        if not any(shared.get(road) == (not against) for road, against in _driven(straight)):
            continue
        if meetings_of(0, turn_as_route(road_map, left), 1, turn_as_route(road_map, straight)):
            expected.add((left.describe(), straight.describe()))
    assert answered == expected and expected
    if bound:  # the oncoming way: from the road opposite, out on the road the left turn comes in on
        assert all(left.split()[3] == straight.split()[-1] for left, straight in answered)


SEQUENCE = """scenario one_junction_after_the_other:
    map: map
    between: road
    map.set_map("town.xodr")
    first_turn: map.roads_follow_in_junction()
    next_turn: map.roads_follow_in_junction()
    map.routes_are_in_sequence(preceding: first_turn.resulting_route, succeeding: next_turn.resulting_route, road: between)
    ego: car
    lead: car
    do parallel(duration: [14s..20s]):
        ego.drive() with:
            along(first_turn.resulting_route)
        lead.drive() with:
            along(next_turn.resulting_route)
"""


def test_routes_are_in_sequence_keeps_exactly_the_ways_that_come_in_on_the_road_the_first_leaves_on(tmp_path):
    ways = load_file(_town_file(tmp_path, SEQUENCE)).scenario_to_run(None).ways
    answered = {(ways.turns[a].describe(), ways.turns[b].describe()) for a, b in ways.combinations}
    # brute force: the second route drives on along the road the first leaves on, the same way
    # (paths in sequence pass different junctions: they are not asked to meet)
    offered = fitting_turns(read_map(TOWN), 1, 200.0, TurnAsk())
    expected = {
        (first.describe(), second.describe())
        for first, second in itertools.product(offered, offered)
        if (first.out_of.id, first.out_of.against) == (second.into.id, second.into.against)
    }
    assert answered == expected and len(expected) == 12  # through road 3, either way along it
    assert {first.split()[-1] for first, _ in answered} == {"3"}


@pytest.mark.parametrize(
    "text, change, message",
    [
        (
            OPPOSITE,
            ("oncoming_way.resulting_route)\n", "oncoming_way.resulting_route, lateral_overlap: always)\n"),
            r"turns.osc:7:\d+: error: not supported: lateral_overlap always",
        ),
        (
            OPPOSITE,
            ("route2: oncoming_way.resulting_route", "route2: ego_turn.resulting_route"),
            r"turns.osc:7:\d+: error: routes_are_opposite\(\) relates the routes of two different paths",
        ),
        (
            SEQUENCE,
            ("road: between", "road: first_turn"),
            r"turns.osc:7:\d+: error: road: takes a road of the map, a field of the scenario",
        ),
        (
            SEQUENCE,
            ('    map.set_map("town.xodr")\n', ""),
            r"turns.osc:\d+:\d+: error: roads_follow_in_junction\(\) asks for a junction, but the scenario runs on the straight road",
        ),
    ],
    ids=["lateral overlap", "one path twice", "road not a road", "no map"],
)
def test_a_relation_between_routes_the_tool_cannot_read_is_refused_at_its_line(tmp_path, text, change, message):
    from pytest_roadlogic.frontend import OscError
    from pytest_roadlogic.pipeline import load_scenario

    with pytest.raises(OscError, match=message):
        load_scenario(_town_file(tmp_path, text.replace(*change)))


@pytest.mark.parametrize(
    "change, message",
    [
        (("overlap_kind: end", "overlap_kind: inside"), r"turns.osc:6:\d+: error: not supported: overlap_kind inside"),
        (
            ("route2: traffic_way.resulting_route", "route2: ego_turn.resulting_route"),
            r"turns.osc:6:\d+: error: routes_overlap\(\) relates the routes of two different paths",
        ),
    ],
    ids=["inside", "one path twice"],
)
def test_a_routes_overlap_the_tool_cannot_read_is_refused_at_its_line(tmp_path, change, message):
    from pytest_roadlogic.frontend import OscError
    from pytest_roadlogic.pipeline import load_scenario

    with pytest.raises(OscError, match=message):
        load_scenario(_standard_file(tmp_path, MERGING.replace(*change)))


def test_a_labels_junction_and_roads_name_what_its_turn_takes_wherever_the_scenario_names_them(tmp_path):
    """my_turn.junction, .in_road and .out_road are the map elements my_turn's way takes, as fields
    bound to them would be: a right turn at ego_turn's junction into the road it leaves on."""
    from pytest_roadlogic.frontend import OscError

    text = OPPOSITE.replace(
        "    ego: car\n",
        "    other_turn: map.roads_follow_in_junction(direction: right, junction: ego_turn.junction, "
        "out_road: ego_turn.out_road)\n    ego: car\n",
    )
    ways = load_file(_town_file(tmp_path, text)).scenario_to_run(None).ways
    assert ways.combinations
    for left, _, right in ((ways.turns[a], ways.turns[b], ways.turns[c]) for a, b, c in ways.combinations):
        assert right.junction == left.junction and right.out_of.id == left.out_of.id
    with pytest.raises(OscError, match=r"the road of ego_turn's turn is ego_turn.in_road or ego_turn.out_road"):
        load_file(_town_file(tmp_path, text.replace("out_road: ego_turn.out_road", "out_road: ego_turn.out")))
