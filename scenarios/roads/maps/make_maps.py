"""The project's test maps, written with scenariogeneration (``python scenarios/roads/maps/make_maps.py``).

Each is one road, driven in the direction of its reference line (OpenDRIVE's right lanes, ids -1,
-2, ...), 3.5 m lanes, with an elevation record (ASAM's checker requires one in an
``elevationProfile``):

- ``curved_highway.xodr``: three lanes; 50 m straight, a 100 m clothoid into a 500 m radius left
  curve held for 700 m, a 100 m clothoid out, 300 m straight (1.25 km).
- ``s_curve.xodr``: three lanes, a motorway limited to 100 km/h; 150 m straight, a 250 m arc of
  400 m radius to the left, a 250 m arc of 400 m radius to the right, 350 m straight (1 km).
- ``on_ramp.xodr``: three lanes and an acceleration lane on their right from 150 m to 450 m (the
  ramp's lane: it opens over 50 m and ends, narrowing to nothing, over the last 60 m), 800 m.
- ``lane_drop.xodr``: three lanes, the rightmost ending between 450 m and 530 m, 900 m.
- ``rural_road.xodr``: a country road of one lane each way (3.25 m; its left lane, id 1, carries
  the other direction), 100 km/h; 300 m straight, a 300 m arc of 800 m radius to the right,
  400 m straight (1 km).

The files are committed; run this to write them anew (the test ``test_roads`` checks that they
are what it writes).
"""

from __future__ import annotations

import sys
from pathlib import Path

from scenariogeneration import xodr

from pytest_roadlogic.roads.opendrive_out import write_maps

HERE = Path(__file__).resolve().parent
LANE_WIDTH = 3.5


def _road(geometry, right_lanes, left_lanes=0, lane_width=LANE_WIDTH, center=xodr.RoadMarkType.solid) -> xodr.Road:
    road = xodr.create_road(
        geometry,
        id=1,
        left_lanes=left_lanes,
        right_lanes=right_lanes,
        lane_width=lane_width,
        center_road_mark=xodr.RoadMark(center, 0.12),
    )
    road.add_elevation(0.0, 0.0, 0.0, 0.0, 0.0)
    return road


def _network(name: str, road: xodr.Road) -> xodr.OpenDrive:
    opendrive = xodr.OpenDrive(name)
    opendrive.add_road(road)
    opendrive.adjust_roads_and_lanes()
    return opendrive


def maps() -> dict[str, xodr.OpenDrive]:
    """Every map by file name."""
    radius = 500.0
    curved = [
        xodr.Line(50.0),
        xodr.Spiral(0.0, 1 / radius, 100.0),
        xodr.Arc(1 / radius, 700.0),
        xodr.Spiral(1 / radius, 0.0, 100.0),
        xodr.Line(300.0),
    ]
    s_curve = [xodr.Line(150.0), xodr.Arc(1 / 400.0, 250.0), xodr.Arc(-1 / 400.0, 250.0), xodr.Line(350.0)]
    # the acceleration lane (-4) opens over 150..200 m and closes over 390..450 m
    ramp = [
        xodr.LaneDef(150.0, 200.0, 3, 4, -4),
        xodr.LaneDef(390.0, 450.0, 4, 3, -4),
    ]
    drop = [xodr.LaneDef(450.0, 530.0, 3, 2, -3)]
    rural = [xodr.Line(300.0), xodr.Arc(-1 / 800.0, 300.0), xodr.Line(400.0)]
    return {
        "curved_highway.xodr": _network("pytest-roadlogic curved highway", _road(curved, 3)),
        "s_curve.xodr": _network(
            "pytest-roadlogic s-curve",
            _road(s_curve, 3).add_type(xodr.RoadType.motorway, 0, speed=100, speed_unit="km/h"),
        ),
        "on_ramp.xodr": _network("pytest-roadlogic on-ramp merge", _road([xodr.Line(800.0)], ramp)),
        "lane_drop.xodr": _network("pytest-roadlogic lane drop", _road([xodr.Line(900.0)], drop)),
        "rural_road.xodr": _network(
            "pytest-roadlogic rural road",
            _road(rural, 1, 1, 3.25, xodr.RoadMarkType.broken).add_type(
                xodr.RoadType.rural, 0, speed=100, speed_unit="km/h"
            ),
        ),
    }


def write(directory: Path = HERE) -> list[Path]:
    """Write every map into ``directory``; their paths."""
    return write_maps(maps(), directory)


if __name__ == "__main__":
    for path in write(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(path)
