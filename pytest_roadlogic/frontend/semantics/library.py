"""The part of the OS2 standard library this tool knows: actor types, enums, compositions, the road,
and the signature machinery (``Signature``, ``bind``).

The actions and modifiers themselves are specified in ``pytest_roadlogic.constructs``, each with
its signature from here. The checker validates every invocation against these signatures, so a
misspelt argument or a speed given where a length belongs is reported with its place before
anything runs. A signature's ``tier`` says how far it is executed (docs/language.md): tier-2 entries check, but the
automaton may still refuse to translate them (it says so by name); arguments marked unsupported
are refused by the checker.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace

from ...settings import DUT_NAMES
from .. import model
from ..syntax.standard_library import LazyTable

# Built-in actor types that can drive on (or stand on) the highway.
ACTOR_TYPES = ("car", "truck", "vehicle", "stationary_object")
# Standard actors that own scenarios (`scenario traffic.overtake:`) but do not drive.
SCENARIO_OWNERS = ("traffic", "env", "osc_actor", "dut")
# Vehicles that CARLA's scenario runner (and suites written for it) use without declaring them:
# read as vehicles, the last two with a warning asking for a declaration.
IMPLICIT_VEHICLES = (*DUT_NAMES, "ego", "npc")  # the device under test as files spell it (settings), first
# The standard library's actors above the road users (stdlib/osc/actors.osc): a type a file derives
# from one of them is driven as a vehicle, with a warning, as a bare actor type is.
ABSTRACT_ACTOR_TYPES: Mapping[str, None] = LazyTable(
    lambda library: dict.fromkeys(
        name
        for name in library.actors
        if any(name in library.ancestors(t) for t in ACTOR_TYPES) and name not in ACTOR_TYPES
    )
)
# Standard actor types that cannot appear on a highway-only road.
UNSUPPORTED_ACTOR_TYPES = ("person", "pedestrian", "animal", "cyclist", "bicycle", "traffic_light")

# The road a scenario runs on, in the dialect of public OS2 scenario runners: a field of this type,
# constrained by modifiers applied to the whole scenario (`path: Path`, `path.path_min_driving_lanes(4)`).
ROAD_TYPE = "Path"
# the same, as the standard declares it (`map: map`, `map.roads_follow_in_junction(...)`, and a
# `route` a vehicle drives along, its lanes kept with `keep(it.min_lanes == 2)`)
ROAD_TYPES = (ROAD_TYPE, "map", "route")

# the map's elements a scenario names as fields of its own (`j: junction`, `r1: road`): the tool
# picks each from the map where roads_follow_in_junction names it (docs/junctions.md)
MAP_ELEMENT_TYPES = ("junction", "road")

NUMBER_TYPES = ("int", "uint", "float")
# the physical types the pipeline models (length, time, speed, acceleration: metres and seconds),
# as the standard library declares them (stdlib/osc/physical.osc); read on first use
PHYSICAL_TYPES: Mapping[str, str] = LazyTable(
    lambda library: {name: dimension for name, dimension in library.types.items() if dimension is not None}
)
SCALAR_TYPES: Mapping[str, None] = LazyTable(
    lambda library: dict.fromkeys([*PHYSICAL_TYPES, *NUMBER_TYPES, "bool", "string"])
)

# the standard library's enums (stdlib/osc/types.osc)
ENUMS: Mapping[str, tuple[str, ...]] = LazyTable(lambda library: library.enums)
# an enum the standard replaced, by its successor: a parameter of the successor's type still takes
# the earlier enum's members (a speed change's rate_profile was a rate_profile in 1.0, with
# constant/smooth/asap, and is a dynamics_shape since 2.0)
ENUM_PREDECESSORS: Mapping[str, str] = {"dynamics_shape": "rate_profile"}


def enum_types(enum: str) -> tuple[str, ...]:
    """The enum types whose members a parameter of type ``enum`` takes: itself and its predecessor."""
    return (enum, ENUM_PREDECESSORS[enum]) if enum in ENUM_PREDECESSORS else (enum,)


@dataclass(frozen=True)
class Parameter:
    """One parameter of an action or modifier.

    ``kind`` is a physical type name (``length``...), ``uint``/``int``/``float``, ``actor`` or
    ``enum:<name>``. ``positional`` parameters may be given without a name, in declaration order.
    """

    name: str
    kind: str
    positional: bool = False
    supported: bool = True
    # also given as ``<name>_range`` (the standard's 2.2 range-typed counterpart: an interval the
    # value stays within, never a value chosen once)
    ranged: bool = False
    # other names it is given by (the standard's 2.2 change_lane(lane: n) for num_of_lanes)
    aliases: tuple[str, ...] = ()


@dataclass(frozen=True)
class Signature:
    name: str
    parameters: tuple[Parameter, ...]
    tier: int = 1
    # Each group lists alternatives of which at most one may be given ...
    exclusive: tuple[tuple[str, ...], ...] = ()
    # ... and of which at least one must be given.
    required: tuple[tuple[str, ...], ...] = ()
    description: str = ""

    def parameter(self, name: str) -> Parameter | None:
        """The parameter called ``name``, or given by it as an alias."""
        for parameter in self.parameters:
            if parameter.name == name:
                return parameter
        for parameter in self.parameters:
            if name in parameter.aliases:
                return parameter
        return None

    @property
    def positional(self) -> tuple[Parameter, ...]:
        return tuple(p for p in self.parameters if p.positional)

    def usage(self) -> str:
        names = [p.name for p in self.parameters if p.supported]
        return f"{self.name}({', '.join(names)})" if names else f"{self.name}()"


@dataclass
class Binding:
    """Arguments matched to a signature's parameters, and those that matched none."""

    arguments: dict[str, model.Argument] = field(default_factory=dict)  # parameter name -> argument
    unknown: list[model.Argument] = field(default_factory=list)  # named, but no such parameter
    surplus: list[model.Argument] = field(default_factory=list)  # positional, beyond the signature's
    repeated: list[tuple[model.Argument, Parameter]] = field(default_factory=list)  # a parameter given again
    ranged: set[str] = field(default_factory=set)  # parameters given by their ``_range`` name

    def __getitem__(self, name: str) -> model.Argument | None:
        return self.arguments.get(name)


