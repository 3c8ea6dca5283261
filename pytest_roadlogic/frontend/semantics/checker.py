"""Resolving names and types: what makes a parsed file a scenario this tool can run.

``check_file`` loads a file and its imports, applies ``extend`` blocks, sorts fields into actors and
parameters, resolves parameter domains, and checks every invocation against the library's
signatures. It reports everything it finds (errors and warnings, each ``path:line:col``) rather
than stopping at the first, because a person fixing a file wants the whole list.
Tier-3 constructs are refused here by name: ``not supported: <construct>``.

Actions and modifiers are looked up in a registry of constructs (``pytest_roadlogic.constructs``):
their signatures, and what each validates beyond its arguments' kinds, live there.
"""

from __future__ import annotations

import math
from collections.abc import Collection
from dataclasses import dataclass, replace
from pathlib import Path

from ...confinement import ReadRoots, project_root
from ...settings import STANDARD_DIALECT
from .. import model
from ..errors import Diagnostic, OscError, SourceLocation
from ..syntax.parser import parse_text
from ..syntax.standard_library import UNITS, standard_library
from ..syntax.units import SI_UNIT, SPEED, TIME
from . import library
from .builtin_events import with_builtin_events
from .checked import CheckedFile, CheckedScenario, Registry
from .coverage import coverage_items
from .dialects import registry as dialect_registry
from .environment import ENVIRONMENT_ACTIONS, EnvironmentActions, environment_names, without_environment
from .events import EventChecks
from .field_types import FieldTyping
from .imports import ImportLoading
from .inheritance import inherited
from .invocation import (
    RECURSION,
    called_scenarios,
    expand_calls,
    owned_by,
    resolve_actor_aliases,
    substitute_calls,
    substitute_names,
)
from .logical import logical_parameters_of, way_parameters
from .methods import Methods, inline_methods, inline_scenario
from .parameters import ParameterSpace, parameter_space
from .physical import declared_physics, parse_with_declared_units
from .road_lanes import DEFAULT_LANES, TURN_RESULTS, RoadLanes, driven_along_only
from .values import EvaluationError, Interval, calls_in, describe, evaluate, names_in


def check_file(
    path: str | Path,
    lanes: int | None = None,
    registry: Registry | None = None,
    dialect: str | None = None,
    roots: ReadRoots | None = None,
    road_map: str | Path | None = None,
) -> CheckedFile:
    """Parse and check ``path`` and the files it imports. Syntax errors raise ``OscError``.

    ``lanes`` fixes the road's lane count; ``None`` takes it from each scenario (see ``_road_lanes``).
    ``registry`` holds the actions and modifiers the file may use (default: those of ``dialect``,
    the standard's unless it names another of ``constructs.DIALECTS``). ``roots``: the folders an
    import may read from (default: the project's root and ``path``'s folder); an import outside
    them is an error at the import, and the file is never opened. ``road_map``: an OpenDRIVE file
    every scenario runs on (the map option), instead of the one its ``set_map`` names.
    """
    checker = _Checker(lanes, registry, dialect, roots or ReadRoots.around(path))
    checker.requested_map = Path(road_map) if road_map else None
    main, checker.units = parse_with_declared_units(path, checker.roots)
    return checker.run(main)


def _attribute_owners(constraint, actors: set[str]) -> set[str]:
    """The actors whose fields a constraint is about (``keep(npc.length == 4.5m)``), or an empty set
    when it mentions anything else (a parameter)."""
    if not isinstance(constraint, model.Keep):
        return set()
    names = [n for n in names_in(constraint.expression) if n.enum is None]
    heads = {n.name.partition(".")[0] for n in names}
    if names and all("." in n.name for n in names) and heads <= actors:
        return heads
    return set()


def check_text(
    text: str,
    path: str = "<string>",
    lanes: int | None = None,
    registry: Registry | None = None,
    dialect: str | None = None,
    roots: ReadRoots | None = None,
) -> CheckedFile:
    """``check_file`` of a text; its imports are read from ``roots`` (default: the project's root)."""
    return _Checker(lanes, registry, dialect, roots or ReadRoots.of(project_root())).run(parse_text(text, path))


def load_file(
    path: str | Path,
    lanes: int | None = None,
    registry: Registry | None = None,
    dialect: str | None = None,
    roots: ReadRoots | None = None,
    road_map: str | Path | None = None,
) -> CheckedFile:
    """``check_file`` that raises ``OscError`` when the file has errors (warnings pass)."""
    checked = check_file(path, lanes, registry, dialect, roots, road_map)
    checked.raise_for_errors()
    return checked


@dataclass
class _ConstructContext:
    """What a construct's ``check`` sees of the checker (``constructs.CheckContext``)."""

    checker: _Checker
    env: dict
    location: SourceLocation | None = None  # the use being checked

    @property
    def lanes(self) -> int:
        return self.checker.lanes

    @property
    def lanes_origin(self) -> str:
        return self.checker.lanes_origin

    def error(self, location: SourceLocation, message: str, hint: str | None = None) -> None:
        self.checker.error(location, message, hint)

    def warning(self, location: SourceLocation, message: str, hint: str | None = None) -> None:
        self.checker.warning(location, message, hint)

    def evaluate(self, argument: model.Argument) -> Interval | None:
        try:
            value = evaluate(argument.value, self.env)
        except EvaluationError:
            return None  # the checker reports it where it checks the argument's kind
        return value if isinstance(value, Interval) else None


def _reaches(start: str, goal: str, calls: dict[str, set[str]]) -> bool:
    """Whether scenario ``start`` calls ``goal``, directly or through other scenarios."""
    seen: set[str] = set()
    frontier = list(calls.get(start, ()))
    while frontier:
        name = frontier.pop()
        if name == goal:
            return True
        if name not in seen:
            seen.add(name)
            frontier.extend(calls.get(name, ()))
    return False


