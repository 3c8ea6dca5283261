"""The dimensions the pipeline models and how a physical literal is split; the units themselves are
the standard library's (``standard_library.UNITS``, declared in ``stdlib/osc/physical.osc``).

Everything inside the pipeline is SI (m, s, m/s, m/s^2); a unit names its dimension so that a
speed given where a length is expected is caught with its location.
"""

from __future__ import annotations

LENGTH = "length"
TIME = "time"
SPEED = "speed"
ACCELERATION = "acceleration"
# how every stage after the parser writes a value of each dimension: in SI, the unit values are kept in
SI_UNIT = {LENGTH: "m", TIME: "s", SPEED: "m/s", ACCELERATION: "m/s^2", None: ""}

# dimension -> exponents of (metre, second), and back
EXPONENTS: dict[str | None, tuple[int, int]] = {
    None: (0, 0),
    LENGTH: (1, 0),
    TIME: (0, 1),
    SPEED: (1, -1),
    ACCELERATION: (1, -2),
}
DIMENSIONS = {v: k for k, v in EXPONENTS.items()}
MODELLED_BASES = ("m", "s")


def dimension_of(exponents: tuple[tuple[str, float], ...]) -> str | None:
    """The dimension with these SI exponents, or None when the pipeline does not model it."""
    powers = {base: 0.0 for base in MODELLED_BASES}
    for base, exponent in exponents:
        if base not in MODELLED_BASES:
            if exponent != 0:
                return None
            continue
        powers[base] += exponent
    key = (powers["m"], powers["s"])
    if not all(float(p).is_integer() for p in key):
        return None
    return DIMENSIONS.get((int(key[0]), int(key[1])))


def split_physical_literal(text: str) -> tuple[float, str]:
    """Split ``'10m'`` into ``(10.0, 'm')``; the lexer guarantees digits then letters."""
    index = len(text)
    while index > 0 and (text[index - 1].isalpha() or text[index - 1] == "_"):
        index -= 1
    number, unit = text[:index], text[index:]
    # An exponent's 'e' belongs to the number when digits follow it (the lexer kept them together).
    return float(number), unit
