"""The scenario model: what an ``.osc`` file says, independent of how it was spelled.

Every node keeps its ``SourceLocation`` so that later stages (the automaton, the planner's
unsatisfiable cores, the monitor's explanations) can point back at the line that caused them.
All physical values are in SI units.

The parser fills this model without judging it; ``checker`` resolves names and types, and
``parameters`` turns fields and ``keep`` constraints into the ranges that sampling draws from.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .errors import SourceLocation

# ------------------------------------------------------------------ expressions


@dataclass(frozen=True)
class Quantity:
    """A number with a physical dimension (``None`` for a plain number), already in SI."""

    value: float
    dimension: str | None
    location: SourceLocation


@dataclass(frozen=True)
class Range:
    """An inclusive interval ``[low..high]``; a logical parameter left for sampling or the solver."""

    low: Quantity
    high: Quantity
    location: SourceLocation

    @property
    def dimension(self) -> str | None:
        return self.low.dimension


@dataclass(frozen=True)
class Name:
    """A bare or dotted identifier: an actor, a parameter, an enum member such as ``start``, ``it.speed``.

    ``enum`` is set for the qualified spelling ``side!left``.
    """

    name: str
    location: SourceLocation
    enum: str | None = None

    @property
    def parts(self) -> tuple[str, ...]:
        return tuple(self.name.split("."))


@dataclass(frozen=True)
class Literal:
    """A string or boolean literal."""

    value: str | bool
    location: SourceLocation


@dataclass(frozen=True)
class ListValue:
    items: tuple[Expression, ...]
    location: SourceLocation


@dataclass(frozen=True)
class Unary:
    operator: str  # '-', '+', 'not'
    operand: Expression
    location: SourceLocation


@dataclass(frozen=True)
class Binary:
    """``left op right`` for arithmetic, comparison (``==``, ``in``, ...) and logic (``and``, ``=>``)."""

    operator: str
    left: Expression
    right: Expression
    location: SourceLocation


@dataclass(frozen=True)
class Call:
    """A function-style expression: ``elapsed(3s)``, ``range(1m, 2m)``, ``sample(...)``."""

    function: str
    arguments: tuple[Argument, ...]
    location: SourceLocation


Expression = Quantity | Range | Name | Literal | ListValue | Unary | Binary | Call
Value = Expression  # kept for readers of older code: an argument's value is any expression


@dataclass(frozen=True)
class Argument:
    name: str | None
    value: Expression
    location: SourceLocation


def argument_named(arguments: tuple[Argument, ...], name: str) -> Argument | None:
    for argument in arguments:
        if argument.name == name:
            return argument
    return None


# ------------------------------------------------------------------ constraints and fields


@dataclass(frozen=True)
class Keep:
    """``keep([default|hard] expression)``. Inside a field's ``with:``, ``subject`` is that field (``it``)."""

    expression: Expression
    strength: str  # 'hard' or 'default'
    location: SourceLocation
    subject: str | None = None


@dataclass(frozen=True)
class RemoveDefault:
    target: Expression
    location: SourceLocation


@dataclass(frozen=True)
class Field:
    """A typed field: an actor (``v1: car``) or a parameter (``gap: length = 10m``).

    Which one depends on the type, known only once imports are loaded; ``checker`` decides.
    """

    name: str
    type: str
    default: Expression | None
    constraints: tuple[Keep | RemoveDefault, ...]
    location: SourceLocation
    is_list: bool = False
    type_location: SourceLocation | None = None


@dataclass(frozen=True)
class Event:
    name: str
    specification: EventSpecification | None
    location: SourceLocation


@dataclass(frozen=True)
class EventReference:
    """``@name [if condition]``."""

    name: str
    condition: Expression | None
    location: SourceLocation


EventSpecification = EventReference | Expression


@dataclass(frozen=True)
class Method:
    """``def name(params) -> type is expression`` (tier 2, expression methods only)."""

    name: str
    parameters: tuple[Field, ...]
    return_type: str | None
    body: Expression | None
    external: bool
    location: SourceLocation


@dataclass(frozen=True)
class Unsupported:
    """A construct that parses but that this tool refuses (tier 3); the checker reports it."""

    construct: str
    location: SourceLocation
    hint: str | None = None
    severity: str = "error"  # "warning": read and ignored, nothing it would change is executed


