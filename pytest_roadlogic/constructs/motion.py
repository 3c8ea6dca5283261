"""Moving and standing: ``drive()`` and ``remain_stationary()``."""

from __future__ import annotations

from ..automaton.guards import SPEED, Bound, Term
from ..automaton.phase import Phase
from ..frontend.library import DURATION, Parameter, Signature
from ..frontend.tolerances import STANDSTILL
from .base import Action, Use


class Drive(Action):
    """``drive()``: the actor drives forward for the phase; its modifiers say how."""

    # ``drive(path)``: CARLA suites name the road; there is one, so it changes nothing
    signature = Signature("drive", (Parameter("path", "road", positional=True), DURATION), description="drive forward for the phase")

    def translate(self, use: Use, phase: Phase) -> None:
        pass  # forward progress is what a moving phase means (Phase.drives)


class RemainStationary(Action):
    """``remain_stationary()``: the speed stays within the standstill band; no progress asked (``moves``)."""

    signature = Signature("remain_stationary", (DURATION,), description="stand still (obstacles)")
    moves = False

    def translate(self, use: Use, phase: Phase) -> None:
        phase.add(invariant=Bound(Term(SPEED, use.actor), -STANDSTILL, STANDSTILL, use.location))


CONSTRUCTS = (Drive(), RemainStationary())
