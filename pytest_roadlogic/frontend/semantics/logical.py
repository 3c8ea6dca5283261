"""A scenario's logical parameters: each open value once, with its one identity from the file to the report.

A logical parameter is a value the scenario leaves open at one instant: a declared parameter with
a range or a set of values (``gap: length with: keep(it in [10..20]m)``), or an inline range that
holds at one point of a phase (``position([10..20]m, ..., at: start)``, ``at: end``, a duration, a
change's target). The checker computes them once (``CheckedScenario.parameters``); the sampler
draws them, the planner's instance names the constraints they bound (``places``), and every
report (the plugin's, the CLI's, the bench's) shows them through ``show``.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass
from typing import Any

from .. import model
from ..errors import SourceLocation
from ..syntax.units import SI_UNIT
from .library import Binding, bind
from .parameters import ParameterSpace
from .values import names_in

UNIT = SI_UNIT


@dataclass(frozen=True)
class LogicalParameter:
    """One open value of a scenario: its name in samples and reports, and the range it is drawn from."""

    name: str
    location: SourceLocation
    dimension: str | None = None
    low: float = 0.0
    high: float = 0.0
    integer: bool = False  # lane numbers, int/uint parameters
    choices: tuple[Any, ...] = ()  # bool and enum parameters (then low/high are unused)
    declared: bool = True  # a declared parameter, not an inline range
    # the planning resolution its sampled value is narrowed with, when not its dimension's
    # (``Construct.sampled_as``: a time headway is a time, but no duration)
    sampled_as: str | None = None
    # why it is a parameter (the README's rule), as reports name it: a declared parameter, a
    # value at one instant (at: start / at: end), a duration, or an action's target
    kind: str = "declared parameter"
    # where its value is used: the invocations, modifiers, arguments and ranges whose constraints
    # it bounds. A constraint names its source (a guard's bound, a phase's duration), so the
    # planner's instance, a no-plan message and a report can name the parameter behind it
    places: tuple[SourceLocation, ...] = ()

    def show(self, value: Any) -> str:
        if self.choices:
            return str(value).lower() if isinstance(value, bool) else str(value)
        number = f"{value:g}" if self.integer else f"{value:.1f}".rstrip("0").rstrip(".")
        return f"{number} {UNIT[self.dimension]}".rstrip()


def logical_parameters_of(scenario: model.Scenario, space: ParameterSpace, registry) -> tuple[LogicalParameter, ...]:
    """Every open value of a scenario, declared parameters first, then inline ranges in source
    order: computed once, by the checker, and kept in ``CheckedScenario.parameters``."""
    found: list[LogicalParameter] = []
    uses = _uses(scenario.behavior)
    for domain in space.domains.values():
        if domain.fixed or not domain.bounded:
            continue
        if domain.interval is not None:
            integer = domain.type in ("int", "uint")
            low, high = domain.interval.low, domain.interval.high
            if integer:
                low, high = math.ceil(low), math.floor(high)
            found.append(
                LogicalParameter(
                    domain.name,
                    domain.location,
                    domain.interval.dimension,
                    low,
                    high,
                    integer,
                    places=uses.get(domain.name, ()),
                )
            )
        elif domain.choices:
            found.append(
                LogicalParameter(
                    domain.name, domain.location, choices=tuple(domain.choices), places=uses.get(domain.name, ())
                )
            )
    inline = list(_inline_ranges(scenario.behavior, registry))
    counts = Counter(name for name, _, _, _, _ in inline)
    for name, node, sampled_as, kind, places in inline:
        if counts[name] > 1:
            name = f"{name}@{node.location.line}"
        low, high = sorted((node.low.value, node.high.value))
        integer = node.dimension is None and float(low).is_integer() and float(high).is_integer()
        found.append(
            LogicalParameter(
                name,
                node.location,
                node.dimension,
                low,
                high,
                integer,
                declared=False,
                sampled_as=sampled_as,
                kind=kind,
                places=places,
            )
        )
    return tuple(found)


WAY = "way through the map"


def way_parameters(ways, asked_at: dict[str, SourceLocation]) -> tuple[LogicalParameter, ...]:
    """A parameter per path of ``ways`` (``roads.ways.Ways``; None: the scenario's paths do not
    turn) that may take more than one way through the map, named after the path and placed at
    the ``roads_follow_in_junction`` that ``asked_at`` says asks for its turn: its choices are the
    ways' labels, the roomiest first (``roads.ways.choose_ways``), the first what a run takes
    when nothing is sampled."""
    if ways is None:
        return ()
    return tuple(
        LogicalParameter(path, asked_at[path], choices=choices, kind=WAY, places=(asked_at[path],))
        for path in ways.paths
        if len(choices := ways.choices(path)) > 1
    )


def _inline_ranges(behavior, registry):
    """(name, Range, resolution or None, kind, places) for every range written in the behavior,
    named after where it stands; its places are the range, its argument and the node it is an
    argument of (an invocation, a modifier, a composition or a wait)."""
    if behavior is None:
        return
    for node in model.walk(behavior):
        if isinstance(node, model.Invocation):
            phase = node.label or f"{node.actor}.{node.action}"
            action = registry.action(node.action)
            binding = bind(action.signature, node.arguments) if action else None
            # an action held throughout (keep_space_gap): its values bound the phase; its duration is a parameter
            held = action is not None and action.held_throughout(binding)
            yield from _ranges_of(
                phase, node.arguments, binding, action, only=("duration",) if held else None, at=node.location
            )
            for modifier in node.modifiers:
                construct = registry.modifier(modifier.name)
                binding = bind(construct.signature, modifier.arguments) if construct else None
                if construct is not None and construct.held_throughout(binding):
                    continue  # a bound of the whole phase, kept by the planner: not a parameter
                yield from _ranges_of(
                    f"{phase}.{modifier.name}", modifier.arguments, binding, construct, at=modifier.location
                )
        elif isinstance(node, model.Composition):
            yield from _ranges_of(node.label or node.operator, node.arguments, None, at=node.location)
        elif isinstance(node, model.Wait) and isinstance(node.condition, model.Call):
            for argument in node.condition.arguments:
                if isinstance(argument.value, model.Range):
                    places = (argument.value.location, argument.location, node.condition.location, node.location)
                    yield f"{node.label or 'wait'}.{node.condition.function}", argument.value, None, "duration", places


def _ranges_of(
    prefix: str,
    arguments: tuple[model.Argument, ...],
    binding: Binding | None,
    construct=None,
    only: tuple[str, ...] | None = None,
    at: SourceLocation | None = None,
):
    named = {id(a): n for n, a in binding.arguments.items()} if binding is not None else {}
    for argument in arguments:
        if isinstance(argument.value, model.Range):
            name = argument.name or named.get(id(argument), "value")
            if only is not None and name not in only:
                continue
            yield (
                f"{prefix}.{name}",
                argument.value,
                construct.sampled_as(name) if construct is not None else None,
                _kind(name, binding, construct),
                tuple(p for p in (argument.value.location, argument.location, at) if p is not None),
            )


def _kind(name: str, binding: Binding | None, construct) -> str:
    """Why an inline range is a logical parameter, in the words of the README's rule."""
    if name == "duration":
        return "duration"
    if construct is not None and construct.kind == "modifier":
        return f"at: {construct.anchor(binding)}"  # a CARLA speed without at: holds at the end
    return f"{construct.name}'s {name}" if construct is not None else "value"


