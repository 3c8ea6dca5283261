"""The refined strategy: a scenario's logical parameters, sampled with Hypothesis, and the guidance they give.

A logical parameter is a value the scenario leaves open at one instant: a declared parameter with
a range or a set of values (``gap: length with: keep(it in [10..20]m)``), or an inline range that
holds at one point of a phase: ``position([10..20]m, ..., at: start)``, ``at: end``, a duration
(``parallel(duration: [4..8]s)``), a change's target (``change_speed(target: [50..70]kph)``).
A range a modifier holds throughout its phase (``speed([0..130]kph)``, whose ``at:`` is ``all``
by default) is not a parameter: it says the motion stays within it, so the planner keeps it as
a bound, and sampling it as one constant held for the whole phase would ask for something the
scenario does not.
The base strategy leaves them all to the planner, which picks whatever its search reaches first;
sampling them instead spreads the instances over the whole logical scenario, and lets Hypothesis
shrink a failure to the simplest values that still fail.

A sample does not replace the scenario: the monitor still checks the simulation against the
scenario as written. The sample only *guides* the planner: each sampled range is narrowed to one
planning cell around the sampled value (kept a margin inside the range where it fits, so that
tracking error in simulation does not cross the range's edge).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .frontend import model
from .frontend.errors import SourceLocation
from .frontend.semantics.checked import CheckedScenario
from .frontend.semantics.logical import UNIT, WAY, LogicalParameter
from .frontend.semantics.parameters import MIRRORED, ParameterSpace
from .frontend.semantics.values import EvaluationError, Interval, evaluate

# Samples of physical values lie on a 0.1 grid (in SI units): readable in reports, and a shrunk
# failure lands on a round value instead of 12.000000000000002.
STEP = 0.1

Values = dict[str, Any]


class UnknownParameter(ValueError):
    """A sample names a value the scenario does not leave open, or gives one outside its range
    or of the wrong kind (``--values``, a case file written by hand)."""


def checked_value(parameter: LogicalParameter, value: Any) -> Any:
    """``value`` when ``parameter`` may take it; else ``UnknownParameter`` saying what it may take.

    Why: a value outside the declared range must not be planned at the range's edge without a word,
    nor a string end in a traceback."""
    if parameter.choices:
        if value not in parameter.choices:
            raise UnknownParameter(
                f"{parameter.name} = {value!r} is not one of {', '.join(map(str, parameter.choices))}"
            )
        return value
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise UnknownParameter(
            f"{parameter.name} = {value!r} is not a number; give one in SI units ({UNIT[parameter.dimension] or 'no unit'})"
        )
    if parameter.integer and not float(value).is_integer():
        raise UnknownParameter(f"{parameter.name} = {value!r} is not a whole number")
    if not parameter.low - 1e-9 <= value <= parameter.high + 1e-9:
        raise UnknownParameter(
            f"{parameter.name} = {value:g} is outside its range {parameter.show(parameter.low)}..{parameter.show(parameter.high)} "
            f"(line {parameter.location.line})"
        )
    return value


# ------------------------------------------------------------------ sampling


def strategy(checked: CheckedScenario, shard: Shard | None = None):
    """A Hypothesis strategy of samples: dicts from parameter name to value (SI units).

    Relations between declared parameters (``keep(b_gap > a_gap + 5m)``) are met by construction
    where they bound one parameter by others drawn before it; any other relation filters samples.
    ``shard``: only the samples that belong to it (``Shard.holds``), so that the shards of one
    scenario draw disjoint samples, and Hypothesis's shrinking stays within its shard.
    """
    from hypothesis import assume
    from hypothesis import strategies as st

    space = checked.space
    parameters = list(checked.parameters)

    @st.composite
    def samples(draw):
        values: Values = {}
        for parameter in parameters:
            if parameter.kind == WAY:
                # only the ways that go with those drawn for the paths before it: the choice is
                # made by construction, never filtered
                values[parameter.name] = draw(st.sampled_from(checked.ways.options(parameter.name, values)))
                continue
            if parameter.choices:
                values[parameter.name] = draw(st.sampled_from(parameter.choices))
                continue
            low, high = _bounded_by_relations(parameter, space, values)
            assume(low <= high)
            step = 1.0 if parameter.integer else STEP
            first, last = math.ceil(low / step - 1e-9), math.floor(high / step + 1e-9)
            assume(first <= last)
            index = draw(st.integers(0, last - first))
            value = (first + index) * step
            values[parameter.name] = int(round(value)) if parameter.integer else round(value, 6)
        assume(space.accepts({k: v for k, v in values.items() if k in space.domains}))
        return values

    return samples() if shard is None or shard.count == 1 else samples().filter(shard.holds)


def drawn(checked: CheckedScenario, count: int, seed: int | str) -> list[Values]:
    """``count`` samples of ``checked``'s logical parameters drawn by Hypothesis from ``seed``, as
    the bench's refined strategy draws them (the default profile, generation only, no database),
    without running them: a campaign hands them to its executor's workers."""
    import hypothesis

    found: list[Values] = []
    if count < 1:
        return found

    def collect(values: Values) -> None:
        if len(found) < count:
            found.append(values)

    hypothesis.seed(seed)(plain_draw(count)(hypothesis.given(strategy(checked))(collect)))()
    return found


