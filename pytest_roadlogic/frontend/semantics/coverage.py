"""The standard's ``cover(...)`` and ``record(...)`` members, read and checked (``coverage_items``).

An item names what it collects (``name``, or ``expression:``): here one of the scenario's logical
parameters, whose value a case samples and keeps whatever event the item names. A ``cover`` item
slices that value into buckets: ``range:`` and ``every:`` in the item's ``unit:``, or
``buckets:`` boundaries, or by default the parameter's own range in five (one bucket per choice of
an enum, a bool, a way through the map, or a whole number of at most ``MAX_VALUE_BUCKETS`` values).
``ignore:`` and ``illegal:`` are conditions on the item's value. What a run then counts per bucket
is ``evaluation.coverage``'s.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from ...dimensions import CAR_LENGTH
from .. import model
from ..errors import SourceLocation
from ..syntax.standard_library import UNITS
from ..syntax.units import ACCELERATION, LENGTH, SI_UNIT, SPEED
from .library import PHYSICAL_TYPES
from .logical import LogicalParameter
from .values import EvaluationError, Interval, evaluate

# a whole-number parameter of at most this many values has a bucket per value
MAX_VALUE_BUCKETS = 20
DEFAULT_BUCKETS = 5
# arguments read, and those refused for now with why
READ = (
    "name",
    "expression",
    "unit",
    "range",
    "every",
    "buckets",
    "text",
    "event",
    "target",
    "ignore",
    "illegal",
    "disable",
)
REFUSED = {"override": "an override of an item (override:) is not read yet: change the item itself"}
CROSS = " x "  # between the buckets of a cross's items, in its buckets' labels
# what an item may read of a vehicle in the run: the quantity -> (the trace's column, its dimension)
TRACE_QUANTITIES = {
    "speed": ("speed", SPEED),
    "acceleration": ("acceleration", ACCELERATION),
    "position": ("x", LENGTH),
}


@dataclass(frozen=True)
class Bucket:
    """One bucket of a cover item: ``[low, high)`` in SI (``closed``: ``[low, high]``, the last of a
    range), or one ``choice``; ``label`` as reports name it, in the item's unit."""

    label: str
    low: float = 0.0
    high: float = 0.0
    closed: bool = False
    choice: Any = None

    def holds(self, value: Any) -> bool:
        if self.choice is not None:
            return value == self.choice
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            return False
        return self.low - 1e-9 <= value < self.high - 1e-9 or (self.closed and abs(value - self.high) <= 1e-9)


@dataclass(frozen=True)
class CoverItem:
    """A checked ``cover`` or ``record`` (``kind``) of the logical parameter ``parameter``: its
    value's ``unit`` (as written, "" for SI) and ``factor`` (SI per unit), its ``buckets`` (a cover),
    how many samples each must have (``target``), and the conditions under which a value is left
    out (``ignore``) or is a malfunction (``illegal``)."""

    kind: str
    name: str
    parameter: str
    location: SourceLocation
    unit: str = ""
    factor: float = 1.0
    buckets: tuple[Bucket, ...] = ()
    text: str = ""
    target: int = 1
    ignore: model.Expression | None = None
    illegal: model.Expression | None = None
    dimension: str | None = None
    # a cross (``items:``): the items it crosses, each bucket one bucket of each (``parameter`` is "")
    crossed: tuple[str, ...] = ()
    # a value the run takes (``parameter`` is ""): vehicles' speeds, accelerations and positions
    # along the road, added and subtracted (``TRACE_QUANTITIES``), read at ``event``: (phase label
    # or "" for the scenario, "start" or "end")
    observed: model.Expression | None = None
    event: tuple[str, str] = ("", "end")

    def value_of(self, state: Mapping[str, Mapping[str, float]]) -> float:
        """The ``observed`` expression's value (SI) where ``state`` gives each vehicle's trace
        columns at the event."""
        return _observed_value(self.observed, state)

    def shown(self, value: Any) -> str:
        """``value`` (SI) as a report names it, in the item's unit."""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return str(value)
        unit = self.unit or SI_UNIT.get(self.dimension, "")
        return f"{value / self.factor:.4g} {unit}".rstrip()

    def ignored(self, value: Any) -> bool:
        return self._condition(self.ignore, value)

    def illegal_value(self, value: Any) -> bool:
        return self._condition(self.illegal, value)

    def _condition(self, expression: model.Expression | None, value: Any) -> bool:
        if expression is None:
            return False
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            value = Interval(float(value), float(value), self.dimension)
        return evaluate(expression, {self.name: value, self.parameter: value}) is True


