"""The scenario model: what an ``.osc`` file says, independent of how it was spelled.

Every node keeps its ``SourceLocation`` so that later stages (the automaton, the planner's
unsatisfiable cores, the monitor's explanations) can point back at the line that caused them.
All values are in SI units.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Union

from .errors import SourceLocation


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
    """A bare or dotted identifier: an actor, an enum member such as ``start``, or ``it``."""

    name: str
    location: SourceLocation


@dataclass(frozen=True)
class Literal:
    """A string or boolean literal."""

    value: str | bool
    location: SourceLocation


Value = Union[Quantity, Range, Name, Literal]


@dataclass(frozen=True)
class Argument:
    name: str | None
    value: Value
    location: SourceLocation


@dataclass(frozen=True)
class Modifier:
    """A modifier invocation inside a ``with:`` block, e.g. ``lane(same_as: v2, at: start)``."""

    name: str
    arguments: tuple[Argument, ...]
    location: SourceLocation

    def argument(self, name: str) -> Argument | None:
        for argument in self.arguments:
            if argument.name == name:
                return argument
        return None

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


@dataclass(frozen=True)
class Composition:
    """``serial``, ``parallel`` or ``one_of`` over child behaviors."""

    operator: str
    arguments: tuple[Argument, ...]
    children: tuple["Behavior", ...]
    label: str | None
    location: SourceLocation


Behavior = Union[Invocation, Composition]


@dataclass(frozen=True)
class Actor:
    name: str
    type: str
    location: SourceLocation


@dataclass(frozen=True)
class Scenario:
    name: str
    actor_type: str | None
    actors: tuple[Actor, ...]
    behavior: Behavior | None
    location: SourceLocation

    def actor(self, name: str) -> Actor | None:
        for actor in self.actors:
            if actor.name == name:
                return actor
        return None


@dataclass(frozen=True)
class OscFile:
    path: str
    scenarios: tuple[Scenario, ...]
    source_text: str

    def scenario(self, name: str) -> Scenario:
        for scenario in self.scenarios:
            if scenario.name == name:
                return scenario
        raise KeyError(name)
