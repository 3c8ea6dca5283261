"""Hostile OpenDRIVE maps get a located error, under a time and a memory bound, never a traceback.

A map comes with a scenario from anywhere (a pull request). Each crafted map below was seen to hang,
to exhaust memory, to crash the simulator or to blame the scenario before the map's bounds
(``roads.opendrive_in``, documented in docs/roads.md) were checked when it is read. The fuzz test
mutates the shipped maps: any mutation is read, or refused with its line, within the bounds.
"""

from __future__ import annotations

import os
import re
import resource
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pytest_roadlogic.roads.choice import pick_route
from pytest_roadlogic.roads.opendrive_in import MapError, read_map
from tests.roads.map_files import MAPS

SECONDS = 10.0  # guards a hang, not a speed: a crafted map is refused in milliseconds
MEGABYTES = 500


def road(geometries: str, lanes: str, length: float = 1000.0, road_id: str = "1") -> str:
    return (
        "<?xml version='1.0'?>\n<OpenDRIVE>\n<header revMajor='1' revMinor='5'/>\n"
        f"<road id='{road_id}' junction='-1' length='{length}'>\n<planView>\n{geometries}</planView>\n"
        f"<lanes><laneSection s='0'><right>\n{lanes}</right></laneSection></lanes>\n</road>\n</OpenDRIVE>\n"
    )


def lane(number: int, width: str = "<width sOffset='0' a='3.5' b='0' c='0' d='0'/>") -> str:
    return f"<lane id='-{number}' type='driving'>{width}</lane>\n"


LINE = "<geometry s='0' x='0' y='0' hdg='0' length='{length}'><line/></geometry>\n"
TWO_LANES = lane(1) + lane(2)

CRAFTED = {
    "sixty geometries of 100 km": (
        road("".join(LINE.format(length=1e5) for _ in range(60)), TWO_LANES, 1e5),
        "runs outside its road|road 100000 m long",
    ),
    "a legal straight road of 100 km": (road(LINE.format(length=1e5), TWO_LANES, 1e5), "a road 100000 m long"),
    "a spiral to curvature 1e6": (
        road(
            "<geometry s='0' x='0' y='0' hdg='0' length='100'><spiral curvStart='0' curvEnd='1e6'/></geometry>\n",
            TWO_LANES,
            100.0,
        ),
        "a spiral of curvature up to 1e\\+06",
    ),
    "a lane width of 1e300": (
        road(LINE.format(length=1000), lane(1, "<width sOffset='0' a='1e300' b='0' c='0' d='0'/>")),
        "width runs outside 0..20 m",
    ),
    "a width of -3.5 m": (
        road(LINE.format(length=1000), lane(1, "<width sOffset='0' a='-3.5' b='0' c='0' d='0'/>")),
        "width runs outside 0..20 m",
    ),
    "a driving lane without a width": (road(LINE.format(length=1000), lane(1, "")), "a driving lane without <width>"),
    "2,000 driving lanes": (
        road(LINE.format(length=1000), "".join(lane(i) for i in range(1, 2001))),
        "more than 16 lanes on one side",
    ),
    "paramPoly3 coefficients of 1e300": (
        road(
            "<geometry s='0' x='0' y='0' hdg='0' length='100'><paramPoly3 aU='0' bU='1e300' cU='1e300' dU='0' "
            "aV='0' bV='0' cV='1e300' dV='1e300' pRange='normalized'/></geometry>\n",
            TWO_LANES,
            100.0,
        ),
        "leaves the map's extent|bends at a curvature",
    ),
    "a road id of 5,000 digits": (road(LINE.format(length=1000), TWO_LANES, road_id="9" * 5000), "more than 1,000"),
    "600,000 width records": (
        road(
            LINE.format(length=1000),
            lane(1, "".join(f"<width sOffset='{i / 1000}' a='3.5' b='0' c='0' d='0'/>" for i in range(600_000))),
        ),
        "more than 200,000 elements",
    ),
}


def refused_within_bounds(path: Path, said: str | None = None) -> MapError | None:
    """Read ``path`` and pick a route of 2 lanes: the ``MapError`` raised (None when the map is
    usable), within ``SECONDS`` and ``MEGABYTES``; ``said`` is what its message must match."""
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    started = time.process_time()
    refused = None
    try:
        pick_route(read_map(path), 2)
    except MapError as error:
        refused = error
    assert time.process_time() - started < SECONDS
    assert (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - peak) / 1024 < MEGABYTES
    if said is not None:
        assert refused is not None and re.search(said, refused.message), refused
    return refused