def plain_draw(count: int):
    """Hypothesis's settings for ``count`` plain samples, the same from the same seed everywhere:
    the default profile (a CI profile's derandomize would override the seed), generation only,
    no database, no health check (a sample is no test)."""
    import hypothesis
    from hypothesis import HealthCheck, Phase

    return hypothesis.settings(
        hypothesis.settings.get_profile("default"),
        max_examples=count,
        database=None,
        deadline=None,
        derandomize=False,
        phases=[Phase.generate],
        print_blob=False,
        suppress_health_check=list(HealthCheck),
    )


def _bounded_by_relations(parameter: LogicalParameter, space: ParameterSpace, drawn: Values) -> tuple[float, float]:
    """The parameter's range, narrowed by every relation that bounds it by parameters already drawn."""
    low, high = parameter.low, parameter.high
    if not parameter.declared:
        return low, high
    env = space.environment({k: v for k, v in drawn.items() if k in space.domains})
    for relation in space.relations:
        atom = relation.expression
        if not (isinstance(atom, model.Binary) and atom.operator in ("<", "<=", ">", ">=", "==")):
            continue
        for this, other, operator in (
            (atom.left, atom.right, atom.operator),
            (atom.right, atom.left, MIRRORED[atom.operator]),
        ):
            if not (isinstance(this, model.Name) and this.name == parameter.name):
                continue
            try:
                bound = evaluate(other, env)
            except EvaluationError:
                continue
            if not (isinstance(bound, Interval) and bound.is_point):
                continue  # depends on a parameter not drawn yet
            value = bound.low
            strict = (
                STEP if operator in ("<", ">") and not parameter.integer else (1.0 if operator in ("<", ">") else 0.0)
            )
            if operator in ("<", "<=", "=="):
                high = min(high, value - strict)
            if operator in (">", ">=", "=="):
                low = max(low, value + strict)
    return low, high


# ------------------------------------------------------------------ guidance


