"""What one atomic phase asks of its actor, before it becomes locations and transitions.

A construct's translation (``pytest_roadlogic.constructs``) writes into a ``Phase``: guards at the
phase's start and end and an invariant throughout, in one or several ``Variant``s. Several
variants arise when a constraint refers to a value the phase started with (``keep_lane()``: one
variant per starting lane), because a guard sees only the current state; the construction turns
the variants into a ``one_of``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .automaton import Ask, PhaseBound
from .guards import TRUE, Guard, conjunction


@dataclass(frozen=True)
class Variant:
    """One way the phase can go: the guard at its start, at its end, and throughout."""

    start: Guard = TRUE
    end: Guard = TRUE
    invariant: Guard = TRUE


@dataclass
class Phase:
    """The guards of one atomic phase; several variants when it depends on a starting value."""

    actor: str
    variants: list[Variant] = field(default_factory=lambda: [Variant()])
    drives: bool = True  # whether the actor must make forward progress in this phase
    # what the phase asks of its start and end together (they hold in every variant)
    rates: list[PhaseBound] = field(default_factory=list)
    # what its constructs ask the actor to change: "lane", "speed" (Construct.asks), a speed to
    # drive toward (Toward) or one speed held over the phase (Steady); and what they ask for
    # already at its first instant (speed(v) throughout, position(..., at: start)), which the
    # phase before it must bring about
    asks: set[Ask] = field(default_factory=set)
    asks_at_start: set[str] = field(default_factory=set)

    def add(self, start: Guard = TRUE, end: Guard = TRUE, invariant: Guard = TRUE) -> None:
        self.variants = [
            Variant(conjunction([v.start, start]), conjunction([v.end, end]), conjunction([v.invariant, invariant]))
            for v in self.variants
        ]

    def anchor(self, guard: Guard, at: str) -> None:
        """Add ``guard`` where ``at:`` puts it: the start, the end, or throughout (``all``)."""
        if at == "start":
            self.add(start=guard)
        elif at == "end":
            self.add(end=guard)
        else:
            self.add(invariant=guard)

    def branch(self, options: list[Variant]) -> None:
        """Multiply the variants by ``options`` (each existing variant combined with each option)."""
        self.variants = [
            Variant(
                conjunction([v.start, o.start]), conjunction([v.end, o.end]), conjunction([v.invariant, o.invariant])
            )
            for v in self.variants
            for o in options
        ]