@pytest.mark.parametrize("name", sorted(CRAFTED))
def test_a_crafted_map_is_refused_at_its_line_within_the_bounds(tmp_path, name):
    text, said = CRAFTED[name]
    path = tmp_path / "m.xodr"
    path.write_text(text)
    refused = refused_within_bounds(path, said)
    assert refused.line > 0, "the element at fault is named by its line"


@pytest.mark.parametrize("kind", ["fifo", "device"])
def test_a_map_that_is_not_a_regular_file_is_refused_unread(tmp_path, kind):
    path = tmp_path / "m.xodr"
    if kind == "fifo":
        os.mkfifo(path)
    else:
        path.symlink_to("/dev/zero")
    refused_within_bounds(path, "not a regular file")


def test_the_cli_refuses_a_crafted_map_as_bad_input_naming_it(tmp_path, monkeypatch, capsys):
    from pytest_roadlogic import cli

    (tmp_path / "pyproject.toml").write_text("")
    (tmp_path / "m.xodr").write_text(CRAFTED["a width of -3.5 m"][0])
    (tmp_path / "a.osc").write_text(
        'scenario s:\n    ego: car\n    path: Path\n    path.set_map("m.xodr")\n    do ego.drive(duration: 3s)\n'
    )
    monkeypatch.chdir(tmp_path)
    assert cli.main(["run", "a.osc", "--out", str(tmp_path / "out")]) == cli.EXIT_INPUT
    said = capsys.readouterr().err
    assert "m.xodr:" in said and "width runs outside 0..20 m" in said and "Traceback" not in said


SHIPPED = sorted(MAPS.glob("*.xodr"))
NUMBER = re.compile(r'(?<==")-?[0-9][0-9.e+-]*(?=")')


@st.composite
def mutated_map(draw) -> bytes:
    """A shipped map with a few of its numbers replaced by hostile ones, or a slice cut out, or
    an element repeated."""
    text = draw(st.sampled_from(SHIPPED)).read_text()
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.sampled_from(["number", "cut", "repeat"]))
        if kind == "number":
            places = list(NUMBER.finditer(text))
            place = places[draw(st.integers(0, len(places) - 1))]
            value = draw(st.sampled_from(["0", "-3.5", "1e300", "-1e300", "nan", "inf", "1e6", "1e-300", "7", "", "x"]))
            text = text[: place.start()] + value + text[place.end() :]
        elif kind == "cut":
            start = draw(st.integers(0, len(text) - 1))
            text = text[:start] + text[start + draw(st.integers(1, 200)) :]
        else:
            elements = list(re.finditer(r"<(width|geometry|lane|road)\b[^>]*/>", text))
            if elements:
                element = elements[draw(st.integers(0, len(elements) - 1))]
                text = text[: element.end()] + element.group() * draw(st.integers(1, 50)) + text[element.end() :]
    return text.encode()


def _read_or_refuse(tmp_path: Path, data: bytes) -> None:
    path = tmp_path / "m.xodr"
    path.write_bytes(data)
    refused_within_bounds(path)  # any other exception fails the test with this input


@settings(max_examples=60, deadline=None, derandomize=True, database=None, suppress_health_check=list(HealthCheck))
@given(mutated_map())
def test_a_mutated_shipped_map_is_read_or_refused_with_a_located_error(tmp_path_factory, data):
    _read_or_refuse(tmp_path_factory.mktemp("map"), data)


@pytest.mark.slow
@settings(max_examples=2_000, deadline=None, derandomize=True, database=None, suppress_health_check=list(HealthCheck))
@given(mutated_map())
def test_two_thousand_mutated_shipped_maps_are_read_or_refused_with_a_located_error(tmp_path_factory, data):
    _read_or_refuse(tmp_path_factory.mktemp("map"), data)


def test_a_route_too_short_for_any_scenario_is_the_maps_fault_not_the_scenarios(tmp_path):
    path = tmp_path / "m.xodr"
    path.write_text(road(LINE.format(length=10), TWO_LANES, 10.0))
    refused_within_bounds(path, "no road of the map has 2 driving lanes over 200 m")
