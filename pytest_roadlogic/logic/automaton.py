"""The symbolic finite automaton: the spine shared by the planner and the monitor.

Locations are the phases of a scenario (a time interval in which each actor is doing one thing);
transitions are instants at which guards must hold. A run takes its transitions at strictly
increasing times, so every phase lasts a positive time, as the paper's semantics of serial
composition demands (the split point lies strictly inside the interval).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar

from ..frontend.errors import SourceLocation
from .guards import TRUE, Guard


@dataclass(frozen=True)
class Toward:
    """A speed band (m/s) its actor is asked to drive towards from the phase's first instant and
    then hold: CARLA's ``speed(v)``, which its runner sets as the phase's target speed. Each change
    of speed the phase asks is one toward the band, never away from it nor past it."""

    low: float
    high: float
    value: float  # the speed asked: the band is it within the tracking tolerance


@dataclass(frozen=True)
class Steady:
    """A change of speed its actor's phase licenses only to be where the phase's end asks (CARLA's
    ``position(..., at: end)``), which CARLA's runner drives at one speed over the phase: the plan
    keeps the actor's speed there unless the end needs a change, and does not adjust it there for
    a later phase (a strong preference of the smoothing program, never a reason for no plan)."""


Ask = str | Toward | Steady  # what a phase asks an actor: "lane", "speed", a target, one speed held


@dataclass(frozen=True)
class Location:
    id: int
    name: str
    # Actors inside a ``drive`` phase here: each must make forward progress while the run stays.
    drivers: frozenset[str] = frozenset()
    # What must hold at every instant the run spends here (modifiers with ``at: all``).
    invariant: Guard = TRUE
    # (actor, "lane" | "speed"): an actor's own construct running here asks it to change lane or
    # speed (a lane or change_lane modifier; a speed, position, change_speed ...). An actor
    # changes neither unless asked where it is (least action: docs/language.md, "Unasked").
    # (actor, Toward): a speed it drives toward here (CARLA's speed(v)): changes toward it only.
    # (actor, Steady): one speed it holds here unless the phase's end needs a change (CARLA's position).
    asks: frozenset[tuple[str, Ask]] = frozenset()

    def asked(self, actor: str, what: str) -> bool:
        return (actor, what) in self.asks

    def toward(self, actor: str) -> Toward | None:
        """The speed band ``actor`` drives toward here, if it is asked one."""
        return next((what for who, what in self.asks if who == actor and isinstance(what, Toward)), None)

    def steady(self) -> list[str]:
        """Every actor asked here to hold one speed over the phase (``Steady``), in a fixed order."""
        return sorted({who for who, what in self.asks if isinstance(what, Steady)})

    def targets(self) -> list[tuple[str, Toward]]:
        """Every (actor, speed band) driven toward here, in a fixed order."""
        return sorted(
            ((who, what) for who, what in self.asks if isinstance(what, Toward)), key=lambda t: (t[0], t[1].low)
        )


@dataclass(frozen=True)
class PhaseBound:
    """A bound on what an actor does between a phase's two ends, read from one quantity at its
    first and last instants: the phase is timed for it, the planner writes linear rows over the
    two ends, the monitor reads the two samples at which its run starts and ends the phase."""

    actor: str
    low: float
    high: float
    phase: str = ""
    source: SourceLocation | None = None

    # the trace's column it reads at the two ends, and how it is named in messages and reports
    column: ClassVar[str]
    construct: ClassVar[str]
    what: ClassVar[str]
    symbol: ClassVar[str]  # the value's name in a report: mean a(car1)
    unit: ClassVar[str]

    def value(self, start: float, end: float, seconds: float) -> float:
        """The bounded value of a phase of ``seconds`` whose column reads ``start`` and ``end``."""
        raise NotImplementedError

    def span(self, series, begun: int, end: int) -> int:
        """The sample up to which the bound reads the phase that runs from sample ``begun`` to
        ``end`` of the actor's column ``series``: its end, unless the bound says otherwise."""
        return end

    def measured(self, series, times, begun: int, end: int) -> float:
        """The bounded value of the phase that runs from sample ``begun`` to ``end`` of the actor's
        column ``series`` (``times``: the samples' times, s): read from its two ends (``span``),
        unless the bound reads the samples between them too."""
        read = self.span(series, begun, end)
        return self.value(series[begun], series[read], times[read] - times[begun])

    def __str__(self) -> str:
        over = f" over {self.phase}" if self.phase else ""
        return f"{self.what} of {self.actor}{over} in {self.low:g}..{self.high:g} {self.unit}"

    @property
    def as_written(self) -> str:
        """How a message names this bound (as ``Bound.as_written``): a conflict's explanation
        names every constraint so, a phase's mean acceleration or distance among them."""
        return str(self)


