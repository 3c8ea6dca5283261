"""OpenDRIVE in (``read_map``): a ``.xodr`` file's roads, as data, or a located error.

A map comes with a scenario from anywhere (a pull request), so it is read as data and nothing
else: the XML is parsed by expat with no document type declaration allowed (no entity of any
kind, hence no external file read and no entity expansion), and a file over ``MAX_BYTES`` is
refused before it is parsed. Every element keeps its line and column for the messages.

Read: each road's id, name, length, junction, links (predecessor, successor), plan view (line,
arc, spiral, poly3, paramPoly3), lane offset (the lanes' centre line off the reference line, as
cubic records), lane sections with their right and left lanes (type, width records) and the speed of its
type records; junctions' ids, names and connections.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

from ..confinement import UnreadableFile, read_bounded
from .cubic_records import LaneWidth, piecewise_cubic, sampled_records
from .reference_line import Geometry, ReferenceLine

# What a map may hold (docs/roads.md, "What a map may hold"). A map is data from anywhere: each
# bound keeps the work of reading and sampling it small (seconds, not minutes; megabytes, not
# gigabytes) and keeps what reaches the planner and the simulator inside what they can take. Public
# maps are far inside them (CARLA's Town04: 16 MB, its longest road 1.2 km, radii from 5 m).
MAX_BYTES = 50_000_000  # read, not as stat says: a link to /dev/zero is never read past it
MAX_ELEMENTS = 200_000  # XML elements: past this a map takes minutes to check
MAX_ATTRIBUTE = 1_000  # characters of one attribute's value: a road id of 5,000 digits
# m: a longer road is refused (a road is sampled every quarter metre, and the simulator's frame
# is built over all of it)
MAX_LENGTH = 20_000.0
MAX_TOTAL_LENGTH = 200_000.0  # m of all roads together: what sampling them holds in memory
MAX_GEOMETRIES = 10_000  # plan-view records of one road
MAX_CURVATURE = 0.5  # 1/m: a radius under 2 m is no road (a spiral to 1e6 broke the simulator's frame)
MAX_COORDINATE = 1e7  # m from the map's origin (10,000 km), of any point of a reference line
MAX_LANES = 16  # lanes on one side of one section: 2,000 driving lanes broke the simulator's projection
MAX_LANE_WIDTH = 20.0  # m: wider is no lane, and 1e300 overflows the simulator's projection
# m: a lane not for driving may be wider (esmini's crest-curve has 30 m of verge), not without end
MAX_VERGE_WIDTH = 200.0
DRIVING = "driving"  # the lane type a car drives in


class MapError(Exception):
    """A map that cannot be read or used: the file, where in it (line and column, 0 when the whole
    file), what is wrong and what to do."""

    def __init__(self, path: str | Path, message: str, hint: str = "", line: int = 0, column: int = 0) -> None:
        self.path, self.message, self.hint, self.line, self.column = str(path), message, hint, line, column
        where = f"{self.path}:{line}:{column}" if line else self.path
        super().__init__(f"{where}: {message}" + (f" ({hint})" if hint else ""))


@dataclass
class _Element:
    tag: str
    attributes: dict[str, str]
    line: int
    column: int
    children: list[_Element] = field(default_factory=list)

    def find(self, tag: str) -> _Element | None:
        return next((c for c in self.children if c.tag == tag), None)

    def findall(self, tag: str) -> list[_Element]:
        return [c for c in self.children if c.tag == tag]


def _parse(path: Path, text: bytes) -> _Element:
    parser = expat.ParserCreate()
    stack: list[_Element] = []
    root: list[_Element] = []

    def doctype(*_):
        raise MapError(
            path,
            "a document type declaration (<!DOCTYPE ...>) is not read",
            "OpenDRIVE needs none; remove it (entities could read other files)",
            parser.CurrentLineNumber,
            parser.CurrentColumnNumber + 1,
        )

    count = [0]

    def start(tag, attributes):
        count[0] += 1
        where = (parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)
        if count[0] > MAX_ELEMENTS:
            raise MapError(path, f"more than {MAX_ELEMENTS:,} elements", "give a smaller map", *where)
        for name, value in attributes.items():
            if len(value) > MAX_ATTRIBUTE or len(name) > MAX_ATTRIBUTE:
                raise MapError(
                    path,
                    f"<{tag[:40]}> has an attribute of more than {MAX_ATTRIBUTE:,} characters",
                    "shorten it",
                    *where,
                )
        element = _Element(tag, dict(attributes), *where)
        (stack[-1].children if stack else root).append(element)
        stack.append(element)

    def end(_tag):
        stack.pop()

    parser.StartDoctypeDeclHandler = doctype
    parser.EntityDeclHandler = doctype
    parser.StartElementHandler = start
    parser.EndElementHandler = end
    try:
        parser.Parse(text, True)
    except expat.ExpatError as error:
        raise MapError(
            path, f"not well-formed XML: {expat.ErrorString(error.code)}", "", error.lineno, error.offset + 1
        ) from None
    if not root or root[0].tag != "OpenDRIVE":
        raise MapError(path, "not an OpenDRIVE file: its root element is not <OpenDRIVE>", "give a .xodr file", 1, 1)
    return root[0]


@dataclass(frozen=True)
class MapLane:
    """A lane of a section: its OpenDRIVE id (negative: right of the reference line), its type and widths."""

    id: int
    type: str
    widths: tuple[LaneWidth, ...]

    def width(self, ds):
        """Its width at ``ds`` metres into its section (an array or a number)."""
        return piecewise_cubic(self.widths, ds)


@dataclass(frozen=True)
class LaneSection:
    """The lanes from ``s`` to ``end``: right lanes in order -1, -2, ..., left lanes 1, 2, ..."""

    s: float
    end: float
    right: tuple[MapLane, ...]
    left: tuple[MapLane, ...] = ()


@dataclass(frozen=True)
class Link:
    """A road's predecessor or successor: a road or a junction, by id; a road's ``contact``: its
    end (start or end) that touches this one."""

    type: str
    id: str
    contact: str = ""


@dataclass(frozen=True)
class Connection:
    """A junction's way from its incoming road into a connecting road (a road inside the junction),
    entered at the connecting road's ``contact`` (start or end)."""

    incoming: str
    connecting: str
    contact: str