def coverage_items(
    scenario: model.Scenario, parameters: tuple[LogicalParameter, ...], warning
) -> tuple[CoverItem, ...]:
    """The scenario's cover and record items, checked against its logical ``parameters``. An item
    the tool cannot collect is left out with a ``warning(location, message, hint)`` saying why:
    coverage never changes what a scenario plans or checks, so it never stops one from running."""

    def error(location: SourceLocation, message: str, hint: str | None = None) -> None:
        warning(location, f"{message}; the item is not collected", hint)

    by_name = {p.name: p for p in parameters}
    items: list[CoverItem] = []
    names: dict[str, SourceLocation] = {}
    for coverage in scenario.coverage:
        if any(argument.name == "items" for argument in coverage.arguments):
            item = _cross(coverage, {i.name: i for i in items}, error)
        else:
            item = _item(coverage, by_name, scenario, error, warning)
        if item is None:
            continue
        if item.name in names:
            error(
                coverage.location,
                f"{coverage.kind}({item.name}) is already declared on line {names[item.name].line}",
                "give each item its own name",
            )
            continue
        names[item.name] = coverage.location
        items.append(item)
    return tuple(items)


def _item(
    coverage: model.Coverage, by_name: dict[str, LogicalParameter], scenario: model.Scenario, error, warning
) -> CoverItem | None:
    kind = coverage.kind
    given: dict[str, model.Argument] = {}
    for position, argument in enumerate(coverage.arguments):
        name = argument.name or ("name" if position == 0 else None)
        if name is None:
            error(
                argument.location, f"{kind}() takes its name first, then named arguments", f"e.g. {kind}(gap, unit: m)"
            )
            return None
        if name in REFUSED:
            error(argument.location, f"not supported: {REFUSED[name]}", f"leave {name}: out")
            return None
        if name not in READ:
            error(argument.location, f"{kind}() has no argument {name!r}", f"it takes: {', '.join(READ)}")
            return None
        given[name] = argument
    if "name" not in given and coverage.field is None:
        error(coverage.location, f"{kind}() needs a name", f"e.g. {kind}(gap, unit: m)")
        return None
    name_value = given["name"].value if "name" in given else model.Name(coverage.field, coverage.location)
    if not isinstance(name_value, model.Name) or name_value.enum is not None:
        error(given["name"].location, f"{kind}(): a name is an identifier", f"e.g. {kind}(gap, unit: m)")
        return None
    name = name_value.name
    disable = given.get("disable")
    if disable is not None:
        if not (isinstance(disable.value, model.Literal) and isinstance(disable.value.value, bool)):
            error(disable.value.location, "disable: takes true or false")
            return None
        if disable.value.value:
            return None
    expression = given["expression"].value if "expression" in given else name_value
    if coverage.field is not None and isinstance(expression, model.Name) and expression.name == "it":
        expression = model.Name(coverage.field, expression.location)  # in a field's with:, it is the field
    sampled = _sampled(expression, name_value, scenario, kind, warning)
    if sampled is not None:
        if not isinstance(sampled.event, model.EventReference):
            error(sampled.event.location, "sample() reads its value when an event happens: give @event, e.g. @slow.end")
            return None
        expression = sampled.expression
        given = {
            **given,
            "event": model.Argument(
                "event", model.Name(sampled.event.name, sampled.event.location), sampled.event.location
            ),
        }
    observed = _observed_dimension(expression, {a.name for a in scenario.actors})
    declared = PHYSICAL_TYPES.get(sampled.type) if sampled is not None and sampled.type else None
    if observed is not None and declared is not None and declared != observed:
        error(
            sampled.location,
            f"var {sampled.name}: {sampled.type} samples a {observed}, not a {declared}",
            f"declare it as var {sampled.name}: {observed} = sample(...)",
        )
        return None
    if observed is not None:
        return _observed_item(coverage, given, name, expression, observed, scenario, error)
    if sampled is not None:
        error(
            sampled.expression.location,
            f"not supported yet: sample() of this value; the tool reads vehicles' {', '.join(TRACE_QUANTITIES)}, "
            "their sums and differences, and a.space_gap(b)",
            "e.g. var gap: length = sample(ego.space_gap(npc), @cut_in.end)",
        )
        return None
    known = ", ".join(by_name) or "none"
    if not isinstance(expression, model.Name) or expression.enum is not None or "." in expression.name:
        error(
            expression.location,
            f"not supported yet: {kind}() of this value of the run; the tool collects the scenario's "
            "logical parameters, and vehicles' speeds, accelerations, positions and gaps (a.space_gap(b)) at an event",
            f"name a logical parameter ({known}), or e.g. expression: npc.position - ego.position, event: end",
        )
        return None
    parameter = by_name.get(expression.name)
    if parameter is None:
        error(
            expression.location,
            f"{kind}({name}): {expression.name} is no logical parameter of the scenario (a value it leaves "
            "open, sampled per case)",
            f"its logical parameters: {known}",
        )
        return None
    unit, factor = _unit(given.get("unit"), parameter, kind, error)
    if factor is None:
        return None
    if "event" in given:
        event = given["event"].value
        if not isinstance(event, model.Name):
            error(given["event"].location, "event: takes the name of an event, e.g. event: end")
            return None
    text = ""
    if "text" in given:
        value = given["text"].value
        if not (isinstance(value, model.Literal) and isinstance(value.value, str)):
            error(value.location, 'text: takes a string, e.g. text: "gap at the cut-in"')
            return None
        text = value.value
    target = 1
    if "target" in given:
        value = _number(given["target"].value)
        if value is None or value < 1 or not float(value).is_integer():
            error(given["target"].value.location, "target: takes a whole number from 1 up")
            return None
        if kind == "record":
            warning(given["target"].location, "target: has no meaning for record(); it is left out")
        target = int(value)
    buckets: tuple[Bucket, ...] = ()
    if kind == "cover":
        buckets = _buckets(given, parameter, unit, factor, error)
        if buckets is None:
            return None
    for condition in ("ignore", "illegal"):
        if condition in given:
            probe = Interval(parameter.low, parameter.low, parameter.dimension) if not parameter.choices else None
            try:
                evaluate(given[condition].value, {name: probe, expression.name: probe} if probe else {})
            except EvaluationError as problem:
                error(problem.location, problem.message, problem.hint)
                return None
    return _built(coverage, given, name, parameter.name, unit, factor, buckets, text, target, parameter.dimension)


