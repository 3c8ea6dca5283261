"""CARLA's scenario-runner dialect: the same constructs, two conventions read differently.

- Lanes are numbered from the left: ``lane(1)`` is the leftmost lane (``from: right`` counts
  from the right). A third of the public CARLA files put one car in ``lane(1)`` and another
  ``right_of`` it, which has no plan under the standard's numbering.
- ``position(d, ahead_of: x, at: end)`` is reached as CARLA's runner reaches it: the phase is
  driven at one speed where it can be, not adjusted there for a later phase's target.
- ``speed(v)`` without ``at:`` is the phase's target speed, as CARLA's runner sets it: from the
  phase's first instant the car drives toward it at a comfortable rate, never away from it nor
  past it, and holds it once reached; it is checked at the phase's end (``at: all`` written out
  still means throughout).
- ``drive(path, adjust: b)``: CARLA's runner builds a drive from its modifiers and reads none of
  its arguments; ``adjust:`` (public CARLA examples give it) is read with one located warning.
- ``change_speed(dv)`` and ``change_lane(lane_changes: k, side: s)`` are modifiers, as its runner
  executes them: the first adds dv to the car's speed from the phase's start, reached soon and
  held (its runner adds dv to the target speed there), the second moves k lanes to the side.

Everything else is the standard's. The dialect is chosen by ``--dialect carla`` /
``roadlogic_dialect = carla`` or, per file, by a ``conftest.py`` (``pytest_roadlogic_dialect``).
"""

from __future__ import annotations

from ..frontend.semantics.library import DURATION, Binding, Parameter, Signature
from ..frontend.semantics.tolerances import SPEED_TOLERANCE, widened
from ..frontend.syntax.units import SPEED
from ..logic.automaton import SpeedGain, Steady, Toward
from ..logic.guards import LANE, POSITION, And, Bound, Guard, Or, Term
from ..logic.guards import SPEED as SPEED_Q
from ..logic.phase import Phase
from ..settings import CARLA_DIALECT
from .base import ASKS_SPEED, CheckContext, Modifier, Use
from .lanes import ChangeLaneModifier, Lane
from .motion import Drive
from .position import Position
from .speed import RELATIONS, Speed

DIALECT = CARLA_DIALECT
# how far ahead a car a target speed yields to may be: this headway at the target's top speed, and
# at least this many metres (centre to centre, as position() measures)
FOLLOWING_HEADWAY = 3.0
FOLLOWING_LEAST = 20.0
CARLA_LANE_CONVENTION = "in CARLA's dialect lanes are numbered from 1 on the left (lane(1) is the leftmost); lane(k, from: right) counts from the right"


class CarlaLane(Lane):
    __doc__ = Lane.__doc__
    counted_from = "left"
    convention = CARLA_LANE_CONVENTION


class CarlaSpeed(Speed):
    """``speed(v)``: the target speed, driven toward from the phase's start and reached by its end
    (``Toward``); with ``at:`` or relative to another car, as the standard reads it."""

    default_anchor = "end"

    @staticmethod
    def targets(binding: Binding) -> bool:
        """Whether this use is a target speed: an absolute speed without ``at:``."""
        return binding["at"] is None and all(binding[r] is None for r in RELATIONS)

    def asked_within(self, binding: Binding) -> bool:
        return not self.targets(binding) and super().asked_within(binding)

    def translate(self, use: Use, phase: Phase) -> None:
        if not self.targets(use.binding):
            super().translate(use, phase)
            return
        asked = use.range("speed", SPEED, "a speed such as 20mps")
        low, high = widened(*asked, SPEED_TOLERANCE)
        phase.asks.add(Toward(max(0.0, low), high, max(0.0, (asked[0] + asked[1]) / 2)))
        phase.anchor(self.reached_or_following(use, max(0.0, low), high), "end")

    @staticmethod
    def reached_or_following(use: Use, low: float, high: float) -> Guard:
        """The phase's end check of a target speed: the speed in its band, or below it with the
        car behind another in its lane within ``FOLLOWING_HEADWAY`` at the target (at least
        ``FOLLOWING_LEAST`` metres between their centres). Why: the standard's avoid_collisions
        (on by default) outranks a target, as a driver's cruise control yields to the car ahead:
        a car asked 40 kph behind a van at 30 kph follows the van, and is not placed where no van
        can be ahead of it. Above the band is never yielding."""
        reached = Bound(Term(SPEED_Q, use.actor), low, high, use.location)
        below = Bound(Term(SPEED_Q, use.actor), 0.0, high, use.location)
        within = max(FOLLOWING_LEAST, FOLLOWING_HEADWAY * high)
        following = [
            And(
                (
                    below,
                    Bound(Term(LANE, other, use.actor), 0.0, 0.0, use.location),
                    Bound(Term(POSITION, other, use.actor), 0.0, within, use.location),
                )
            )
            for other in use.actors
            if other != use.actor
        ]
        return Or((reached, *following)) if following else reached