class _Checker(ImportLoading, FieldTyping, RoadLanes, EventChecks, EnvironmentActions):
    """Checks one file and its imports; its parts: loading imports (``imports``), typing fields
    (``field_types``), the road's lanes (``road_lanes``), events (``events``), the environment's
    actions (``environment``)."""

    def __init__(
        self,
        lanes: int | None,
        registry: Registry | None = None,
        dialect: str | None = None,
        roots: ReadRoots | None = None,
    ) -> None:
        self.roots = roots or ReadRoots.of(project_root())
        self.registry = registry if registry is not None else dialect_registry(dialect or STANDARD_DIALECT)
        self.requested_lanes = lanes
        self.requested_map: Path | None = None  # the map option's file, which wins over a scenario's set_map
        self.route = None  # the route of the scenario being checked on its map (roads.Route), None: the straight road
        self.routes: tuple = ()  # every route of it (CheckedScenario.routes)
        self.ways = None  # the ways its paths may take through the map (CheckedScenario.ways)
        self.turn_asks: dict = {}  # its roads_follow_in_junction asks (road_lanes)
        self.relation_asks: list = []  # its map relations between routes (road_lanes)
        self.map_asked = None  # (the map file a scenario's set_map names, where) while it is checked
        self.route_asks: dict = {}  # path_length / path_curve of the scenario being checked (road_lanes)
        # The road of the scenario being checked, and why it has that many lanes (for error messages).
        self.lanes = lanes or DEFAULT_LANES
        self.lanes_origin = ""
        self.diagnostics: list[Diagnostic] = []
        self.sources: dict[str, str] = {}
        self.files: dict[str, model.OscFile] = {}
        self.enums: dict[str, tuple[str, ...]] = dict(library.ENUMS)
        self.types: dict[str, model.TypeDeclaration] = {}
        # method calls refused where they stand: their value is unknown, and said to be once
        self.refused_calls: set[SourceLocation] = set()
        self.scenarios: dict[str, model.Scenario] = {}
        self.units: dict[str, tuple[str | None, float]] = UNITS  # what imported files are parsed with
        self.physical_types: dict[str, str | None] = dict(library.PHYSICAL_TYPES)
        self.roads: set[str] = set()  # the road fields of the scenario being checked
        # the labels of its map modifiers (``my_turn: map.roads_follow_in_junction(...)``): each a
        # path, driven as ``along(my_turn.resulting_route)``
        self.turn_labels: set[str] = set()
        # label.member of a labelled roads_follow_in_junction -> the field it binds (road_lanes)
        self.turn_results: dict[str, str] = {}
        # its fields of the map's elements (``j: junction``, ``r1: road``): name -> type
        self.map_elements: dict[str, str] = {}
        self.shadowed: set[tuple[str, str]] = set()  # (parameter, enum) already warned of, once each
        self.environments: frozenset[str] = frozenset()  # the names of the checked scenario's environment

    def error(self, location: SourceLocation, message: str, hint: str | None = None) -> None:
        self.diagnostics.append(Diagnostic(location, message, hint))

    def warning(self, location: SourceLocation, message: str, hint: str | None = None) -> None:
        self.diagnostics.append(Diagnostic(location, message, hint, "warning"))

    def _actor_attributes(self, location: SourceLocation, actors: str) -> None:
        """A constraint on an actor's own fields (its length, colour, model): read and not enforced,
        since every vehicle is simulated with the tool's dimensions; said where it is written."""
        self.warning(
            location,
            f"a constraint on the fields of {actors} is read but not enforced: vehicles are simulated with the tool's own dimensions",
            "constrain what the scenario does through modifiers (speed, position, lane)",
        )

    # -------------------------------------------------------------- files

    def run(self, main: model.OscFile) -> CheckedFile:
        self.sources[main.path] = main.source_text
        self._load_imports(main, stack=(str(Path(main.path).resolve()),))
        self._declarations(main)
        self._modifier_declarations(main)
        physics = declared_physics([*self.files.values(), main])
        self.diagnostics.extend(physics.problems)
        self.physical_types = physics.types
        globals_ = tuple(g for f in self.files.values() for g in f.globals) + main.globals
        inlined = inline_methods(globals_, Methods.declared(self.types, (), globals_))
        globals_ = inlined.node
        self.refused_calls |= inlined.refused
        self.diagnostics.extend(inlined.problems)
        for misplaced in main.misplaced_imports:
            self.error(misplaced.location, "an import after a declaration", "put every import at the top of the file")
        for item in main.unsupported:
            self._unsupported(item)
        scenarios: list[CheckedScenario] = []
        own = {s.name for s in main.scenarios}
        extensions = [e for f in (*self.files.values(), main) for e in f.extensions]
        for extension in extensions:
            if extension.target not in self.scenarios and extension.target not in own:
                self.error(
                    extension.location,
                    f"extend names an unknown scenario {extension.target!r}",
                    self._known("scenarios", [*self.scenarios, *own]),
                )
        seen: dict[str, model.Scenario] = {}
        # this file's scenarios over imported ones of the same name, the first of two with one name
        # (the second is an error below)
        declared = {**self.scenarios, **{s.name: s for s in reversed(main.scenarios)}}
        # every scenario with the extends that name it and the members it inherits, before calls are expanded
        # (a call of a scenario that inherits runs the whole of it)
        extended = {name: _extended(s, extensions) for name, s in declared.items()}
        callable_ = {}
        for name, scenario in extended.items():
            callable_[name], problems = inherited(scenario, extended)
            # a callee's @L.end refers to its own label L, which the call renames: mark it first
            callable_[name] = with_builtin_events(callable_[name])
            methods = Methods.declared(self.types, callable_[name].methods, (*globals_, *callable_[name].fields))
            inlined = inline_scenario(callable_[name], methods)
            callable_[name] = inlined.node
            self.refused_calls |= inlined.refused
            if scenario.path == main.path:
                self.diagnostics.extend(problems + inlined.problems)
        is_action = lambda name: self.registry.action(name) is not None  # noqa: E731
        # a scenario another one of this file calls is checked (and run) as part of its callers
        calls = {name: called_scenarios(s, callable_, is_action) for name, s in callable_.items()}
        called = {name for s in main.scenarios for name in calls.get(s.name, ())}
        for scenario in main.scenarios:
            # a scenario that calls itself, directly or through others, is checked on its own, so that
            # expand_calls reports the recursion at the call (as a callee alone it would be skipped)
            if (
                scenario.name in called
                and scenario.name not in seen
                and not _reaches(scenario.name, scenario.name, calls)
            ):
                seen[scenario.name] = scenario
                continue
            if scenario.name in seen:
                first = seen[scenario.name].location
                self.error(
                    scenario.location,
                    f"scenario {scenario.name!r} is already declared on line {first.line}",
                    "give each scenario its own name",
                )
                continue
            if scenario.name in self.scenarios and self.scenarios[scenario.name].path != main.path:
                other = self.scenarios[scenario.name].location
                self.error(
                    scenario.location,
                    f"scenario {scenario.name!r} is already declared in {other.path}:{other.line}",
                    "rename one of them",
                )
            seen[scenario.name] = scenario
            is_actor = lambda f: self._field_kind(self._aliased(f)) == "actor"  # noqa: E731
            scenario, problems = expand_calls(callable_[scenario.name], callable_, is_action, is_actor)
            self.diagnostics.extend(problems)
            if any(RECURSION in problem.message for problem in problems):
                continue  # the call left in place would only be reported again as an unknown action
            scenario = resolve_actor_aliases(scenario, is_actor)
            scenario = self._string_constants(scenario, globals_)
            scenario = _map_sides(scenario)
            scenario = self._owner_drives(scenario)
            checked, space, lanes = self._scenario(scenario, globals_)
            try:
                parameters = logical_parameters_of(checked, space, self.registry) + way_parameters(
                    self.ways, {path: where for path, (_, where) in self.turn_asks.items()}
                )
            except OscError:
                parameters = ()  # a scenario with errors is reported, never sampled: the checker said why
            coverage = coverage_items(checked, parameters, self.warning)
            scenarios.append(
                CheckedScenario(
                    checked,
                    space,
                    lanes,
                    self.registry,
                    self.sources,
                    parameters,
                    self.route,
                    self.routes,
                    self.ways,
                    coverage,
                )
            )
        self.diagnostics = list(dict.fromkeys(self.diagnostics))
        self.diagnostics.sort(
            key=lambda d: (d.location.path != main.path, d.location.path, d.location.line, d.location.column)
        )
        checked_file = replace(main, scenarios=tuple(c.scenario for c in scenarios))
        return CheckedFile(checked_file, self.diagnostics, self.sources, tuple(scenarios))

    def _owner_drives(self, scenario: model.Scenario) -> model.Scenario:
        """A scenario that belongs to a road user (``scenario vehicle.two_phases:``, the standard's
        examples) run as the main scenario: its invocations that name no actor are that vehicle's,
        an actor named after its type (``vehicle``) that ``_scenario`` adds."""
        owner = self._implicit_owner(scenario, {item.name for item in scenario.fields})
        if owner is None:
            return scenario
        return _rewritten(scenario, lambda node: owned_by(node, owner))

    def _implicit_owner(self, scenario: model.Scenario, declared: Collection[str]) -> str | None:
        """The road user ``scenario`` belongs to (``scenario vehicle.two_phases:``) when no field
        of that name is ``declared``: the actor that drives its invocations naming none. None for
        an owner that does not drive (traffic, dut, ...) or a type that is no road user."""
        owner = scenario.actor_type
        if owner is None or owner in library.SCENARIO_OWNERS or owner in declared or self._actor_base(owner) is None:
            return None
        return owner

    def _string_constants(self, scenario: model.Scenario, globals_: tuple[model.Field, ...]) -> model.Scenario:
        """The scenario with each string parameter that is a constant (a value, no constraint)
        written out where its behaviors use it: CARLA's suites name the map and an ``at:`` in
        globals (``global my_map: string = "Town04"``, ``at: start_point`` with ``"start"``). A value
        that is a member of an enum becomes that member; another, the string."""
        members = {m for values in self.enums.values() for m in values}
        constants = {}
        for item in (*globals_, *scenario.fields):
            if item.type == "string" and isinstance(item.default, model.Literal) and not item.constraints:
                text = item.default.value
                if isinstance(text, str):
                    constants[item.name] = (
                        model.Name(text, item.default.location)
                        if text in members
                        else model.Literal(text, item.default.location)
                    )
        mentioned = {n.name for c in scenario.constraints if isinstance(c, model.Keep) for n in names_in(c.expression)}
        constants = {name: value for name, value in constants.items() if name not in mentioned}
        if not constants:
            return scenario
        return _rewritten(scenario, lambda node: substitute_names(node, constants))

    def _declarations(self, osc: model.OscFile) -> None:
        for enum in osc.enums:
            if enum.extends:
                self._extend_enum(enum)
                continue
            if enum.name in self.enums or enum.name in self.types:
                self.error(enum.location, f"type {enum.name!r} is already declared", "rename the enum")
                continue
            members: list[str] = []
            for member in enum.members:
                if member in members:
                    self.error(enum.location, f"enum {enum.name!r} lists {member!r} twice")
                members.append(member)
            self.enums[enum.name] = tuple(members)
        for declared in osc.types:
            if declared.condition is not None:
                declared = self._category_parent(declared)
                if declared is None:
                    continue
                if declared.name == declared.parent and not (
                    declared.fields or declared.constraints or declared.methods
                ):
                    continue  # the standard's way of declaring a car: the built-in car restated
            if (
                declared.name in self.types
                or declared.name in self.enums
                or declared.name in library.SCALAR_TYPES
                or declared.name in library.ACTOR_TYPES
            ):
                self.error(declared.location, f"type {declared.name!r} is already declared", "rename the declaration")
                continue
            self.types[declared.name] = declared

    def _category_parent(self, declared: model.TypeDeclaration) -> model.TypeDeclaration | None:
        """``actor car inherits vehicle(vehicle_category == vehicle_category!car)``, as the standard's
        examples declare a car: a vehicle of the category car is this tool's car (truck: truck), so
        the declaration derives from that type. Any other condition is refused at its place (None)."""
        condition = declared.condition
        category = None
        if (
            declared.parent == "vehicle"
            and isinstance(condition, model.Binary)
            and condition.operator == "=="
            and isinstance(condition.left, model.Name)
            and condition.left.name == "vehicle_category"
            and isinstance(condition.right, model.Name)
            and condition.right.enum in (None, "vehicle_category")
        ):
            category = condition.right.name
        if category in ("car", "truck"):
            return replace(declared, parent=category, condition=None)
        self.error(
            condition.left.location if isinstance(condition, model.Binary) else condition.location,
            "not supported: conditional inheritance",
            "derive the type from car or truck (actor x inherits car); the tool reads "
            "inherits vehicle(vehicle_category == vehicle_category!car) as that",
        )
        return None

    def _extend_enum(self, extension: model.EnumDeclaration) -> None:
        """``extend e: [a, b]``: members added to an enum this file or an import declares."""
        if extension.name not in self.enums:
            self.error(
                extension.location,
                f"extend of an unknown enum {extension.name!r}",
                "declare the enum first: enum name: [a, b]",
            )
            return
        members = list(self.enums[extension.name])
        for member in extension.members:
            if member in members:
                self.error(extension.location, f"enum {extension.name!r} already has {member!r}")
            else:
                members.append(member)
        self.enums[extension.name] = tuple(members)

    def _modifier_declarations(self, osc: model.OscFile) -> None:
        """A library may declare the modifiers it uses (``modifier Path.set_map``); one the tool
        does not provide would need its meaning, which a declaration without a body does not give."""
        for declared in osc.modifier_declarations:
            if declared.parameters:
                self.error(
                    declared.location,
                    "not supported: modifier declarations",
                    "use the built-in modifiers (speed, position, lane, ...)",
                )
                continue
            if declared.owner in library.ROAD_TYPES:
                known = declared.name in library.ROAD_MODIFIERS
            else:
                known = self.registry.modifier(declared.name) is not None
            if not known:
                self.error(
                    declared.location,
                    f"not supported: the declared modifier {declared.name!r}",
                    "the tool plans only the modifiers it provides; "
                    + self._known("modifiers", [*self.registry.modifiers, *library.ROAD_MODIFIERS]),
                )

    def _unsupported(self, item: model.Unsupported) -> None:
        if item.severity == "warning":
            self.warning(item.location, f"{item.construct} is read and ignored", item.hint)
        else:
            self.error(item.location, f"not supported: {item.construct}", item.hint)

    # -------------------------------------------------------------- scenarios

    def _scenario(
        self, scenario: model.Scenario, globals_: tuple[model.Field, ...]
    ) -> tuple[model.Scenario, ParameterSpace, int]:
        for item in scenario.unsupported:
            self._unsupported(item)
        if scenario.kind == "action":
            self.error(scenario.location, "not supported: action declarations", "declare a scenario instead")
        owner = scenario.actor_type
        if owner is not None and owner not in library.SCENARIO_OWNERS and self._actor_base(owner) is None:
            self.error(
                scenario.location,
                f"unknown actor type {owner!r}",
                self._known("actor types", [*library.SCENARIO_OWNERS, *self._actor_type_names()]),
            )

        actors: list[model.Actor] = []
        parameters: list[model.Field] = []
        roads: list[str] = []
        environments: list[str] = []
        self.map_elements = {}
        declared: dict[str, SourceLocation] = {}
        for item in (*globals_, *scenario.fields):
            item = self._aliased(item)
            if item.name in declared:
                self.error(
                    item.location,
                    f"{item.name!r} is already declared on line {declared[item.name].line}",
                    "give each field its own name",
                )
                continue
            declared[item.name] = item.location
            kind = self._field_kind(item)
            if kind == "actor":
                base = self._actor_base(item.type)
                actors.append(model.Actor(item.name, item.type, item.location, base))
                if item.constraints or item.default is not None:
                    where = item.constraints[0].location if item.constraints else item.default.location
                    self._actor_attributes(where, item.name)
            elif kind == "parameter":
                parameters.append(item)
            elif kind == "road":
                roads.append(item.name)
            elif kind == "map_element" and item.type == "road" and driven_along_only(scenario, item.name):
                roads.append(item.name)  # `my_road: road` driven along(my_road): the scenario's road
            elif kind == "map_element":
                self.map_elements[item.name] = item.type
            elif kind == "environment":
                environments.append(item.name)
        self.roads = set(roads)
        self.environments = environment_names(environments, declared)
        self.turn_labels = {
            m.label for m in scenario.modifiers if m.label is not None and m.name == "roads_follow_in_junction"
        }
        for label in self.turn_labels:  # the map elements its turn takes: my_turn.in_road, ...
            self.map_elements.update({f"{label}.{member}": element for member, element in TURN_RESULTS.items()})
        owner = self._implicit_owner(scenario, declared)
        if owner is not None and _mentions(scenario, owner):
            # the vehicle the scenario belongs to, which drives its actor-less invocations
            actors.append(model.Actor(owner, owner, scenario.location, self._actor_base(owner)))
            declared[owner] = scenario.location
        for implicit in library.IMPLICIT_VEHICLES:
            if implicit not in declared and _mentions(scenario, implicit):
                actors.append(model.Actor(implicit, "vehicle", scenario.location, "vehicle"))
                if not implicit.startswith("dut"):
                    self.warning(
                        _first_mention(scenario, implicit) or scenario.location,
                        f"{implicit!r} is not declared: read as a vehicle, as CARLA's scenario runner does",
                        f"declare it: {implicit}: vehicle",
                    )
        actor_names = {a.name for a in actors}
        constraints = []
        for constraint in scenario.constraints:
            owners = _attribute_owners(constraint, actor_names)
            if owners:
                self._actor_attributes(constraint.location, ", ".join(sorted(owners)))
            else:
                constraints.append(constraint)
        space, diagnostics = parameter_space(tuple(parameters), tuple(constraints), self.enums, self.refused_calls)
        self.diagnostics.extend(diagnostics)
        checked = replace(scenario, actors=tuple(actors), parameters=tuple(parameters))
        env = self._environment(checked, space)
        lanes = self._road_lanes(checked, env, roads)
        env.update({f"{actor.name}.lane": Interval(1.0, float(self.lanes), None) for actor in actors})

        if len(scenario.behaviors) > 1:
            for extra in scenario.behaviors[1:]:
                self.error(
                    extra.location,
                    "a scenario has at most one `do`",
                    "compose the behaviors with serial: or parallel: under one do",
                )
        for event in scenario.events:
            if event.specification is not None:
                self._event_specification(event.specification, checked, env, event.location, waits=True)
        labels: dict[str, SourceLocation] = {}
        used_actors: set[str] = set()
        used_names: set[str] = set()
        for behavior in scenario.behaviors:
            for node in model.walk(behavior):
                label = getattr(node, "label", None)
                if label is not None:
                    if label in labels:
                        self.error(
                            node.location,
                            f"label {label!r} is already used on line {labels[label].line}",
                            "give each phase its own label",
                        )
                    else:
                        labels[label] = node.location
                self._behavior(node, checked, env, used_actors, used_names)
        valueless = {p.name for p in parameters if p.default is not None and p.default.location in self.refused_calls}
        for name, domain in space.domains.items():
            if name in used_names and not domain.bounded and name not in valueless:
                interval = domain.interval
                if math.isfinite(interval.low) or math.isfinite(interval.high):
                    known, missing = (
                        (f"at least {interval.low:g}{_unit_of(domain.type)}", "upper")
                        if math.isfinite(interval.low)
                        else (f"at most {interval.high:g}{_unit_of(domain.type)}", "lower")
                    )
                    self.error(
                        domain.location,
                        f"parameter {name!r} is {known} but has no {missing} bound: a sample needs both ends",
                        "bound it on the other side too, e.g. keep(it in [a..b])",
                    )
                    continue
                self.error(
                    domain.location,
                    f"parameter {name!r} has no range or value",
                    f"give it a value ({name}: {domain.type} = ...) or a range (with: keep(it in [a..b]...))",
                )
        for relation in space.relations:
            used_names.update(n.name for n in names_in(relation.expression))
        for parameter in parameters if scenario.behaviors else ():  # without a do: a base to inherit from
            if parameter.name not in used_names and parameter in scenario.fields:
                self.warning(parameter.location, f"parameter {parameter.name!r} is never used")
        if scenario.behaviors and not actors:
            # nothing to plan or simulate; found by the fuzz test (an IndexError in the planner)
            self.error(
                scenario.behaviors[0].location,
                "the behavior drives no vehicle: the scenario declares no actor",
                "declare one (v1: vehicle) and give it an action (v1.drive())",
            )
        if scenario.behaviors:
            for actor in actors:
                if actor.name not in used_actors:
                    self.warning(
                        actor.location,
                        f"actor {actor.name!r} takes no part in the behavior",
                        "give it an action, or remove it",
                    )
        driven = without_environment(checked.behaviors, self.environments)
        for behavior in checked.behaviors if driven != checked.behaviors else ():
            for node in model.walk(behavior):
                if isinstance(node, model.Composition) and node.operator == "one_of":
                    for member in node.children:
                        if not without_environment((member,), self.environments):
                            self.error(
                                member.location,
                                "this one_of member only sets the environment: it takes no time and drives nothing",
                                "give it a duration: argument, or a vehicle's action beside it",
                            )
        if driven != checked.behaviors:
            if not driven and actors:
                self.error(
                    scenario.behaviors[0].location,
                    "the behavior only sets the environment: no vehicle is driven",
                    "give a vehicle an action (v1.drive())",
                )
            checked = replace(checked, behaviors=driven, behavior=driven[0] if driven else None)
        return checked, space, lanes

    # -------------------------------------------------------------- behavior

    def _behavior(
        self, node: model.Behavior, scenario: model.Scenario, env: dict, used_actors: set[str], used_names: set[str]
    ) -> None:
        if isinstance(node, model.Composition):
            signature = library.COMPOSITIONS[node.operator]
            self._arguments(
                signature, node.arguments, node.location, scenario, env, used_actors, used_names, what=node.operator
            )
            if not node.children:
                self.error(node.location, f"{node.operator} has no members")
            return
        if isinstance(node, model.Invocation):
            self._invocation(node, scenario, env, used_actors, used_names)
            return
        if isinstance(node, model.Wait):
            used_names.update(
                n.name for n in names_in(node.condition) if not isinstance(node.condition, model.EventReference)
            )
            self._event_specification(node.condition, scenario, env, node.location, waits=True)
            return
        if isinstance(node, model.Emit):
            if node.event not in {e.name for e in scenario.events}:
                self.error(
                    node.location,
                    f"emit names an undeclared event {node.event!r}",
                    f"declare it in the scenario: event {node.event}",
                )
            return
        self.error(node.location, "not supported: call", "methods with side effects cannot be planned; remove the call")

    def _unprovided(self, location: SourceLocation, kind: str, name: str, declared: dict, provided) -> None:
        """An action or modifier the registry lacks: one the standard library declares is refused
        by name (the tool does not execute it), any other is unknown."""
        if kind == "action" and name in ENVIRONMENT_ACTIONS:
            self.error(
                location,
                f"{name}() is an action of the environment, not of a vehicle",
                f"write it as env.{name}(...) with a field env: environment",
            )
        elif name in declared:
            self.error(
                location,
                f"not supported: the standard's {kind} {name!r}",
                f"declared in {declared[name].part}; this tool does not execute it. "
                + self._known(f"{kind}s", provided),
            )
        else:
            self.error(location, f"unknown {kind} {name!r}", self._known(f"{kind}s", provided))

    def _invocation(self, node: model.Invocation, scenario, env, used_actors, used_names) -> None:
        actor = node.actor
        if actor in self.environments:
            self._environment_action(node, scenario, env, used_actors, used_names)
            return
        if actor is None:
            self.error(
                node.location,
                f"{node.action}() needs an actor",
                f"write it as {scenario.actors[0].name if scenario.actors else 'v1'}.{node.action}()",
            )
        elif scenario.actor(actor) is None:
            self.error(
                node.location, f"unknown actor {actor!r}", self._known("actors", [a.name for a in scenario.actors])
            )
        else:
            used_actors.add(actor)
        context = _ConstructContext(self, env)
        action = self.registry.action(node.action)
        if action is None:
            self._unprovided(node.location, "action", node.action, standard_library().actions, self.registry.actions)
        else:
            binding = self._arguments(
                action.signature,
                node.arguments,
                node.location,
                scenario,
                env,
                used_actors,
                used_names,
                what=f"{node.action}()",
            )
            action.check(binding, replace(context, location=node.location))
            if actor is not None and scenario.actor(actor) is not None:
                stationary = scenario.actor(actor).stationary
                if stationary and action.moves:
                    standing = [name for name, a in self.registry.actions.items() if not a.moves]
                    self.error(
                        node.location,
                        f"{actor!r} is a stationary_object: it can only {' or '.join(n + '()' for n in standing)}",
                        "declare it as a car if it should move",
                    )
        for modifier in node.modifiers:
            # a label on a modifier (`l1: lane(...)`, as the standard's examples name them) only
            # names the use: read, with nothing to refer to it
            if modifier.actor is not None and modifier.actor != actor:
                self.error(
                    modifier.location,
                    f"this modifier names {modifier.actor!r} but the invocation is for {actor!r}",
                    "put it in a with: block of that actor's invocation",
                )
            construct = self.registry.modifier(modifier.name)
            if construct is None:
                self._unprovided(
                    modifier.location, "modifier", modifier.name, standard_library().modifiers, self.registry.modifiers
                )
                continue
            binding = self._arguments(
                construct.signature,
                modifier.arguments,
                modifier.location,
                scenario,
                env,
                used_actors,
                used_names,
                what=f"{modifier.name}()",
            )
            construct.check(binding, replace(context, location=modifier.location))
            construct.check_movement_options(binding, replace(context, location=modifier.location))
            self._not_relative_to_itself(construct.signature, binding, actor, modifier.name)
        local = dict(env)
        local["it.duration"] = Interval(0.0, math.inf, TIME)
        for constraint in node.constraints:
            if isinstance(constraint, model.RemoveDefault):
                continue
            for name in names_in(constraint.expression):
                if name.name != "it.duration" and name.name not in local and name.enum is None:
                    self.error(
                        name.location,
                        f"unknown name {name.name!r}",
                        "inside an invocation's with:, keep() can constrain it.duration",
                    )
                    break
            else:
                try:
                    value = evaluate(constraint.expression, local)
                except EvaluationError as error:
                    self.error(error.location, error.message, error.hint)
                    continue
                if not isinstance(value, bool):
                    self.error(constraint.location, "keep() needs a condition, e.g. keep(it.duration <= 5s)")
            used_names.update(n.name for n in names_in(constraint.expression))
        if node.until is not None:
            self._event_specification(node.until, scenario, env, node.location)

    def _not_relative_to_itself(self, signature, binding: library.Binding, actor: str | None, what: str) -> None:
        """An error at an argument that places the invocation's own actor relative to itself
        (``ego.drive() with: lane(right_of: ego)``): no plan can meet it, so check says so."""
        for parameter in signature.parameters:
            argument = binding[parameter.name] if parameter.kind == "actor" else None
            if actor is not None and argument is not None and isinstance(argument.value, model.Name):
                if argument.value.name == actor:
                    self.error(
                        argument.location,
                        f"{what}() places {actor!r} relative to itself ({parameter.name}: {actor})",
                        "name another vehicle: a modifier constrains the actor of the invocation it is given to",
                    )

    def _arguments(
        self, signature, arguments, location, scenario, env, used_actors, used_names, what: str
    ) -> library.Binding:
        binding = library.bind(signature, arguments)
        for argument in binding.surplus:
            self.error(argument.location, f"too many positional arguments to {what}", f"usage: {signature.usage()}")
        for argument in binding.unknown:
            self.error(
                argument.location, f"unknown argument {argument.name!r} of {what}", f"usage: {signature.usage()}"
            )
        for argument, parameter in binding.repeated:
            # a value and its range-typed counterpart (one of them given by its _range name)
            if parameter.ranged and (parameter.name in binding.ranged or (argument.name or "").endswith("_range")):
                self.error(
                    argument.location,
                    f"{what} takes one of {parameter.name} and {parameter.name}_range",
                    f"{parameter.name}: a value (a range: one value within it), {parameter.name}_range: an interval the value stays within",
                )
                continue
            self.error(argument.location, f"{what} is given {parameter.name!r} twice")
        given: dict[str, model.Argument] = {}
        for name, argument in binding.arguments.items():
            parameter = signature.parameter(name)
            if not parameter.supported:
                self.error(
                    argument.location,
                    f"not supported: argument {parameter.name!r} of {what}",
                    f"usage: {signature.usage()}",
                )
                continue
            given[name] = argument
            used_names.update(n.name for n in names_in(argument.value))
            self._value(argument, parameter, scenario, env, used_actors, what)
        for group in signature.exclusive:
            present = [given[name] for name in group if name in given]
            if len(present) > 1:
                self.error(present[1].location, f"{what} takes only one of {', '.join(group)}")
        for group in signature.required if not binding.unknown else ():
            if not any(name in given for name in group):
                options = " or ".join(
                    f"{name}:" if signature.parameter(name) and not signature.parameter(name).positional else name
                    for name in group
                )
                self.error(location, f"{what} needs {options}", f"usage: {signature.usage()}")
        return binding

    def _value(
        self, argument: model.Argument, parameter: library.Parameter, scenario, env, used_actors, what: str
    ) -> None:
        value = argument.value
        kind = parameter.kind
        if kind == "actor":
            if not isinstance(value, model.Name) or value.enum is not None:
                self.error(
                    value.location,
                    f"{parameter.name}: takes an actor",
                    self._known("actors", [a.name for a in scenario.actors]),
                )
            elif scenario.actor(value.name) is None:
                self.error(
                    value.location,
                    f"unknown actor {value.name!r}",
                    self._known("actors", [a.name for a in scenario.actors]),
                )
            else:
                used_actors.add(value.name)
            return
        if kind == "string":
            named = scenario.parameter(value.name) if isinstance(value, model.Name) else None
            if named is not None and named.type == "string":
                return  # a string parameter (CARLA's suites: a global map name)
            if not (isinstance(value, model.Literal) and isinstance(value.value, str)):
                self.error(value.location, f'{parameter.name}: takes a string, e.g. "Town04"')
            return
        if kind == "bool":
            if not (isinstance(value, model.Literal) and isinstance(value.value, bool)):
                self.error(value.location, f"{parameter.name}: takes true or false")
            return
        if kind.startswith("map:"):
            element = kind[4:]
            if not isinstance(value, model.Name) or self.map_elements.get(value.name) != element:
                owner = value.name.split(".")[0] if isinstance(value, model.Name) else ""
                members = [f"{owner}.{m}" for m, kind in TURN_RESULTS.items() if kind == element]
                hint = (
                    f"the {element} of {owner}'s turn is {' or '.join(members)}"
                    if owner in self.turn_labels
                    else f"declare one: {value.name if isinstance(value, model.Name) else 'x'}: {element}"
                )
                self.error(
                    value.location, f"{parameter.name}: takes a {element} of the map, a field of the scenario", hint
                )
            return
        if kind == "road":
            if isinstance(value, model.Name) and self._route_named(value.name) is not None:
                return
            owner = value.name.split(".")[0] if isinstance(value, model.Name) else ""
            if owner in self.turn_labels:
                self.error(
                    value.location,
                    f"not supported: {value.name}: a vehicle drives along {owner}.resulting_route "
                    "(the road in, the way through the junction and the road out)",
                    f"drive along({owner}.resulting_route)",
                )
                return
            self.error(
                value.location,
                f"{parameter.name}: takes the scenario's road",
                f"declare one: path: {library.ROAD_TYPE}",
            )
            return
        if kind.startswith("enum:"):
            enum = kind[5:]
            types = library.enum_types(enum)
            members = tuple(m for t in types for m in self.enums[t])
            if isinstance(value, model.Name) and scenario.parameter(value.name) is not None:
                if scenario.parameter(value.name).type not in types and value.enum is None and value.name in members:
                    # the argument's type decides: CARLA's examples declare `global start: string`
                    # and still write at: start
                    if (value.name, enum) not in self.shadowed:
                        self.shadowed.add((value.name, enum))
                        self.warning(
                            value.location,
                            f"{value.name!r} is read as the {enum} value {value.name} here and wherever a {enum} "
                            f"is taken, not as the {scenario.parameter(value.name).type} parameter of that name",
                            f"write {enum}!{value.name} to say so, or rename the parameter",
                        )
                elif scenario.parameter(value.name).type not in types:
                    self.error(
                        value.location,
                        f"{parameter.name}: takes a {enum}, but {value.name!r} is a {scenario.parameter(value.name).type}",
                    )
                return
            if (
                not isinstance(value, model.Name)
                or value.name not in members
                or (value.enum is not None and value.enum not in types)
            ):
                self.error(
                    value.location,
                    f"{parameter.name}: takes {', '.join(members[:-1])} or {members[-1]}"
                    if len(members) > 1
                    else f"{parameter.name}: takes {members[0]}",
                )
            return
        for call in calls_in(value):
            self.error(
                call.location, f"a function call is not allowed in {parameter.name}:", "write the value, or a parameter"
            )
            return
        try:
            result = evaluate(value, env)
        except EvaluationError as error:
            self.error(error.location, error.message, error.hint)
            return
        expected = library.PHYSICAL_TYPES.get(kind)
        example = {"length": "10m", "time": "3s", "speed": "20mps", "acceleration": "2mpss"}.get(kind, "1")
        if isinstance(result, model.Name):
            if scenario.actor(result.name) is not None:
                self.error(
                    value.location, f"{parameter.name}: takes {describe(expected)}, not the actor {result.name!r}"
                )
            else:
                self.error(value.location, f"unknown name {result.name!r}", "declare it as a parameter of the scenario")
            return
        if not isinstance(result, Interval):
            listed = isinstance(value, model.ListValue)
            self.error(
                value.location,
                f"{parameter.name}: takes {describe(expected)}, e.g. {example}",
                "[a, b] is a list; a range of values is written [a..b]" if listed else None,
            )
            return
        if result.dimension != expected:
            if expected is None:
                hint = "write a plain number, without a unit"
            elif result.dimension is None:
                hint = f"write it with a unit of {expected}, e.g. {example}"
            else:
                hint = f"use a unit of {expected}, e.g. {example}"
            self.error(
                value.location,
                f"{what} expects {describe(expected)} for {parameter.name}, got {describe(result.dimension)}",
                hint,
            )
            return
        if parameter.name == "duration" and result.low < 0:
            # here rather than where the automaton reads it, so that every negative one is reported
            self.error(value.location, "a duration must not be negative", "give a time from 0s up, e.g. 3s or [2s..4s]")
        if kind == "uint":
            if result.low < 0 or (result.is_point and not float(result.low).is_integer()):
                self.error(value.location, f"{parameter.name}: takes a whole number from 0 up")

    # -------------------------------------------------------------- road

    def _environment(self, scenario: model.Scenario, space: ParameterSpace) -> dict[str, object]:
        """Names an expression of this scenario may read: parameters (their ranges) and actors' speed and lane."""
        env = space.environment()
        for actor in scenario.actors:
            env[f"{actor.name}.speed"] = Interval(0.0, math.inf, SPEED)
            env[f"{actor.name}.lane"] = Interval(1.0, float(self.lanes), None)
        return env