def _unit(argument: model.Argument | None, parameter: LogicalParameter, kind: str, error) -> tuple[str, float | None]:
    """The item's unit as written and its factor to SI; (unit, None) after an error."""
    if argument is None:
        return "", 1.0
    value = argument.value
    if not isinstance(value, model.Name) or value.name not in UNITS:
        error(value.location, f"unit: takes a unit, e.g. unit: {SI_UNIT.get(parameter.dimension) or 'kph'}")
        return "", None
    dimension, factor = UNITS[value.name][:2]
    if parameter.choices or dimension != parameter.dimension:
        of = f"a {parameter.dimension}" if parameter.dimension else "a number without a unit"
        error(
            value.location,
            f"{kind}(): unit {value.name} is a unit of {dimension}, but {parameter.name} is {of}",
            f"give a unit of {parameter.dimension}" if parameter.dimension else "leave unit: out",
        )
        return "", None
    return value.name, factor


def _number(value: model.Expression) -> float | None:
    if isinstance(value, model.Quantity) and value.dimension is None:
        return value.value
    return None


def _in_si(value: model.Expression, factor: float, dimension: str | None) -> float | None:
    """A bound written in the item's unit (a plain number) or with its own unit, in SI."""
    if isinstance(value, model.Quantity):
        if value.dimension is None:
            return value.value * factor
        if value.dimension == dimension:
            return value.value
    return None