def _uses(behavior) -> dict[str, tuple[SourceLocation, ...]]:
    """Per name an argument mentions, the places it is used: the argument, and the invocation,
    modifier, composition or wait it is an argument of."""
    uses: dict[str, list[SourceLocation]] = {}
    if behavior is None:
        return {}

    def note(arguments, at: SourceLocation) -> None:
        for argument in arguments:
            for name in names_in(argument.value):
                uses.setdefault(name.name, []).extend((argument.location, at))

    for node in model.walk(behavior):
        if isinstance(node, model.Invocation):
            note(node.arguments, node.location)
            for modifier in node.modifiers:
                note(modifier.arguments, modifier.location)
        elif isinstance(node, model.Composition):
            note(node.arguments, node.location)
        elif isinstance(node, model.Wait) and isinstance(node.condition, model.Call):
            note(node.condition.arguments, node.location)
    return {name: tuple(dict.fromkeys(places)) for name, places in uses.items()}


def names_by_place(parameters) -> dict[SourceLocation, tuple[str, ...]]:
    """Per place in the file, the logical parameters used there (``LogicalParameter.places``)."""
    found: dict[SourceLocation, list[str]] = {}
    for parameter in parameters:
        for place in parameter.places:
            names = found.setdefault(place, [])
            if parameter.name not in names:
                names.append(parameter.name)
    return {place: tuple(names) for place, names in found.items()}


def describe_values(parameters, values: dict[str, Any]) -> list[str]:
    """``name = value unit (line L, kind)`` for every sampled value, for reports."""
    by_name = {p.name: p for p in parameters}
    return [
        f"{name} = {by_name[name].show(value)} (line {by_name[name].location.line}, {by_name[name].kind})"
        for name, value in values.items()
        if name in by_name
    ]