@dataclass(frozen=True)
class MapRoad:
    """One road of a map: where it is in the file (line), its reference line and lane sections."""

    id: str
    name: str
    length: float
    junction: str
    line: int
    reference_line: ReferenceLine
    sections: tuple[LaneSection, ...]
    predecessor: Link | None
    successor: Link | None
    speed_limit: float | None  # m/s, the least of its type records' speeds; None: the map gives none
    # the lane offset: metres left of the reference line at which its lanes begin, by records from
    # their s on (none: the reference line)
    lane_offset: tuple[LaneWidth, ...] = ()
    # its traffic rule: RHT (right-hand traffic, OpenDRIVE's default) or LHT
    rule: str = "RHT"
    # read against its reference line (``directions.against``): s from its end, its left lanes as right
    against: bool = False
    # its first right lanes that carry the other direction's traffic (``directions.with_oncoming``)
    oncoming: int = 0
    # a road of left-hand traffic as a route drives it: its left lanes as right ones, from the
    # road's edge in (``directions.left_hand``)
    left_hand: bool = False
    # roads one after another (``chains.chained``): their labels, in order; () for a road of the map
    chain: tuple[str, ...] = ()

    def offset(self, s):
        """The lane offset at ``s`` metres along the road (an array or a number)."""
        return piecewise_cubic(self.lane_offset, s)

    @property
    def label(self) -> str:
        if len(self.chain) > 3:
            return f"roads: {self.chain[0]}, then {len(self.chain) - 2} more, then {self.chain[-1]}"
        if self.chain:
            return "roads: " + ", then ".join(self.chain)
        return (
            f"road {self.id}"
            + (f" ({self.name!r})" if self.name else "")
            + (" against its reference line" if self.against else "")
        )


@dataclass(frozen=True)
class RoadMap:
    """A map: its file, its roads by id, its junctions' names by id, the file's bytes as read, and
    each junction's connections."""

    path: Path
    roads: dict[str, MapRoad]
    junctions: dict[str, str]
    data: bytes = field(default=b"", repr=False, compare=False)
    connections: dict[str, tuple[Connection, ...]] = field(default_factory=dict, compare=False)


