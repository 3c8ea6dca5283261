"""How many lanes a scenario's road has: from its road fields, its path modifiers, and the lanes its constructs use."""

from __future__ import annotations

import math
from pathlib import Path

from ...roads.asks import RouteRelation, TurnAsk
from ...settings import STANDARD_DIALECT
from .. import model
from ..errors import SourceLocation
from . import library
from .parameters import MIRRORED
from .values import EvaluationError, Interval, evaluate

DEFAULT_LANES = 3  # a road whose scenario says nothing of its lanes

# what a labelled map.roads_follow_in_junction(...) names of the turn its path takes, as a field of
# that kind would: my_turn.in_road is the road it comes in on, wherever the scenario names it
TURN_RESULTS = {"junction": "junction", "in_road": "road", "out_road": "road"}

# the default driver's Frenet frame reaches 25 m from the road's right edge (frenetix's projection
# domain): past 7 lanes of 3.5 m it fails inside the simulation
MAX_LANES = 6


MAX_LANES_WHY = " (the simulated road is one straight highway of at most that many lanes)"


class RoadLanes:
    """A part of the checker (``checker._Checker``): its state is the checker's."""

    def _road_lanes(self, scenario: model.Scenario, env: dict, roads: list[str]) -> int:
        """The lane count of the road ``scenario`` runs on, also kept in ``self.lanes`` for the lane checks.

        The lanes option wins when given (a conflict with the scenario's own bounds is an error).
        Otherwise the road is as wide as the scenario needs: at least DEFAULT_LANES, at least its
        ``path_min_driving_lanes``, at least its highest lane number or lane change plus one, and at most
        its ``path_max_lanes``, so that a file states its road and runs the same from every entry point.
        """
        self.route, self.routes, self.map_asked, self.route_asks = None, (), None, {}
        self.ways = None  # the ways its paths may take through the map (roads.ways.Ways), when they turn
        self.turn_asks: dict[str, tuple] = {}  # road field -> (roads.asks.TurnAsk, where)
        # the map relations between routes it asks for: (modifier, relation, path, path, kind, road field, where)
        self.relation_asks: list[tuple] = []
        bounds = self._road_bounds(scenario, env, roads)
        least, most = bounds.get("path_min_driving_lanes"), bounds.get("path_max_lanes")
        if self.requested_map is not None:  # the map option wins over the file's set_map
            self.map_asked = (self.requested_map, None)
        if self.map_asked is not None:
            used, where = self._lanes_used(scenario, env)
            return self._lanes_of_map(scenario, max(least[0] if least else 1, used), most, where)
        if "path_curve" in self.route_asks:
            self.error(
                self.route_asks["path_curve"][3],
                "path_curve() asks for a curve, but the scenario runs on the straight road",
                'give it a map with one: set_map("file.xodr"), or --roadlogic-map FILE',
            )
        if self.turn_asks or self.relation_asks:
            where = next(iter(self.turn_asks.values()))[1] if self.turn_asks else self.relation_asks[0][-1]
            what = "roads_follow_in_junction()" if self.turn_asks else f"{self.relation_asks[0][0]}()"
            self.error(
                where,
                f"{what} asks for a junction, but the scenario runs on the straight road",
                'give it a map with one: set_map("file.xodr"), or --roadlogic-map FILE',
            )
        if least and most and least[0] > most[0]:
            self.error(
                most[1],
                f"at most {most[0]} lanes contradicts at least {least[0]} (line {least[1].line})",
                "make path_max_lanes at least path_min_driving_lanes",
            )
        if self.requested_lanes is not None:
            lanes = self.requested_lanes
            self.lanes_origin = " (set by the lanes option)"
            for name, (value, location, *_) in bounds.items():
                if (name == "path_min_driving_lanes" and lanes < value) or (name == "path_max_lanes" and lanes > value):
                    bound = "at least" if name == "path_min_driving_lanes" else "at most"
                    self.error(
                        location,
                        f"the scenario asks for {bound} {value} lanes, but the lanes option sets {lanes}",
                        "leave out the lanes option (--lanes, roadlogic_lanes) to take the road from the scenario",
                    )
            if lanes > MAX_LANES:
                self.error(
                    scenario.location,
                    f"a road of {lanes} lanes (the lanes option); the tool drives at most {MAX_LANES}",
                    "give a smaller --lanes" + MAX_LANES_WHY,
                )
        else:
            used, where = self._lanes_used(scenario, env)
            if least and least[0] >= used:
                where = least[1]
            lanes = max(DEFAULT_LANES, least[0] if least else 1, used)
            self.lanes_origin = ""
            if most and lanes > most[0]:
                lanes = most[0]
                self.lanes_origin = f" ({_written(most, 'path_max_lanes')} on line {most[1].line})"
            if lanes > MAX_LANES:
                # the one error for it: the road keeps the lanes asked for, so the lane checks stay quiet
                self.error(
                    where,
                    f"a road of {lanes} lanes; the tool drives at most {MAX_LANES}",
                    f"use lanes 1 to {MAX_LANES}" + MAX_LANES_WHY,
                )
        self.lanes = lanes
        return lanes

    def _lanes_of_map(
        self,
        scenario: model.Scenario,
        needed: int,
        most: tuple[int, SourceLocation] | None,
        where: SourceLocation,
    ) -> int:
        """The lanes of the route the scenario runs on in the map it asked for (``self.map_asked``):
        the map's road that has the ``needed`` lanes; an error at ``set_map`` (or at the scenario,
        for the map option) saying why no road fits, or why the map cannot be read."""
        from ...roads.choice import NoFittingTurn, pick_route
        from ...roads.opendrive_in import MapError, read_map

        path, location = self.map_asked
        at = location or scenario.location
        origin = "" if location is not None else " (the map option)"
        # a map that cannot be used leaves the scenario the lanes it asks for: one error, at set_map
        self.lanes = needed
        if not self.roots.allows(path):
            self.error(
                at,
                f"the map {str(path)!r} is outside the folders the tool reads ({self.roots.describe()})",
                "put the map inside the project, or name its folder with --allow-read",
            )
            return needed
        asks = self.route_asks
        length = (asks["path_length"][0] or 0.0) if "path_length" in asks else 0.0
        curve = asks["path_curve"][:3] if "path_curve" in asks else None
        turn_asks = list(self.turn_asks.values())
        turn_at = turn_asks[-1][1] if turn_asks else None

        def refused(where: SourceLocation, error: MapError) -> int:
            in_map = f"{error.path}:{error.line}:{error.column}: " if error.line else f"{error.path}: "
            self.error(where, f"the map{origin}: {in_map}{error.message}", error.hint or None)
            return needed

        try:
            road_map = read_map(path)
        except MapError as error:
            return refused(at, error)
        if self.relation_asks and len(turn_asks) < 2:
            name = self.relation_asks[0][0]
            self.error(
                self.relation_asks[0][-1],
                f"{name}() relates the routes of two paths that turn at a junction, but the scenario has "
                f"{len(turn_asks) or 'no'} such path{'' if len(turn_asks) == 1 else 's'}",
                f"give each way its own path with roads_follow_in_junction(...), or leave {name}() out",
            )
            return needed
        if turn_asks:
            if curve is not None:
                self.error(
                    asks["path_curve"][3],
                    "not supported: path_curve() on a route that turns at a junction",
                    "leave it out: the route is the turn roads_follow_in_junction asks for",
                )
                return needed
            try:
                self._routes_of_map(scenario, road_map, needed, length, at)
            except NoFittingTurn as error:  # at the path whose turns lack the lanes or the room
                return refused(self.turn_asks.get(error.asked_by, (None, turn_at))[1], error)
            except MapError as error:
                return refused(turn_at, error)
        else:
            try:
                self.route = pick_route(road_map, needed, length, curve)
            except MapError as error:
                return refused(at, error)
            self.routes = (self.route,)
        lanes = self.route.lanes
        if most and lanes > most[0]:
            self.error(
                most[1],
                f"the route on {self.route.name} has {lanes} driving lanes, more than {_written(most, 'path_max_lanes')}",
                f"leave out {_written(most, 'path_max_lanes')}, or give a map whose road has that many lanes",
            )
        if self.requested_lanes is not None and self.requested_lanes != lanes:
            self.error(
                at,
                f"the lanes option sets {self.requested_lanes} lanes, but the route on {self.route.name} has {lanes}",
                "leave out the lanes option with a map: the map gives the lanes",
            )
        oncoming = self.route.road.oncoming
        if oncoming:
            # said plainly: no road has the lanes one way, so the scenario's leftmost lanes carry the
            # other direction's traffic (an overtake on a country road passes in them)
            which = f"lane {lanes}" if oncoming == 1 else f"lanes {lanes - oncoming + 1} to {lanes}"
            self.warning(
                at,
                f"no road of the map has {needed} driving lanes one way: the route on {self.route.name} "
                f"has {lanes - oncoming} of its own and {which} the oncoming "
                f"{'lane' if oncoming == 1 else 'lanes'} (a car there drives on the other direction's side of the road)",
                "give a map with a road of that many lanes one way, unless the scenario passes in the oncoming lane",
            )
        if self.route.road.left_hand:
            # said plainly: nothing is mirrored, so a scenario written for right-hand traffic
            # passes on the side it names, which there is the road's edge
            self.warning(
                at,
                f"the route on {self.route.name} is of left-hand traffic: left and right are as a driver "
                f"there sees them: the rightmost lane is the one beside the centre line, and a car left_of "
                f"another is nearer the road's edge",
                "write the sides as they are on this road (an overtake there passes on the right)",
            )
        self.lanes = lanes
        self.lanes_origin = (
            f" (the route on {self.route.name})"
            if len(self.routes) == 1
            else f" (the routes on {self.route.source.name})"
        )
        return lanes

    def _routes_of_map(
        self, scenario: model.Scenario, road_map, needed: int, length: float, at: SourceLocation
    ) -> None:
        """The routes of a scenario whose paths turn at junctions of ``road_map``
        (``roads_follow_in_junction``, one per path), in ``self.route``/``self.routes``: of the ways
        the paths may take together (``roads.ways.choose_ways``, kept in ``self.ways``: a logical
        parameter per path that may take several), the first (the roomiest). Each route is
        driven by the vehicles whose drive goes ``along`` its path; with one path, by every vehicle
        that goes ``along`` a path; with several, the first also by those that name none.
        ``MapError`` from the choice; errors where a vehicle drives along two paths, along a path
        that does not turn while others do, or is related to a vehicle on another route."""
        from ...roads.ways import choose_ways

        paths = list(self.turn_asks)
        if len(paths) == 1:
            crossers = (frozenset(actor for actor, _ in _alongs(scenario)),)
            driven = {}
        else:
            driven = self._paths_driven(scenario, paths)
            crossers = tuple(frozenset(v for v, p in driven.items() if p == path) for path in paths)
        asks = tuple(ask for ask, _ in self.turn_asks.values())
        relations = []
        for name, relation, first, second, kind, road, where in self.relation_asks:
            if first not in paths or second not in paths or first == second:
                self.error(
                    where,
                    f"{name}() relates the routes of two different paths that turn at a junction ({', '.join(paths)})",
                    f"name two of them: {name}({_RELATION_EXAMPLE[relation]})",
                )
                continue
            relations.append(RouteRelation(relation, paths.index(first), paths.index(second), kind, road))
        self.ways = choose_ways(road_map, needed, length, asks, crossers, tuple(relations))
        routes = self.ways.routes()
        self.route, self.routes = routes[0], routes
        if len(paths) == 1:
            if not crossers[0]:
                self.warning(
                    at,
                    f"the route turns ({self.route.turn}), but no vehicle drives along it through the junction",
                    "add along(path) to the drive of each vehicle that takes the turn",
                )
            return
        if not self.ways.meet:
            # two paths through a junction are there to meet; said where the map has no such ways
            self.warning(
                self.turn_asks[paths[-1]][1],
                f"no ways of the kinds {', '.join(paths)} ask cross, join or part anywhere in the map with room "
                f"for the scenario: they take {' and '.join(route.turn for route in routes)}, whose cars never meet",
                "give a map with a junction where such ways meet, or ask for other turns",
            )
        lanes = {route.lanes for route in routes}
        if len(lanes) > 1:
            self.error(
                self.turn_asks[paths[-1]][1],
                "not supported yet: routes with different numbers of driving lanes ("
                + ", ".join(f"{path}: {route.lanes} on {route.turn}" for path, route in zip(paths, routes))
                + ")",
                "give a map whose roads at the junction have as many lanes each",
            )
        for path, route in zip(paths, routes):
            if not route.crossers and path != paths[0]:
                self.warning(
                    self.turn_asks[path][1],
                    f"no vehicle drives along {path} ({route.turn})",
                    f"add along({path}) to the drive of the vehicle that takes this way, or leave the path out",
                )
        self._apart(scenario, {v: paths.index(p) for v, p in driven.items()})

    def _route_named(self, name: str) -> str | None:
        """The path a vehicle drives ``along(name)``: a road field, or the route a labelled
        ``roads_follow_in_junction`` results in (``my_turn.resulting_route``: the path
        ``my_turn``); None when ``name`` is neither."""
        if name in self.roads:
            return name
        label, _, member = name.partition(".")
        return label if member == "resulting_route" and label in self.turn_labels else None

    def _paths_driven(self, scenario: model.Scenario, paths: list[str]) -> dict[str, str]:
        """vehicle -> the path its drive goes ``along`` (each vehicle one path, a path that turns)."""
        driven: dict[str, tuple[str, SourceLocation]] = {}
        for actor, modifier in _alongs(scenario):
            value = modifier.arguments[0].value if modifier.arguments else None
            path = self._route_named(value.name) if isinstance(value, model.Name) else None
            if path is None:
                continue  # reported where along() is checked
            if path not in paths:
                self.error(
                    value.location,
                    f"{path} does not turn at a junction, but the scenario's other paths do",
                    f"give {path} its turn: {path}.roads_follow_in_junction(direction: ...)",
                )
            elif actor in driven and driven[actor][0] != path:
                self.error(
                    modifier.location,
                    f"{actor} drives along {driven[actor][0]} (line {driven[actor][1].line}): one vehicle drives one route",
                    f"drive it along {driven[actor][0]} here too",
                )
            else:
                driven.setdefault(actor, (path, modifier.location))
        return {vehicle: path for vehicle, (path, _) in driven.items()}

    def _apart(self, scenario: model.Scenario, route_of: dict[str, int]) -> None:
        """An error wherever a construct of one vehicle names a vehicle on another route, but a
        ``position()`` between two routes laid onto each other where they meet
        (``roads.conflicts.alignments``): there a position is the distance to the meeting, and
        "15 m ahead of" is "15 m nearer to it". Lanes and gaps are a route's own. Vehicles that name
        no path drive the first route."""
        from ...roads.conflicts import alignments, conflicts

        names = {actor.name for actor in scenario.actors}
        laid = {frozenset((a.route, a.onto)) for a in alignments(self.routes)}
        meet = {frozenset((m.first, m.second)) for m in conflicts(self.routes)}
        for behavior in scenario.behaviors:
            for node in model.walk(behavior):
                if not isinstance(node, model.Invocation) or node.actor not in names:
                    continue
                own = route_of.get(node.actor, 0)
                named = [(None, a) for a in node.arguments] + [(m.name, a) for m in node.modifiers for a in m.arguments]
                for modifier, argument in named:
                    other = argument.value.name if isinstance(argument.value, model.Name) else None
                    theirs = route_of.get(other, 0)
                    if other not in names or other == node.actor or theirs == own:
                        continue
                    pair = frozenset((own, theirs))
                    if modifier == "position" and pair in laid:
                        continue
                    if pair in laid:
                        why = "a lane or gap between them has no meaning"
                    elif pair in meet:
                        why = (
                            "their routes are laid onto each other through a third route, not where they "
                            "meet, so a position, lane or gap between them has no meaning"
                        )
                    else:
                        why = "their routes do not meet, so a position, lane or gap between them has no meaning"
                    self.error(
                        argument.value.location,
                        f"{node.actor} and {other} drive different routes "
                        f"({self.routes[own].turn}; {self.routes[theirs].turn}): {why}",
                        "relate vehicles on one route, or vehicles of two routes that meet with position(): "
                        "the distance to where their routes meet",
                    )

    def _road_bounds(
        self, scenario: model.Scenario, env: dict, roads: list[str]
    ) -> dict[str, tuple[int, SourceLocation]]:
        """The lane bounds the scenario's road modifiers state, by modifier name; other scenario-wide modifiers are refused."""
        bounds: dict[str, tuple[int, SourceLocation]] = {}
        fields = {f.name for f in scenario.fields}
        self.turn_results = _turn_results(scenario)
        for modifier in scenario.modifiers:
            if modifier.label is not None and modifier.name != "roads_follow_in_junction":
                self.error(
                    modifier.location,
                    f"not supported: a label on {modifier.name}()",
                    "leave the label out; the tool reads a label on map.roads_follow_in_junction(...), "
                    "whose resulting_route a vehicle drives along",
                )
                continue
            if modifier.label is not None and modifier.label in fields:
                self.error(
                    modifier.location,
                    f"{modifier.label} is already a field of the scenario",
                    "give the modifier a label of its own",
                )
                continue
            on_road = modifier.actor in roads or (modifier.actor is None and modifier.name in library.ROAD_MODIFIERS)
            if not on_road:
                if modifier.name == "set_position" and modifier.actor is not None and scenario.actor(modifier.actor):
                    # CARLA's examples place the ego by a town's world coordinates
                    self.warning(
                        modifier.location,
                        f"{modifier.actor}.set_position(...) is read but not simulated: world coordinates need "
                        f"the map; {modifier.actor} starts where the scenario's other constraints put it",
                        "place it with lane(..., at: start) and position(..., at: start) on its first drive",
                    )
                    continue
                if modifier.actor is None or scenario.actor(modifier.actor) is not None:
                    self.error(
                        modifier.location,
                        "not supported: a modifier applied to the whole scenario",
                        "put it in the with: block of an invocation",
                    )
                else:
                    self.error(
                        modifier.location,
                        f"unknown road {modifier.actor!r}",
                        f"declare it in the scenario: {modifier.actor}: {library.ROAD_TYPE}",
                    )
                continue
            signature = library.ROAD_MODIFIERS.get(modifier.name)
            if signature is None:
                self.error(
                    modifier.location,
                    f"not supported: {modifier.name}() of the road",
                    f"the road is one straight highway or a map's route; {self._known('road modifiers', library.ROAD_MODIFIERS)}",
                )
                continue
            before = len(self.diagnostics)
            binding = self._arguments(
                signature, modifier.arguments, modifier.location, scenario, env, set(), set(), what=f"{modifier.name}()"
            )
            if modifier.name == "set_map":
                argument = binding["map"]
                name = (
                    argument.value.value if argument is not None and isinstance(argument.value, model.Literal) else ""
                )
                if isinstance(name, str) and name.lower().endswith(".xodr"):
                    asked = Path(modifier.location.path).parent / name
                    if self.map_asked is not None and self.map_asked[0] != asked:
                        self.error(
                            modifier.location,
                            f"a second map: the scenario's map is {self.map_asked[0].name} (line {self.map_asked[1].line})",
                            "a scenario runs on one map: set it once (its paths all take their turns in it)",
                        )
                        continue
                    self.map_asked = (asked, modifier.location)
                    continue
                hint = 'give an OpenDRIVE file (set_map("road.xodr"), relative to this file), or the road\'s lanes with path_min_driving_lanes(n)'
                if self.registry.dialect == STANDARD_DIALECT:
                    hint += "; a file written for CARLA's scenario runner is read with --dialect carla (pytest: --roadlogic-dialect carla or roadlogic_dialect = carla): lanes numbered from the left, speed(v) a target"
                self.warning(
                    modifier.location, "the map is not available: the scenario runs on one straight road", hint
                )
                continue
            if modifier.name in ("path_length", "path_curve"):
                self._route_ask(modifier, binding, env, before)
                continue
            if modifier.name == "roads_follow_in_junction":
                self._turn_ask(modifier, binding, env, before)
                continue
            if modifier.name in _RELATIONS:
                self._relation_ask(modifier, binding, before)
                continue
            if modifier.name == "number_of_lanes":
                self._number_of_lanes(modifier, binding, env, before, bounds)
                continue
            argument = binding["lanes"]
            if argument is None or any(d.severity == "error" for d in self.diagnostics[before:]):
                continue
            value = evaluate(argument.value, env)
            if not (
                isinstance(value, Interval) and value.is_point and float(value.low).is_integer() and value.low >= 1
            ):
                self.error(
                    argument.value.location,
                    f"{modifier.name}() takes one whole number of lanes from 1 up, e.g. {modifier.name}(3)",
                )
            elif modifier.name in bounds:
                self.error(
                    modifier.location,
                    f"{modifier.name}() is already given on line {bounds[modifier.name][1].line}",
                    "give it once",
                )
            else:
                bounds[modifier.name] = (int(value.low), modifier.location)
        for item in scenario.fields:
            if item.name in roads:
                for keep in item.constraints:
                    if isinstance(keep, model.Keep):
                        self._route_lanes_kept(keep, env, bounds)
        return bounds

    def _route_lanes_kept(self, keep: model.Keep, env: dict, bounds: dict) -> None:
        """``route: route with: keep(it.min_lanes == 2)`` (the standard's example): a bound on the
        road's driving lanes one way, kept in ``bounds`` as path_min_driving_lanes / path_max_lanes
        would be. The tool's road keeps its lane count along the route, so ``min_lanes`` and
        ``max_lanes`` both are that count: ``== n`` fixes it, ``>= n`` / ``> n`` bound it below,
        ``<= n`` / ``< n`` above."""
        comparison = keep.expression
        if isinstance(comparison, model.Binary) and comparison.operator in MIRRORED:
            operator, field, other = comparison.operator, comparison.left, comparison.right
            if not _lanes_field(field):
                operator, field, other = MIRRORED[operator], other, field
        else:
            field = None
        if not _lanes_field(field):
            self.error(
                keep.location,
                "not supported: this keep() of a road",
                "a road's lanes are kept with keep(it.min_lanes >= n), keep(it.max_lanes <= n) or keep(it.min_lanes == n)",
            )
            return
        try:
            value = evaluate(other, env)
        except EvaluationError as error:
            self.error(error.location, error.message, error.hint)
            return
        if isinstance(value, model.Name):
            self.error(value.location, f"unknown name {value.name!r}", "give a number of lanes, e.g. 2")
            return
        if not (isinstance(value, Interval) and value.is_point and float(value.low).is_integer() and value.low >= 1):
            self.error(other.location, f"{field.name} is compared with one whole number of lanes from 1 up, e.g. 2")
            return
        lanes = {">": int(value.low) + 1, "<": int(value.low) - 1}.get(operator, int(value.low))
        if lanes < 1:
            self.error(keep.location, "a road has at least one lane", "compare with 2 or more, e.g. it.max_lanes < 3")
            return
        written = f"keep({field.name} {comparison.operator} {int(value.low)})"
        asked = {
            "==": ("path_min_driving_lanes", "path_max_lanes"),
            ">=": ("path_min_driving_lanes",),
            ">": ("path_min_driving_lanes",),
            "<=": ("path_max_lanes",),
            "<": ("path_max_lanes",),
        }[operator]
        for name in asked:
            if name in bounds:
                self.error(
                    keep.location,
                    f"{written} bounds the road's lanes again: {_written(bounds[name], name)} on line {bounds[name][1].line}",
                    "give the road's lanes once",
                )
                return
        for name in asked:
            bounds[name] = (lanes, keep.location, written)

    def _number_of_lanes(self, modifier: model.Modifier, binding, env: dict, before: int, bounds: dict) -> None:
        """``number_of_lanes(route, n)``: the road has ``n`` driving lanes one way, kept in ``bounds``
        as ``path_min_driving_lanes`` and ``path_max_lanes`` both (so a road of the map is picked
        and judged as with those); the lanes it counts are a road's driving lanes, one way."""
        if any(d.severity == "error" for d in self.diagnostics[before:]):
            return
        for name, counted in (("lane_type", "driving"), ("directionality", "uni_direction")):
            given = binding[name]
            if given is not None and given.value.name != counted:
                self.error(
                    given.value.location,
                    f"not supported: {name} {given.value.name}: the tool counts a road's driving lanes one way",
                    f"give {name}: {counted}, or leave it out",
                )
                return
        argument = binding["num_of_lanes"]
        value = evaluate(argument.value, env)
        if not (isinstance(value, Interval) and value.is_point and float(value.low).is_integer() and value.low >= 1):
            self.error(argument.value.location, "num_of_lanes takes one whole number of lanes from 1 up, e.g. 3")
            return
        lanes = int(value.low)
        for name in ("path_min_driving_lanes", "path_max_lanes"):
            if name in bounds and bounds[name][0] != lanes:
                self.error(
                    modifier.location,
                    f"number_of_lanes({lanes}) contradicts {name}({bounds[name][0]}) on line {bounds[name][1].line}",
                    "give the road's lanes once",
                )
                return
        for name in ("path_min_driving_lanes", "path_max_lanes"):
            bounds[name] = (lanes, modifier.location, f"number_of_lanes({lanes})")

    def _turn_ask(self, modifier: model.Modifier, binding, env: dict, before: int) -> None:
        """``roads_follow_in_junction``: the path it is applied to turns at a junction, kept in
        ``self.turn_asks`` (path -> (``roads.asks.TurnAsk``, where)), in the order given."""
        if any(d.severity == "error" for d in self.diagnostics[before:]):
            return
        path = modifier.label or modifier.actor or ""
        if path in self.turn_asks:
            self.error(
                modifier.location,
                f"roads_follow_in_junction() is already given on line {self.turn_asks[path][1].line}",
                "a path turns at one junction: give it once, or give each vehicle's way a path of its own",
            )
            return

        def field(parameter: str) -> str | None:
            given = binding[parameter]
            if given is not None and isinstance(given.value, model.Name):
                return self.turn_results.get(given.value.name, given.value.name)
            # a label's result the scenario names elsewhere stands for the element the turn takes
            named = f"{modifier.label}.{parameter}"
            return named if modifier.label and parameter in TURN_RESULTS and named in self.turn_results else None

        roads = None
        argument = binding["number_of_roads"]
        if argument is not None:
            value = evaluate(argument.value, env)
            if not (
                isinstance(value, Interval) and value.is_point and float(value.low).is_integer() and value.low >= 3
            ):
                self.error(
                    argument.value.location, "number_of_roads takes one whole number from 3 up, e.g. number_of_roads: 4"
                )
                return
            roads = int(value.low)
        ask = TurnAsk(field("direction"), roads, field("junction"), field("in_road"), field("out_road"), path or "path")
        self.turn_asks[path] = (ask, modifier.location)

    def _relation_ask(self, modifier: model.Modifier, binding, before: int) -> None:
        """One of the standard's map relations between the routes of two paths (``routes_overlap``,
        ``routes_are_opposite``, ``routes_are_in_sequence``), kept in ``self.relation_asks``;
        checked against the paths that turn once they are all read (``_routes_of_map``)."""
        if any(d.severity == "error" for d in self.diagnostics[before:]):
            return
        relation, (first_name, second_name), road_name = _RELATIONS[modifier.name]
        first, second = (self._route_named(binding[name].value.name) for name in (first_name, second_name))
        kind = None
        if relation == "overlap":
            kind = binding["overlap_kind"].value.name
            if kind in ("inside", "other"):
                why = (
                    "each turn's route runs from its road in to its road out, so neither lies inside the other"
                    if kind == "inside"
                    else "the tool reads the overlaps the standard names"
                )
                self.error(
                    binding["overlap_kind"].value.location,
                    f"not supported: overlap_kind {kind}: {why}",
                    "use start (the same road in), end (the same road out), any (either) or equal (one way)",
                )
                return
        lateral = binding["lateral_overlap"] if relation == "opposite" else None
        if lateral is not None and lateral.value.name != "never":
            self.error(
                lateral.value.location,
                f"not supported: lateral_overlap {lateral.value.name}: the tool reads the lanes of a map's "
                "roads one way each, so two routes the opposite way never share a lane",
                "leave lateral_overlap out, or give never",
            )
            return
        road = binding[road_name].value.name if road_name and binding[road_name] is not None else None
        road = self.turn_results.get(road, road) if road is not None else None
        self.relation_asks.append((modifier.name, relation, first, second, kind, road, modifier.location))

    def _route_ask(self, modifier: model.Modifier, binding, env: dict, before: int) -> None:
        """``path_length`` / ``path_curve``: what the route on a map must have, kept in
        ``self.route_asks`` (name -> (metres low, metres high, side or None, where))."""
        if any(d.severity == "error" for d in self.diagnostics[before:]):
            return
        low_name, high_name = (
            ("min_length", "max_length") if modifier.name == "path_length" else ("min_radius", "max_radius")
        )
        bounds = []
        for name in (low_name, high_name):
            argument = binding[name]
            value = evaluate(argument.value, env) if argument is not None else None
            if value is None:
                bounds.append(None)
            elif isinstance(value, Interval) and value.is_point and value.low > 0:
                bounds.append(float(value.low))
            else:
                self.error(argument.value.location, f"{name} takes one length above 0, e.g. {name}: 300m")
                return
        side = binding["side"] if modifier.name == "path_curve" else None
        side_name = side.value.name if side is not None and isinstance(side.value, model.Name) else None
        if modifier.name in self.route_asks:
            self.error(modifier.location, f"{modifier.name}() is already given", "give it once")
            return
        self.route_asks[modifier.name] = (bounds[0], bounds[1], side_name, modifier.location)

    def _lanes_used(self, scenario: model.Scenario, env: dict) -> tuple[int, SourceLocation]:
        """The fewest lanes on which every lane number and lane change the scenario writes exists,
        and where the use that needs the most stands."""

        def highest(argument: model.Argument | None) -> int:
            try:
                value = evaluate(argument.value, env) if argument is not None else None
            except EvaluationError:
                return 1  # reported by the main pass
            if isinstance(value, Interval) and value.dimension is None and math.isfinite(value.high):
                return int(math.floor(value.high))
            return 1

        needed, where = 1, scenario.location
        for behavior in scenario.behaviors:
            for node in model.walk(behavior):
                if not isinstance(node, model.Invocation):
                    continue
                uses = [(self.registry.action(node.action), node.arguments, node.location)]
                uses += [(self.registry.modifier(m.name), m.arguments, m.location) for m in node.modifiers]
                for construct, arguments, location in uses:
                    if construct is not None:
                        lanes = construct.lanes_needed(library.bind(construct.signature, arguments), highest)
                        if lanes > needed:
                            needed, where = lanes, location
        return needed, where