def _mentions(scenario: model.Scenario, actor: str) -> bool:
    return _first_mention(scenario, actor) is not None


def _first_mention(scenario: model.Scenario, actor: str) -> SourceLocation | None:
    """Where the scenario's behaviors first name ``actor``: as an invocation's actor or an argument."""
    for behavior in scenario.behaviors:
        for node in model.walk(behavior):
            if isinstance(node, model.Invocation):
                if node.actor == actor:
                    return node.location
                arguments = [*node.arguments, *(a for m in node.modifiers for a in m.arguments)]
                for argument in arguments:
                    if isinstance(argument.value, model.Name) and argument.value.name == actor:
                        return argument.value.location
    return None


def _extended(scenario: model.Scenario, extensions) -> model.Scenario:
    """``scenario`` with the members of every ``extend`` block that names it, in file order."""
    for extension in extensions:
        if extension.target == scenario.name:
            scenario = _extend(scenario, extension.scenario)
    return scenario


def _extend(scenario: model.Scenario, extra: model.Scenario) -> model.Scenario:
    return replace(
        scenario,
        fields=scenario.fields + extra.fields,
        constraints=scenario.constraints + extra.constraints,
        events=scenario.events + extra.events,
        methods=scenario.methods + extra.methods,
        behaviors=scenario.behaviors + extra.behaviors,
        behavior=scenario.behavior
        if scenario.behavior is not None
        else (extra.behaviors[0] if extra.behaviors else None),
        unsupported=scenario.unsupported + extra.unsupported,
        modifiers=scenario.modifiers + extra.modifiers,
        coverage=scenario.coverage + extra.coverage,
        samples=scenario.samples + extra.samples,
    )