def read_map(path: str | Path) -> RoadMap:
    """The map of the OpenDRIVE file ``path``; ``MapError`` naming the file, line and column when it
    cannot be read."""
    path = Path(path)
    try:
        text = read_bounded(path, MAX_BYTES)
    except UnreadableFile as error:
        raise MapError(
            path, f"cannot be read: {error}", "give a smaller map" if error.too_large else "give an OpenDRIVE file"
        ) from None
    root = _parse(path, text)
    roads: dict[str, MapRoad] = {}
    total = 0.0
    for element in root.findall("road"):
        road = _road(path, element)
        if road.id in roads:
            raise MapError(path, f"a second road with id {road.id!r}", "give each road its own id", element.line)
        total += road.length
        if total > MAX_TOTAL_LENGTH:
            raise MapError(
                path,
                f"the roads up to {road.label} are {total:g} m long together, more than {MAX_TOTAL_LENGTH:g} m",
                "give a map of the part of the network the scenario needs",
                element.line,
                element.column,
            )
        roads[road.id] = road
    if not roads:
        raise MapError(path, "the map has no road", "give a .xodr file with at least one <road>", root.line)
    junctions = {j.attributes.get("id", ""): j.attributes.get("name", "") for j in root.findall("junction")}
    connections = {
        j.attributes.get("id", ""): tuple(
            Connection(
                c.attributes.get("incomingRoad", ""),
                c.attributes.get("connectingRoad", ""),
                c.attributes.get("contactPoint", "start"),
            )
            for c in j.findall("connection")
        )
        for j in root.findall("junction")
    }
    return RoadMap(path, roads, junctions, text, connections)


def _number(path: Path, element: _Element, name: str, default: float | None = None) -> float:
    text = element.attributes.get(name)
    if text is None:
        if default is not None:
            return default
        raise MapError(path, f"<{element.tag}> has no {name}", f"give {name}=...", element.line, element.column)
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise MapError(
            path,
            f"<{element.tag}> {name}={text!r} is not a number",
            "give a finite number",
            element.line,
            element.column,
        )
    return value


def _road(path: Path, element: _Element) -> MapRoad:
    length = _number(path, element, "length")
    if not 0 < length <= MAX_LENGTH:
        raise MapError(
            path, f"a road {length:g} m long", f"a road is 0 to {MAX_LENGTH:g} m long", element.line, element.column
        )
    plan_view = element.find("planView")
    if plan_view is None or not plan_view.findall("geometry"):
        raise MapError(path, "a road without a planView geometry", "give its reference line", element.line)
    records = plan_view.findall("geometry")
    if len(records) > MAX_GEOMETRIES:
        raise MapError(
            path, f"a road of more than {MAX_GEOMETRIES:,} geometries", "give fewer", plan_view.line, plan_view.column
        )
    geometries = tuple(_geometry(path, g) for g in records)
    for geometry, record in zip(geometries, records):
        if geometry.s < -0.01 or geometry.s + geometry.length > length + max(1.0, 0.01 * length):
            raise MapError(
                path,
                f"a geometry from s={geometry.s:g} m over {geometry.length:g} m runs outside its road of {length:g} m",
                "give geometries that lie along the road's length",
                record.line,
                record.column,
            )
    _check_reference_line(path, records, geometries)
    lanes = element.find("lanes")
    if lanes is None:
        raise MapError(path, "a road without <lanes>", "give its lane sections", element.line, element.column)
    lane_offset = _lane_offset(path, lanes.findall("laneOffset"), length)
    starts = [_number(path, s, "s") for s in lanes.findall("laneSection")]
    if not starts:
        raise MapError(path, "a road without a lane section", "give one", lanes.line, lanes.column)
    sections = tuple(
        _section(path, s, start, end)
        for s, start, end in zip(lanes.findall("laneSection"), starts, [*starts[1:], length])
    )
    link = element.find("link")
    types = element.findall("type")
    speeds = [_speed(path, t) for t in types]
    speeds = [s for s in speeds if s is not None]
    return MapRoad(
        element.attributes.get("id", ""),
        element.attributes.get("name", ""),
        length,
        element.attributes.get("junction", "-1"),
        element.line,
        ReferenceLine(geometries),
        sections,
        _link(link, "predecessor"),
        _link(link, "successor"),
        min(speeds) if speeds else None,
        lane_offset,
        "LHT" if element.attributes.get("rule", "RHT").upper() == "LHT" else "RHT",
    )