@dataclass(frozen=True)
class MeanAcceleration(PhaseBound):
    """``acceleration(a)`` on a phase (the standard's ``at: all``): the actor accelerates at a rate
    in low..high (m/s^2) while it moves in the phase. A car braking to a standstill inside the
    phase meets a braking bound by standing still after (it cannot brake further).

    The planner holds the bound on every step of the phase. The monitor judges the mean, (v(end)
    - v(start)) / duration, from the phase's start to its end or to the first sample at which the
    actor stands still (its speed at most ``standstill``, m/s), whichever comes first: a real
    car's brakes ramp up within a few tenths of a second, so a bound on every instant would fail
    at each phase's first one."""

    standstill: float = 0.0

    column: ClassVar[str] = "speed"
    construct: ClassVar[str] = "the acceleration modifier"
    what: ClassVar[str] = "mean acceleration"
    symbol: ClassVar[str] = "mean a"
    unit: ClassVar[str] = "m/s^2"

    def value(self, start: float, end: float, seconds: float) -> float:
        return (end - start) / seconds

    def span(self, series, begun: int, end: int) -> int:
        """The phase's end, or the first sample at which an actor moving at its start stands still."""
        if series[begun] <= self.standstill:
            return end
        for k in range(begun + 1, end):
            if series[k] <= self.standstill:
                return k
        return end


# a speed change's shape (the standard's dynamics_shape) -> its peak acceleration over its mean:
# linear and step keep one rate; cubic, v0 + dv (3s^2 - 2s^3), peaks at 1.5 times its mean;
# sinusoidal, v0 + dv (1 - cos(pi s)) / 2, at pi/2 times it
SHAPE_PEAK_OVER_MEAN = {"linear": 1.0, "step": 1.0, "cubic": 1.5, "sinusoidal": math.pi / 2}


@dataclass(frozen=True)
class ShapedSpeedChange(MeanAcceleration):
    """``change_speed(target, rate_profile: shape, rate_peak: p)``: the speed moves from its value at
    the phase's start to the target in the standard's ``dynamics_shape``, its acceleration peaking at
    p (low..high: the peak's size, m/s^2, either way). ``linear``: at p on every step until the
    target; ``cubic`` / ``sinusoidal``: from no acceleration at the start to p halfway to none at the
    end; ``step`` (the target at once, which no car can): at the car's limit, low..high the
    least and most a brisk change is judged to have.

    The planner keeps the shape on every step (``asp/continuous/rates.lp``). The monitor judges
    the peak the shape implies from the mean, the shape's factor times |v(end) - v(start)| / the
    time, from the phase's start to the first sample at the target (``target``, m/s: the action
    ends when its target is reached, so a change made faster and then held is not read as a slow
    one), or to the phase's end when it never gets there."""

    shape: str = "linear"
    target: tuple[float, float] = (0.0, math.inf)

    construct: ClassVar[str] = "change_speed's rate_profile"
    what: ClassVar[str] = "peak acceleration"
    symbol: ClassVar[str] = "peak a"

    def value(self, start: float, end: float, seconds: float) -> float:
        return SHAPE_PEAK_OVER_MEAN[self.shape] * abs(end - start) / seconds

    def span(self, series, begun: int, end: int) -> int:
        """The first sample after the phase's start at which the speed is at the target, else its end."""
        low, high = self.target
        for k in range(begun + 1, end):
            if low <= series[k] <= high:
                return k
        return end

    def __str__(self) -> str:
        over = f" over {self.phase}" if self.phase else ""
        return f"{self.shape} speed change of {self.actor}{over}, {self.what} {self.low:g}..{self.high:g} {self.unit}"


@dataclass(frozen=True)
class ChangeOverPhase(PhaseBound):
    """A bound on how much the column changes between the phase's two ends, x(end) - x(start),
    whatever the phase's length."""

    def value(self, start: float, end: float, seconds: float) -> float:
        return end - start


@dataclass(frozen=True)
class SpeedGain(ChangeOverPhase):
    """CARLA's ``change_speed(dv)`` modifier on a phase: its runner adds dv to the actor's target
    speed at the phase's start and holds the new one, so the speed gains dv over the phase,
    v(end) - v(start) in low..high (m/s), whatever the phase's length."""

    column: ClassVar[str] = "speed"
    construct: ClassVar[str] = "the change_speed modifier"
    what: ClassVar[str] = "speed gained"
    symbol: ClassVar[str] = "gained v"
    unit: ClassVar[str] = "m/s"