def _buckets(given: dict, parameter: LogicalParameter, unit: str, factor: float, error) -> tuple[Bucket, ...] | None:
    if parameter.choices:
        for name in ("range", "every", "buckets"):
            if name in given:
                error(given[name].location, f"{name}: slices a number; {parameter.name} takes one of its values")
                return None
        return tuple(Bucket(str(c).lower() if isinstance(c, bool) else str(c), choice=c) for c in parameter.choices)
    if "buckets" in given and ("range" in given or "every" in given):
        error(given["buckets"].location, "buckets: is given with range: or every:", "give one or the other")
        return None
    shown = unit or SI_UNIT.get(parameter.dimension, "")

    def label(low: float, high: float, closed: bool) -> str:
        return f"[{low / factor:.4g}..{high / factor:.4g}{']' if closed else ')'} {shown}".rstrip()

    if "buckets" in given:
        value = given["buckets"].value
        bounds = [
            _in_si(item, factor, parameter.dimension)
            for item in (value.items if isinstance(value, model.ListValue) else ())
        ]
        if len(bounds) < 2 or None in bounds or any(b < a for a, b in zip(bounds, bounds[1:])):
            error(
                value.location,
                "buckets: takes a list of at least two boundaries, each no less than the one before",
                "e.g. buckets: [1, 2, 6.5, 10]",
            )
            return None
        pairs = list(zip(bounds, bounds[1:]))
        last = len(pairs) - 1
        return tuple(Bucket(label(a, b, k == last), a, b, k == last) for k, (a, b) in enumerate(pairs))
    low, high = parameter.low, parameter.high
    if "range" in given:
        value = given["range"].value
        if not isinstance(value, model.Range):
            error(value.location, "range: takes a range, e.g. range: [10..130]")
            return None
        low, high = _in_si(value.low, factor, parameter.dimension), _in_si(value.high, factor, parameter.dimension)
        if low is None or high is None or high <= low:
            error(
                value.location,
                f"range: takes a range of {parameter.dimension or 'numbers'} whose low end is below its high end",
            )
            return None
    if parameter.integer and "every" not in given and high - low + 1 <= MAX_VALUE_BUCKETS:
        return tuple(Bucket(f"{v:g}", choice=float(v)) for v in range(int(low), int(high) + 1))
    if "every" in given:
        every = _in_si(given["every"].value, factor, parameter.dimension)
        if every is None or every <= 0:
            error(given["every"].value.location, "every: takes a positive width, in the item's unit, e.g. every: 5")
            return None
    else:
        every = (high - low) / DEFAULT_BUCKETS
    count = max(1, math.ceil((high - low) / every - 1e-9))
    edges = [low + k * every for k in range(count)] + [high]
    return tuple(
        Bucket(label(a, b, k == count - 1), a, b, k == count - 1) for k, (a, b) in enumerate(zip(edges, edges[1:]))
    )


def _cross(coverage: model.Coverage, declared: dict[str, CoverItem], error) -> CoverItem | None:
    """``cover(name, items: [a, b, ...])``: the Cartesian product of cover items declared before it
    (every combination of their buckets is a bucket); ``text:`` and ``target:`` as for any item."""
    given = {argument.name or ("name" if k == 0 else ""): argument for k, argument in enumerate(coverage.arguments)}
    other = sorted(set(given) - {"name", "items", "text", "target", "event"})
    if other:
        error(given[other[0]].location, f"a cross takes name, items:, text:, target: and event:, not {other[0]}:")
        return None
    name = given.get("name")
    if name is None or not isinstance(name.value, model.Name):
        error(coverage.location, "a cross needs a name", "e.g. cover(gap_by_speed, items: [gap, speed])")
        return None
    listed = given["items"].value
    names = [
        i.name if isinstance(i, model.Name) else None
        for i in (listed.items if isinstance(listed, model.ListValue) else ())
    ]
    if len(names) < 2 or None in names:
        error(listed.location, "items: takes a list of two or more cover items", "e.g. items: [gap, speed]")
        return None
    for item_name, item in zip(names, listed.items):
        if item_name not in declared or declared[item_name].kind != "cover" or declared[item_name].crossed:
            error(
                item.location,
                f"{item_name} is no cover item declared before this cross",
                f"cover items so far: {', '.join(n for n, i in declared.items() if i.kind == 'cover' and not i.crossed) or 'none'}",
            )
            return None
    if coverage.kind == "record":
        error(
            coverage.location,
            "a cross of record items is not collected yet",
            "cross cover items: cover(name, items: [...])",
        )
        return None
    parts = [declared[n] for n in names]
    buckets = [()]
    for part in parts:
        buckets = [(*combination, bucket) for combination in buckets for bucket in part.buckets]
    text = given["text"].value.value if "text" in given and isinstance(given["text"].value, model.Literal) else ""
    target = int(_number(given["target"].value) or 1) if "target" in given else 1
    return CoverItem(
        "cover",
        name.value.name,
        "",
        coverage.location,
        buckets=tuple(Bucket(CROSS.join(b.label for b in combination)) for combination in buckets),
        text=text,
        target=target,
        crossed=tuple(names),
    )


