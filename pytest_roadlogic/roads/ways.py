"""The ways a scenario's paths may take through its map together (``Ways``), found by the
answer-set solver (``asp/map/ways.lp``) from the standard's ``map.roads_follow_in_junction()``.

Each path asks for a turn of some kind (direction, roads at the junction) and may name fields of
the scenario as its junction, its road in and its road out: two paths that name one field take
the same junction or road. Which turns satisfy that is a constraint problem over the map's graph;
every answer is a way the scenario may run, and the choice among them is a logical parameter of
the scenario, one per path (``Ways.choices``): sampled, shrunk to the first (the roomiest ways
first: ``choose_ways``), written into the case file by its label ("left from road 2 into road 1
at junction 100") and replayed.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import clingo

from ..asp_dir import ASP_DIR
from .asks import RouteRelation, TurnAsk
from .choice import MIN_ROUTE_LENGTH, ROOM, fitting_turns, turn_as_route
from .junctions import Turn, describe_junctions, turns
from .opendrive_in import MapError, RoadMap
from .route import Route, through_lanes

ENCODING = ASP_DIR / "map" / "ways.lp"
# answers enumerated at most: a map of many junctions and a scenario that names nothing could
# have more; the first in the map's order are kept
MAX_WAYS = 5000


class WaysError(ValueError):
    """Ways of paths that do not go together, or a way a path cannot take (a case file, --values)."""


def _key(turn: Turn) -> tuple[str, str, str, str]:
    return (turn.junction, turn.into.id, turn.inside.id, turn.out_of.id)


@dataclass(frozen=True)
class Ways:
    """The ways ``paths`` may take together in ``road_map``: ``combinations`` holds, per answer, the
    index in ``turns`` (the map's turns that fit some path, in the map's order) of each path's
    turn, the roomiest first (``choose_ways``); the first is the one a scenario runs when nothing
    is sampled.
    ``crossers``: per path, the vehicles that drive it."""

    road_map: RoadMap
    paths: tuple[str, ...]
    turns: tuple[Turn, ...]
    labels: tuple[str, ...]  # one per turn, as reports, case files and --values name it
    combinations: tuple[tuple[int, ...], ...]
    crossers: tuple[frozenset[str], ...]
    # whether every two paths' ways meet (cross, join or part; paths in sequence apart) in every
    # answer: False where the map has no such ways of the kinds asked, and the paths take ways
    # that never meet
    meet: bool = True
    # (path index, turn index) -> its route, built when first asked for (``route_of``)
    built: dict = field(default_factory=dict, compare=False, hash=False, repr=False)

    def choices(self, path: str) -> tuple[str, ...]:
        """The ways ``path`` takes in some answer, in the answers' order."""
        return self.options(path, {})

    def options(self, path: str, drawn: dict[str, str]) -> tuple[str, ...]:
        """The ways ``path`` may take together with the ways ``drawn`` for other paths, in the
        order of the first answer each is in (the roomiest first)."""
        k = self.paths.index(path)
        return tuple(self.labels[t] for t in dict.fromkeys(c[k] for c in self._agreeing(drawn)))

    def chosen(self, given: dict[str, str]) -> tuple[int, ...]:
        """The first answer (the roomiest) whose ways are those ``given`` (path -> label; a
        path not given: any); ``WaysError`` when the ways given do not go together."""
        for combination in self._agreeing(given):
            return combination
        # the first path, in the scenario's order, whose way does not go with those before it
        before: dict[str, str] = {}
        for path in self.paths:
            if path not in given:
                continue
            options = self.options(path, before)
            if given[path] not in options:
                unknown = given[path] not in self.choices(path)
                why = (
                    "is no way it may take"
                    if unknown or not before
                    else f"does not go with {', '.join(f'{p} = {v!r}' for p, v in before.items())}"
                )
                raise WaysError(f"{path} = {given[path]!r} {why}; it may take: {', '.join(options)}")
            before[path] = given[path]
        raise WaysError(f"no ways of the map go together as {given!r} name them")

    def routes(self, given: dict[str, str] | None = None) -> tuple[Route, ...]:
        """The routes of the first answer with the ways ``given``, one per path (built once each)."""
        return tuple(self.route_of(k, t) for k, t in enumerate(self.chosen(given or {})))

    def _agreeing(self, given: dict[str, str]) -> Iterable[tuple[int, ...]]:
        wanted = {self.paths.index(path): label for path, label in given.items() if path in self.paths}
        return (c for c in self.combinations if all(self.labels[c[k]] == label for k, label in wanted.items()))

    def route_of(self, k: int, turn: int) -> Route:
        """The route of path ``k`` (driven by its ``crossers``) along ``turns[turn]``."""
        if (k, turn) not in self.built:
            self.built[k, turn] = turn_as_route(self.road_map, self.turns[turn], self.crossers[k])
        return self.built[k, turn]