def _turn_results(scenario: model.Scenario) -> dict[str, str]:
    """``label.member`` (``TURN_RESULTS``) of each labelled ``roads_follow_in_junction`` that the
    scenario's map modifiers name -> the field that modifier binds the member to (``in_road:
    approach``: both names are one map element), or itself when it binds none (``_turn_ask``)."""
    named = {
        argument.value.name
        for modifier in scenario.modifiers
        for argument in modifier.arguments
        if isinstance(argument.value, model.Name)
    }
    results = {}
    for modifier in scenario.modifiers:
        if modifier.label is None or modifier.name != "roads_follow_in_junction":
            continue
        bound = {a.name: a.value.name for a in modifier.arguments if isinstance(a.value, model.Name)}
        for member in TURN_RESULTS:
            result = f"{modifier.label}.{member}"
            if result in named:
                results[result] = bound.get(member, result)
    return results


def driven_along_only(scenario: model.Scenario, name: str) -> bool:
    """Whether the field ``name`` is driven ``along(name)`` and named by no map modifier of the
    scenario: the standard's "move along a road" (``my_road: road``, ``along(my_road)``) is the
    road the scenario runs on, not a road of a junction for the map's relations to pick."""

    def names(arguments) -> bool:
        return any(isinstance(a.value, model.Name) and a.value.name == name for a in arguments)

    named_by_map = any(names(modifier.arguments) for modifier in scenario.modifiers)
    return not named_by_map and any(names(modifier.arguments) for _, modifier in _alongs(scenario))