def guided(
    checked: CheckedScenario,
    values: Values,
    resolution: dict[str | None, float],
    margins: dict[str | None, float],
) -> tuple[CheckedScenario, dict[str, object]]:
    """The scenario the planner solves for a sample: each sampled range narrowed to one cell around its value.

    Returns the scenario with its inline ranges narrowed, and the declared parameters' narrowed
    ranges (for ``build_automaton(values=...)``). ``resolution`` is the planning grid per dimension
    (1 m, 1 m/s, 1 s); ``margins`` what the planner keeps inside a range's edges.
    """
    by_name = {p.name: p for p in checked.parameters}
    unknown = sorted(set(values) - set(by_name))
    if unknown:
        raise UnknownParameter(
            f"no logical parameter named {', '.join(map(repr, unknown))}; the scenario has {', '.join(by_name) or 'none'}"
        )
    values = _with_determined(checked, {name: checked_value(by_name[name], value) for name, value in values.items()})
    declared: dict[str, object] = {}
    narrowed: dict[SourceLocation, tuple[float, float]] = {}
    for name, value in values.items():
        parameter = by_name[name]
        if parameter.kind == WAY:
            continue  # the route, not a constraint: on_ways
        if parameter.choices or parameter.integer:
            band: Any = value
        else:
            kind = parameter.sampled_as or parameter.dimension
            band = _band(parameter, float(value), resolution.get(kind, 0.0), margins.get(kind, 0.0))
        if parameter.declared:
            declared[name] = Interval(band[0], band[1], parameter.dimension) if isinstance(band, tuple) else band
        else:
            narrowed[parameter.location] = band if isinstance(band, tuple) else (float(band), float(band))
    given = {name: values[name] for name in values if name in checked.space.domains}
    if (relation := checked.space.broken(given)) is not None:
        # a keep relating several parameters: the monitor checks the trace, not the parameters, so a
        # sample that breaks one would be planned and reported conformant
        where = relation.location
        raise UnknownParameter(
            f"{', '.join(f'{k} = {v!r}' for k, v in sorted(given.items()))} break the constraint at {Path(where.path).name}:{where.line}:{where.column}"
        )
    if narrowed:
        scenario = checked.scenario
        checked = dataclasses.replace(
            checked, scenario=dataclasses.replace(scenario, behavior=_narrow(scenario.behavior, narrowed))
        )
    return checked, declared


def _with_determined(checked: CheckedScenario, values: Values) -> Values:
    """``values`` with each parameter they leave out whose relations fix it to one value given them
    (``far: length = near + 10m`` with ``near`` given), as the sampler draws it; why: the planner
    reads a parameter's range, not the relations, so a value left out would be planned anywhere
    in its range."""
    values = dict(values)
    changed = True
    while changed:
        changed = False
        for parameter in checked.parameters:
            if parameter.name in values or parameter.name not in checked.space.domains or parameter.choices:
                continue
            low, high = _bounded_by_relations(parameter, checked.space, values)
            if low == high:
                values[parameter.name] = int(low) if parameter.integer else low
                changed = True
    return values


def within(checked: CheckedScenario, name: str, low: float, high: float) -> tuple[CheckedScenario, dict[str, object]]:
    """``checked`` with the numeric logical parameter ``name`` narrowed to ``[low, high]`` (within
    its own range), as ``guided`` narrows a sample to its band: the scenario with its inline range
    narrowed, or the declared parameter's range for ``build_automaton(values=...)``. Why: a
    question about a part of a parameter's range (a coverage bucket) is a planning problem with
    the range narrowed to that part."""
    parameter = next(p for p in checked.parameters if p.name == name)
    band = (max(low, parameter.low), min(high, parameter.high))
    if parameter.declared:
        return checked, {name: Interval(band[0], band[1], parameter.dimension)}
    scenario = checked.scenario
    narrowed = _narrow(scenario.behavior, {parameter.location: band})
    return dataclasses.replace(checked, scenario=dataclasses.replace(scenario, behavior=narrowed)), {}


