"""How a single value is read: a continuous trace never meets a point exactly.

docs/language.md: a point value in a modifier or a duration stands for a small band around it.
The planner plans inside the band and the monitor checks the band, so both read these numbers.
"""

# a speed as value +- 0.5 m/s, a distance as value +- 1 m (one planning cell)
SPEED_TOLERANCE = 0.5
POSITION_TOLERANCE = 1.0
# a single time headway as value +- 0.2 s (two tenths of the simulation's step)
HEADWAY_TOLERANCE = 0.2
# a single mean acceleration as value +- 0.5 m/s^2 (a speed tolerance per second of phase)
ACCELERATION_TOLERANCE = 0.5
# a single duration as value +- 0.5 s (the planner's time step is 1 s)
DURATION_TOLERANCE = 0.5
# what "standing still" means for a trace's speed, in m/s
STANDSTILL = 0.1


def widened(low: float, high: float, tolerance: float) -> tuple[float, float]:
    """A single value (``low == high``) as the band value +- ``tolerance``; a range as it is."""
    return (low - tolerance, high + tolerance) if low == high else (low, high)
