"""The junction suite's maps, written with scenariogeneration (``python scenarios/junctions/maps/make_maps.py``).

Town streets of one 3.5 m lane each way (OpenDRIVE's lane -1 along the reference line, lane 1
against it), 50 km/h, each arm 200 m long, meeting in a junction whose connecting roads
scenariogeneration builds (clothoid-arc-clothoid turns, both directions of travel in each):

- ``crossing.xodr``: a four-way crossing, its arms at right angles (roads 1 to 4 counter-clockwise,
  road 1 from the west); every turn from every arm (left, straight on, right).
- ``t_junction.xodr``: a T-junction: a through road (roads 1 and 3, west and east) and a side road
  from the south (road 2); every turn.
- ``town.xodr``: the two in one street: the crossing (junction 100, roads 1 to 4 as above) and,
  road 3 on from its east, the T-junction (junction 200: road 3 from its west, road 5 from the
  south, road 6 from the east), so that a scenario may leave the junction to the solver.

A turn's radius is about 14 m at the lanes' centres (a car holds it at 19-20 kph at 2 m/s^2 of
lateral acceleration). The files are committed; run this to write them anew (``tests/roads``
checks that they are what it writes).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from scenariogeneration import xodr

from pytest_roadlogic.roads.opendrive_out import write_maps

HERE = Path(__file__).resolve().parent
LANE_WIDTH = 3.5
ARM = 200.0  # m of each road into the junction
JUNCTION_RADIUS = 20.0  # m from the junction's centre to where its arms begin


def _arm(road_id: int) -> xodr.Road:
    road = xodr.create_road(
        xodr.Line(ARM),
        id=road_id,
        left_lanes=1,
        right_lanes=1,
        lane_width=LANE_WIDTH,
        center_road_mark=xodr.RoadMark(xodr.RoadMarkType.broken, 0.12),
    )
    road.add_elevation(0.0, 0.0, 0.0, 0.0, 0.0)
    road.add_type(xodr.RoadType.town, 0, speed=50, speed_unit="km/h")
    return road


def _creator(junction: int, name: str, arms: dict[int, tuple[xodr.Road, float, str]]) -> xodr.CommonJunctionCreator:
    """Junction ``junction`` with its ``arms`` (road id -> the road, its angle in radians
    counter-clockwise from the west, the road's end at the junction: ``successor`` or
    ``predecessor``), every pair of arms connected both ways; its connecting roads numbered from
    the junction's id."""
    creator = xodr.CommonJunctionCreator(junction, name, startnum=junction)
    for road, angle, end in arms.values():
        creator.add_incoming_road_circular_geometry(road, JUNCTION_RADIUS, angle, end)
    ids = sorted(arms)
    for k, first in enumerate(ids):
        for second in ids[k + 1 :]:
            creator.add_connection(first, second)
    return creator


def _opendrive(name: str, roads: list[xodr.Road], creators: list[xodr.CommonJunctionCreator]) -> xodr.OpenDrive:
    opendrive = xodr.OpenDrive(f"pytest-roadlogic {name}")
    for road in roads:
        opendrive.add_road(road)
    for creator in creators:
        opendrive.add_junction_creator(creator)
    # the connecting roads the creator builds have no elevation record; ASAM's checker requires one
    for road in opendrive.roads.values():
        if not road.elevationprofile.elevations:
            road.add_elevation(0.0, 0.0, 0.0, 0.0, 0.0)
    opendrive.adjust_roads_and_lanes()
    return opendrive


def _junction(name: str, angles: list[float]) -> xodr.OpenDrive:
    """Arms at ``angles`` (radians, counter-clockwise from the west) around one junction, each
    arm's end (its successor) at the junction."""
    arms = {number: (_arm(number), angle, "successor") for number, angle in enumerate(angles, start=1)}
    return _opendrive(name, [road for road, _, _ in arms.values()], [_creator(100, name, arms)])


def _town() -> xodr.OpenDrive:
    """The crossing and the T-junction one street apart: road 3 leaves the T-junction westwards
    (its start there) and ends at the crossing."""
    roads = {number: _arm(number) for number in range(1, 7)}
    west, south, east, north = 0.0, math.pi / 2, math.pi, 3 * math.pi / 2
    crossing = {n: (roads[n], angle, "successor") for n, angle in ((1, west), (2, south), (3, east), (4, north))}
    tee = {3: (roads[3], west, "predecessor"), 5: (roads[5], south, "successor"), 6: (roads[6], east, "successor")}
    creators = [_creator(100, "crossing", crossing), _creator(200, "t-junction", tee)]
    return _opendrive("town", list(roads.values()), creators)


def maps() -> dict[str, xodr.OpenDrive]:
    """Every map by file name."""
    return {
        "crossing.xodr": _junction("crossing", [0.0, math.pi / 2, math.pi, 3 * math.pi / 2]),
        "t_junction.xodr": _junction("t-junction", [0.0, math.pi / 2, math.pi]),
        "town.xodr": _town(),
    }


def write(directory: Path = HERE) -> list[Path]:
    """Write every map into ``directory``; their paths."""
    return write_maps(maps(), directory)


if __name__ == "__main__":
    for path in write(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(path)