def on_ways(checked: CheckedScenario, values: Values) -> CheckedScenario:
    """``checked`` on the routes of the ways through the map that ``values`` name for its paths
    (a way parameter's value, ``frontend.semantics.logical.way_parameters``); a path not named
    takes the first way that goes with the others. ``UnknownParameter`` when a value is no way of
    its path, or the ways named do not go together."""
    by_name = {p.name: p for p in checked.parameters}
    given = {name: value for name, value in values.items() if name in by_name and by_name[name].kind == WAY}
    if not given:
        return checked
    from .roads.ways import WaysError

    for name, value in given.items():
        checked_value(by_name[name], value)
    try:
        routes = checked.ways.routes(given)
    except WaysError as error:
        raise UnknownParameter(str(error)) from None
    return dataclasses.replace(checked, route=routes[0], routes=routes)


def _band(parameter: LogicalParameter, value: float, cell: float, margin: float) -> tuple[float, float]:
    """The band a sampled value is planned in: ``cell`` wide around the value, the value first
    moved ``margin`` inside the parameter's range where the range is wide enough (so that tracking
    error in simulation does not cross its edge). The one inset of a sampled value: the planner
    plans the band as given (``SymbolicAutomaton.sampled``)."""
    low, high = parameter.low, parameter.high
    if high - low > 2 * margin:
        value = min(max(value, low + margin), high - margin)
    return max(low, value - cell / 2), min(high, value + cell / 2)


def _narrow(node: Any, narrowed: dict[SourceLocation, tuple[float, float]]) -> Any:
    """A copy of a behavior tree with the ranges at the given places narrowed."""
    if isinstance(node, model.Range):
        if node.location in narrowed:
            low, high = narrowed[node.location]
            return dataclasses.replace(
                node, low=dataclasses.replace(node.low, value=low), high=dataclasses.replace(node.high, value=high)
            )
        return node
    if isinstance(node, tuple):
        return tuple(_narrow(item, narrowed) for item in node)
    if dataclasses.is_dataclass(node) and not isinstance(node, (SourceLocation, type)):
        changes = {f.name: _narrow(getattr(node, f.name), narrowed) for f in dataclasses.fields(node)}
        return dataclasses.replace(node, **{k: v for k, v in changes.items() if v is not getattr(node, k)})
    return node


@dataclass(frozen=True)
class Shard:
    """Shard ``index`` (from 0) of ``count``: the samples whose stable hash is ``index`` modulo
    ``count``. The shards of a scenario partition its samples, whatever process draws them; each
    runs its share of the examples (``examples``)."""

    index: int = 0
    count: int = 1

    def holds(self, values: Values) -> bool:
        return _stable_hash(values, 8) % self.count == self.index

    def examples(self, total: int) -> int:
        """This shard's share of ``total`` examples: the shares add up to ``total``."""
        return total // self.count + (1 if self.index < total % self.count else 0)

    def __str__(self) -> str:
        return f"shard {self.index + 1} of {self.count}"


def sample_seed(seed: int, values: Values) -> int:
    """The planner's seed for one sample: a stable hash of the run's seed and the values.

    Not Python's ``hash`` (salted per process): a case replayed in another process must get the
    same plan.
    """
    return _stable_hash([seed, values], 4) >> 1


def _stable_hash(data: Any, size: int) -> int:
    """The first ``size`` bytes of the SHA-256 of ``data`` as JSON, as an integer: the same in
    every process, unlike Python's salted ``hash``."""
    digest = hashlib.sha256(json.dumps(data, sort_keys=True).encode()).digest()
    return int.from_bytes(digest[:size], "big")


# ------------------------------------------------------------------ public helpers


def logical_parameters(checked: CheckedScenario) -> list[LogicalParameter]:
    """A checked scenario's logical parameters (computed once by the checker: ``CheckedScenario.parameters``)."""
    return list(checked.parameters)


def parameters(path: str | Path, scenario: str | None = None, lanes: int | None = None):
    """The Hypothesis strategy of a scenario file's logical parameters, for ``@given`` tests.

    ``scenario`` names one of the file's scenarios (default: the first with a behavior).
    """
    from .frontend import load_file

    return strategy(load_file(path, lanes).scenario_to_run(scenario))
