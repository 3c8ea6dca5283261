"""Constructs of the standard the checker accepts and the automaton does not translate yet (tier 2).

A scenario using one checks (its arguments are validated like any other's), and is refused when
its automaton is built, with "not supported yet by the automaton" at the place of the use. Giving
one a ``translate`` and ``translated = True`` is how it becomes supported.
"""

from __future__ import annotations

from ..frontend.library import AT, DURATION, Parameter, Signature
from .base import Action, Modifier

GAP_OPTIONS = (Parameter("direction", "enum:direction"), Parameter("reference", "actor"), DURATION)


def _pending_action(name: str, first: Parameter) -> Action:
    signature = Signature(name, (first, *GAP_OPTIONS), tier=2)
    return type(name, (Action,), {"signature": signature, "translated": False, "__doc__": f"``{name}()`` (tier 2)"})()


def _pending_modifier(signature: Signature) -> Modifier:
    return type(signature.name, (Modifier,), {"signature": signature, "translated": False, "__doc__": f"``{signature.name}()`` (tier 2)"})()


CONSTRUCTS = (
    _pending_action("keep_space_gap", Parameter("gap", "length", positional=True)),
    _pending_action("keep_time_gap", Parameter("gap", "time", positional=True)),
    _pending_action("change_space_gap", Parameter("target", "length", positional=True)),
    _pending_action("change_time_gap", Parameter("target", "time", positional=True)),
    _pending_modifier(Signature("lateral", (Parameter("distance", "length", positional=True), Parameter("side_of", "actor"), Parameter("side", "enum:side"), AT), tier=2)),
)
