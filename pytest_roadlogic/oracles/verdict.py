"""Did the vehicle under test fail? The oracles' verdict on one trace (``judge``).

The monitor says whether the scenario happened; this says whether the vehicle under test
misbehaved while it did: a collision it caused, leaving the road, or any oracle of the registry
(``registries.oracles.ORACLES``: time to collision, gap, braking) past its threshold. Every value
is kept (``DutReport.values``), failed or not, for reports and case files; ``margin`` is how far
the closest oracle is from failing, what a search for failures steers by.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import asdict, dataclass, field

import numpy as np

from ..dimensions import CAR_LENGTH, CAR_WIDTH
from ..registries.oracles import ORACLES, Oracle
from ..simulation.trace import Trace
from . import measures
from .measures import Closest, Seen, gaps_ahead
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
    """The oracles' verdict on the vehicle under test in one trace: its collisions, when it left
    the road, and each oracle's measured value by the oracle's name (``registries.oracles``)."""

    vehicle: str
    thresholds: Thresholds
    collisions: tuple[Collision, ...] = ()
    off_road: float | None = None  # when it first left the road
    measured: Mapping[str, Closest] = field(default_factory=dict)  # an oracle missing: it never applied

    def value(self, oracle: Oracle) -> Closest:
        """What ``oracle`` measured (its never-failing value where it never applied)."""
        return self.measured.get(oracle.name) or Closest(oracle.never)

    @property
    def failures(self) -> list[str]:
        """Each oracle that failed, as a sentence naming the value, the threshold and when."""
        found = [str(c) for c in self.collisions if c.caused]
        if self.off_road is not None:
            found.append(f"left the road at t={self.off_road:.1f} s")
        for oracle in ORACLES:
            closest, threshold = self.value(oracle), self.thresholds[oracle.name]
            if oracle.fails(closest.value, threshold):
                found.append(
                    oracle.failure.format(
                        value=closest.value, threshold=threshold, other=closest.other, time=closest.time
                    )
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
        return min(oracle.margin(self.value(oracle).value, self.thresholds[oracle.name]) for oracle in ORACLES)

    def values(self) -> dict[str, object]:
        """Every value measured, for JUnit properties and case files (inf as None), each oracle's
        under its ``Oracle.value_key``."""

        def number(x: float) -> float | None:
            return None if not math.isfinite(x) else round(x, 3)

        return {
            "vehicle": self.vehicle,
            **{oracle.value_key: number(self.value(oracle).value) for oracle in ORACLES},
            "collisions": [asdict(c) for c in self.collisions],
            "off_road_at_s": self.off_road,
            "thresholds": self.thresholds.by_key(),
            "failures": self.failures,
        }


def judge(
    trace: Trace, vehicle: str, thresholds: Thresholds | None = None, apart: frozenset[str] = frozenset()
) -> DutReport:
    """The oracles' verdict on ``vehicle`` (the vehicle under test) in ``trace``. ``apart``: the
    vehicles of other routes of the map than its own (different ways through a junction), never
    in its path by road coordinates (a route's own); a collision with one is judged in the map's."""
    thresholds = thresholds or Thresholds()
    collisions = tuple(
        _collision(trace, vehicle, other, incident.time, other in apart)
        for incident in trace.incidents
        if incident.kind == "collision" and vehicle in incident.actors
        for other in [next(a for a in incident.actors if a != vehicle)]
    )
    off_road = next(
        (i.time for i in trace.incidents if i.kind == "off-road" and vehicle in i.actors),
        None,
    )
    # after another vehicle ran into it, what it does is no longer judged: the scenario went wrong
    hit = min((c.time for c in collisions if not c.caused), default=None)
    until = int(np.searchsorted(trace.times, hit - 1e-9)) if hit is not None else None
    gaps = {o: g for o, g in gaps_ahead(trace, vehicle, thresholds.reaction_time, until).items() if o not in apart}
    seen = Seen(trace, vehicle, gaps, until, apart, thresholds.reaction_time)
    return DutReport(
        vehicle,
        thresholds,
        collisions,
        off_road,
        {oracle.name: getattr(measures, oracle.measure)(seen) for oracle in ORACLES},
    )


# m/s below which a vehicle stands (waiting to give way)
STANDING = 0.5


def _collision(trace: Trace, vehicle: str, other: str, time: float, in_world: bool = False) -> Collision:
    """Who hit whom: by where ``other`` was relative to ``vehicle`` at the instant of contact (the
    boxes touch on the side along which they overlap least: front or back, else a flank), and, for a
    contact on a flank, which of the two had moved across toward the other in the second before.
    ``in_world``: ``other`` drives another route; where it was is read in the map's coordinates,
    turned to ``vehicle``'s heading, and a contact on a flank is ``vehicle``'s failure to give way
    unless it stood."""
    k = int(np.argmin(np.abs(trace.times - time)))
    me, them = trace.actors[vehicle], trace.actors[other]
    if in_world:
        ex, ey = float(them["world_x"][k] - me["world_x"][k]), float(them["world_y"][k] - me["world_y"][k])
        heading = float(me["world_heading"][k])
        dx = ex * np.cos(heading) + ey * np.sin(heading)
        dy = -ex * np.sin(heading) + ey * np.cos(heading)
    else:
        dx, dy = float(them["x"][k] - me["x"][k]), float(them["y"][k] - me["y"][k])
    if CAR_LENGTH - abs(dx) <= CAR_WIDTH - abs(dy):
        if dx > 0:
            return Collision(time, other, f"{vehicle} ran into {other} ahead", True)
        return Collision(time, other, f"{other} ran into {vehicle} from behind", False)
    side = "left" if dy > 0 else "right"
    if in_world:
        # two ways crossing at a junction without signs or signals: the vehicle under test gives
        # way to the car whose way crosses its own (the gap-acceptance rule its reference drivers
        # keep), so a contact on a flank is its failure to, unless it stood waiting
        if abs(float(me["speed"][k])) < STANDING:
            return Collision(time, other, f"{other} ran into {vehicle} standing, from its {side}", False)
        return Collision(time, other, f"{vehicle} did not give way to {other}, which came from its {side}", True)
    before = max(0, k - int(round(1.0 / max(float(trace.times[1] - trace.times[0]), 1e-9)))) if len(trace) > 1 else k
    # how far each moved across toward the other in the last second
    mine = (me["y"][k] - me["y"][before]) * np.sign(dy)
    theirs = (them["y"][before] - them["y"][k]) * np.sign(dy)
    if mine > theirs:
        return Collision(time, other, f"{vehicle} moved into {other} on its {side}", True)
    return Collision(time, other, f"{other} moved into {vehicle} from its {side}", False)
