"""Did the vehicle under test fail? The oracles' verdict on one trace (``judge``).

The monitor says whether the scenario happened; this says whether the vehicle under test
misbehaved while it did: a collision it caused, leaving the road, a time to collision or a gap
to the vehicle ahead in its path below a threshold, braking harder than a threshold. Every value
is kept (``DutReport.values``), failed or not, for reports and case files; ``margin`` is how far
the closest oracle is from failing, what a search for failures steers by.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np

from ..logic.dimensions import CAR_LENGTH, CAR_WIDTH
from ..simulation.trace import Trace
from .measures import Closest, gaps_ahead, greatest_deceleration, least_gap, least_time_to_collision
from .thresholds import Thresholds


@dataclass(frozen=True)
class Collision:
    """A collision of the vehicle under test: when, with whom, how, and whether it caused it
    (it ran into a vehicle ahead, or moved sideways into one beside it)."""

    time: float
    other: str
    how: str
    caused: bool

    def __str__(self) -> str:
        return f"collision with {self.other} at t={self.time:.1f} s: {self.how}"


@dataclass(frozen=True)
class DutReport:
    """The oracles' verdict on the vehicle under test in one trace."""

    vehicle: str
    thresholds: Thresholds
    collisions: tuple[Collision, ...] = ()
    off_road: float | None = None  # when it first left the road
    time_to_collision: Closest = field(default_factory=lambda: Closest(math.inf))
    gap: Closest = field(default_factory=lambda: Closest(math.inf))
    deceleration: Closest = field(default_factory=lambda: Closest(0.0))

    @property
    def failures(self) -> list[str]:
        """Each oracle that failed, as a sentence naming the value, the threshold and when."""
        t = self.thresholds
        found = [str(c) for c in self.collisions if c.caused]
        if self.off_road is not None:
            found.append(f"left the road at t={self.off_road:.1f} s")
        if self.time_to_collision.value < t.min_time_to_collision:
            found.append(
                f"time to collision {self.time_to_collision.value:.2f} s (threshold {t.min_time_to_collision:g} s) "
                f"behind {self.time_to_collision.other} at t={self.time_to_collision.time:.1f} s"
            )
        if self.gap.value < t.min_gap:
            found.append(
                f"gap {self.gap.value:.2f} m (threshold {t.min_gap:g} m) behind {self.gap.other} at t={self.gap.time:.1f} s"
            )
        if self.deceleration.value > t.max_deceleration:
            found.append(
                f"braked at {self.deceleration.value:.2f} m/s^2 (threshold {t.max_deceleration:g} m/s^2) at t={self.deceleration.time:.1f} s"
            )
        return found

    @property
    def failed(self) -> bool:
        return bool(self.failures)

    @property
    def hit_by_others(self) -> list[Collision]:
        """Collisions another vehicle caused: not the vehicle under test's failure, and no run of the scenario either."""
        return [c for c in self.collisions if not c.caused]

    def margin(self) -> float:
        """How far the closest oracle is from failing, each as a fraction of its threshold
        (negative once one fails; -1 for a collision it caused or leaving the road)."""
        if any(c.caused for c in self.collisions) or self.off_road is not None:
            return -1.0
        t = self.thresholds
        margins = [
            _fraction(self.time_to_collision.value, t.min_time_to_collision),
            _fraction(self.gap.value, t.min_gap),
            (t.max_deceleration - self.deceleration.value) / t.max_deceleration,
        ]
        return min(margins)

    def values(self) -> dict[str, object]:
        """Every value measured, for JUnit properties and case files (inf as None)."""

        def number(x: float) -> float | None:
            return None if not math.isfinite(x) else round(x, 3)

        return {
            "vehicle": self.vehicle,
            "min_time_to_collision_s": number(self.time_to_collision.value),
            "min_gap_m": number(self.gap.value),
            "max_deceleration_mps2": number(self.deceleration.value),
            "collisions": [asdict(c) for c in self.collisions],
            "off_road_at_s": self.off_road,
            "thresholds": asdict(self.thresholds),
            "failures": self.failures,
        }


def _fraction(value: float, threshold: float) -> float:
    if not math.isfinite(value):
        return 1.0
    return min(1.0, (value - threshold) / threshold) if threshold > 0 else 1.0


def judge(trace: Trace, vehicle: str, thresholds: Thresholds | None = None) -> DutReport:
    """The oracles' verdict on ``vehicle`` (the vehicle under test) in ``trace``."""
    thresholds = thresholds or Thresholds()
    collisions = tuple(
        _collision(trace, vehicle, next(a for a in incident.actors if a != vehicle), incident.time)
        for incident in trace.incidents
        if incident.kind == "collision" and vehicle in incident.actors
    )
    off_road = next(
        (i.time for i in trace.incidents if i.kind == "off-road" and vehicle in i.actors),
        None,
    )
    # after another vehicle ran into it, what it does is no longer judged: the scenario went wrong
    hit = min((c.time for c in collisions if not c.caused), default=None)
    until = int(np.searchsorted(trace.times, hit - 1e-9)) if hit is not None else None
    gaps = gaps_ahead(trace, vehicle, thresholds.reaction_time, until)
    return DutReport(
        vehicle,
        thresholds,
        collisions,
        off_road,
        least_time_to_collision(trace, vehicle, gaps),
        least_gap(trace, gaps),
        greatest_deceleration(trace, vehicle, until),
    )


def _collision(trace: Trace, vehicle: str, other: str, time: float) -> Collision:
    """Who hit whom: by where ``other`` was relative to ``vehicle`` at the instant of contact (the
    boxes touch on the side along which they overlap least: front or back, else a flank), and, for a
    contact on a flank, which of the two had moved across toward the other in the second before."""
    k = int(np.argmin(np.abs(trace.times - time)))
    me, them = trace.actors[vehicle], trace.actors[other]
    dx, dy = float(them["x"][k] - me["x"][k]), float(them["y"][k] - me["y"][k])
    if CAR_LENGTH - abs(dx) <= CAR_WIDTH - abs(dy):
        if dx > 0:
            return Collision(time, other, f"{vehicle} ran into {other} ahead", True)
        return Collision(time, other, f"{other} ran into {vehicle} from behind", False)
    side = "left" if dy > 0 else "right"
    before = max(0, k - int(round(1.0 / max(float(trace.times[1] - trace.times[0]), 1e-9)))) if len(trace) > 1 else k
    # how far each moved across toward the other in the last second
    mine = (me["y"][k] - me["y"][before]) * np.sign(dy)
    theirs = (them["y"][before] - them["y"][k]) * np.sign(dy)
    if mine > theirs:
        return Collision(time, other, f"{vehicle} moved into {other} on its {side}", True)
    return Collision(time, other, f"{other} moved into {vehicle} from its {side}", False)
