"""Constructs of the standard the checker accepts and the automaton does not translate yet (tier 2).

A scenario using one checks (its arguments are validated like any other's), and is refused when
its automaton is built, with "not supported yet by the automaton" at the place of the use. Giving
one a ``translate`` and ``translated = True`` is how it becomes supported.
"""

from __future__ import annotations

from ..frontend.semantics.library import AT, Parameter, Signature
from .base import Modifier


def _pending_modifier(signature: Signature) -> Modifier:
    return type(
        signature.name,
        (Modifier,),
        {"signature": signature, "translated": False, "__doc__": f"``{signature.name}()`` (tier 2)"},
    )()


CONSTRUCTS = (
    _pending_modifier(
        Signature(
            "lateral",
            (
                Parameter("distance", "length", positional=True),
                Parameter("side_of", "actor"),
                Parameter("side", "enum:side"),
                AT,
            ),
            tier=2,
        )
    ),
)
