"""OpenDRIVE's cubic records (lane widths, the lane offset): evaluated, sampled for the map's
bounds, read from the other end, and added up.

A record holds from its ``offset`` on, to the next record's: a + b du + c du^2 + d du^3 with du
metres from its offset (``LaneWidth``; ``piecewise_cubic`` evaluates a tuple of them). A road
driven against its reference line reads its widths and its offset backwards, and a route whose
lanes begin beyond the oncoming lanes has its lanes' edge at the offset plus their widths: both
are again cubic records, so that everything downstream reads them as it reads the map's own.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class LaneWidth:
    """One width record of a lane: from ``offset`` metres into its section, a + b ds + c ds^2 + d ds^3."""

    offset: float
    a: float
    b: float
    c: float
    d: float


def piecewise_cubic(records: tuple[LaneWidth, ...], u):
    """The value of the records at ``u`` (an array or a number): 0 before the first record."""
    u = np.asarray(u, dtype=float)
    result = np.zeros_like(u)
    for record, end in _stretches(records, math.inf):
        inside = (u >= record.offset - 1e-9) & (u < end)
        du = u - record.offset
        result = np.where(inside, record.a + record.b * du + record.c * du**2 + record.d * du**3, result)
    return result


def sampled_records(records: tuple[LaneWidth, ...], length: float) -> list[np.ndarray]:
    """Each record's values at 9 points over its stretch (from its offset to the next record's, the
    last to ``length``), as the map's bounds on widths and offsets check them."""
    sampled = []
    for record, end in _stretches(records, length):
        u = np.linspace(0.0, max(0.0, end - record.offset), 9)
        with np.errstate(all="ignore"):
            sampled.append(record.a + record.b * u + record.c * u**2 + record.d * u**3)
    return sampled


def _expanded(record: LaneWidth, at: float) -> tuple[float, float, float, float]:
    """The coefficients of ``record``'s cubic around ``at`` metres past its offset (Taylor's
    expansion of a cubic, exact)."""
    x = at
    a = record.a + record.b * x + record.c * x**2 + record.d * x**3
    b = record.b + 2 * record.c * x + 3 * record.d * x**2
    c = record.c + 3 * record.d * x
    return a, b, c, record.d


def _stretches(records: tuple[LaneWidth, ...], length: float):
    """Each record with where it ends: its successor's offset, the last ``length``."""
    for i, record in enumerate(records):
        yield record, (records[i + 1].offset if i + 1 < len(records) else length)


def reversed_records(records: tuple[LaneWidth, ...], length: float, sign: float = 1.0) -> tuple[LaneWidth, ...]:
    """``records`` over 0..``length`` read from ``length`` back to 0: the value at u' is the
    original's at ``length`` - u', times ``sign`` (-1 for a lateral offset, which changes side when
    the direction does). A stretch of no length is dropped; none: none. Before the first record
    the value is 0, and stays so read backwards."""
    result = []
    if records and records[0].offset > 1e-9:
        result.append(LaneWidth(length - records[0].offset, 0.0, 0.0, 0.0, 0.0))
    for record, end in _stretches(records, length):
        span = end - record.offset
        if span <= 1e-9:
            continue
        a, b, c, d = _expanded(record, span)  # the cubic around the stretch's far end
        result.append(LaneWidth(length - end, sign * a, -sign * b, sign * c, -sign * d))
    result.sort(key=lambda record: record.offset)
    return tuple(result)


def summed(parts: list[tuple[float, float, tuple[LaneWidth, ...]]], length: float) -> tuple[LaneWidth, ...]:
    """The sum of several piecewise cubics over 0..``length``, as records: each part is (where its
    records' offsets count from, where it ends, its records), 0 outside them (before its first
    record and from its end on). The sum's records start wherever one of the parts' does or ends."""
    starts = {0.0}
    for start, end, records in parts:
        starts |= {start + record.offset for record in records} | {end}
    result = []
    for s in sorted(x for x in starts if -1e-9 <= x < length - 1e-9):
        total = [0.0, 0.0, 0.0, 0.0]
        for start, end, records in parts:
            if not start - 1e-9 <= s < end - 1e-9:
                continue
            active = None
            for record, stop in _stretches(records, end - start):
                if record.offset <= s - start + 1e-9 and s - start < stop - 1e-9:
                    active = record
            if active is not None:
                for k, value in enumerate(_expanded(active, s - start - active.offset)):
                    total[k] += value
        result.append(LaneWidth(max(0.0, s), *total))
    return tuple(result)
