"""The junction suite's maps, written with scenariogeneration (``python scenarios/junctions/maps/make_maps.py``).

Town streets of one 3.5 m lane each way (OpenDRIVE's lane -1 along the reference line, lane 1
against it), 50 km/h, each arm 200 m long, meeting in a junction whose connecting roads
scenariogeneration builds (clothoid-arc-clothoid turns, both directions of travel in each):

- ``crossing.xodr``: a four-way crossing, its arms at right angles (roads 1 to 4 counter-clockwise,
  road 1 from the west); every turn from every arm (left, straight on, right).
- ``t_junction.xodr``: a T-junction: a through road (roads 1 and 3, west and east) and a side road
  from the south (road 2); every turn.

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


def _junction(name: str, angles: list[float]) -> xodr.OpenDrive:
    """Arms at ``angles`` (radians, counter-clockwise from the west) around one junction, each
    arm's end (its successor) at the junction, every pair of arms connected both ways."""
    creator = xodr.CommonJunctionCreator(100, name)
    arms = []
    for number, angle in enumerate(angles, start=1):
        arm = _arm(number)
        creator.add_incoming_road_circular_geometry(arm, JUNCTION_RADIUS, angle, "successor")
        arms.append(arm)
    for first in range(1, len(angles) + 1):
        for second in range(first + 1, len(angles) + 1):
            creator.add_connection(first, second)
    opendrive = xodr.OpenDrive(f"pytest-roadlogic {name}")
    for arm in arms:
        opendrive.add_road(arm)
    opendrive.add_junction_creator(creator)
    # the connecting roads the creator builds have no elevation record; ASAM's checker requires one
    for road in opendrive.roads.values():
        if not road.elevationprofile.elevations:
            road.add_elevation(0.0, 0.0, 0.0, 0.0, 0.0)
    opendrive.adjust_roads_and_lanes()
    return opendrive


def maps() -> dict[str, xodr.OpenDrive]:
    """Every map by file name."""
    return {
        "crossing.xodr": _junction("crossing", [0.0, math.pi / 2, math.pi, 3 * math.pi / 2]),
        "t_junction.xodr": _junction("t-junction", [0.0, math.pi / 2, math.pi]),
    }


def write(directory: Path = HERE) -> list[Path]:
    """Write every map into ``directory``; their paths."""
    return write_maps(maps(), directory)


if __name__ == "__main__":
    for path in write(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(path)