def bind(signature: Signature, arguments: tuple[model.Argument, ...]) -> Binding:
    """Match arguments to parameters: named ones by name, positional ones in the signature's order."""
    binding = Binding()
    positional = list(signature.positional)
    for argument in arguments:
        if argument.name is None:
            if not positional:
                binding.surplus.append(argument)
                continue
            parameter = positional.pop(0)
        else:
            parameter = signature.parameter(argument.name)
            if parameter is None and argument.name.endswith("_range"):
                counterpart = signature.parameter(argument.name.removesuffix("_range"))
                if counterpart is not None and counterpart.ranged:
                    parameter = counterpart
                    if parameter.name not in binding.arguments:
                        binding.ranged.add(parameter.name)
            if parameter is None:
                binding.unknown.append(argument)
                continue
            if parameter in positional:
                positional.remove(parameter)
        if parameter.name in binding.arguments:
            binding.repeated.append((argument, parameter))
            continue
        binding.arguments[parameter.name] = argument
    return binding


AT = Parameter("at", "enum:at")
# the parameters the standard gives every movement modifier besides ``at`` (its domain model,
# "common parameters"): how physically it moves, whether a reference is tracked as it actually
# moves or as projected, and a shape of the change (not read: the motion planner shapes it)
MOVEMENT_OPTIONS = (
    Parameter("movement_mode", "enum:movement_mode"),
    Parameter("track", "enum:track"),
    Parameter("shape", "shape", supported=False),
)


def with_movement_options(signature: Signature) -> Signature:
    """``signature`` with the standard's common movement-modifier parameters it does not declare itself."""
    missing = tuple(p for p in MOVEMENT_OPTIONS if signature.parameter(p.name) is None)
    return replace(signature, parameters=signature.parameters + missing) if missing else signature


DURATION = Parameter("duration", "time")
# a lane change's rate: its lateral speed, which the motion planner chooses
RATE = (
    Parameter("rate_profile", "enum:rate_profile", supported=False),
    Parameter("rate_peak", "speed", supported=False),
)


def _signatures(*items: Signature) -> dict[str, Signature]:
    return {s.name: s for s in items}


COMPOSITIONS: dict[str, Signature] = _signatures(
    Signature("serial", (DURATION,)),
    Signature(
        "parallel",
        (
            DURATION,
            Parameter("overlap", "enum:overlap"),
            Parameter("start_to_start", "time"),
            Parameter("end_to_end", "time"),
        ),
    ),
    Signature("one_of", (DURATION,)),
)