def _sampled(expression, name_value, scenario: model.Scenario, kind: str, warning) -> model.SampledVariable | None:
    """The ``var ... = sample(...)`` an item reads: the one its expression names, or, where its
    ``expression:`` compares the item's own sampled variable with a constant (``expression: gap >
    50cm`` beside ``range:`` and ``every:``, as public files write it), that variable, said in a
    warning: the buckets slice the value, not the comparison."""
    samples = {v.name: v for v in scenario.samples}
    if isinstance(expression, model.Name) and expression.name in samples:
        return samples[expression.name]
    own = samples.get(name_value.name) if isinstance(name_value, model.Name) else None
    if (
        own is not None
        and isinstance(expression, model.Binary)
        and expression.operator in ("<", "<=", ">", ">=", "==", "!=")
        and any(isinstance(side, model.Name) and side.name == own.name for side in (expression.left, expression.right))
    ):
        warning(
            expression.location,
            f"{kind}({own.name}): expression: compares {own.name}; the item slices {own.name} itself into the "
            "buckets range: and every: name",
            f"leave expression: out, or cover the comparison alone: {kind}(name, expression: ...) without range:",
        )
        return own
    return None


def space_gap(behind_or_ahead: float) -> float:
    """The gap between two cars' bumpers, from the distance between their centres along the
    road (signed: positive when the other car is ahead); 0 while they overlap."""
    gap = max(0.0, abs(behind_or_ahead) - CAR_LENGTH)
    return math.copysign(gap, behind_or_ahead)


def space_gap_actors(expression) -> tuple[str, str] | None:
    """(a, b) of ``a.space_gap(b)``; None for any other expression."""
    if (
        isinstance(expression, model.Call)
        and expression.function.endswith(".space_gap")
        and len(expression.arguments) == 1
        and isinstance(expression.arguments[0].value, model.Name)
    ):
        return expression.function.rpartition(".")[0], expression.arguments[0].value.name
    return None


def _observed_value(expression: model.Expression, state: Mapping[str, Mapping[str, float]]) -> float:
    if isinstance(expression, model.Quantity):
        return expression.value
    pair = space_gap_actors(expression)
    if pair is not None:
        reference, other = pair
        return space_gap(float(state[other]["x"]) - float(state[reference]["x"]))
    if isinstance(expression, model.Name):
        actor, _, quantity = expression.name.rpartition(".")
        return float(state[actor][TRACE_QUANTITIES[quantity][0]])
    left, right = _observed_value(expression.left, state), _observed_value(expression.right, state)
    return left + right if expression.operator == "+" else left - right


def _observed_dimension(expression: model.Expression, actors: set[str]) -> str | None:
    """The dimension of a value the run takes (``TRACE_QUANTITIES`` of actors, added and
    subtracted, with constants of the same kind); None when ``expression`` is not one."""
    if isinstance(expression, model.Name) and expression.enum is None:
        actor, _, quantity = expression.name.rpartition(".")
        return TRACE_QUANTITIES[quantity][1] if actor in actors and quantity in TRACE_QUANTITIES else None
    pair = space_gap_actors(expression)
    if pair is not None:
        return LENGTH if set(pair) <= actors and pair[0] != pair[1] else None
    if isinstance(expression, model.Binary) and expression.operator in ("+", "-"):
        sides = [_observed_dimension(side, actors) for side in (expression.left, expression.right)]
        constants = [side.dimension for side in (expression.left, expression.right) if isinstance(side, model.Quantity)]
        known = [d for d in sides if d is not None]
        if known and len(known) + len(constants) == 2 and len(set(known + constants)) == 1:
            return known[0]
    return None


