"""Translating a scenario's behavior into a ``SymbolicAutomaton`` (the paper, section 3.2).

- atomic ``drive`` with start guard g1 and end guard g2:  i --g1--> s --g2--> f
- serial A . B: A's final and B's initial location are one instant, so every transition into
  f_A is fused with every transition out of i_B into one transition guarded by both (the end of A
  and the start of B happen at the same split point, as the semantics demands).
- parallel A || B: the product, built only over reachable locations. A component that ends of
  itself (a duration, an until, a wait) may, as the parallel's ``overlap:`` allows, stay at its
  initial location while others move (a late start) or reach its final location before them and
  stay there (an early end); the others leave theirs together and reach theirs with the last of
  those, or when the parallel's own duration is over; in between they move alone or jointly.
- one_of A | B: the union, with a fresh initial and final location.
- events: ``emit e`` is no phase but a mark on the instant between its serial neighbours;
  ``wait @e`` and ``until @e`` end their phase on an edge that *awaits* e. The product of a
  parallel keeps a combination of moves only if every event awaited in it is emitted in it (or,
  inside a nested parallel, may still be emitted by an outer member: such edges carry the event
  up, and the ones still waiting at the top are dropped), and never lets a component that waits
  for e without a condition stay put while e is emitted (a wait ends at the event's first
  occurrence, not at a later one).
Locations that cannot reach the final location are pruned.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Hashable
from dataclasses import dataclass, field, replace

from ..frontend import model
from ..frontend.errors import error_at
from ..frontend.semantics.checked import CheckedScenario
from ..frontend.semantics.logical import names_by_place
from ..frontend.semantics.tolerances import DURATION_TOLERANCE
from ..logic.automaton import Ask, Location, PhaseBound, SymbolicAutomaton, Timing, Transition
from ..logic.guards import LANE, TRUE, Guard, Not, conjunction
from ..logic.phase import Variant
from .translation import check_behavior_arguments, duration_interval, offset_interval, phase_guards

Key = Hashable


@dataclass
class _Edge:
    source: Key
    guard: Guard
    events: tuple[str, ...]
    target: Key
    starts: frozenset[int] = frozenset()
    ends: frozenset[int] = frozenset()
    emits: frozenset[str] = frozenset()  # events emitted at this instant
    awaits: frozenset[str] = frozenset()  # events that must be emitted at this instant, not yet matched
    # events that components staying put across this edge wait for: none of them may be emitted here
    deaf: frozenset[str] = frozenset()
    # (actor, "lane" | "speed"): what the phases this edge starts ask for already at their first
    # instant (the location before it must bring it about); only theirs, never what members of a
    # parallel staying put asked when they started
    early: frozenset[tuple[str, Ask]] = frozenset()


def _simultaneous(source: Key, moves: list[_Edge], target: Key, deaf: frozenset[str] = frozenset()) -> _Edge:
    """``moves`` taken at one instant, as one edge: a serial's junction (one phase's end and the
    next one's start) or a combination of a parallel's members. ``deaf``: the events that members
    staying put wait for."""
    emits = frozenset().union(*(m.emits for m in moves))
    return _Edge(
        source,
        conjunction([m.guard for m in moves]),
        tuple(ev for m in moves for ev in m.events),
        target,
        frozenset().union(*(m.starts for m in moves)),
        frozenset().union(*(m.ends for m in moves)),
        emits,
        frozenset().union(*(m.awaits for m in moves)) - emits,
        frozenset().union(deaf, *(m.deaf for m in moves)),
        frozenset().union(*(m.early for m in moves)),
    )


@dataclass
class _Fragment:
    """An automaton under construction, with hashable location keys."""

    initial: Key
    final: Key
    edges: list[_Edge]
    names: dict[Key, tuple[str, bool]] = field(default_factory=dict)  # key -> (name, labelled)
    drivers: dict[Key, frozenset[str]] = field(default_factory=dict)
    invariants: dict[Key, Guard] = field(default_factory=dict)
    # locations whose phase ends at the first emission of these events (wait @e, until @e)
    listening: dict[Key, frozenset[str]] = field(default_factory=dict)
    # (actor, "lane" | "speed"): what the actors' own constructs ask of them here (Location.asks)
    asks: dict[Key, frozenset[tuple[str, Ask]]] = field(default_factory=dict)
    # it ends of itself (a duration, an until, a wait): in a parallel it may end before the others
    ends_itself: bool = False

    def outgoing(self, key: Key) -> list[_Edge]:
        return [e for e in self.edges if e.source == key]


def build_automaton(checked: CheckedScenario, values: dict[str, object] | None = None) -> SymbolicAutomaton:
    """The automaton of a checked scenario, on its road.

    ``values`` fixes logical parameters (the refined strategy samples them); a parameter left out
    keeps its range, which the planner then chooses within (the base strategy).
    """
    if not isinstance(checked, CheckedScenario):
        raise TypeError(
            "build_automaton takes a CheckedScenario: load it with frontend.check_file, load_file or pipeline.load_scenario"
        )
    scenario = checked.scenario
    if scenario.behavior is None:
        raise error_at(
            scenario.location,
            f"scenario {scenario.name!r} has no `do` behavior",
            hint="add do: with what the actors must do",
        )
    env = checked.space.environment(values)
    builder = _Builder(checked, env)
    fragment = builder.translate(scenario.behavior)
    automaton = _finish(fragment, tuple(a.name for a in scenario.actors), scenario, builder.timings, checked.lanes)
    automaton.parameters = names_by_place(checked.parameters)
    return automaton


class _Builder:
    """Walks the behavior tree; numbers fragments and collects the timed phases on the way."""

    def __init__(self, checked: CheckedScenario, env: dict) -> None:
        self.checked = checked
        self.env = env
        self.counter = itertools.count()
        self.timings: dict[int, Timing] = {}
        self.actors = tuple(a.name for a in checked.scenario.actors)
        self.events = {e.name: e for e in checked.scenario.events}

    def translate(self, behavior: model.Behavior) -> _Fragment:
        rates: tuple[PhaseBound, ...] = ()
        if isinstance(behavior, model.Invocation):
            fragment, rates = _atomic(behavior, self.checked, self.counter, self.env, self.actors)
            if behavior.until is not None:
                fragment = self.end_on(
                    fragment,
                    behavior.until,
                    behavior.label or _phase_name(behavior),
                    behavior.location,
                    rising=True,
                    actor=behavior.actor,
                )
            duration = behavior.argument("duration")
        elif isinstance(behavior, model.Wait):
            return self.wait(behavior)
        elif isinstance(behavior, model.Composition):
            fragment = self.composition(behavior)
            duration = behavior.argument("duration")
        elif isinstance(behavior, model.Emit):
            raise error_at(
                behavior.location,
                "emit is a member of a serial or a parallel: it marks an instant of its neighbours",
                hint="put it in a serial, after the phase whose end it announces, or in a parallel, emitted at its start",
            )
        else:
            raise error_at(
                behavior.location,
                "not supported yet by the automaton: call",
                hint="methods with side effects cannot be planned; remove the call",
            )
        name = getattr(behavior, "label", None) or _phase_name(behavior)
        if duration is not None:
            low, high = duration_interval(duration, self.env)
            fragment = self.timed(fragment, name, low, high, duration.location, rates)
        elif rates:  # timed for its start and end only
            fragment = self.timed(fragment, name, 0.0, math.inf, None, rates)
        if duration is not None or (isinstance(behavior, model.Invocation) and behavior.until is not None):
            fragment.ends_itself = True
        return fragment

    def composition(self, behavior: model.Composition) -> _Fragment:
        check_behavior_arguments(behavior)
        if not behavior.children:
            raise error_at(behavior.location, f"{behavior.operator} has no members")
        if behavior.operator == "serial":
            return self.serial(behavior)
        if behavior.operator == "parallel":
            return self.parallel(behavior)
        children = [self.translate(child) for child in behavior.children]
        fragment = _one_of(children, next(self.counter))
        fragment.ends_itself = all(child.ends_itself for child in children)
        return fragment

    def parallel(self, behavior: model.Composition) -> _Fragment:
        """Members that run side by side, placed in time by the parallel's ``overlap:`` (``_Overlap``).
        With ``overlap: start`` (the standard's default, and what CARLA's runner does) they start
        together, each member that ends of itself (a duration, an until, a wait) ends when it ends,
        and the others end with the last one: a member with nothing to end it lasts as long as the
        parallel, as its author means it. An ``emit`` among them is emitted at the parallel's
        start, an instant it shares with every member that starts then (the standard allows emit
        in any composition)."""
        events = [child.event for child in behavior.children if isinstance(child, model.Emit)]
        children = [self.translate(child) for child in behavior.children if not isinstance(child, model.Emit)]
        if not children:
            raise error_at(
                behavior.location,
                "a parallel of only emit has no instant to emit at",
                hint="emit beside a phase, or between two phases of a serial",
            )
        overlap = behavior.argument("overlap")
        kind = overlap.value.name if overlap is not None and isinstance(overlap.value, model.Name) else "start"
        members = [c for c in behavior.children if not isinstance(c, model.Emit)]
        offsets = [self.offset(behavior, which, kind, members) for which in ("start_to_start", "end_to_end")]
        # a parallel with a duration of its own ends when that is over: a member with nothing to
        # end it lasts until then, even after those that end of themselves
        timed = behavior.argument("duration") is not None
        placement = _Overlap(kind, *offsets)
        fragment = _parallel(children, placement, behavior.location, timed) if len(children) > 1 else children[0]
        fragment.ends_itself = all(child.ends_itself for child in children)
        if events:
            _emit(fragment.outgoing(fragment.initial), events)
        return fragment

    def offset(
        self, behavior: model.Composition, which: str, kind: str, members: list[model.Behavior]
    ) -> _Offset | None:
        """The parallel's ``start_to_start:`` or ``end_to_end:`` (``which``) as timed phases, one
        per secondary member and order: from the primary's instant to the secondary's when the
        primary's comes first, from the secondary's to the primary's when it comes second. None
        when the parallel has none (or one member); refused when its overlap puts those instants
        together and the offset cannot be 0."""
        argument = behavior.argument(which)
        if argument is None or len(members) < 2:
            return None
        low, high = offset_interval(argument, self.env)
        together = ("equal", "start") if which == "start_to_start" else ("equal", "end")
        instant = "start" if which == "start_to_start" else "end"
        if kind in together and not low <= 0 <= high:
            raise error_at(
                argument.location,
                f"overlap: {kind} {instant}s every member with the primary, so a {which} of "
                f"{_seconds(low, high)} cannot hold",
                hint=f"give overlap: any (or initial, final, inside, full) for members that {instant} apart",
            )
        primary = _member_name(members[0])
        after: dict[int, int] = {}
        before: dict[int, int] = {}
        for index, member in enumerate(members[1:], start=1):
            name = _member_name(member)
            if high > 0:
                after[index] = phase = next(self.counter)
                self.timings[phase] = Timing(
                    phase, f"from {primary}'s {instant} to {name}'s", max(low, 0.0), high, argument.location
                )
            if low < 0:
                before[index] = phase = next(self.counter)
                self.timings[phase] = Timing(
                    phase, f"from {name}'s {instant} to {primary}'s", max(-high, 0.0), -low, argument.location
                )
        return _Offset(low, high, after, before)

    def serial(self, behavior: model.Composition) -> _Fragment:
        """Members one after another; an ``emit`` marks the junction it stands at."""
        result: _Fragment | None = None
        pending: list[str] = []  # emitted since the last phase
        for child in behavior.children:
            if isinstance(child, model.Emit):
                pending.append(child.event)
                continue
            fragment = self.translate(child)
            last_ends_itself = fragment.ends_itself
            if pending and result is None:
                _emit(fragment.outgoing(fragment.initial), pending)
            elif pending:
                _emit([e for e in result.edges if e.target == result.final], pending)
            pending = []
            result = fragment if result is None else _serial(result, fragment, behavior.location)
        if result is None:
            raise error_at(
                behavior.location,
                "a serial of only emit has no instant to emit at",
                hint="emit between two phases, or after one",
            )
        _emit([e for e in result.edges if e.target == result.final], pending)
        result.ends_itself = last_ends_itself
        return result

    def wait(self, wait: model.Wait) -> _Fragment:
        """A phase in which nothing is asked of anyone: it lasts the given time, or until the condition or event."""
        name = wait.label or "wait"
        fragment = _phase(
            next(self.counter), name, wait.label is not None, Variant(), frozenset(), frozenset(), frozenset()
        )
        fragment.ends_itself = True
        return self.end_on(fragment, wait.condition, name, wait.location)

    def end_on(
        self,
        fragment: _Fragment,
        spec: model.EventSpecification,
        name: str,
        location,
        rising: bool = False,
        actor: str | None = None,
    ) -> _Fragment:
        """The fragment ending as ``spec`` says (``until``, ``wait``): where a condition holds, at an
        emitted event, or ``elapsed(t)`` after it began (a timed phase). ``rising``: an ``until``
        condition is an event that happens when the condition becomes true, so it does not hold
        yet when the phase starts (a ``wait`` on a condition that already holds ends at once).
        ``actor``: the ``until``'s invocation's, whom the condition asks (``_asked_by_until``)."""
        guard, event, first, timed = self.ending(spec)
        if actor is not None:
            _asked_by_until(fragment, actor, guard)
        if timed is not None:
            fragment = self.timed(fragment, name, timed[0], timed[1], location)
        if rising and event is None and timed is None and not guard.is_true:
            for edge in fragment.outgoing(fragment.initial):
                edge.guard = conjunction([edge.guard, Not(guard)])
        _end_on(fragment, guard, event, first)
        return fragment

    def ending(
        self, spec: model.EventSpecification, seen: tuple[str, ...] = ()
    ) -> tuple[Guard, str | None, bool, tuple[float, float] | None]:
        """What ends a phase on ``spec``: a guard at its end, the event its end awaits, whether it
        ends at the event's first emission (no ``if`` condition), and how long it lasts when the
        event is ``elapsed(t)`` (counted from the phase's start)."""
        if isinstance(spec, model.Call) and spec.function == "elapsed":
            return TRUE, None, False, duration_interval(spec.arguments[0], self.env)
        if not isinstance(spec, model.EventReference):
            return self.checked.registry.condition(spec, self.env, self.actors), None, False, None
        declared = self.events.get(spec.name)
        if declared is None or spec.name in seen:
            what = "an undeclared event" if declared is None else "an event defined through itself"
            raise error_at(
                spec.location,
                f"not supported yet by the automaton: @{spec.name} ({what})",
                hint="wait for an event the scenario declares and emits, or on a condition",
            )
        extra = (
            self.checked.registry.condition(spec.condition, self.env, self.actors)
            if spec.condition is not None
            else TRUE
        )
        if declared.specification is not None:  # event e is @other / is (condition) / is elapsed(t)
            guard, event, first, timed = self.ending(declared.specification, seen + (spec.name,))
            return conjunction([guard, extra]), event, first and spec.condition is None, timed
        return extra, spec.name, spec.condition is None, None

    def timed(
        self, fragment: _Fragment, name: str, low: float, high: float, source, rates: tuple[PhaseBound, ...] = ()
    ) -> _Fragment:
        """Mark the fragment's first and last instants as one timed phase lasting low..high seconds
        (with the bounds ``rates`` over its two ends)."""
        phase = next(self.counter)
        rates = tuple(replace(rate, phase=name) for rate in rates)
        self.timings[phase] = Timing(phase, name, low, high, source, rates)
        for edge in fragment.edges:
            if edge.source == fragment.initial:
                edge.starts = edge.starts | {phase}
            if edge.target == fragment.final:
                edge.ends = edge.ends | {phase}
        return fragment


def _seconds(low: float, high: float) -> str:
    """An offset as its author wrote it: a single value (widened by the tolerance) or a range."""
    if math.isclose(high - low, 2 * DURATION_TOLERANCE):
        return f"{(low + high) / 2:g} s"
    return f"{low:g}..{high:g} s"


def _member_name(behavior: model.Behavior) -> str:
    """How a message names a member of a composition: its label, else its phase's name."""
    return getattr(behavior, "label", None) or _phase_name(behavior)


def _phase_name(behavior: model.Behavior) -> str:
    if isinstance(behavior, model.Invocation):
        return f"{behavior.actor}.{behavior.action}"
    return getattr(behavior, "operator", "phase")


def _atomic(
    invocation: model.Invocation, checked: CheckedScenario, counter, env: dict, actors: tuple[str, ...]
) -> tuple[_Fragment, tuple[PhaseBound, ...]]:
    """The phase's fragment, and what it asks of its start and end together (``actors``: the scenario's)."""
    phase = phase_guards(invocation, checked.registry, checked.lanes, env, actors)
    labelled = invocation.label is not None
    name = invocation.label if labelled else _phase_name(invocation)
    drivers = frozenset([invocation.actor]) if phase.drives else frozenset()
    asks = frozenset((invocation.actor, what) for what in phase.asks)
    early = frozenset((invocation.actor, what) for what in phase.asks_at_start)
    fragments = [_phase(next(counter), name, labelled, variant, drivers, asks, early) for variant in phase.variants]
    return (fragments[0] if len(fragments) == 1 else _one_of(fragments, next(counter))), tuple(phase.rates)


def _asked_by_until(fragment: _Fragment, actor: str, guard: Guard) -> None:
    """An ``until`` condition the phase's actor takes part in asks it for what the condition reads
    (its lane, or its speed for a speed, a gap or a distance): the actor is to bring it about."""
    asked = set()
    for bound in guard.atoms():
        if actor in bound.term.actors:
            asked.add("lane" if bound.term.quantity == LANE else "speed")
    for key in fragment.names:
        fragment.asks[key] = fragment.asks.get(key, frozenset()) | {(actor, what) for what in asked}


def _emit(edges: list[_Edge], events: list[str]) -> None:
    for edge in edges:
        edge.emits = edge.emits | frozenset(events)
        edge.awaits = edge.awaits - edge.emits
        edge.events = edge.events + tuple(f"{e} emitted" for e in events)


def _end_on(fragment: _Fragment, guard: Guard, event: str | None, first: bool) -> None:
    """End the fragment's phase where ``guard`` holds and, when ``event`` is given, ``event`` is
    emitted (at its first emission when ``first``)."""
    for edge in fragment.edges:
        if edge.target != fragment.final:
            continue
        edge.guard = conjunction([edge.guard, guard])
        if event is not None:
            edge.awaits = edge.awaits | {event}
            if first:
                fragment.listening[edge.source] = fragment.listening.get(edge.source, frozenset()) | {event}


def _phase(
    uid: int,
    name: str,
    labelled: bool,
    variant: Variant,
    drivers: frozenset[str],
    asks: frozenset[tuple[str, Ask]],
    early: frozenset[tuple[str, Ask]],
) -> _Fragment:
    """``init --start--> phase --end--> fin`` for one phase (of an action, or a wait)."""
    i, s, f = ("i", uid), ("s", uid), ("f", uid)
    # An invariant holds throughout the phase, its first and last instants included.
    start = conjunction([variant.start, variant.invariant])
    end = conjunction([variant.end, variant.invariant])
    return _Fragment(
        initial=i,
        final=f,
        edges=[_Edge(i, start, (f"{name} start",), s, early=early), _Edge(s, end, (f"{name} end",), f)],
        names={s: (name, labelled)},
        drivers={s: drivers},
        invariants={s: variant.invariant} if not variant.invariant.is_true else {},
        asks={s: asks},
    )


def _serial(first: _Fragment, second: _Fragment, location=None) -> _Fragment:
    edges = [e for e in first.edges if e.target != first.final]
    edges += [e for e in second.edges if e.source != second.initial]
    into = [e for e in first.edges if e.target == first.final]
    out = second.outgoing(second.initial)
    _check_size(len(edges) + len(into) * len(out), location, "serial")
    for a in into:
        for b in out:
            edges.append(_simultaneous(a.source, [a, b], b.target))
    return _Fragment(
        initial=first.initial,
        final=second.final,
        edges=edges,
        names={**first.names, **second.names},
        drivers={**first.drivers, **second.drivers},
        invariants={**first.invariants, **second.invariants},
        listening={**first.listening, **second.listening},
        asks={**first.asks, **second.asks},
    )


# The most transitions a parallel's product or a serial's junctions may make. Variants per starting
# lane multiply across the members of a parallel and across a serial's junctions; the bound is far
# above any hand-written scenario's (docs/decisions.md). Past it, building the automaton stops
# with a located error.
MAX_TRANSITIONS = 20_000


def _check_size(transitions: int, location, composition: str) -> None:
    if transitions > MAX_TRANSITIONS:
        raise error_at(
            location,
            f"this {composition}'s automaton grows past {MAX_TRANSITIONS:,} transitions: its members' choices multiply "
            "(a variant per starting lane for keep_lane() and change_lane())",
            hint="give the lanes the members start in (lane(k, at: start)), narrow the road (path_max_lanes), or split the parallel into phases",
        )


@dataclass(frozen=True)
class _Offset:
    """A parallel's ``start_to_start:`` (or ``end_to_end:``): the seconds from the primary member's
    start (end) to each secondary's, ``low..high``, negative when the secondary's comes first. Each
    secondary's offset is a timed phase of the product, one per order (``after``: the primary's
    instant first; ``before``: the secondary's first), from secondary index to phase; both at one
    instant is an offset of 0."""

    low: float
    high: float
    after: dict[int, int]
    before: dict[int, int]

    def marks(self, now: list[bool], done: list[bool]) -> tuple[frozenset[int], frozenset[int]] | None:
        """The offset phases a move starts and ends, given which members reach their instant in
        it (``now``) and which had before it (``done``); None when it breaks an offset."""
        starts: set[int] = set()
        ends: set[int] = set()
        for j in range(1, len(now)):
            if now[0] and now[j]:
                if not self.low <= 0 <= self.high:
                    return None
            elif now[0] and not done[j]:
                if j not in self.after:
                    return None
                starts.add(self.after[j])
            elif now[j] and not done[0]:
                if j not in self.before:
                    return None
                starts.add(self.before[j])
            elif now[j]:
                ends.add(self.after[j])
            elif now[0]:
                ends.add(self.before[j])
        return frozenset(starts), frozenset(ends)


@dataclass(frozen=True)
class _Overlap:
    """How a parallel's members sit in time (the standard, 7.6.2.1.4), the first member being the
    primary: which may start after the parallel starts, which may end before it ends, and the
    order of starts and ends the kind asks, with the offsets between the primary's start (end) and
    the others' (``start_to_start``, ``end_to_end``). Only a member that ends of itself (a
    duration, an until, a wait) starts late or ends early, or one whose instant an offset gives:
    one with nothing to end it and no offset spans the parallel, since nothing its author wrote
    says when it would start or stop otherwise."""

    kind: str
    start_offset: _Offset | None = None
    end_offset: _Offset | None = None

    def may_start_late(self, index: int, child: _Fragment) -> bool:
        if self.kind in ("equal", "start") or not {"inside": index > 0, "full": index == 0}.get(self.kind, True):
            return False
        offset = self.start_offset
        return child.ends_itself or (offset is not None and (offset.high > 0 if index else offset.low < 0))

    def may_end_early(self, index: int, child: _Fragment) -> bool:
        if self.kind in ("equal", "end") or not {"inside": index > 0, "full": index == 0}.get(self.kind, True):
            return False
        offset = self.end_offset
        return child.ends_itself or (offset is not None and (offset.low < 0 if index else offset.high > 0))

    def ends_itself(self, child: _Fragment) -> bool:
        """Whether the member ends of itself in this parallel: its own duration, until or wait, or
        an end offset that times it against the primary's end."""
        return child.ends_itself or self.end_offset is not None

    def marks(
        self, current: tuple[Key, ...], target: tuple[Key, ...], children: list[_Fragment]
    ) -> tuple[frozenset[int], frozenset[int]] | None:
        """The offset phases the move from ``current`` to ``target`` starts and ends (none without
        offsets); None when it breaks one."""
        starts: frozenset[int] = frozenset()
        ends: frozenset[int] = frozenset()
        for offset, reached in ((self.start_offset, False), (self.end_offset, True)):
            if offset is None:
                continue
            if reached:
                done = [key == c.final for key, c in zip(current, children)]
                now = [k != t and t == c.final for k, t, c in zip(current, target, children)]
            else:
                done = [key != c.initial for key, c in zip(current, children)]
                now = [k == c.initial and t != k for k, t, c in zip(current, target, children)]
            marked = offset.marks(now, done)
            if marked is None:
                return None
            starts, ends = starts | marked[0], ends | marked[1]
        return starts, ends

    def keeps_order(self, target: tuple[Key, ...], children: list[_Fragment]) -> bool:
        """Whether members at ``target`` (each at its start, inside, or at its end) have started
        and ended in the order the kind asks: ``initial``, each secondary starts no later than the
        primary and ends no earlier than the primary starts; ``final``, each secondary starts no
        later than the primary ends and ends no earlier; ``any``, all have started before any ends."""
        waiting = [key == c.initial for key, c in zip(target, children)]
        done = [key == c.final for key, c in zip(target, children)]
        if self.kind == "initial":
            return not any(not waiting[0] and w or waiting[0] and d for w, d in zip(waiting[1:], done[1:]))
        if self.kind == "final":
            return not any(done[0] and w or d and not done[0] for w, d in zip(waiting[1:], done[1:]))
        if self.kind == "any":
            return not (any(done) and any(waiting))
        return True


def _parallel(children: list[_Fragment], overlap: _Overlap, location=None, timed: bool = False) -> _Fragment:
    """The product of a parallel's members, as ``overlap`` places them: a member that may start
    late stays at its start until it starts, one that may end early stays at its end after it
    ended, and no move breaks the order of starts and ends the overlap asks. Every other member
    ends with the last that ends of itself (with the last of all when none ends of itself), or,
    ``timed`` (the parallel's own duration), when the parallel ends."""
    initial = tuple(c.initial for c in children)
    final = tuple(c.final for c in children)
    edges: list[_Edge] = []
    seen = {initial}
    frontier = [initial]
    while frontier:
        current = frontier.pop()
        # each member's moves split into those that leave it final and those that do not: the
        # combinations made are the all-final ones, and those in which only members that end of
        # themselves become final (never the product of all moves, 2^n for n members, filtered)
        ending: list[list[_Edge | None]] = []
        going_on: list[list[_Edge | None]] = []
        for index, (child, key) in enumerate(zip(children, current)):
            moves: list[_Edge | None] = list(child.outgoing(key))
            if current != initial or overlap.may_start_late(index, child):
                moves.append(None)  # this component stays (or, late, has not started yet)
            ending.append([m for m in moves if (m.target if m is not None else key) == child.final])
            # a member that may end early may end while others go on: all its moves go on with them
            early = overlap.may_end_early(index, child) and key != child.final
            going_on.append(
                moves if early else [m for m in moves if (m.target if m is not None else key) != child.final]
            )
        for options in (going_on, ending):
            _check_size(
                math.prod(len(o) for o in options) - 1, location, "parallel"
            )  # an upper bound of the edges it makes, before making them
        combinations = itertools.chain(
            ((c, True) for c in itertools.product(*going_on)), ((c, False) for c in itertools.product(*ending))
        )
        for combination, mixed in combinations:
            if all(m is None for m in combination):
                continue
            target = tuple(m.target if m is not None else key for m, key in zip(combination, current))
            # a member with nothing to end it lasts as long as the parallel: it ends with the last
            # member that ends of itself, so no combination leaves only such members going on
            if mixed and (
                _all_final(target, children) or not (timed or _one_ending_itself_goes_on(target, children, overlap))
            ):
                continue
            if not overlap.keeps_order(target, children):
                continue
            marked = overlap.marks(current, target, children)
            if marked is None:
                continue  # it breaks a start_to_start or an end_to_end
            moving = [m for m in combination if m is not None]
            staying = frozenset().union(
                *(c.listening.get(k, frozenset()) for m, c, k in zip(combination, children, current) if m is None)
            )
            edge = _simultaneous(current, moving, target, staying)
            if edge.deaf & edge.emits:
                continue  # a member waiting for the event would miss it
            edge.starts, edge.ends = edge.starts | marked[0], edge.ends | marked[1]
            edges.append(edge)
            _check_size(len(edges), location, "parallel")
            if target not in seen:
                seen.add(target)
                frontier.append(target)
    names: dict[Key, tuple[str, bool]] = {}
    drivers: dict[Key, frozenset[str]] = {}
    invariants: dict[Key, Guard] = {}
    listening: dict[Key, frozenset[str]] = {}
    asks: dict[Key, frozenset[tuple[str, Ask]]] = {}
    for key in seen:
        parts = [c.names[k] for c, k in zip(children, key) if k in c.names]
        labelled = [n for n, is_labelled in parts if is_labelled]
        chosen = labelled or [n for n, _ in parts]
        if chosen:
            names[key] = (" | ".join(chosen), bool(labelled))
        drivers[key] = frozenset().union(*(c.drivers.get(k, frozenset()) for c, k in zip(children, key)))
        asks[key] = frozenset().union(*(c.asks.get(k, frozenset()) for c, k in zip(children, key)))
        parts = [c.invariants[k] for c, k in zip(children, key) if k in c.invariants]
        if parts:
            invariants[key] = conjunction(parts)
        waiting = frozenset().union(*(c.listening.get(k, frozenset()) for c, k in zip(children, key)))
        if waiting:
            listening[key] = waiting
    return _Fragment(initial, final, edges, names, drivers, invariants, listening, asks)


def _all_final(target: tuple[Key, ...], children: list[_Fragment]) -> bool:
    """Whether members at ``target`` are all at their ends."""
    return all(key == c.final for key, c in zip(target, children))


def _one_ending_itself_goes_on(target: tuple[Key, ...], children: list[_Fragment], overlap: _Overlap) -> bool:
    """Whether, with members at ``target``, a member that ends of itself is still going on (or
    none of the members ends of itself, and all go on together)."""
    selfending = [(key, c) for key, c in zip(target, children) if overlap.ends_itself(c)]
    return not selfending or any(key != c.final for key, c in selfending)


def _one_of(children: list[_Fragment], uid: int) -> _Fragment:
    initial, final = ("oi", uid), ("of", uid)
    edges: list[_Edge] = []
    names: dict[Key, tuple[str, bool]] = {}
    drivers: dict[Key, frozenset[str]] = {}
    invariants: dict[Key, Guard] = {}
    listening: dict[Key, frozenset[str]] = {}
    asks: dict[Key, frozenset[tuple[str, Ask]]] = {}
    for child in children:
        rename = {child.initial: initial, child.final: final}
        for e in child.edges:
            edges.append(replace(e, source=rename.get(e.source, e.source), target=rename.get(e.target, e.target)))
        names.update(child.names)
        drivers.update(child.drivers)
        invariants.update(child.invariants)
        listening.update(child.listening)
        asks.update(child.asks)
    return _Fragment(initial, final, edges, names, drivers, invariants, listening, asks)


def _finish(
    fragment: _Fragment, actors: tuple[str, ...], scenario: model.Scenario, timings: dict[int, Timing], lanes: int
) -> SymbolicAutomaton:
    # an edge still awaiting an event here awaits one that no member emits at that instant
    unmatched = sorted({event for e in fragment.edges for event in e.awaits})
    fragment = replace(fragment, edges=[e for e in fragment.edges if not e.awaits])
    # Keep locations that are reachable from the initial one and can still reach the final one.
    successors: dict[Key, list[Key]] = {}
    predecessors: dict[Key, list[Key]] = {}
    for e in fragment.edges:
        successors.setdefault(e.source, []).append(e.target)
        predecessors.setdefault(e.target, []).append(e.source)
    forward = _closure(fragment.initial, lambda k: successors.get(k, ()))
    backward = _closure(fragment.final, lambda k: predecessors.get(k, ()))
    useful = forward & backward
    if fragment.initial not in useful:
        hint = "check that the members of each parallel can end together"
        if unmatched:
            hint += f"; a wait for {', '.join('@' + e for e in unmatched)} ends only while another member emits it (an emit before the wait began is missed)"
        raise error_at(
            scenario.location, f"scenario {scenario.name!r} can never finish: its phases cannot all end", hint=hint
        )
    # what is asked here, and what the phases an edge from here starts ask for at their first
    # instant (a change the next phase needs at its start comes in the phase before it). Per edge,
    # so that a parallel member's own start is not asked again at another member's later junction
    asked = {
        key: fragment.asks.get(key, frozenset()).union(
            *(e.early for e in fragment.edges if e.source == key and e.target in useful)
        )
        for key in useful
    }
    order = _bfs_order(fragment, useful, successors)
    ids = {key: index for index, key in enumerate(order)}
    used: dict[str, int] = {}
    locations = []
    for key in order:
        if key == fragment.initial:
            name = "init"
        elif key == fragment.final:
            name = "fin"
        else:
            name = fragment.names.get(key, ("phase", False))[0]
        used[name] = used.get(name, 0) + 1
        if used[name] > 1:
            name = f"{name}#{used[name]}"
        locations.append(
            Location(
                ids[key],
                name,
                fragment.drivers.get(key, frozenset()),
                fragment.invariants.get(key, TRUE),
                asked[key],
            )
        )
    transitions = []
    for edge in fragment.edges:
        if edge.source in useful and edge.target in useful:
            transitions.append(
                Transition(
                    len(transitions),
                    ids[edge.source],
                    ids[edge.target],
                    edge.guard,
                    edge.events,
                    edge.starts,
                    edge.ends,
                )
            )
    transitions.sort(key=lambda t: (t.source, t.target))
    transitions = [
        Transition(i, t.source, t.target, t.guard, t.events, t.starts, t.ends) for i, t in enumerate(transitions)
    ]
    stationary = frozenset(a.name for a in scenario.actors if a.stationary)
    return SymbolicAutomaton(
        locations, transitions, ids[fragment.initial], ids[fragment.final], actors, stationary, timings, lanes
    )


def _closure(start: Key, neighbours) -> set[Key]:
    seen = {start}
    stack = [start]
    while stack:
        for nxt in neighbours(stack.pop()):
            if nxt not in seen:
                seen.add(nxt)
                stack.append(nxt)
    return seen


def _bfs_order(fragment: _Fragment, useful: set[Key], successors: dict[Key, list[Key]]) -> list[Key]:
    """Useful locations in breadth-first order from the initial one, successors in edge order."""
    order = [fragment.initial]
    placed = {fragment.initial}
    index = 0
    while index < len(order):
        for target in successors.get(order[index], ()):
            if target in useful and target not in placed:
                placed.add(target)
                order.append(target)
        index += 1
    return order