@dataclass(frozen=True)
class Travelled(ChangeOverPhase):
    """``distance(d)`` on a phase: the actor covers d metres in it, x(end) - x(start) in low..high.
    Unlike a mean acceleration it does not depend on the phase's length: the planner writes one row."""

    column: ClassVar[str] = "x"
    construct: ClassVar[str] = "the distance modifier"
    what: ClassVar[str] = "distance travelled"
    symbol: ClassVar[str] = "travelled"
    unit: ClassVar[str] = "m"


@dataclass(frozen=True)
class HeldSpeed(PhaseBound):
    """``keep_speed()``: the actor's speed stays within ``high`` (m/s) of its value at the phase's
    start, at every instant of the phase: the largest |v(t) - v(start)| over it is at most
    ``high`` (``low`` is -inf: a speed held exactly is as far inside the bound as it can be, not at
    its edge).

    Why a bound over the phase and not a guard: the speed it holds is the one the phase starts
    with, which a guard cannot name; one row per step against the phase's first speed says it
    exactly, where a choice among bands of starting speeds multiplied the automaton by their
    number. The planner holds it on every step (``asp/continuous/rates.lp``; the grid holds the
    speed exactly), the monitor reads every sample of the phase."""

    column: ClassVar[str] = "speed"
    construct: ClassVar[str] = "keep_speed()"
    what: ClassVar[str] = "largest change of speed from the phase's start"
    symbol: ClassVar[str] = "max |dv|"
    unit: ClassVar[str] = "m/s"

    def value(self, start: float, end: float, seconds: float) -> float:
        return abs(end - start)

    def measured(self, series, times, begun: int, end: int) -> float:
        first = series[begun]
        return max(abs(series[k] - first) for k in range(begun, end + 1))

    def __str__(self) -> str:
        over = f" over {self.phase}" if self.phase else ""
        return f"keep_speed() of {self.actor}{over}: its speed within {self.high:g} {self.unit} of the phase's first"


@dataclass(frozen=True)
class Timing:
    """How long a phase may last, in seconds: from the transition that starts it to the one that ends it.

    ``high`` may be infinite: a phase that is timed only for its ``rates`` (``PhaseBound``s: mean
    accelerations and distances travelled) and has no ``duration:``."""

    phase: int
    name: str
    low: float
    high: float
    source: SourceLocation | None = None
    rates: tuple[PhaseBound, ...] = ()

    def admits(self, seconds: float, tolerance: float = 1e-6) -> bool:
        return self.low - tolerance <= seconds <= self.high + tolerance

    def admits_start(self, seconds: float, tolerance: float = 1e-6) -> bool:
        """Whether a phase that has run ``seconds`` so far can still end in time."""
        return seconds <= self.high + tolerance

    def __str__(self) -> str:
        if math.isinf(self.high):
            return f"{self.name} lasts at least {self.low:g} s"
        return f"{self.name} lasts {self.low:g}..{self.high:g} s"

    @property
    def as_written(self) -> str:
        """How a message names this timing (as ``Bound.as_written``)."""
        return str(self)


@dataclass(frozen=True)
class Transition:
    id: int
    source: int
    target: int
    guard: Guard
    # What happens at this instant, e.g. ("A end", "B start"), for reports and plots.
    events: tuple[str, ...] = ()
    # Timed phases (keys of SymbolicAutomaton.timings) that start / end at this instant.
    starts: frozenset[int] = frozenset()
    ends: frozenset[int] = frozenset()

    @property
    def label(self) -> str:
        return ", ".join(self.events)