def _phase_labels(behavior: model.Behavior | None) -> set[str]:
    """Every label of a phase in a behaviour (an invocation's or a composition's)."""
    return {node.label for node in model.walk(behavior) if node.label} if behavior is not None else set()


def _event(argument: model.Argument | None, scenario: model.Scenario, error) -> tuple[str, str] | None:
    """Where an item on a value of the run reads it: (phase label, "start" or "end"); ("", "end")
    the scenario's end, the standard's default. A name is "start" or "end" (the scenario's), a
    phase's ``label.start``/``label.end``, or an event of the scenario defined as one."""
    if argument is None:
        return ("", "end")
    value = argument.value
    name = value.name if isinstance(value, model.Name) else None
    for event in scenario.events:
        if event.name == name and isinstance(event.specification, model.EventReference):
            name = event.specification.name
    labels = _phase_labels(scenario.behavior)
    if name in ("start", "end"):
        return ("", name)
    if name is not None:
        label, _, end = name.rpartition(".")
        if label in labels and end in ("start", "end"):
            return (label, end)
        if name in labels:
            return (name, "end")  # a phase's label alone: the phase's end, when its outcome is known
    error(
        value.location,
        "event: takes start or end (the scenario's), a phase's label.start or label.end, or an event "
        "of the scenario defined as one (event e is @label.end)",
        f"the scenario's phases: {', '.join(sorted(labels)) or 'none labelled'}",
    )
    return None


def _observed_item(
    coverage: model.Coverage, given: dict, name: str, expression, dimension: str, scenario: model.Scenario, error
) -> CoverItem | None:
    """An item on a value the run takes at an event: its buckets are the ones ``range:``/``every:``
    or ``buckets:`` name (the run gives no range of its own)."""
    event = _event(given.get("event"), scenario, error)
    if event is None:
        return None
    probe = LogicalParameter(name, coverage.location, dimension, 0.0, 0.0)
    unit, factor = _unit(given.get("unit"), probe, coverage.kind, error)
    if factor is None:
        return None
    buckets: tuple[Bucket, ...] = ()
    if coverage.kind == "cover":
        if "range" not in given and "buckets" not in given:
            error(
                coverage.location,
                f"cover({name}) of a value the run takes needs its buckets: range: and every:, or buckets:",
                f"e.g. cover({name}, expression: ..., unit: {unit or SI_UNIT[dimension]}, range: [0..50], every: 10)",
            )
            return None
        buckets = _buckets(given, probe, unit, factor, error)
        if buckets is None:
            return None
    text = given["text"].value.value if "text" in given and isinstance(given["text"].value, model.Literal) else ""
    target = int(_number(given["target"].value) or 1) if "target" in given else 1
    built = _built(coverage, given, name, "", unit, factor, buckets, text, target, dimension)
    return dataclasses.replace(built, observed=expression, event=event)


def _built(coverage, given, name, parameter, unit, factor, buckets, text, target, dimension) -> CoverItem:
    """The item, its ``ignore:`` and ``illegal:`` conditions as written."""
    ignore, illegal = (given[c].value if c in given else None for c in ("ignore", "illegal"))
    return CoverItem(
        coverage.kind,
        name,
        parameter,
        coverage.location,
        unit,
        factor,
        buckets,
        text,
        target,
        ignore,
        illegal,
        dimension,
    )


def held(item: CoverItem, bucket: Bucket, items: Mapping[str, CoverItem]) -> list[tuple[CoverItem, Bucket]]:
    """Each item ``bucket`` of ``item`` holds a value of, with the bucket it holds it in: the item
    itself, or for a cross each of its items (``items``: the scenario's, by name)."""
    if not item.crossed:
        return [(item, bucket)]
    parts = [items[name] for name in item.crossed]
    return [
        (part, next(b for b in part.buckets if b.label == name)) for part, name in zip(parts, bucket.label.split(CROSS))
    ]
