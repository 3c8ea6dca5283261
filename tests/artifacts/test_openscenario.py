"""Issue 21: every concrete scenario is also written as OpenSCENARIO XML 1.2 with an OpenDRIVE road,
valid against the standard's schema, carrying every vehicle's simulated trajectory exactly enough to
replay it (1 cm, 1 ms), on a road with the simulated road's lanes and widths."""

import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

from pytest_roadlogic.artifacts.openscenario import OPENSCENARIO_MINOR_VERSION, write_openscenario
from pytest_roadlogic.pipeline import load_scenario, run_scenario
from pytest_roadlogic.simulation.geometry import WHEELBASE
from tests.conftest import ROOT

SCENARIOS = ("overtake.osc", "overtake_obstacle.osc")  # driven vehicles only; a standing obstacle besides


@pytest.fixture(scope="module", params=SCENARIOS)
def written(request, tmp_path_factory):
    """(the simulation, the folder its scenario.xosc and road.xodr were written to)."""
    outcome = run_scenario(load_scenario(ROOT / "scenarios" / request.param), seed=1)
    folder = tmp_path_factory.mktemp(request.param.split(".")[0])
    write_openscenario(outcome.simulation, folder, outcome.scenario.name)
    return outcome.simulation, folder


def schema_path() -> Path:
    """The XSD that scenariogeneration ships for the version written (installed beside it)."""
    import scenariogeneration

    name = {
        0: "OpenSCENARIO_1_0.xsd",
        1: "OpenSCENARIO_1_1.xsd",
        2: "OpenSCENARIO_1_2.xsd",
        3: "OpenSCENARIO_1_3_1.xsd",
    }[OPENSCENARIO_MINOR_VERSION]
    return Path(scenariogeneration.__file__).parent.parent / "schemas" / name


def test_the_scenario_validates_against_the_openscenario_schema_of_its_version(written):
    import xmlschema

    _, folder = written
    root = etree.parse(str(folder / "scenario.xosc")).getroot()
    assert root.find("FileHeader").get("revMinor") == str(OPENSCENARIO_MINOR_VERSION)
    xmlschema.XMLSchema(str(schema_path())).validate(str(folder / "scenario.xosc"))


def read_trajectories(path: Path) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Every vehicle's (times, box-centre x, box-centre y) read back from the file: its polyline's
    vertices are rear-axle positions, moved by the box centre's offset the file declares."""
    root = etree.parse(str(path)).getroot()
    offsets = {o.get("name"): float(o.find("Vehicle/BoundingBox/Center").get("x")) for o in root.iter("ScenarioObject")}
    result = {}
    for group in root.iter("ManeuverGroup"):
        vehicle = group.find("Actors/EntityRef").get("entityRef")
        vertices = group.findall(".//FollowTrajectoryAction//Polyline/Vertex")
        times = np.array([float(v.get("time")) for v in vertices])
        world = [v.find("Position/WorldPosition") for v in vertices]
        h = np.array([float(w.get("h")) for w in world])
        x = np.array([float(w.get("x")) for w in world]) + np.cos(h) * offsets[vehicle]
        y = np.array([float(w.get("y")) for w in world]) + np.sin(h) * offsets[vehicle]
        result[vehicle] = (times, x, y)
    return result


def test_reading_the_file_back_gives_every_driven_vehicles_trace_within_1_cm_and_1_ms(written):
    simulation, folder = written
    trajectories = read_trajectories(folder / "scenario.xosc")
    driven = [v for v in simulation.trace.actors if v not in simulation.stationary]
    assert sorted(trajectories) == sorted(driven)
    for vehicle, (times, x, y) in trajectories.items():
        columns = simulation.trace.actors[vehicle]
        assert len(times) == len(simulation.trace), f"{vehicle}: one vertex per trace sample"
        assert np.abs(times - simulation.trace.times).max() <= 1e-3
        assert np.hypot(x - columns["x"], y - columns["y"]).max() <= 0.01, f"{vehicle} moved off its trace"