def _lane_offset(path: Path, records: list[_Element], length: float) -> tuple[LaneWidth, ...]:
    """A road's lane offset records, in order of s; ``MapError`` at one that moves the lanes more
    than ``MAX_LANE_WIDTH`` times ``MAX_LANES`` off the reference line (no real road's lanes lie
    so far from it) or is not finite."""
    import numpy as np

    offsets = sorted(
        ((LaneWidth(*(_number(path, r, n, 0.0) for n in ("s", "a", "b", "c", "d"))), r) for r in records),
        key=lambda item: item[0].offset,
    )
    most = MAX_LANE_WIDTH * MAX_LANES
    for (_, element), value in zip(offsets, sampled_records(tuple(record for record, _ in offsets), length)):
        if not np.all(np.isfinite(value)) or np.max(np.abs(value)) > most:
            raise MapError(
                path,
                f"a lane offset that moves the lanes {np.max(np.abs(value)):g} m off the reference line",
                f"give a lane offset within {most:g} m",
                element.line,
                element.column,
            )
    if not any(record.a or record.b or record.c or record.d for record, _ in offsets):
        return ()  # all zero: the reference line
    return tuple(record for record, _ in offsets)


def _check_reference_line(path: Path, records: list[_Element], geometries: tuple[Geometry, ...]) -> None:
    """``MapError`` at the geometry whose line leaves the map's extent, is not finite, or bends
    tighter than ``MAX_CURVATURE``: what the simulator's frame and the plot cannot take."""
    import numpy as np

    for geometry, record in zip(geometries, records):
        where = (record.line, record.column)
        bends = {"arc": (geometry.curvature,), "spiral": (geometry.curvature_start, geometry.curvature_end)}
        if any(abs(k) > MAX_CURVATURE for k in bends.get(geometry.kind, ())):
            raise MapError(
                path,
                f"a {geometry.kind} of curvature up to {max(abs(k) for k in bends[geometry.kind]):g} 1/m",
                f"a road's curvature is at most {MAX_CURVATURE:g} 1/m (a radius of {1 / MAX_CURVATURE:g} m)",
                *where,
            )
        with np.errstate(all="ignore"):
            x, y, heading, curvature = geometry.sample(np.linspace(0.0, geometry.length, 64))
        values = np.concatenate([x, y, heading, curvature])
        if not np.all(np.isfinite(values)) or np.max(np.abs(np.concatenate([x, y]))) > MAX_COORDINATE:
            raise MapError(
                path,
                f"the {geometry.kind} leaves the map's extent (a point not finite or over {MAX_COORDINATE:g} m out)",
                "check its coefficients",
                *where,
            )
        if geometry.kind in ("poly3", "param_poly3") and np.max(np.abs(curvature)) > MAX_CURVATURE:
            raise MapError(
                path,
                f"a {geometry.kind} that bends at a curvature of {np.max(np.abs(curvature)):g} 1/m",
                f"a road's curvature is at most {MAX_CURVATURE:g} 1/m (a radius of {1 / MAX_CURVATURE:g} m)",
                *where,
            )


def _link(link: _Element | None, kind: str) -> Link | None:
    found = link.find(kind) if link is not None else None
    if found is None:
        return None
    return Link(
        found.attributes.get("elementType", "road"),
        found.attributes.get("elementId", ""),
        found.attributes.get("contactPoint", ""),
    )


_SPEED_UNITS = {"m/s": 1.0, "km/h": 1 / 3.6, "mph": 0.44704}


def _speed(path: Path, road_type: _Element) -> float | None:
    speed = road_type.find("speed")
    if speed is None or speed.attributes.get("max") in (None, "no limit", "undefined"):
        return None
    unit = speed.attributes.get("unit", "m/s")
    if unit not in _SPEED_UNITS:
        raise MapError(path, f"unknown speed unit {unit!r}", "m/s, km/h or mph", speed.line, speed.column)
    return _number(path, speed, "max") * _SPEED_UNITS[unit]


