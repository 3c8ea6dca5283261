"""From parameter fields and ``keep`` constraints to the domains that sampling draws from.

OS2's rules, as this module applies them:
- ``x: T = v`` is ``keep(default x == v)``; a ``default`` constraint is soft. A ``v`` that names
  other parameters (``fast: speed = base + 2mps``) is the relation ``x == v``, held unless a hard
  ``==`` or ``in`` of ``x``'s own overrides it.
- A hard ``keep(x == v)`` or ``keep(x in [a..b])`` on the same parameter overrides its default;
  ``remove_default(x)`` drops it. A default that contradicts the hard bounds is ignored, with a warning.
- Hard constraints on one parameter (``==``, ``in``, ``<``, ``<=``, ``>``, ``>=``, joined by ``and``)
  intersect into an interval; an empty intersection is an error.
- Constraints relating several parameters are kept as ``relations``: samples must satisfy them.
The result, a ``ParameterSpace``, is what the refined strategy samples and what the automaton reads
when a parameter is left open (the base strategy: the planner picks within the range).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import model
from ..errors import Diagnostic, SourceLocation
from . import library
from .invocation import substitute_names
from .values import EvaluationError, Interval, describe, evaluate, names_in, possibly

_BOUND_OPERATORS = ("==", "in", "<", "<=", ">", ">=")
# a comparison seen from its other side: a < b is b > a
MIRRORED = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "==": "=="}


@dataclass(frozen=True)
class ParameterDomain:
    """The values one parameter may take.

    Numeric parameters have ``interval``; enum, bool and string parameters have ``choices``.
    """

    name: str
    type: str
    location: SourceLocation
    interval: Interval | None = None
    choices: tuple[object, ...] | None = None

    @property
    def fixed(self) -> bool:
        if self.interval is not None:
            return self.interval.is_point
        return self.choices is not None and len(self.choices) == 1

    @property
    def bounded(self) -> bool:
        return self.interval is None or (math.isfinite(self.interval.low) and math.isfinite(self.interval.high))

    def describe(self) -> str:
        if self.interval is not None:
            return str(self.interval)
        return " | ".join(str(c).lower() if isinstance(c, bool) else str(c) for c in self.choices or ())


@dataclass(frozen=True)
class ParameterSpace:
    domains: dict[str, ParameterDomain]
    relations: tuple[model.Keep, ...] = ()

    def environment(self, values: dict[str, object] | None = None) -> dict[str, object]:
        """Names to values for ``evaluate``: sampled values where given, domains elsewhere."""
        env: dict[str, object] = {}
        for name, domain in self.domains.items():
            if values is not None and name in values:
                env[name] = as_value(domain, values[name])
            elif domain.interval is not None:
                env[name] = domain.interval
            elif domain.fixed:
                env[name] = _choice_value(domain.choices[0], domain.location)
        return env

    def accepts(self, values: dict[str, object]) -> bool:
        """Whether sampled values satisfy the relations between parameters."""
        env = self.environment(values)
        try:
            return all(evaluate(relation.expression, env) is True for relation in self.relations)
        except EvaluationError:
            return False

    def refutes(self, relation: model.Keep, values: dict[str, object] | None = None) -> bool:
        """Whether ``relation`` fails for certain: at every value of the domains, ``values`` where given."""
        return not possibly(relation.expression, self.environment(values))

    def broken(self, values: dict[str, object]) -> model.Keep | None:
        """The first relation that ``values`` (some or all of the parameters) break for certain."""
        return next((relation for relation in self.relations if self.refutes(relation, values)), None)

    @property
    def free(self) -> tuple[ParameterDomain, ...]:
        return tuple(d for d in self.domains.values() if not d.fixed)


def as_value(domain: ParameterDomain, value: object) -> object:
    if isinstance(value, Interval):  # a band the refined strategy plans within
        return value
    if domain.interval is not None:
        number = float(value)  # type: ignore[arg-type]
        return Interval(number, number, domain.interval.dimension)
    return _choice_value(value, domain.location)


def _choice_value(value: object, location: SourceLocation) -> object:
    if isinstance(value, bool):
        return value
    if isinstance(value, str) and not value.startswith('"'):
        return model.Name(value, location)
    return model.Literal(value, location)


def parameter_space(
    parameters: tuple[model.Field, ...],
    constraints: tuple[model.Keep | model.RemoveDefault, ...],
    enums: dict[str, tuple[str, ...]] | None = None,
    refused_calls: set[SourceLocation] = frozenset(),
) -> tuple[ParameterSpace, list[Diagnostic]]:
    """Resolve parameter fields and the constraints on them; diagnostics are errors and warnings.
    ``refused_calls``: where calls stand that were refused already (a value is not asked of them)."""
    resolver = _Resolver(parameters, {**library.ENUMS, **(enums or {})}, refused_calls)
    return resolver.resolve(constraints), resolver.diagnostics


class _Resolver:
    """The state of one resolution: what is known of each parameter as constraints are read."""

    def __init__(
        self,
        parameters: tuple[model.Field, ...],
        enums: dict[str, tuple[str, ...]],
        refused_calls: set[SourceLocation] = frozenset(),
    ) -> None:
        self.parameters = parameters
        self.refused_calls = refused_calls
        self.enums = enums
        self.by_name = {p.name: p for p in parameters}
        self.hard: dict[str, Interval] = {}  # numeric parameters: the intersection of hard bounds
        self.hard_sources: dict[str, list[SourceLocation]] = {}
        self.overridden: set[str] = set()  # a hard == or in overrides the default
        self.defaults: dict[str, tuple[object, SourceLocation]] = {}
        self.choices: dict[str, tuple[object, ...]] = {}  # bool, enum and string parameters
        self.relations: list[model.Keep] = []
        self.computed: list[tuple[str, str, model.Expression, model.Expression, model.Keep]] = []
        self.diagnostics: list[Diagnostic] = []
        for parameter in parameters:
            if parameter.type in library.PHYSICAL_TYPES or parameter.type in library.NUMBER_TYPES:
                dimension = library.PHYSICAL_TYPES.get(parameter.type)
                low = 0.0 if parameter.type == "uint" else -math.inf
                self.hard[parameter.name] = Interval(low, math.inf, dimension)
            elif parameter.type == "bool":
                self.choices[parameter.name] = (False, True)
            elif parameter.type in enums:
                self.choices[parameter.name] = enums[parameter.type]
            else:
                self.choices[parameter.name] = ()  # strings: only a given value
        # for evaluating constraints: every numeric parameter unbounded, so only units are checked
        self.env = dict(self.hard)

    def add_error(self, location, message, hint=None, severity="error") -> None:
        self.diagnostics.append(Diagnostic(location, message, hint, severity))

    def resolve(self, constraints: tuple[model.Keep | model.RemoveDefault, ...]) -> ParameterSpace:
        related: list[model.Field] = []  # ``fast: speed = base + 2mps``: the value follows ``base``
        for parameter in self.parameters:
            if parameter.default is None:
                continue
            if parameter.name in self.hard and {n.name for n in names_in(parameter.default)} & set(self.by_name):
                related.append(parameter)
                continue
            value = self.value_for(parameter, parameter.default)
            if value is not None:
                self.defaults[parameter.name] = (value, parameter.default.location)
        for constraint in [c for p in self.parameters for c in p.constraints] + list(constraints):
            if isinstance(constraint, model.RemoveDefault):
                target = constraint.target
                if isinstance(target, model.Name) and target.name in self.by_name:
                    self.defaults.pop(target.name, None)
                elif not (isinstance(target, model.Name) and target.name == "it"):
                    self.add_error(constraint.location, "remove_default() takes the name of a parameter")
                continue
            for atom in _conjuncts(constraint.expression):
                self.apply_atom(atom, constraint)
        for parameter in related:
            # a value computed from other parameters holds unless a keep(== or in) of its own overrides it,
            # as a default does; it is a relation every sample meets
            if parameter.name not in self.overridden:
                location = parameter.default.location
                atom = model.Binary("==", model.Name(parameter.name, parameter.location), parameter.default, location)
                self.apply_atom(atom, model.Keep(atom, "hard", location))
        self.apply_computed()
        space = ParameterSpace({p.name: self.domain(p) for p in self.parameters}, tuple(self.relations))
        for relation in space.relations:
            if space.refutes(relation):
                # keep(a + b <= 20m) with a and b in [15..25]m: no sample can meet it; said here,
                # before Hypothesis filters every sample out or --values runs a case that breaks it
                names = sorted({n.name for n in names_in(relation.expression)} & set(space.domains))
                self.add_error(
                    relation.location,
                    "no values of the parameters' ranges meet this constraint",
                    f"widen the ranges of {', '.join(names)} or the constraint" if names else "widen the constraint",
                )
        return space

    def apply_computed(self) -> None:
        """Bounds computed from other parameters: each bounds its parameter by the hull of the
        values the others' ranges give it, and the constraint is a relation every sample meets."""
        for name, operator, other, atom, constraint in self.computed:
            mentioned = {n.name for n in names_in(other)} & set(self.by_name)
            env = {**self.env, **{m: self.current(m) for m in mentioned if m in self.hard}}
            saved, self.env = self.env, env
            try:
                self.bound(name, operator, other, atom, constraint)
            finally:
                self.env = saved
            it = {"it": model.Name(name, constraint.location)}
            self.relations.append(
                model.Keep(substitute_names(atom, it), constraint.strength, constraint.location, constraint.subject)
            )

    def current(self, name: str) -> Interval:
        """A numeric parameter's range as read so far: its hard bounds, narrowed by its default."""
        interval = self.hard[name]
        default = self.defaults.get(name) if name not in self.overridden else None
        if default is not None and isinstance(default[0], Interval):
            narrowed = interval.intersect(default[0])
            if not narrowed.empty:
                return narrowed
        return interval

    def domain(self, parameter: model.Field) -> ParameterDomain:
        name = parameter.name
        default = self.defaults.get(name) if name not in self.overridden else None
        if name in self.hard:
            interval = self.hard[name]
            if interval.empty:
                lines = ", ".join(str(loc.line) for loc in self.hard_sources.get(name, []))
                location = self.hard_sources.get(name, [parameter.location])[-1]
                self.add_error(
                    location,
                    f"parameter {name!r} is constrained to an empty range",
                    f"the constraints on lines {lines} contradict each other" if lines else "widen the range",
                )
                interval = Interval(interval.high, interval.high, interval.dimension)
            elif default is not None:
                value = default[0]
                if isinstance(value, Interval):
                    narrowed = interval.intersect(value)
                    if narrowed.empty:
                        self.add_error(
                            default[1],
                            f"the default of {name!r} ({value}) lies outside its range {interval}; it is ignored",
                            severity="warning",
                        )
                    else:
                        interval = narrowed
            return ParameterDomain(name, parameter.type, parameter.location, interval=interval)
        options = self.choices[name]
        if default is not None:
            value = default[0]
            if options and value not in options:
                self.add_error(
                    default[1], f"the default of {name!r} is not one of its values ({', '.join(map(str, options))})"
                )
            else:
                options = (value,)
        return ParameterDomain(name, parameter.type, parameter.location, choices=options)

    def subject(self, expression: model.Expression, constraint: model.Keep) -> str | None:
        if isinstance(expression, model.Name) and expression.enum is None:
            if expression.name == "it" and constraint.subject in self.by_name:
                return constraint.subject
            if expression.name in self.by_name:
                return expression.name
        return None

    def apply_atom(self, atom: model.Expression, constraint: model.Keep) -> None:
        by_name = self.by_name
        mentioned = {
            (constraint.subject if n.name == "it" else n.name)
            for n in names_in(atom)
            if (n.name == "it" and constraint.subject in by_name) or n.name in by_name
        }
        for name in names_in(atom):
            if (
                name.enum is None
                and name.name not in by_name
                and not (name.name == "it" and constraint.subject in by_name)
            ):
                if not any(name.name in members for members in self.enums.values()):
                    self.add_error(
                        name.location,
                        f"unknown name {name.name!r} in a constraint",
                        "a keep() constrains parameters of this scenario",
                    )
                    return
        if not mentioned:
            self.add_error(
                constraint.location,
                "this constraint mentions no parameter",
                "a keep() constrains parameters of this scenario",
            )
            return
        if isinstance(atom, model.Binary) and atom.operator in _BOUND_OPERATORS:
            left, right = self.subject(atom.left, constraint), self.subject(atom.right, constraint)
            operator = atom.operator
            other = atom.right
            name = left
            if left is None and right is not None and operator != "in":
                name, other, operator = right, atom.left, MIRRORED[operator]
            if name is not None and not (set(n.name for n in names_in(other)) & set(by_name)):
                self.bound(name, operator, other, atom, constraint)
                return
            if name is not None and name in self.hard and operator in ("in", "==", "<", "<=", ">", ">="):
                # a bound computed from other parameters (``it in [min_gap..max_gap]``): bounded by
                # their ranges once all constraints are read, and kept as a relation for samples
                self.computed.append((name, operator, other, atom, constraint))
                return
        # A relation between parameters (or a form with or/not/=>): checked on samples.
        if constraint.strength == "default":
            self.add_error(
                constraint.location,
                "not supported: a default constraint relating several parameters",
                "make it a hard keep()",
            )
            return
        try:
            evaluate(atom, self.env)
        except EvaluationError as error:
            self.add_error(error.location, error.message, error.hint)
            return
        self.relations.append(model.Keep(atom, constraint.strength, constraint.location, constraint.subject))

    def bound(
        self, name: str, operator: str, other: model.Expression, atom: model.Expression, constraint: model.Keep
    ) -> None:
        parameter = self.by_name[name]
        if constraint.strength == "default":
            if operator not in ("==", "in"):
                self.add_error(constraint.location, "not supported: a default constraint other than == or in")
                return
            value = self.value_for(parameter, other, allow_range=operator == "in")
            if value is not None:
                self.defaults[name] = (value, constraint.location)
            return
        if operator in ("==", "in"):
            self.overridden.add(name)
        if name not in self.hard:
            if operator != "==":
                self.add_error(atom.location, f"{operator!r} does not apply to {parameter.type} parameter {name!r}")
                return
            value = self.value_for(parameter, other)
            if value is not None:
                options = self.choices[name]
                if options and value not in options:
                    self.add_error(
                        other.location,
                        f"{value!r} is not a value of {parameter.type}",
                        f"its values: {', '.join(map(str, options))}",
                    )
                else:
                    self.choices[name] = (value,)
            return
        try:
            value = evaluate(other, self.env)
        except EvaluationError as error:
            self.add_error(error.location, error.message, error.hint)
            return
        if not isinstance(value, Interval):
            self.add_error(other.location, f"expected {describe(self.hard[name].dimension)} for {name!r}")
            return
        if value.dimension != self.hard[name].dimension:
            self.add_error(
                other.location,
                f"{name!r} is {_kind(parameter)} but this is {describe(value.dimension)}",
                "use a unit of the parameter's kind",
            )
            return
        if operator in ("==", "in"):
            bound = value
        elif operator in ("<", "<="):
            bound = Interval(-math.inf, value.high, value.dimension)
        else:
            bound = Interval(value.low, math.inf, value.dimension)
        self.hard[name] = self.hard[name].intersect(bound)
        self.hard_sources.setdefault(name, []).append(constraint.location)

    def value_for(self, parameter: model.Field, expression, allow_range: bool = True):
        """A default or fixed value of the parameter's type, or None after reporting why not."""
        if parameter.type in library.PHYSICAL_TYPES or parameter.type in library.NUMBER_TYPES:
            try:
                value = evaluate(expression, self.env)
            except EvaluationError as error:
                self.add_error(error.location, error.message, error.hint)
                return None
            dimension = library.PHYSICAL_TYPES.get(parameter.type)
            if isinstance(value, model.Call):
                if value.location in self.refused_calls:
                    return None
                self.add_error(
                    expression.location,
                    f"{value.function}(...) has no value the tool can compute for {parameter.name!r}",
                    "write the value as an expression, or as a method `def name(...) -> type is expression ...`",
                )
                return None
            if not isinstance(value, Interval) or value.dimension != dimension:
                got = describe(value.dimension) if isinstance(value, Interval) else "a name"
                self.add_error(
                    expression.location,
                    f"{parameter.name!r} is {_kind(parameter)} but this is {got}",
                    "use a unit of the parameter's kind",
                )
                return None
            if not value.is_point and not allow_range:
                self.add_error(expression.location, "expected a single value, not a range")
                return None
            return value
        if parameter.type == "bool":
            if isinstance(expression, model.Literal) and isinstance(expression.value, bool):
                return expression.value
            self.add_error(expression.location, f"{parameter.name!r} is a bool: write true or false")
            return None
        if parameter.type == "string":
            if isinstance(expression, model.Literal) and isinstance(expression.value, str):
                return expression.value
            self.add_error(expression.location, f"{parameter.name!r} is a string: write it in quotes")
            return None
        if isinstance(expression, model.Name):
            if expression.enum is not None and expression.enum != parameter.type:
                self.add_error(
                    expression.location, f"{expression.enum}!{expression.name} is not a value of {parameter.type}"
                )
                return None
            return expression.name
        self.add_error(expression.location, f"{parameter.name!r} is a {parameter.type}: write one of its values")
        return None


def _conjuncts(expression: model.Expression):
    if isinstance(expression, model.Binary) and expression.operator == "and":
        yield from _conjuncts(expression.left)
        yield from _conjuncts(expression.right)
    else:
        yield expression


def _kind(parameter: model.Field) -> str:
    dimension = library.PHYSICAL_TYPES.get(parameter.type)
    return describe(dimension) if dimension is not None else f"{describe(None)} ({parameter.type})"