def choose_ways(
    road_map: RoadMap,
    lanes: int,
    length: float,
    asks: tuple[TurnAsk, ...],
    crossers: tuple[frozenset[str], ...],
    relations: tuple[RouteRelation, ...] = (),
) -> Ways:
    """Every way ``asks``' paths may take together in ``road_map`` (``asp/map/ways.lp``): a turn per
    ask of the kind it names with ``lanes`` driving lanes and ``length`` metres in all
    (``choice.fitting_turns``), the junction and roads agreeing with the fields the asks share,
    and, where some choice allows it, every path's way with as many driving lanes and every two
    paths on different turns whose ways meet; else only the first answer that agrees (two paths in
    sequence are not there to meet); and the standard's map ``relations`` between the paths'
    routes. Answers whose routes' lanes differ from the first's are left out (a scenario has one
    lane count). ``MapError`` when an ask has no turn of its kind, or
    no turns of their kinds go together."""
    length = length or MIN_ROUTE_LENGTH  # room to drive, as pick_route gives a single route
    fitting_by_ask = [fitting_turns(road_map, lanes, length, ask) for ask in asks]
    fitting = [{_key(t) for t in turns_of_ask} for turns_of_ask in fitting_by_ask]
    # room enough is ROOM each side of the junction (what ``choice.roomy`` gives a short turn)
    room = {
        _key(t): min(t.clear_before, ROOM) + min(t.clear_after, ROOM)
        for turns_of_ask in fitting_by_ask
        for t in turns_of_ask
    }
    offered = [t for t in turns(road_map) if any(_key(t) in keys for keys in fitting)]
    facts = [f"path({k})." for k in range(len(asks))]
    # the map's junctions and roads by number: their ids are the map's text, never the program's
    junction = {j: n for n, j in enumerate(dict.fromkeys(t.junction for t in offered))}
    road = {r: n for n, r in enumerate(dict.fromkeys(r.id for t in offered for r in (t.into, t.out_of)))}
    for index, turn in enumerate(offered):
        facts.append(
            f"at({index},{junction[turn.junction]}). into({index},{road[turn.into.id]}). "
            f"out_of({index},{road[turn.out_of.id]})."
        )
        facts += [f"fits({k},{index})." for k, keys in enumerate(fitting) if _key(turn) in keys]
    fields: dict[str, int] = {}  # the scenario's fields by number, as the map's ids
    for k, ask in enumerate(asks):
        for kind, name in (("junction", ask.junction), ("in_road", ask.in_road), ("out_road", ask.out_road)):
            if name is not None:
                facts.append(f"names({k},{fields.setdefault(name, len(fields))},{kind}).")
    for r in relations:
        if r.relation == "overlap":
            facts.append(f"overlaps({r.first},{r.second},{r.kind}).")
        else:
            facts.append(f"relation({r.first},{r.second},{r.relation}).")
        if r.road is not None:
            facts.append(f"on_road({r.first},{r.second},{r.relation},{fields.setdefault(r.road, len(fields))}).")
    lanes_of = [min(through_lanes(t.into)[1], through_lanes(t.out_of)[1]) for t in offered]
    facts += [f"lanes({index},{lanes})." for index, lanes in enumerate(lanes_of)]
    partial = Ways(road_map, tuple(a.path for a in asks), tuple(offered), (), (), crossers)
    facts += [f"meets({t},{u})." for t, u in _meeting(partial, asks, fitting)]
    # ways of as many lanes first (a scenario plans one number of lanes: other ways are refused
    # naming their lanes), then ways that meet
    answers, together = [], True
    for together, same_lanes, every in (
        (True, True, True),
        (False, True, False),
        (True, False, False),
        (False, False, False),
    ):
        answers = _solve(facts, together=together, same_lanes=same_lanes)
        if answers:
            answers = answers if every else answers[:1]
            break
    if not answers:
        raise MapError(
            road_map.path,
            "no turns of the map go together as the scenario asks ("
            + "; ".join(ask.describe() for ask in asks)
            + f"): {describe_junctions(road_map)}",
            "name in roads_follow_in_junction only the junction and roads two turns must share, or give a map with such a junction",
        )
    answers = [a for a in answers if [lanes_of[t] for t in a] == [lanes_of[t] for t in answers[0]]]
    # the roomiest first: the least room any of its routes has around its junction, the most (a
    # scenario's cars need room to approach and leave, and a town's short roads have little); ways
    # with room enough, and equal ones, in the map's order
    answers.sort(key=lambda answer: -min(room[_key(offered[t])] for t in answer))
    return Ways(
        road_map, partial.paths, partial.turns, _labels(offered), tuple(answers), crossers, together, partial.built
    )