def test_every_vehicle_starts_where_the_trace_starts_and_a_standing_one_stays(written):
    simulation, folder = written
    root = etree.parse(str(folder / "scenario.xosc")).getroot()
    for private in root.iter("Private"):
        vehicle = private.get("entityRef")
        world = private.find(".//TeleportAction/Position/WorldPosition")
        columns = simulation.trace.actors[vehicle]
        h = float(world.get("h"))
        x = float(world.get("x")) + math.cos(h) * WHEELBASE / 2
        assert abs(x - columns["x"][0]) <= 0.01 and abs(float(world.get("y")) - columns["y"][0]) <= 0.01
        speed = private.find(".//AbsoluteTargetSpeed")
        assert abs(float(speed.get("value")) - columns["speed"][0]) <= 1e-6
    stationary = set(simulation.stationary)
    followers = {g.find("Actors/EntityRef").get("entityRef") for g in root.iter("ManeuverGroup")}
    assert not stationary & followers, "a standing obstacle follows no trajectory"


def test_the_road_has_the_simulated_roads_lanes_widths_and_place(written):
    simulation, folder = written
    road = simulation.road
    root = etree.parse(str(folder / "road.xodr")).getroot()
    (geometry,) = root.iter("geometry")
    assert (
        float(geometry.get("x")) == road.x_start
        and float(geometry.get("y")) == road.width
        and float(geometry.get("hdg")) == 0.0
    )
    assert abs(float(geometry.get("length")) - (road.x_end - road.x_start)) < 1e-9
    assert geometry.find("line") is not None, "a straight road"
    (section,) = root.iter("laneSection")
    right = section.find("right")
    lanes = {int(lane.get("id")): lane for lane in right.findall("lane")}
    assert sorted(lanes) == list(range(-road.lanes, 0)) and section.find("left") is None
    for lane in lanes.values():
        assert lane.get("type") == "driving"
        assert float(lane.find("width").get("a")) == road.lane_width


def test_an_openscenario_player_replays_the_file_along_the_trace(written, tmp_path):
    """esmini, where installed: the file played headless, each vehicle within 0.1 m of its trace."""
    player = shutil.which("esmini")
    if player is None:
        pytest.skip("no OpenSCENARIO player (esmini) on PATH: the replay is checked where one is installed")
    simulation, folder = written
    log = tmp_path / "esmini.csv"
    dt = f"{simulation.dt:g}"
    result = subprocess.run(
        [
            player,
            "--headless",
            "--osc",
            str(folder / "scenario.xosc"),
            "--fixed_timestep",
            dt,
            "--csv_logger",
            str(log),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    lines = [line for line in log.read_text().splitlines() if line.strip()]
    header_at = next(
        k
        for k, line in enumerate(lines)
        if "time" in line.lower() and "x" in [c.strip().lower() for c in line.split(",")]
    )
    header = [c.strip().lower() for c in lines[header_at].split(",")]
    time_column = next(k for k, c in enumerate(header) if "time" in c)
    rows = [
        dict(zip(header, (c.strip() for c in line.split(",")))) | {"time": line.split(",")[time_column].strip()}
        for line in lines[header_at + 1 :]
    ]
    for vehicle in simulation.trace.actors:
        played = [r for r in rows if r.get("name") == vehicle]
        assert played, f"esmini logged no {vehicle}"
        columns = simulation.trace.actors[vehicle]
        for row in played:
            k = int(round(float(row["time"]) / simulation.dt))
            if 0 <= k < len(simulation.trace):
                h = float(row["h"])
                x = float(row["x"]) + math.cos(h) * WHEELBASE / 2
                y = float(row["y"]) + math.sin(h) * WHEELBASE / 2
                assert math.hypot(x - columns["x"][k], y - columns["y"][k]) <= 0.1, f"{vehicle} at {row['time']} s"
