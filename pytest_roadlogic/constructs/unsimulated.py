"""Modifiers the standard declares that the simulation does not model: read, warned, not executed.

``yaw()``, ``orientation()`` and ``physical_movement()`` say how a vehicle is turned or how
physically it is moved; the planner plans in road coordinates and the simulation drives every
car with its own motion model, so neither can honour them. A file that uses them (public files
do, on otherwise ordinary drives) is read with one located warning per use instead of being
refused: what it asks of lanes, speeds and positions is still planned and checked. Their
parameters are the standard library's (stdlib/osc/movement.osc), checked as declared.
"""

from __future__ import annotations

from ..frontend.semantics.library import AT, Binding, Parameter, Signature
from ..logic.phase import Phase
from .base import CheckContext, Modifier, Use


class NotSimulated(Modifier):
    """A modifier read for its place in the file only: its use is a warning, its translation nothing."""

    def check(self, binding: Binding, context: CheckContext) -> None:
        context.warning(
            context.location,
            f"{self.name}() is read but not simulated: the simulation does not model it",
            "the rest of the invocation is planned and checked; remove it to silence this warning",
        )

    def translate(self, use: Use, phase: Phase) -> None:
        return None


class Yaw(NotSimulated):
    signature = Signature("yaw", (Parameter("angle", "angle", positional=True), AT), description="heading")


class Orientation(NotSimulated):
    signature = Signature("orientation", (Parameter("yaw", "angle"), AT), description="orientation")


class PhysicalMovement(NotSimulated):
    signature = Signature(
        "physical_movement", (Parameter("option", "string", positional=True),), description="how it is moved"
    )


CONSTRUCTS = (Yaw(), Orientation(), PhysicalMovement())