def _alongs(scenario: model.Scenario) -> list[tuple[str, model.Modifier]]:
    """Every ``along(...)`` of the scenario's drives, with the actor whose drive it is, in order."""
    return [
        (node.actor, modifier)
        for behavior in scenario.behaviors
        for node in model.walk(behavior)
        if isinstance(node, model.Invocation)
        for modifier in node.modifiers
        if modifier.name == "along"
    ]


# the standard's map relations between two routes: modifier -> (the tool's name for the relation,
# its two route parameters, its road parameter or None)
_RELATIONS = {
    "routes_overlap": ("overlap", ("route1", "route2"), None),
    "routes_are_opposite": ("opposite", ("route1", "route2"), "containing_road"),
    "routes_are_in_sequence": ("sequence", ("preceding", "succeeding"), "road"),
}
_RELATION_EXAMPLE = {
    "overlap": "route1: a.resulting_route, route2: b.resulting_route, overlap_kind: end",
    "opposite": "route1: a.resulting_route, route2: b.resulting_route",
    "sequence": "preceding: a.resulting_route, succeeding: b.resulting_route",
}


def _lanes_field(expression) -> bool:
    """Whether ``expression`` names a road's lane count as a keep() of it does (``it.min_lanes``)."""
    return (
        isinstance(expression, model.Name)
        and expression.parts[-1] in ("min_lanes", "max_lanes")
        and len(expression.parts) <= 2
    )


def _written(bound: tuple, name: str) -> str:
    """A lane bound as it was written: ``name(n)``, or the text that gave it (``number_of_lanes(3)``,
    ``keep(it.min_lanes == 2)``)."""
    return bound[2] if len(bound) > 2 else f"{name}({bound[0]})"