# ------------------------------------------------------------------ behavior


@dataclass(frozen=True)
class Modifier:
    """A modifier invocation inside a ``with:`` block, e.g. ``lane(same_as: v2, at: start)``."""

    name: str
    arguments: tuple[Argument, ...]
    location: SourceLocation
    actor: str | None = None  # ``v1.lane(...)`` names the actor explicitly
    # ``my_mod: map.roads_follow_in_junction(...)``: the name its results are read by (``my_mod.resulting_route``)
    label: str | None = None

    def argument(self, name: str) -> Argument | None:
        return argument_named(self.arguments, name)

    def positional(self) -> tuple[Argument, ...]:
        return tuple(a for a in self.arguments if a.name is None)


@dataclass(frozen=True)
class Invocation:
    """An action invoked on an actor, e.g. ``A: v1.drive() with: ...``."""

    actor: str | None
    action: str
    arguments: tuple[Argument, ...]
    modifiers: tuple[Modifier, ...]
    label: str | None
    location: SourceLocation
    constraints: tuple[Keep | RemoveDefault, ...] = ()
    until: EventSpecification | None = None

    def argument(self, name: str) -> Argument | None:
        return argument_named(self.arguments, name)


@dataclass(frozen=True)
class Composition:
    """``serial``, ``parallel`` or ``one_of`` over child behaviors."""

    operator: str
    arguments: tuple[Argument, ...]
    children: tuple[Behavior, ...]
    label: str | None
    location: SourceLocation

    def argument(self, name: str) -> Argument | None:
        return argument_named(self.arguments, name)


@dataclass(frozen=True)
class Wait:
    """``wait elapsed(3s)``, ``wait @event``, ``wait <condition>``."""

    condition: EventSpecification
    label: str | None
    location: SourceLocation


@dataclass(frozen=True)
class Emit:
    event: str
    arguments: tuple[Argument, ...]
    label: str | None
    location: SourceLocation


@dataclass(frozen=True)
class CallStatement:
    """``call method()`` (tier 3: parsed so the checker can refuse it by name)."""

    expression: Expression
    label: str | None
    location: SourceLocation


Behavior = Invocation | Composition | Wait | Emit | CallStatement


def walk(behavior: Behavior):
    """Every behavior node of a tree, parents before children."""
    yield behavior
    if isinstance(behavior, Composition):
        for child in behavior.children:
            yield from walk(child)


# ------------------------------------------------------------------ declarations


@dataclass(frozen=True)
class Actor:
    """An actor field of a scenario. ``base`` is the built-in type it derives from (car, truck, ...)."""

    name: str
    type: str
    location: SourceLocation
    base: str | None = None

    @property
    def kind(self) -> str:
        return self.base or self.type

    @property
    def stationary(self) -> bool:
        return self.kind == "stationary_object"


@dataclass(frozen=True)
class Coverage:
    """A ``cover(...)`` or ``record(...)`` member (``kind``), its arguments as written; a field's
    own (in its ``with:``) names the field (``field``) when it gives no name."""

    kind: str
    arguments: tuple[Argument, ...]
    location: SourceLocation
    field: str | None = None


@dataclass(frozen=True)
class SampledVariable:
    """``var name: type = sample(expression, @event)``: a value the run takes when ``event``
    happens, read by the scenario's ``cover(...)``/``record(...)`` items."""

    name: str
    type: str | None
    expression: Expression
    event: EventSpecification
    location: SourceLocation


