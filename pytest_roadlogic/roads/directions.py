"""The two directions of a road: its lanes against the reference line as a road of their own
(``against``), and a road whose oncoming lanes are joined to its own (``with_oncoming``).

A route drives a road's right lanes along its reference line (right-hand traffic). Its left lanes
carry the other direction: read from the road's end, with left and right exchanged, they are the
right lanes of the same road driven the other way, and every stage reads that road as it reads
any. On a road of one lane each way an overtake passes in the oncoming lane: the road with its
oncoming lanes joined has them as its leftmost lanes (``MapRoad.oncoming`` says how many), and its
lanes' edge lies beyond them. Both are data, made of the map's own records (``cubic_records``).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .cubic_records import reversed_records, summed
from .opendrive_in import LaneSection, MapLane, MapRoad
from .route import DRIVING, USABLE_WIDTH


def _mirrored(lanes: tuple[MapLane, ...], length: float) -> tuple[MapLane, ...]:
    """A side's lanes read from the section's other end, on the other side (ids change sign)."""
    return tuple(MapLane(-lane.id, lane.type, reversed_records(lane.widths, length)) for lane in lanes)


def against(road: MapRoad) -> MapRoad:
    """``road`` driven against its reference line: s from its end, its left lanes as its right ones
    (and the other way round), its lane offset on the other side, its links exchanged."""
    length = road.length
    sections = tuple(
        LaneSection(
            length - section.end,
            length - section.s,
            _mirrored(section.left, section.end - section.s),
            _mirrored(section.right, section.end - section.s),
        )
        for section in reversed(road.sections)
    )
    return dataclasses.replace(
        road,
        reference_line=road.reference_line.reversed(),
        sections=sections,
        predecessor=road.successor,
        successor=road.predecessor,
        lane_offset=reversed_records(road.lane_offset, length, sign=-1.0),
        against=not road.against,
        oncoming=0,
    )


def left_hand(road: MapRoad) -> MapRoad:
    """A road of left-hand traffic driven along its reference line, as a route reads any road: its
    left lanes, which carry that direction there, as its right lanes listed from the road's edge
    in (lane 0, the leftmost, by the edge; the last beside the centre line), its lane offset moved
    out to their outer edge (the lane offset plus their widths, up to the outermost driving lane).
    Nothing is mirrored: left and right stay the world's, as a driver there sees them, and the
    lane beside the centre line is the rightmost. No oncoming lanes are joined. Driven against its
    reference line, the road is ``left_hand(against(road))``."""
    sections = []
    widths = [(0.0, road.length, road.lane_offset)]
    for section in road.sections:
        outermost = max((k for k, lane in enumerate(section.left) if lane.type == DRIVING), default=-1)
        kept = section.left[: outermost + 1]
        right = tuple(MapLane(-(k + 1), lane.type, lane.widths) for k, lane in enumerate(reversed(kept)))
        sections.append(LaneSection(section.s, section.end, right))
        widths += [(section.s, section.end, lane.widths) for lane in kept]
    return dataclasses.replace(
        road, sections=tuple(sections), lane_offset=summed(widths, road.length), left_hand=True, oncoming=0
    )


def oncoming_lanes(section: LaneSection) -> int:
    """How many of the section's left lanes, side by side from the reference line, are for driving,
    a car's width wide all along it, and adjoin its first right lane (itself for driving): the
    lanes an overtake may pass in. A median (a lane not for driving) between the directions leaves
    none; a lane that narrows to nothing (a row of parking bays drawn as a driving lane, esmini's
    parking_demo) ends them."""
    if not section.right or section.right[0].type != DRIVING:
        return 0
    along = np.linspace(0.0, section.end - section.s, 65)
    count = 0
    for lane in section.left:
        if lane.type != DRIVING or float(np.min(lane.width(along))) < USABLE_WIDTH:
            break
        count += 1
    return count


def with_oncoming(road: MapRoad) -> MapRoad | None:
    """``road`` with its oncoming lanes joined to its own as its leftmost right lanes (the same
    number in every section, else None: a lane number must mean one lane along the route); their
    outer edge is its lanes' edge (the lane offset plus their widths). None when it has none."""
    counts = {oncoming_lanes(section) for section in road.sections}
    if len(counts) != 1 or 0 in counts:
        return None
    (count,) = counts
    sections = []
    widths = [(0.0, road.length, road.lane_offset)]
    for section in road.sections:
        length = section.end - section.s
        joined = [MapLane(0, lane.type, lane.widths) for lane in reversed(section.left[:count])]
        joined += section.right
        right = tuple(MapLane(-(k + 1), lane.type, lane.widths) for k, lane in enumerate(joined))
        sections.append(LaneSection(section.s, section.end, right, section.left[count:]))
        widths += [(section.s, section.s + length, lane.widths) for lane in section.left[:count]]
    return dataclasses.replace(road, sections=tuple(sections), lane_offset=summed(widths, road.length), oncoming=count)
