"""Moving and standing: ``drive()``, ``remain_stationary()`` and ``keep_position()``; the modifiers of
the motion as a whole: ``distance()``, ``along()`` and ``avoid_collisions()``."""

from __future__ import annotations

from ..frontend import model
from ..frontend.semantics.library import DURATION, Binding, Parameter, Signature
from ..frontend.semantics.tolerances import POSITION_TOLERANCE, STANDSTILL, widened
from ..frontend.syntax.units import LENGTH
from ..logic.automaton import Travelled
from ..logic.guards import SPEED, Bound, Term
from ..logic.phase import Phase
from .base import ASKS_SPEED, Action, CheckContext, Modifier, Use


class Drive(Action):
    """``drive()``: the actor drives forward for the phase; its modifiers say how."""

    # ``drive(path)``: CARLA suites name the road; there is one, so it changes nothing
    signature = Signature(
        "drive", (Parameter("path", "road", positional=True), DURATION), description="drive forward for the phase"
    )

    def translate(self, use: Use, phase: Phase) -> None:
        pass  # forward progress is what a moving phase means (Phase.drives)


class RemainStationary(Action):
    """``remain_stationary()``: the speed stays within the standstill band; no progress asked (``moves``)."""

    asks = ASKS_SPEED
    signature = Signature("remain_stationary", (DURATION,), description="stand still (obstacles)")
    moves = False

    def translate(self, use: Use, phase: Phase) -> None:
        phase.add(invariant=Bound(Term(SPEED, use.actor), -STANDSTILL, STANDSTILL, use.location))


class KeepPosition(RemainStationary):
    """``keep_position()``: the actor stays where it is, which on a road is standing still."""

    signature = Signature("keep_position", (DURATION,), description="stay where it is (stand still)")


class Distance(Modifier):
    """``distance(d)``: the actor covers d in the phase, x(end) - x(start) (``Travelled``); a single
    value is read +- the position tolerance. Like a duration, a range of it is left open by the
    scenario (a logical parameter), not a bound held at every instant."""

    asks = ASKS_SPEED
    signature = Signature(
        "distance",
        (Parameter("distance", "length", positional=True),),
        required=(("distance",),),
        description="the distance travelled in the phase",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        value = context.evaluate(binding["distance"]) if binding["distance"] is not None else None
        if value is not None and value.low < 0:
            context.error(
                binding["distance"].value.location,
                "a distance travelled must not be negative",
                "vehicles drive forward; e.g. distance([50..80]m)",
            )

    def translate(self, use: Use, phase: Phase) -> None:
        low, high = widened(*use.range("distance", LENGTH, "a length such as 50m or [50..80]m"), POSITION_TOLERANCE)
        phase.rates.append(Travelled(use.actor, max(0.0, low), high, source=use.location))


class Along(Modifier):
    """``along(path)``: the motion follows the road; there is one straight road, so it holds always."""

    signature = Signature(
        "along",
        (
            Parameter("route", "road", positional=True),
            # where on the route the motion starts and ends: not read (vehicles are placed by
            # the scenario's own position() and lane() constraints)
            Parameter("start_offset", "length", supported=False),
            Parameter("end_offset", "length", supported=False),
        ),
        required=(("route",),),
        description="follow the road (there is one)",
    )

    def translate(self, use: Use, phase: Phase) -> None:
        pass


class AvoidCollisions(Modifier):
    """``avoid_collisions(true)``: the collision rule, which this tool applies to every run anyway;
    ``avoid_collisions(false)`` (a crash asked for) is refused: no plan here ever collides."""

    signature = Signature(
        "avoid_collisions", (Parameter("avoid", "bool", positional=True),), description="no collisions (always applied)"
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        given = binding["avoid"]
        if given is not None and isinstance(given.value, model.Literal) and given.value.value is False:
            context.error(
                given.location,
                "not supported: avoid_collisions(false)",
                "this tool never plans a collision: every run keeps the vehicles apart",
            )

    def translate(self, use: Use, phase: Phase) -> None:
        pass


CONSTRUCTS = (Drive(), RemainStationary(), KeepPosition(), Distance(), Along(), AvoidCollisions())