@dataclass(frozen=True)
class Scenario:
    """A ``scenario`` (or ``action``) declaration.

    The parser puts every typed field in ``fields``; the checker splits them into ``actors`` and
    ``parameters``. ``behaviors`` holds every ``do`` so that a second one is reported, not lost.
    """

    name: str
    actor_type: str | None
    actors: tuple[Actor, ...]
    behavior: Behavior | None
    location: SourceLocation
    kind: str = "scenario"
    parent: str | None = None
    fields: tuple[Field, ...] = ()
    parameters: tuple[Field, ...] = ()
    constraints: tuple[Keep | RemoveDefault, ...] = ()
    events: tuple[Event, ...] = ()
    methods: tuple[Method, ...] = ()
    behaviors: tuple[Behavior, ...] = ()
    unsupported: tuple[Unsupported, ...] = ()
    path: str | None = None
    # Modifiers applied to the whole scenario (``path.path_min_driving_lanes(4)``): only road ones are accepted.
    modifiers: tuple[Modifier, ...] = ()
    # its cover(...) and record(...) members, and those of its fields
    coverage: tuple[Coverage, ...] = ()
    samples: tuple[SampledVariable, ...] = ()  # its var ... = sample(...) members

    def actor(self, name: str) -> Actor | None:
        for actor in self.actors:
            if actor.name == name:
                return actor
        return None

    def parameter(self, name: str) -> Field | None:
        for parameter in self.parameters:
            if parameter.name == name:
                return parameter
        return None


@dataclass(frozen=True)
class TypeDeclaration:
    """An ``actor`` or ``struct`` declaration (tier 2): a named type with fields."""

    kind: str  # 'actor' or 'struct'
    name: str
    parent: str | None
    fields: tuple[Field, ...]
    constraints: tuple[Keep | RemoveDefault, ...]
    location: SourceLocation
    methods: tuple[Method, ...] = ()
    # ``inherits vehicle(vehicle_category == vehicle_category!car)``: the parent's condition
    condition: Expression | None = None


@dataclass(frozen=True)
class PhysicalTypeDeclaration:
    """``type velocity is SI(m: 1, s: -1)``: a physical type by its SI base-unit exponents."""

    name: str
    exponents: tuple[tuple[str, float], ...]  # (base unit, exponent), as written
    location: SourceLocation


@dataclass(frozen=True)
class UnitDeclaration:
    """``unit kph of velocity is SI(m: 1, s: -1, factor: 0.277777778)``."""

    name: str
    type: str
    exponents: tuple[tuple[str, float], ...]
    factor: float
    location: SourceLocation
    offset: float = 0.0  # SI value of the unit's zero (a temperature's): value * factor + offset


@dataclass(frozen=True)
class ModifierDeclaration:
    """``modifier Path.set_map``: a library's declaration of a modifier it names, with its
    parameters when it has a body of fields (the standard library's, ``stdlib/osc/movement.osc``)."""

    owner: str | None
    name: str
    location: SourceLocation
    parameters: tuple[Field, ...] = ()


@dataclass(frozen=True)
class EnumDeclaration:
    name: str
    members: tuple[str, ...]
    location: SourceLocation
    extends: bool = False  # `extend e: [...]`: members added to an enum declared elsewhere


@dataclass(frozen=True)
class Extension:
    """``extend name:`` adds members to a scenario declared here or in an imported file."""

    target: str
    scenario: Scenario  # the members, gathered as a scenario body
    location: SourceLocation


@dataclass(frozen=True)
class Import:
    """``import osc.standard`` (the built-in library) or ``import "lib.osc"`` (a file, relative)."""

    target: str
    is_file: bool
    location: SourceLocation

    def file(self, importing: str) -> Path | None:
        """The file this import names, relative to the importing file: a quoted path, or an
        unquoted one ending in ``.osc`` (``import basic.osc``, as CARLA suites write it); None for
        a library (``osc.standard``)."""
        if self.is_file or self.target.endswith(".osc"):
            return (Path(importing).parent / self.target).resolve()
        return None


@dataclass(frozen=True)
class OscFile:
    path: str
    scenarios: tuple[Scenario, ...]
    source_text: str
    imports: tuple[Import, ...] = ()
    types: tuple[TypeDeclaration, ...] = ()
    enums: tuple[EnumDeclaration, ...] = ()
    globals: tuple[Field, ...] = ()
    extensions: tuple[Extension, ...] = ()
    unsupported: tuple[Unsupported, ...] = ()
    misplaced_imports: tuple[Import, ...] = field(default=())
    physical_types: tuple[PhysicalTypeDeclaration, ...] = ()
    units: tuple[UnitDeclaration, ...] = ()
    modifier_declarations: tuple[ModifierDeclaration, ...] = ()

    def scenario(self, name: str) -> Scenario:
        for scenario in self.scenarios:
            if scenario.name == name:
                return scenario
        raise KeyError(name)