# Modifiers of the road (ROAD_TYPE), applied to the whole scenario: its lanes, its map, and, on a
# map, what the route must have (docs/roads.md).
ROAD_MODIFIERS: dict[str, Signature] = _signatures(
    Signature(
        "path_min_driving_lanes",
        (Parameter("lanes", "uint", positional=True),),
        required=(("lanes",),),
        description="the road has at least this many lanes",
    ),
    Signature(
        "path_max_lanes",
        (Parameter("lanes", "uint", positional=True),),
        required=(("lanes",),),
        description="the road has at most this many lanes",
    ),
    # the standard's map.number_of_lanes on the scenario's road (or a turning path's route): its
    # driving lanes one way, as path_min_driving_lanes and path_max_lanes together
    Signature(
        "number_of_lanes",
        (
            Parameter("route", "road", positional=True),
            Parameter("num_of_lanes", "uint", positional=True),
            Parameter("lane_type", "enum:lane_type", positional=True),
            Parameter("lane_use", "enum:lane_use", supported=False),
            Parameter("directionality", "enum:directionality"),
        ),
        required=(("route",), ("num_of_lanes",)),
        description="the road has this many driving lanes one way (lane_type: driving, directionality: uni_direction)",
    ),
    Signature(
        "path_length",
        (Parameter("min_length", "length"), Parameter("max_length", "length")),
        required=(("min_length", "max_length"),),
        description="on a map: the route is at least min_length long",
    ),
    Signature(
        "path_curve",
        (Parameter("min_radius", "length"), Parameter("max_radius", "length"), Parameter("side", "enum:side")),
        required=(("min_radius", "max_radius"),),
        description="on a map: the route has a curve of a radius in min_radius..max_radius (to the side)",
    ),
    # the standard's map.roads_follow_in_junction: the route turns at a junction of the map, at the
    # junction and from and into the roads it names (fields of the scenario, shared by the turns of
    # several paths); its lanes and routes as values of their own are not yet (docs/junctions.md)
    Signature(
        "roads_follow_in_junction",
        (
            Parameter("direction", "enum:junction_direction"),
            Parameter("number_of_roads", "uint"),
            Parameter("junction", "map:junction"),
            Parameter("in_road", "map:road"),
            Parameter("out_road", "map:road"),
            Parameter("clockwise_count", "uint", supported=False),
            Parameter("in_lane", "road", supported=False),
            Parameter("out_lane", "road", supported=False),
            Parameter("junction_route", "road", supported=False),
            Parameter("resulting_route", "road", supported=False),
        ),
        description="on a map: the route turns at a junction (direction: straight, left, right, uturn)",
    ),
    # the standard's map relations between the routes of two paths that turn at junctions
    # (roads.asks.RouteRelation): map.routes_overlap, map.routes_are_opposite, map.routes_are_in_sequence
    Signature(
        "routes_overlap",
        (
            Parameter("route1", "road"),
            Parameter("route2", "road"),
            Parameter("overlap_kind", "enum:route_overlap_kind"),
        ),
        required=(("route1",), ("route2",), ("overlap_kind",)),
        description="on a map: two turning routes share their road in (start), their road out (end), either (any), or are one (equal)",
    ),
    Signature(
        "routes_are_opposite",
        (
            Parameter("route1", "road"),
            Parameter("route2", "road"),
            Parameter("containing_road", "map:road"),
            Parameter("lateral_overlap", "enum:lateral_overlap_kind"),
        ),
        required=(("route1",), ("route2",)),
        description="on a map: two turning routes drive a road (containing_road) in opposite directions",
    ),
    Signature(
        "routes_are_in_sequence",
        (
            Parameter("preceding", "road"),
            Parameter("succeeding", "road"),
            Parameter("road", "map:road"),
        ),
        required=(("preceding",), ("succeeding",)),
        description="on a map: the succeeding turning route comes in on the road (road) the preceding one leaves on",
    ),
    # an OpenDRIVE file: the scenario's map; a name (CARLA's towns): a warning, the straight road stands in
    Signature(
        "set_map",
        (Parameter("map", "string", positional=True),),
        required=(("map",),),
        description="the map the scenario was written for",
    ),
)

# Functions usable in expressions, and those refused by name (tier 3).
FUNCTIONS = ("elapsed", "range")
UNSUPPORTED_FUNCTIONS = ("rise", "fall", "every", "sample", "random")
# expressions the grammar reads and nothing evaluates, by the function name the parser gives them
UNSUPPORTED_EXPRESSIONS = {
    "is": "a type test x.is(T)",
    "as": "a cast x.as(T)",
    "[]": "list element access x[i]",
    "?:": "a conditional expression c ? a : b",
}


def refused_call(expression: object) -> str | None:
    """What a call the tool reads but never evaluates is called in ``not supported: ...`` (a
    function such as ``rise()``, or an expression the parser reads as a call, such as a type
    test); None for any other expression."""
    if not isinstance(expression, model.Call):
        return None
    if expression.function in UNSUPPORTED_EXPRESSIONS:
        return UNSUPPORTED_EXPRESSIONS[expression.function]
    return f"{expression.function}()" if expression.function in UNSUPPORTED_FUNCTIONS else None
