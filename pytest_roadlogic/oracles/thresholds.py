"""Where the oracles fail: plain data, read by the run settings without loading numpy."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Thresholds:
    """Where an oracle fails: below ``min_time_to_collision`` (s) or ``min_gap`` (m, bumper to
        bumper) to the vehicle ahead in the path (from ``reaction_time`` after it entered the path),
    above ``max_deceleration`` (m/s^2). Options
        ``--roadlogic-min-ttc``, ``--roadlogic-min-gap``, ``--roadlogic-max-decel`` (and ini keys)."""

    min_time_to_collision: float = 1.5
    min_gap: float = 2.0
    max_deceleration: float = 8.0
    # s after a vehicle enters the path of the one under test before its gap to it is judged: a
    # car that cuts in close is the scenario's doing, what the vehicle under test does next its own
    reaction_time: float = 1.0
