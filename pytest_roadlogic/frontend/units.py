"""Physical units of the OS2 standard library, converted to SI on reading.

Everything inside the pipeline is SI (m, s, m/s, m/s^2); a unit names its dimension so that a
speed given where a length is expected is caught with its location.
"""

from __future__ import annotations

LENGTH = "length"
TIME = "time"
SPEED = "speed"
ACCELERATION = "acceleration"

# unit name -> (dimension, factor to SI)
UNITS: dict[str, tuple[str, float]] = {
    "m": (LENGTH, 1.0),
    "meter": (LENGTH, 1.0),
    "km": (LENGTH, 1000.0),
    "cm": (LENGTH, 0.01),
    "s": (TIME, 1.0),
    "sec": (TIME, 1.0),
    "second": (TIME, 1.0),
    "ms": (TIME, 0.001),
    "min": (TIME, 60.0),
    "mps": (SPEED, 1.0),
    "kph": (SPEED, 1 / 3.6),
    "kmph": (SPEED, 1 / 3.6),
    "mph": (SPEED, 0.44704),
    "mpsps": (ACCELERATION, 1.0),
    "mpss": (ACCELERATION, 1.0),
    "kmphps": (ACCELERATION, 1 / 3.6),
    "kphps": (ACCELERATION, 1 / 3.6),
}


def split_physical_literal(text: str) -> tuple[float, str]:
    """Split ``'10m'`` into ``(10.0, 'm')``; the lexer guarantees digits then letters."""
    index = len(text)
    while index > 0 and (text[index - 1].isalpha() or text[index - 1] == "_"):
        index -= 1
    number, unit = text[:index], text[index:]
    # An exponent's 'e' belongs to the number when digits follow it (the lexer kept them together).
    return float(number), unit
