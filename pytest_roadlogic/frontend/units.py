"""Physical units of the OS2 standard library (declared in ``stdlib/osc/physical.osc``), converted to SI on reading.

Everything inside the pipeline is SI (m, s, m/s, m/s^2); a unit names its dimension so that a
speed given where a length is expected is caught with its location.
"""

from __future__ import annotations

from collections.abc import Mapping

from .standard_library import LazyTable

LENGTH = "length"
TIME = "time"
SPEED = "speed"
ACCELERATION = "acceleration"
# how every stage after the parser writes a value of each dimension: in SI, the unit values are kept in
SI_UNIT = {LENGTH: "m", TIME: "s", SPEED: "m/s", ACCELERATION: "m/s^2", None: ""}

# unit name -> (dimension, factor to SI): the modelled units the standard library declares
# (stdlib/osc/physical.osc), read on first use
UNITS: Mapping[str, tuple[str, float]] = LazyTable(lambda library: library.units)


def split_physical_literal(text: str) -> tuple[float, str]:
    """Split ``'10m'`` into ``(10.0, 'm')``; the lexer guarantees digits then letters."""
    index = len(text)
    while index > 0 and (text[index - 1].isalpha() or text[index - 1] == "_"):
        index -= 1
    number, unit = text[:index], text[index:]
    # An exponent's 'e' belongs to the number when digits follow it (the lexer kept them together).
    return float(number), unit
