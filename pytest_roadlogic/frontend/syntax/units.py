"""Dimensions and how a physical literal is split; the units themselves are the standard library's
(``standard_library.UNITS``, declared in ``stdlib/osc/physical.osc``) and a file's own.

Everything inside the pipeline is SI (m, s, m/s, m/s^2); a unit names its dimension so that a
speed given where a length is expected is caught with its location. The pipeline plans four
dimensions (length, time, speed, acceleration: ``PLANNED``); every other one (an angle, a
temperature) is read, named and checked the same way, and refused only where a value of it would
have to be planned (a modifier's argument, a condition), never where it is declared.
"""

from __future__ import annotations

LENGTH = "length"
TIME = "time"
SPEED = "speed"
ACCELERATION = "acceleration"
# how every stage after the parser writes a value of each dimension: in SI, the unit values are kept in
SI_UNIT = {LENGTH: "m", TIME: "s", SPEED: "m/s", ACCELERATION: "m/s^2", None: ""}
PLANNED = (LENGTH, TIME, SPEED, ACCELERATION)

# the standard's other dimensions by their SI exponents (sorted base -> exponent), named as its
# physical types are; a dimension of none of these is named by its exponents, e.g. "SI(kg: 1, m: 2)"
NAMED: dict[tuple[tuple[str, int], ...], tuple[str, str]] = {
    (("m", 1), ("s", -3)): ("jerk", "m/s^3"),
    (("rad", 1),): ("angle", "rad"),
    (("rad", 1), ("s", -1)): ("angular_rate", "rad/s"),
    (("rad", 1), ("s", -2)): ("angular_acceleration", "rad/s^2"),
    (("kg", 1),): ("mass", "kg"),
    (("K", 1),): ("temperature", "K"),
    (("kg", 1), ("m", -1), ("s", -2)): ("pressure", "Pa"),
    (("cd", 1),): ("luminous_intensity", "cd"),
    (("cd", 1), ("m", -2)): ("illuminance", "lx"),
}
SI_UNIT.update(NAMED.values())

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
    """The name of the dimension with these SI exponents; None for a plain number (no exponent)."""
    powers: dict[str, float] = {}
    for base, exponent in exponents:
        powers[base] = powers.get(base, 0.0) + exponent
    key = tuple(sorted((b, int(e) if float(e).is_integer() else e) for b, e in powers.items() if e != 0))
    if all(base in MODELLED_BASES for base, _ in key) and all(isinstance(e, int) for _, e in key):
        found = dict(key)
        planned = DIMENSIONS.get((found.get("m", 0), found.get("s", 0)), "absent")
        if planned != "absent":
            return planned
    if key in NAMED:
        return NAMED[key][0]
    return "SI(" + ", ".join(f"{b}: {e:g}" for b, e in key) + ")"


def split_physical_literal(text: str) -> tuple[float, str]:
    """Split ``'10m'`` into ``(10.0, 'm')``; the lexer guarantees digits then letters."""
    index = len(text)
    while index > 0 and (text[index - 1].isalpha() or text[index - 1] == "_"):
        index -= 1
    number, unit = text[:index], text[index:]
    # An exponent's 'e' belongs to the number when digits follow it (the lexer kept them together).
    return float(number), unit