def _map_sides(scenario: model.Scenario) -> model.Scenario:
    """The scenario with ``m.inner_side()`` and ``m.outer_side()`` of its map ``m`` written out as
    the side they name: the tool's roads have right-hand traffic, so the inner side (toward
    oncoming traffic) is the left and the outer side the right (the standard's swerving example
    writes ``lane(side_of: x, side: map.inner_side())``)."""
    members = {}
    for item in scenario.fields:
        if item.type in library.ROAD_TYPES:
            members[f"{item.name}.inner_side"] = "left"
            members[f"{item.name}.outer_side"] = "right"
    if not members:
        return scenario
    return _rewritten(scenario, lambda node: substitute_calls(node, members))


def _rewritten(scenario: model.Scenario, rewrite) -> model.Scenario:
    """The scenario with ``rewrite`` applied to its behaviors and its scenario-wide modifiers."""
    return replace(
        scenario,
        behavior=rewrite(scenario.behavior),
        behaviors=rewrite(scenario.behaviors),
        modifiers=rewrite(scenario.modifiers),
    )


def _unit_of(type_name: str) -> str:
    """The SI unit a bound of a parameter of ``type_name`` is shown in (`` m``, `` s``, ...; none for a number)."""
    unit = SI_UNIT.get(library.PHYSICAL_TYPES.get(type_name), "")
    return f" {unit}" if unit else ""