def _meeting(ways: Ways, asks: tuple[TurnAsk, ...], fitting: list[set]) -> list[tuple[int, int]]:
    """The pairs of ``ways.turns`` (t < u) that two different paths could take together (each fits
    its path, and they agree on the fields both paths name) and whose ways meet."""
    from .conflicts import meetings_of

    keys = [_key(t) for t in ways.turns]
    found: set[tuple[int, int]] = set()
    tried: set[tuple[int, int]] = set()
    for p in range(len(asks)):
        for q in range(p + 1, len(asks)):
            for t, key_t in enumerate(keys):
                if key_t not in fitting[p]:
                    continue
                for u, key_u in enumerate(keys):
                    pair = (min(t, u), max(t, u))
                    if u == t or key_u not in fitting[q] or pair in tried:
                        continue
                    if not _agree(asks[p], ways.turns[t], asks[q], ways.turns[u]):
                        continue
                    tried.add(pair)
                    if meetings_of(0, ways.route_of(p, t), 1, ways.route_of(q, u)):
                        found.add(pair)
    return sorted(found)


def _fields(ask: TurnAsk, turn: Turn) -> dict[str, tuple[str, str]]:
    """The values ``turn`` gives the fields ``ask`` names."""
    given = (
        (ask.junction, ("junction", turn.junction)),
        (ask.in_road, ("road", turn.into.id)),
        (ask.out_road, ("road", turn.out_of.id)),
    )
    return {name: value for name, value in given if name is not None}


def _agree(ask: TurnAsk, turn: Turn, other_ask: TurnAsk, other: Turn) -> bool:
    mine, theirs = _fields(ask, turn), _fields(other_ask, other)
    return all(theirs.get(name, value) == value for name, value in mine.items())


def _solve(facts: list[str], together: bool, same_lanes: bool) -> list[tuple[int, ...]]:
    """The answers of ``asp/map/ways.lp`` on ``facts`` (each path's turn index), in the map's order,
    with its externals ``together`` and ``same_lanes`` set as given."""
    # projected on the ways: a road field named only by a relation may be any road it holds on
    control = clingo.Control([str(MAX_WAYS), "--project", "--warn=none"])
    control.load(str(ENCODING))
    control.add("base", [], "\n".join(facts))
    control.ground([("base", [])])
    control.assign_external(clingo.Function("together"), together)
    control.assign_external(clingo.Function("same_lanes"), same_lanes)
    answers = []
    with control.solve(yield_=True) as handle:
        for model in handle:
            ways = sorted((a.arguments[0].number, a.arguments[1].number) for a in model.symbols(shown=True))
            answers.append(tuple(t for _, t in ways))
    return sorted(answers)


def _labels(offered: list[Turn]) -> tuple[str, ...]:
    """Each turn's label: what it is and where, with its connecting road where two are alike."""
    plain = [f"{t.describe()} at junction {t.junction}" for t in offered]
    return tuple(
        label if plain.count(label) == 1 else f"{label} via road {t.inside.id}" for label, t in zip(plain, offered)
    )
