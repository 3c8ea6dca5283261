"""What a specification of an OS2 action or modifier consists of, and the registry that holds them.

One construct is one class: its signature (what the checker binds and type-checks arguments
against), what the checker validates beyond argument kinds (``check``), how many lanes a use of it
needs (``lanes_needed``, so that the road is as wide as the scenario), and how it translates into
the guards of its phase (``translate``). The planner and the monitor need nothing else from it:
both read only the automaton's guards (one guard algebra), and whether the actor drives in the
phase (``Action.moves``).

The checker and the automaton both read a ``Registry``; the checked scenario carries the registry
it was checked with, so a construct added to a registry (a test's toy modifier, a dialect) is
checked and translated without touching either stage.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable
from dataclasses import dataclass
from typing import ClassVar, Protocol

from ..frontend import model
from ..frontend.errors import SourceLocation, error_at
from ..frontend.semantics.library import Binding, Signature, bind, with_movement_options
from ..frontend.semantics.values import Interval, argument_interval, argument_range
from ..logic.guards import Guard
from ..logic.phase import Phase
from ..settings import STANDARD_DIALECT

AT_VALUES = ("start", "end", "all")
# what a construct asks its actor to change (Construct.asks)
ASKS_LANE: frozenset[str] = frozenset({"lane"})
ASKS_SPEED: frozenset[str] = frozenset({"speed"})


class CheckContext(Protocol):
    """What the checker tells a construct's ``check``: the road as resolved so far, the names in
    scope, and where to report."""

    lanes: int
    lanes_origin: str  # why the road has that many lanes, for messages (" (set by the lanes option)")
    env: dict

    # the use being checked (a construct's warnings and errors about the whole use point here)
    location: SourceLocation

    def error(self, location: SourceLocation, message: str, hint: str | None = None) -> None: ...

    def warning(self, location: SourceLocation, message: str, hint: str | None = None) -> None: ...

    def evaluate(self, argument: model.Argument) -> Interval | None:
        """The argument's value, or None when it cannot be evaluated (the checker reports that itself)."""


@dataclass(frozen=True)
class Use:
    """One use of a construct inside an invocation, as its translation sees it."""

    node: model.Invocation | model.Modifier
    binding: Binding
    actor: str  # the actor of the invocation
    lanes: int  # lanes of the road
    env: dict  # parameter values or ranges
    # every actor of the scenario (a construct that reads the others: CARLA's target speed yields
    # to a car ahead in its lane)
    actors: tuple[str, ...]

    @property
    def location(self) -> SourceLocation:
        return self.node.location

    def argument(self, name: str) -> model.Argument | None:
        return self.binding[name]

    def interval(self, name: str) -> Interval:
        return argument_interval(self.binding[name], self.env)

    def range(self, name: str, dimension: str, example: str) -> tuple[float, float]:
        """The argument ``name`` as a bounded range of ``dimension`` (``example`` for messages)."""
        return argument_range(self.binding[name], dimension, example, self.env)

    def name(self, argument: str) -> str | None:
        """The name an argument gives (an actor, an enum member); None when it is not given."""
        given = self.binding[argument]
        if given is None:
            return None
        if not isinstance(given.value, model.Name):
            raise error_at(given.location, f"`{given.name or 'this argument'}` takes a name")
        return given.value.name

    def relation(self, keywords: tuple[str, ...]) -> tuple[str, str] | None:
        """The relation keyword given among ``keywords`` (e.g. ``same_as``) and the actor it names."""
        for keyword in keywords:
            if self.binding[keyword] is not None:
                return keyword, self.name(keyword)
        return None


def anchor_of(binding: Binding, default: str = "all") -> str:
    """``at:`` of a bound modifier: start, end or all (the standard's default: all)."""
    given = binding["at"]
    if given is None:
        return default
    if not isinstance(given.value, model.Name) or given.value.name not in AT_VALUES:
        raise error_at(given.location, "`at:` takes start, end or all")
    return given.value.name


class Construct:
    """An OS2 action or modifier: its signature and its meaning, in one place.

    A subclass sets ``signature`` and overrides what it needs. One left ``translated = False`` is
    accepted by the checker and refused by the automaton with "not supported yet by the automaton"
    at its place (the standard has it; this tool cannot plan it yet).
    """

    kind: ClassVar[str]
    signature: ClassVar[Signature]
    translated: ClassVar[bool] = True
    # what a use asks its actor to change while its phase runs: "lane", "speed", both or neither.
    # Nothing else moves an actor off its lane or its speed (least action, docs/language.md).
    asks: ClassVar[frozenset[str]] = frozenset()

    @property
    def name(self) -> str:
        return self.signature.name

    def check(self, binding: Binding, context: CheckContext) -> None:
        """Report what the signature's argument kinds cannot say (a lane outside the road, ...)."""

    def lanes_needed(self, binding: Binding, highest: Callable[[model.Argument | None], int]) -> int:
        """The fewest lanes on which this use exists. ``highest(argument)`` is the largest whole
        value an argument can take (1 when it is absent or not a number)."""
        return 1

    def held_throughout(self, binding: Binding) -> bool:
        """Whether this use's values bound the whole phase (``at: all``) rather than one instant:
        its ranges are then bounds the plan stays within, not logical parameters (sampling.py).
        For an action, every argument but its ``duration`` (which stays a parameter)."""
        return False

    def sampled_as(self, argument: str) -> str | None:
        """The planning resolution a sampled value of ``argument`` is narrowed with, when it is
        not its unit's dimension (a time headway is a time, but no duration: sampling.py)."""
        return None

    def translate(self, use: Use, phase: Phase) -> None:
        """Add this use's guards to its phase."""
        raise NotImplementedError(f"{type(self).__name__} is translated = {self.translated} but has no translate()")

    def apply(
        self,
        node: model.Invocation | model.Modifier,
        actor: str,
        lanes: int,
        env: dict,
        phase: Phase,
        actors: tuple[str, ...],
    ) -> None:
        """Translate one use (its arguments bound to the signature) into ``phase``: what the automaton
        calls (``actors``: every actor of the scenario)."""
        binding = bind(self.signature, node.arguments)
        if self.asked_within(binding):
            phase.asks |= self.asks
        if self.asked_at_start(binding):
            phase.asks_at_start |= self.asks
        self.translate(Use(node, binding, actor, lanes, env, actors), phase)

    def asked_at_start(self, binding: Binding) -> bool:
        """Whether this use asks for its lane or speed already at its phase's first instant (so that
        the change it asks for falls in the phase before): an action's change comes within its phase."""
        return False

    def asked_within(self, binding: Binding) -> bool:
        """Whether this use asks its actor to change lane or speed while its phase runs: an action
        or a modifier about the whole phase (change_lane, acceleration, distance) does."""
        return True

    def __repr__(self) -> str:
        return f"<{self.kind} {self.name}>"