@dataclass
class SymbolicAutomaton:
    locations: list[Location]
    transitions: list[Transition]
    initial: int
    final: int
    actors: tuple[str, ...] = field(default_factory=tuple)
    # Actors that never move (stationary_object): the planner pins them, the simulator does not drive them.
    stationary: frozenset[str] = frozenset()
    # Duration bounds of phases (``duration:``, ``wait elapsed(...)``), by phase id.
    timings: dict[int, Timing] = field(default_factory=dict)
    # Lanes of the road the guards were built for (keep_lane and change_lane enumerate them).
    lanes: int = 3
    # The logical parameters used at each place of the file (``frontend.semantics.logical.names_by_place``):
    # a bound's or a duration's source names the parameters behind it, for the planner's instance
    # and the messages that name constraints.
    parameters: dict = field(default_factory=dict, compare=False)
    # The places of the parameters a sample narrowed to bands (``sampling.guided``): the sampler
    # chose each band inside the range's margins, so the planner plans it as given, without a
    # margin of its own (one inset per value, not two).
    sampled: frozenset = field(default=frozenset(), compare=False)

    def planned_margin(self, constraint, margin: float) -> float:
        """The margin the planner keeps inside ``constraint``'s range: none for a sampled band."""
        return 0.0 if getattr(constraint, "source", None) in self.sampled else margin

    def parameters_of(self, constraint) -> tuple[str, ...]:
        """The logical parameters behind a constraint (a bound, a duration, a rate), by its source."""
        return self.parameters.get(getattr(constraint, "source", None), ())

    def location(self, location_id: int) -> Location:
        return self.locations[location_id]

    def run_locations(self, fired: dict[int, int], horizon: int) -> list[int]:
        """The location a run is in at each step 0..``horizon`` (after that step's transition),
        given the transition it takes at each step it takes one (``fired``: step -> transition)."""
        targets = {t.id: t.target for t in self.transitions}
        location, result = self.initial, []
        for step in range(horizon + 1):
            if step in fired:
                location = targets[fired[step]]
            result.append(location)
        return result

    def outgoing(self, location_id: int) -> list[Transition]:
        return [t for t in self.transitions if t.source == location_id]

    def driving_itself(self, vehicle: str) -> SymbolicAutomaton:
        """This automaton with ``vehicle`` among no location's ``drivers``: a vehicle that drives
        itself (the vehicle under test) is not asked forward progress; it may stop where its own
        driving asks (giving way at a junction, behind a car that stopped), as its plan lets it.
        Every guard and invariant still judges where it is and how fast."""
        import dataclasses

        locations = [dataclasses.replace(q, drivers=q.drivers - {vehicle}) for q in self.locations]
        return dataclasses.replace(self, locations=locations)

    def depth(self) -> dict[int, int]:
        """Fewest transitions from the initial location; used to say how far a run got."""
        depth = {self.initial: 0}
        frontier = [self.initial]
        while frontier:
            nxt = []
            for loc in frontier:
                for t in self.outgoing(loc):
                    if t.target not in depth:
                        depth[t.target] = depth[loc] + 1
                        nxt.append(t.target)
            frontier = nxt
        return depth

    def transitions_at(self, phase: str, end: str) -> list[Transition]:
        """The transitions that start (``end`` "start") or end ("end") the timed phase labelled
        ``phase``; "" the scenario's own: those out of the initial location, or into the final one."""
        if not phase:
            if end == "start":
                return self.outgoing(self.initial)
            return [t for t in self.transitions if t.target == self.final]
        phases = {k for k, timing in self.timings.items() if timing.name == phase}
        return [t for t in self.transitions if phases & (t.starts if end == "start" else t.ends)]

    def names_ahead(self, location_id: int, actor: str) -> bool:
        """Whether anything a run may still meet from ``location_id`` on names ``actor``: the
        invariant of a location it may reach (this one included), the guard of a transition it
        may take, a rate of a phase such a transition ends. Why: where nothing ahead names the
        vehicle under test, what the other vehicles must still do does not depend on it."""
        reached, frontier = {location_id}, [location_id]
        while frontier:
            location = frontier.pop()
            if any(actor in atom.term.actors for atom in self.locations[location].invariant.atoms()):
                return True
            for transition in self.outgoing(location):
                if any(actor in atom.term.actors for atom in transition.guard.atoms()):
                    return True
                rates = (
                    rate for phase in transition.ends if phase in self.timings for rate in self.timings[phase].rates
                )
                if any(rate.actor == actor for rate in rates):
                    return True
                if transition.target not in reached:
                    reached.add(transition.target)
                    frontier.append(transition.target)
        return False

    def describe(self) -> str:
        lines = [f"locations: {', '.join(loc.name for loc in self.locations)}"]
        for loc in self.locations:
            if not loc.invariant.is_true:
                lines.append(f"  {loc.name} invariant: {loc.invariant}")
        for t in self.transitions:
            lines.append(f"  {self.locations[t.source].name} -> {self.locations[t.target].name}: {t.guard}")
        for timing in self.timings.values():
            if math.isfinite(timing.high) or timing.low > 0:
                lines.append(f"  {timing}")
            lines.extend(f"  {rate}" for rate in timing.rates)
        return "\n".join(lines)
