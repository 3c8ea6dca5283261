"""The OS2 actions and modifiers this tool knows, one specification each (see ``base``).

``STANDARD`` is the registry the checker uses unless it is given another; ``STANDARD.extended(...)``
makes one with more constructs. To add a construct: write its class (signature, ``check``,
``lanes_needed``, ``translate``) in the module of its family, list it in that module's
``CONSTRUCTS`` and below, and test it; neither the checker nor the automaton changes.
"""

from . import lanes, motion, pending, position, speed
from .base import Action, AnchoredModifier, CheckContext, Construct, Modifier, Registry, Use
from .lanes import LANE_CONVENTION

# the order hints list them in ("known actions: drive, change_lane, ...")
_ACTION_ORDER = ("drive", "change_lane", "change_speed", "keep_speed", "follow_lane", "remain_stationary",
                 "keep_space_gap", "keep_time_gap", "change_space_gap", "change_time_gap", "assign_speed")
_MODIFIER_ORDER = ("speed", "position", "lane", "keep_lane", "keep_speed", "change_lane", "acceleration", "lateral")


def _standard() -> Registry:
    constructs = (*motion.CONSTRUCTS, *lanes.CONSTRUCTS, *speed.CONSTRUCTS, *position.CONSTRUCTS, *pending.CONSTRUCTS)
    actions = sorted((c for c in constructs if c.kind == "action"), key=lambda c: _ACTION_ORDER.index(c.name))
    modifiers = sorted((c for c in constructs if c.kind == "modifier"), key=lambda c: _MODIFIER_ORDER.index(c.name))
    return Registry([*actions, *modifiers])


STANDARD = _standard()

__all__ = ["Action", "AnchoredModifier", "CheckContext", "Construct", "LANE_CONVENTION", "Modifier", "Registry", "STANDARD", "Use"]