class CarlaPosition(Position):
    """``position(d, ahead_of: x, at: end)``: where the phase's end asks the car to be, which
    CARLA's runner reaches by driving the phase at one speed; the plan holds one speed there
    (``Steady``) unless the end needs a change, and does not adjust it for a later phase."""

    def translate(self, use: Use, phase: Phase) -> None:
        super().translate(use, phase)
        if self.anchor(use.binding) == "end":
            phase.asks.add(Steady())


class CarlaDrive(Drive):
    """``drive()`` as CARLA's examples write it: ``adjust:`` is accepted and, as by CARLA's runner, not used."""

    signature = Signature(
        "drive",
        (Parameter("path", "road", positional=True), DURATION, Parameter("adjust", "bool")),
        description="drive forward for the phase; adjust: is read and not used (CARLA)",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        super().check(binding, context)
        if binding["adjust"] is not None:
            context.warning(
                binding["adjust"].location,
                "drive(adjust: ...) is read but not used: CARLA's runner does not read it either",
                "the drive's modifiers say what it does; remove adjust: to silence this warning",
            )


class CarlaChangeSpeed(Modifier):
    """``change_speed(dv)`` on a drive: the speed gains dv over the phase (``SpeedGain``), set as
    the target at the phase's start and held (the planner's ``gain_target``): CARLA's runner sets
    the car's target speed to the one before plus dv at the phase's start."""

    asks = ASKS_SPEED
    signature = Signature(
        "change_speed",
        (Parameter("speed", "speed", positional=True),),
        required=(("speed",),),
        description="change the speed by the given amount over the phase (CARLA)",
    )

    def translate(self, use: Use, phase: Phase) -> None:
        low, high = widened(*use.range("speed", SPEED, "a change of speed such as 3kph or -10kph"), SPEED_TOLERANCE)
        phase.rates.append(SpeedGain(use.actor, low, high, source=use.location))


class CarlaChangeLane(ChangeLaneModifier):
    """``change_lane(lane_changes: k, side: s)`` on a drive: k lanes (a range: one of them) to the side."""

    count = "lane_changes"
    signature = Signature(
        "change_lane",
        (Parameter("lane_changes", "uint", positional=True), Parameter("side", "enum:side", positional=True)),
        description="change lane_changes lanes to the side during the phase (CARLA)",
    )


class CarlaFollowTrajectory(Modifier):
    """``follow_trajectory(input_file: f, control: c)``: CARLA's runner replays a recorded log, rows
    of world x, y, z and time in one of its towns. Refused where it is written: a log fixes every
    instant of the vehicle in a town's coordinates, which is no constraint to plan around on this
    tool's roads, and the file is not the scenario's to read."""

    signature = Signature(
        "follow_trajectory",
        (Parameter("input_file", "string"), Parameter("control", "string")),
        description="replay a recorded log of world positions (CARLA)",
    )

    def check(self, binding: Binding, context: CheckContext) -> None:
        context.error(
            context.location,
            "not supported: follow_trajectory() replays a recorded log in a CARLA town's world coordinates",
            "say what the log shows with the drive's lane(), speed() and position(), or replay the log in CARLA",
        )

    def translate(self, use: Use, phase: Phase) -> None:
        return None  # never reached: the checker refuses every use


# CARLA's own constructs and arguments, as CARLA's runner reads them, not the standard's declarations
CARLA_OWN = (CarlaDrive(), CarlaChangeSpeed(), CarlaChangeLane(), CarlaFollowTrajectory())
CONSTRUCTS = (CarlaLane(), CarlaSpeed(), CarlaPosition(), *CARLA_OWN)