def _geometry(path: Path, element: _Element) -> Geometry:
    common = dict(
        s=_number(path, element, "s"),
        x=_number(path, element, "x"),
        y=_number(path, element, "y"),
        heading=_number(path, element, "hdg"),
        length=_number(path, element, "length"),
    )
    if not 0 < common["length"] <= MAX_LENGTH:
        raise MapError(
            path,
            f"a geometry {common['length']:g} m long",
            f"give a length above 0 and at most {MAX_LENGTH:g} m",
            element.line,
            element.column,
        )
    shape = element.children[0] if element.children else None
    kind = shape.tag if shape is not None else ""
    if kind == "line":
        return Geometry(**common, kind="line")
    if kind == "arc":
        return Geometry(**common, kind="arc", curvature=_number(path, shape, "curvature"))
    if kind == "spiral":
        return Geometry(
            **common,
            kind="spiral",
            curvature_start=_number(path, shape, "curvStart"),
            curvature_end=_number(path, shape, "curvEnd"),
        )
    if kind == "poly3":
        return Geometry(**common, kind="poly3", poly=tuple(_number(path, shape, c) for c in "abcd"))
    if kind == "paramPoly3":
        return Geometry(
            **common,
            kind="param_poly3",
            u=tuple(_number(path, shape, f"{c}U") for c in "abcd"),
            v=tuple(_number(path, shape, f"{c}V") for c in "abcd"),
            normalized=shape.attributes.get("pRange", "normalized") != "arcLength",
        )
    raise MapError(
        path,
        f"unknown plan view geometry <{kind or 'nothing'}>",
        "line, arc, spiral, poly3 or paramPoly3",
        element.line,
        element.column,
    )


def _check_widths(path: Path, lane: _Element, widths: tuple[LaneWidth, ...], length: float) -> str:
    """The lane's type as read (a driving lane never 0.5 m wide in its section is none there);
    ``MapError`` at a driving lane with no width, or at a width record whose cubic leaves
    0..``MAX_LANE_WIDTH`` (a lane not for driving: ``MAX_VERGE_WIDTH``) over its stretch: the map is at fault, and is named, not the scenario
    reported without a plan)."""
    import numpy as np

    kind = lane.attributes.get("type", "none")
    if not widths:
        if kind == DRIVING:
            raise MapError(path, "a driving lane without <width>", "give its widths", lane.line, lane.column)
        return kind
    records = lane.findall("width")
    widest = MAX_LANE_WIDTH if kind == DRIVING else MAX_VERGE_WIDTH
    most = 0.0
    for element, width in zip(records, sampled_records(widths, length)):
        if not np.all(np.isfinite(width)) or np.min(width) < -1e-6 or np.max(width) > widest:
            raise MapError(
                path,
                f"lane {lane.attributes.get('id', '?')[:20]}'s width runs outside 0..{widest:g} m "
                f"(from {np.min(width):g} to {np.max(width):g} m)",
                "give a lane's width in metres, 0 where it begins or ends",
                element.line,
                element.column,
            )
        most = max(most, float(np.max(width)))
    if kind == DRIVING and most < 0.5:
        # no car fits: a lane that exists in other sections of its road is written so in this one
        # (esmini's tunnels): it is no lane for driving here
        return "none"
    return kind


def _section(path: Path, element: _Element, start: float, end: float) -> LaneSection:
    right = element.find("right")
    left = element.find("left")
    for side in (right, left):
        if side is not None and len(side.findall("lane")) > MAX_LANES:
            raise MapError(
                path, f"more than {MAX_LANES} lanes on one side", "give a map of real roads", side.line, side.column
            )
    return LaneSection(start, end, _side(path, right, end - start, -1), _side(path, left, end - start, 1))


def _side(path: Path, side: _Element | None, length: float, sign: int) -> tuple[MapLane, ...]:
    """A section's lanes on one side (``sign`` -1: right, 1: left), in order from the reference line
    outward; ``MapError`` at a lane given by its border or at ids not numbered in turn."""
    lanes = []
    for lane in side.findall("lane") if side is not None else []:
        widths = tuple(
            LaneWidth(*(_number(path, w, n) for n in ("sOffset", "a", "b", "c", "d"))) for w in lane.findall("width")
        )
        kind = _check_widths(path, lane, widths, length)
        if lane.findall("border"):
            raise MapError(
                path,
                "not supported: a lane given by its border",
                "give its widths (<width>)",
                lane.line,
                lane.column,
            )
        lanes.append(MapLane(int(_number(path, lane, "id")), kind, widths))
    lanes.sort(key=lambda lane: sign * lane.id)
    if [lane.id for lane in lanes] != [sign * k for k in range(1, len(lanes) + 1)]:
        name = "right" if sign < 0 else "left"
        numbers = "-1, -2" if sign < 0 else "1, 2"
        raise MapError(
            path,
            f"the {name} lanes' ids are not {numbers}, ... in turn",
            "number them from the centre",
            side.line,
            side.column,
        )
    return tuple(lanes)
