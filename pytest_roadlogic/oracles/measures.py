"""What the oracles measure on a trace, with one meaning each (docs/vehicle-under-test.md).

All read a ``Trace`` (the vehicles' centres, headings, speeds and accelerations every ``dt``) and
the shared car box (``simulation.geometry``): a vehicle is *ahead in the path* of another when it
is clear ahead along the road (no overlap along it: that would be a collision) and their boxes
overlap across it (a car halfway through a lane change into the lane is in the path already). A
vehicle is judged by its gap to one ahead only from ``reaction`` seconds after that one entered
its path (a car that cuts in close gives it that long to react). Between such a follower and its
leader:

- the **gap** is bumper to bumper: the centres' distance along the road less a car's length;
- the **time to collision** is the gap over the speed at which the follower closes in, when it
  does (infinite otherwise);
- the **time headway** is that gap over the follower's own speed, judged while it closes in;
- the **deceleration** of a vehicle is minus its acceleration, when it brakes;
- the **post-encroachment time** with a vehicle of another way through a junction (one of the
  ``apart``) is the least time between the two being at places where their boxes, grown by
  ``CONFLICT_MARGIN``, overlap (read in the map's coordinates): how soon one came where the other
  was before, or was to be. Two cars that touch have 0.

Each oracle's measure (``registries.oracles.Oracle.measure``) reads one ``Seen`` and returns the
``Closest`` its oracle judges.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..dimensions import CAR_LENGTH, CAR_WIDTH
from ..simulation.trace import Trace


@dataclass(frozen=True)
class Closest:
    """The least of a measure over a trace, when it was reached, and whom it was measured to."""

    value: float  # math.inf when the measure never applied (no vehicle ahead in the path)
    time: float | None = None
    other: str | None = None


@dataclass(frozen=True)
class Seen:
    """What every measure reads: the trace, the vehicle under test, its gaps to each vehicle ahead
    in its path (``gaps_ahead``), and the sample from which nothing is judged (None: none)."""

    trace: Trace
    vehicle: str
    gaps: dict[str, np.ndarray]
    until: int | None = None
    apart: frozenset[str] = frozenset()  # the vehicles of other routes (other ways through a junction)
    # seconds from the run's start before which it could not yet act (Thresholds.reaction_time)
    reaction: float = 0.0


def in_path(trace: Trace, follower: str, leader: str) -> np.ndarray:
    """Per sample: ``leader`` is clear ahead of ``follower`` along the road and their boxes overlap across it."""
    f, lead = trace.actors[follower], trace.actors[leader]
    return (lead["x"] - f["x"] >= CAR_LENGTH) & (np.abs(lead["y"] - f["y"]) < CAR_WIDTH)


def settled(trace: Trace, inside: np.ndarray, reaction: float) -> np.ndarray:
    """Per sample: ``inside`` has held for at least ``reaction`` seconds (counted from its start)."""
    since = np.full(len(inside), -np.inf)
    entered = None
    for k, now in enumerate(inside):
        if not now:
            entered = None
            continue
        if entered is None:
            entered = trace.times[k]
        since[k] = trace.times[k] - entered
    return since >= reaction - 1e-9


def gaps_ahead(trace: Trace, follower: str, reaction: float = 0.0, until: int | None = None) -> dict[str, np.ndarray]:
    """Per other vehicle: the bumper-to-bumper gap while it is ahead in ``follower``'s path and has
    been for ``reaction`` seconds, inf otherwise; samples from ``until`` on are not judged."""
    f = trace.actors[follower]
    gaps = {}
    for other, columns in trace.actors.items():
        if other == follower:
            continue
        gap = np.maximum(columns["x"] - f["x"] - CAR_LENGTH, 0.0)
        judged = settled(trace, in_path(trace, follower, other), reaction)
        if until is not None:
            judged[until:] = False
        gaps[other] = np.where(judged, gap, np.inf)
    return gaps


def least_gap(seen: Seen) -> Closest:
    """The smallest gap of the vehicle under test to a vehicle ahead in its path."""
    return _least(seen.trace, seen.gaps)


def least_time_to_collision(seen: Seen) -> Closest:
    """The smallest time to collision of the vehicle under test with a vehicle ahead in its path."""
    return _least(seen.trace, _while_closing_in(seen, lambda closing, speed: closing))


def least_time_headway(seen: Seen) -> Closest:
    """The smallest time headway of the vehicle under test while it closes in on a vehicle ahead
    in its path: how near in time it drove up to one (a car that cut in close and draws away
    leaves it a short headway that is the scenario's doing, not its own)."""
    return _least(seen.trace, _while_closing_in(seen, lambda closing, speed: speed))


def _while_closing_in(seen: Seen, per: Callable[[np.ndarray, np.ndarray], np.ndarray]) -> dict[str, np.ndarray]:
    """Per vehicle ahead: the gap to it over ``per(closing speed, own speed)`` where the vehicle
    under test closes in on it, inf elsewhere."""
    speed = seen.trace.actors[seen.vehicle]["speed"]
    ratios = {}
    for other, gap in seen.gaps.items():
        closing = speed - seen.trace.actors[other]["speed"]
        with np.errstate(divide="ignore", invalid="ignore"):
            ratios[other] = np.where((closing > 1e-6) & np.isfinite(gap), gap / per(closing, speed), np.inf)
    return ratios


def greatest_deceleration(seen: Seen) -> Closest:
    """The hardest braking of the vehicle under test (m/s^2, positive), 0 when it never brakes."""
    deceleration = -seen.trace.actors[seen.vehicle]["acceleration"][: seen.until]
    if not len(deceleration):
        return Closest(0.0)
    k = int(np.argmax(deceleration))
    return Closest(max(0.0, float(deceleration[k])), float(seen.trace.times[k]))


CONFLICT_MARGIN = 0.25  # m around each car's box where a post-encroachment time is measured


def least_post_encroachment_time(seen: Seen) -> Closest:
    """The least post-encroachment time of the vehicle under test with a vehicle of another way
    through a junction (inf when none comes where it drives); its time is when the vehicle under
    test was at the place. An encroachment over before ``seen.reaction`` (the second of the two
    cars there earlier than that) is the start the scenario gave it, not its driving."""
    from ..roads.conflicts import touching_pairs

    trace, me = seen.trace, seen.trace.actors[seen.vehicle]
    stop = len(trace.times) if seen.until is None else seen.until
    if not seen.apart or stop == 0 or "world_x" not in me:
        return Closest(math.inf)
    mine = (me["world_x"][:stop], me["world_y"][:stop], me["world_heading"][:stop])
    best = Closest(math.inf)
    for other in sorted(seen.apart):
        them = trace.actors[other]
        i, j = touching_pairs(mine, (them["world_x"], them["world_y"], them["world_heading"]), CONFLICT_MARGIN)
        if not len(i):
            continue
        later = np.maximum(trace.times[i], trace.times[j]) >= seen.reaction - 1e-9
        i, j = i[later], j[later]
        if not len(i):
            continue
        apart_in_time = np.abs(trace.times[i] - trace.times[j])
        k = int(np.argmin(apart_in_time))
        if apart_in_time[k] < best.value:
            best = Closest(float(apart_in_time[k]), float(trace.times[i[k]]), other)
    return best


def _least(trace: Trace, series: dict[str, np.ndarray]) -> Closest:
    best = Closest(math.inf)
    for other, values in series.items():
        if not len(values):
            continue
        k = int(np.argmin(values))
        if values[k] < best.value:
            best = Closest(float(values[k]), float(trace.times[k]), other)
    return best