class Action(Construct):
    kind = "action"
    # False: the actor stands still in the phase (it need not make progress); the only kind of
    # action a stationary object may take
    moves: ClassVar[bool] = True


class Modifier(Construct):
    """A modifier. Every one takes the standard's common movement-modifier parameters
    (``movement_mode:``, ``track:``, ``shape:``) beside its own: ``check_movement_options`` says
    how they are read."""

    kind = "modifier"
    # where the modifier holds when ``at:`` is not given: the standard's all (a dialect may differ)
    default_anchor: ClassVar[str] = "all"

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        own = cls.__dict__.get("signature")
        if own is not None:
            cls.signature = with_movement_options(own)

    def check_movement_options(self, binding: Binding, context: CheckContext) -> None:
        """The standard's common movement-modifier arguments of a use, as the tool reads them:
        ``movement_mode`` either way (every plan keeps to the vehicles' acceleration and jerk
        limits, what ``monotonous`` asks), ``track: actual`` (the default: a vehicle meets its
        reference where that one is), and ``track: projected`` read as actual, with a warning."""
        track = binding["track"]
        if track is not None and isinstance(track.value, model.Name) and track.value.name == "projected":
            context.warning(
                track.location,
                "track: projected is read as actual: a vehicle meets where its reference is, "
                "not where it was projected to be",
                "leave track: out to silence this warning",
            )

    def anchor(self, binding: Binding) -> str:
        """Where this use holds: its ``at:``, else the modifier's default (start, end or all)."""
        return anchor_of(binding, self.default_anchor)

    def asked_at_start(self, binding: Binding) -> bool:
        return self.anchor(binding) in ("start", "all")


class AnchoredModifier(Modifier):
    """A modifier that is one guard, placed by ``at:`` at the phase's start, end, or throughout."""

    def guard(self, use: Use) -> Guard:
        raise NotImplementedError

    def held_throughout(self, binding: Binding) -> bool:
        """Its ranges bound the plan, not chosen as logical parameters: held throughout (``at:
        all``), or given as the standard's range-typed ``<name>_range`` (an interval the value
        stays within, at whichever instant)."""
        return self.anchor(binding) == "all" or bool(binding.ranged)

    def asked_within(self, binding: Binding) -> bool:
        """Asked per instant (docs/language.md, "What a vehicle is asked to do"): a lane or a
        speed asked ``at: start`` is asked at the phase's first instant only (reached before it,
        then kept, licensing no change of lane or speed later in the phase); ``at: end`` asks for a change within the phase, and so does a range
        held throughout."""
        return self.anchor(binding) != "start"

    def translate(self, use: Use, phase: Phase) -> None:
        phase.anchor(self.guard(use), self.anchor(use.binding))


class Registry:
    """The actions and modifiers a scenario may use, by name."""

    def __init__(self, constructs: Iterable[Construct] = (), dialect: str = STANDARD_DIALECT) -> None:
        self.dialect = dialect  # whose conventions the constructs follow, for messages and case files
        self.actions: dict[str, Action] = {}
        self.modifiers: dict[str, Modifier] = {}
        for construct in constructs:
            self._add(construct)

    def _add(self, construct: Construct) -> None:
        table = self.actions if construct.kind == "action" else self.modifiers
        table[construct.name] = construct  # type: ignore[assignment]

    def action(self, name: str) -> Action | None:
        return self.actions.get(name)

    def modifier(self, name: str) -> Modifier | None:
        return self.modifiers.get(name)

    def extended(self, *constructs: Construct, dialect: str | None = None) -> Registry:
        """A copy with ``constructs`` added (replacing any of the same kind and name)."""
        copy = Registry([*self.actions.values(), *self.modifiers.values()], dialect or self.dialect)
        for construct in constructs:
            copy._add(construct)
        return copy

    def condition(self, expression, env: dict, actors: Collection[str]):
        """The guard of a condition (``wait c``, ``until c``, an event's ``is c``) over ``actors``."""
        from .conditions import condition_guard

        return condition_guard(expression, env, actors)

    def translated(self, kind: str) -> list[str]:
        table = self.actions if kind == "action" else self.modifiers
        return [name for name, construct in table.items() if construct.translated]

    def lane_number(self, index: int, lanes: int) -> int:
        """The number this dialect's files give the lane of ``index`` (0: the leftmost, as the
        pipeline counts), for plots and reports: the standard's 1 is the rightmost, CARLA's the
        leftmost (the lane modifier's own convention)."""
        lane = self.modifier("lane")
        counted_from = getattr(lane, "counted_from", "right")
        return index + 1 if counted_from == "left" else lanes - index
