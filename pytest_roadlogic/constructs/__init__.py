"""The OS2 actions and modifiers this tool knows, one specification each (see ``base``).

``STANDARD`` is the registry the checker uses unless it is given another; ``STANDARD.extended(...)``
makes one with more constructs. To add a construct: write its class (signature, ``check``,
``lanes_needed``, ``translate``) in the module of its family, list it in that module's
``CONSTRUCTS``, and test it; neither the checker nor the automaton changes. A new family is a
module here and its ``CONSTRUCTS`` in ``STANDARD``.
"""

from . import carla, gaps, lanes, motion, position, speed, unsimulated
from .base import Action, AnchoredModifier, CheckContext, Construct, Modifier, Registry, Use
from .lanes import LANE_CONVENTION

# in the order hints list them ("known actions: drive, remain_stationary, ...")
STANDARD = Registry(
    (
        *motion.CONSTRUCTS,
        *lanes.CONSTRUCTS,
        *speed.CONSTRUCTS,
        *position.CONSTRUCTS,
        *gaps.CONSTRUCTS,
        *unsimulated.CONSTRUCTS,
    )
)
CARLA = STANDARD.extended(*carla.CONSTRUCTS, dialect=carla.DIALECT)
# by their names, which settings.DIALECTS lists (the options' values)
DIALECTS = {STANDARD.dialect: STANDARD, CARLA.dialect: CARLA}

__all__ = [
    "Action",
    "AnchoredModifier",
    "CARLA",
    "CheckContext",
    "Construct",
    "DIALECTS",
    "LANE_CONVENTION",
    "Modifier",
    "Registry",
    "STANDARD",
    "Use",
]
