"""OpenDRIVE in (``read_map``): a ``.xodr`` file's roads, as data, or a located error.

A map comes with a scenario from anywhere (a pull request), so it is read as data and nothing
else: the XML is parsed by expat with no document type declaration allowed (no entity of any
kind, hence no external file read and no entity expansion), and a file over ``MAX_BYTES`` is
refused before it is parsed. Every element keeps its line and column for the messages.

Read: each road's id, name, length, junction, links (predecessor, successor), plan view (line,
arc, spiral, poly3, paramPoly3), lane offset (refused unless zero: the routes here run along the
reference line), lane sections with their right lanes (type, width records) and the speed of its
type records; junctions' ids and names. Left lanes are read for the refusal of a route in them:
routes run in the direction of the reference line (right-hand traffic).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

from .reference_line import Geometry, ReferenceLine

MAX_BYTES = 50_000_000  # a larger file is refused unread
# m: a longer road or geometry is refused (a road is sampled every half metre: a crafted length of
# 1e12 m would be two trillion samples, a hang rather than a message)
MAX_LENGTH = 100_000.0


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

    def start(tag, attributes):
        element = _Element(tag, dict(attributes), parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)
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
class LaneWidth:
    """One width record of a lane: from ``offset`` metres into its section, a + b ds + c ds^2 + d ds^3."""

    offset: float
    a: float
    b: float
    c: float
    d: float


@dataclass(frozen=True)
class MapLane:
    """A lane of a section: its OpenDRIVE id (negative: right of the reference line), its type and widths."""

    id: int
    type: str
    widths: tuple[LaneWidth, ...]

    def width(self, ds):
        """Its width at ``ds`` metres into its section (an array or a number)."""
        import numpy as np

        ds = np.asarray(ds, dtype=float)
        result = np.zeros_like(ds)
        for i, record in enumerate(self.widths):
            end = self.widths[i + 1].offset if i + 1 < len(self.widths) else math.inf
            inside = (ds >= record.offset - 1e-9) & (ds < end)
            u = ds - record.offset
            result = np.where(inside, record.a + record.b * u + record.c * u**2 + record.d * u**3, result)
        return result


@dataclass(frozen=True)
class LaneSection:
    """The lanes from ``s`` to ``end``: right lanes in order -1, -2, ..., and how many left lanes."""

    s: float
    end: float
    right: tuple[MapLane, ...]
    left_lanes: int


@dataclass(frozen=True)
class Link:
    """A road's predecessor or successor: a road or a junction, by id."""

    type: str
    id: str


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

    @property
    def label(self) -> str:
        return f"road {self.id}" + (f" ({self.name!r})" if self.name else "")


@dataclass(frozen=True)
class RoadMap:
    """A map: its file, its roads by id, its junctions' names by id, the file's bytes as read."""

    path: Path
    roads: dict[str, MapRoad]
    junctions: dict[str, str]
    data: bytes = field(default=b"", repr=False, compare=False)


def read_map(path: str | Path) -> RoadMap:
    """The map of the OpenDRIVE file ``path``; ``MapError`` naming the file, line and column when it
    cannot be read."""
    path = Path(path)
    try:
        size = path.stat().st_size
        if size > MAX_BYTES:
            raise MapError(path, f"{size} bytes: a map over {MAX_BYTES} bytes is not read", "give a smaller map")
        text = path.read_bytes()
    except OSError as error:
        raise MapError(path, f"cannot be read: {error.strerror or error}", "check the path") from None
    root = _parse(path, text)
    roads: dict[str, MapRoad] = {}
    for element in root.findall("road"):
        road = _road(path, element)
        if road.id in roads:
            raise MapError(path, f"a second road with id {road.id!r}", "give each road its own id", element.line)
        roads[road.id] = road
    if not roads:
        raise MapError(path, "the map has no road", "give a .xodr file with at least one <road>", root.line)
    junctions = {j.attributes.get("id", ""): j.attributes.get("name", "") for j in root.findall("junction")}
    return RoadMap(path, roads, junctions, text)


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
    geometries = tuple(_geometry(path, g) for g in plan_view.findall("geometry"))
    lanes = element.find("lanes")
    if lanes is None:
        raise MapError(path, "a road without <lanes>", "give its lane sections", element.line, element.column)
    for offset in lanes.findall("laneOffset"):
        if any(_number(path, offset, c, 0.0) for c in "abcd"):
            raise MapError(
                path,
                "not supported: a lane offset (the lanes shifted off the reference line)",
                "use a map whose lanes start at the reference line",
                offset.line,
                offset.column,
            )
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
    )


def _link(link: _Element | None, kind: str) -> Link | None:
    found = link.find(kind) if link is not None else None
    if found is None:
        return None
    return Link(found.attributes.get("elementType", "road"), found.attributes.get("elementId", ""))


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


def _section(path: Path, element: _Element, start: float, end: float) -> LaneSection:
    right = element.find("right")
    left = element.find("left")
    lanes = []
    for lane in right.findall("lane") if right is not None else []:
        widths = tuple(
            LaneWidth(*(_number(path, w, n) for n in ("sOffset", "a", "b", "c", "d"))) for w in lane.findall("width")
        )
        if lane.findall("border"):
            raise MapError(
                path,
                "not supported: a lane given by its border",
                "give its widths (<width>)",
                lane.line,
                lane.column,
            )
        lanes.append(MapLane(int(_number(path, lane, "id")), lane.attributes.get("type", "none"), widths))
    lanes.sort(key=lambda lane: -lane.id)
    if [lane.id for lane in lanes] != list(range(-1, -len(lanes) - 1, -1)):
        raise MapError(
            path, "the right lanes' ids are not -1, -2, ... in turn", "number them from the centre", element.line
        )
    return LaneSection(start, end, tuple(lanes), len(left.findall("lane")) if left is not None else 0)
