"""Two dialects: the standard's and CARLA's scenario runner (constructs/carla.py).

In CARLA's, lane(1) is the leftmost lane and speed(v) without at: is a target driven toward from
the phase's start and checked at its end (tests/constructs/test_carla_as_its_runner.py); everything else reads
as in the standard. The dialect travels with a case, so a
replay reads the file as the run did.
"""

from pathlib import Path

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.case import Case
from pytest_roadlogic.frontend import check_file, check_text
from pytest_roadlogic.settings import RunSettings

ROOT = Path(__file__).resolve().parents[2]
CARLA_FILE = ROOT / "scenarios" / "realistic" / "carla_dialect" / "slow_cut_in.osc"
TEXT = "scenario s:\n  a: car\n  road: Path\n  road.path_min_driving_lanes(3)\n  do a.drive(road) with:\n    lane(1)\n    speed(20mps)\n"


def phase_guards(dialect: str):
    a = build_automaton(check_text(TEXT, dialect=dialect).scenarios[0])
    (phase,) = [loc for loc in a.locations if loc.name == "a.drive"]
    end = [t.guard for t in a.transitions if t.target == a.final][0]
    return phase.invariant, end


def test_in_the_standard_lane_1_is_the_rightmost_and_speed_holds_throughout():
    invariant, _ = phase_guards("standard")
    assert str(invariant) == "l(a) = 2 and 19.5 <= v(a) <= 20.5"


def test_in_carlas_dialect_lane_1_is_the_leftmost_and_speed_is_a_target_at_the_end():
    invariant, end = phase_guards("carla")
    assert str(invariant) == "l(a) = 0"
    assert "19.5 <= v(a) <= 20.5" in str(end)


def test_carlas_speed_with_at_all_written_out_still_holds_throughout():
    text = TEXT.replace("speed(20mps)", "speed(20mps, at: all)")
    a = build_automaton(check_text(text, dialect="carla").scenarios[0])
    (phase,) = [loc for loc in a.locations if loc.name == "a.drive"]
    assert "v(a)" in str(phase.invariant)


def test_a_file_written_for_carla_read_as_standard_says_which_option_reads_it():
    report = check_file(CARLA_FILE).report()
    assert "warning: the map is not available" in report and "--dialect carla" in report
    assert "--dialect carla" not in check_file(CARLA_FILE, dialect="carla").report()


def test_the_realistic_carla_file_and_its_library_check_clean_in_carlas_dialect():
    for path in (CARLA_FILE, CARLA_FILE.parent / "lib.osc"):
        checked = check_file(path, dialect="carla")
        assert not checked.errors, checked.report()


def test_the_dialect_travels_with_a_case_and_its_replay_command():
    case = Case.of(CARLA_FILE, "top", RunSettings(dialect="carla"), strategy="refined", values={})
    assert "--dialect carla" in case.command()
    assert Case(**{**case.__dict__}).settings.dialect == "carla"
    assert "--dialect" not in Case.of(CARLA_FILE, "top", RunSettings(), strategy="refined", values={}).command()


def test_an_unknown_dialect_is_refused_by_name():
    from pytest_roadlogic.settings import OptionError, RunSettings

    with pytest.raises(OptionError, match="dialect: 'carla2' is not a dialect; give standard or carla"):
        RunSettings.from_texts({"dialect": "carla2"})


def test_every_dialect_option_value_has_its_registry_and_no_registry_lacks_an_option():
    from pytest_roadlogic import settings
    from pytest_roadlogic.constructs import DIALECTS

    assert tuple(DIALECTS) == settings.DIALECTS
    assert all(registry.dialect == name for name, registry in DIALECTS.items())


def test_a_carla_speed_range_is_a_parameter_reported_as_held_at_the_end():
    from pytest_roadlogic.sampling import logical_parameters

    text = (
        "scenario s:\n    a: car\n    do a.drive(duration: 5s) with:\n        speed([20mps..25mps])\n        lane(1)\n"
    )
    kinds = {
        dialect: [(p.name, p.kind) for p in logical_parameters(check_text(text, "k.osc", dialect=dialect).scenarios[0])]
        for dialect in ("standard", "carla")
    }
    assert kinds == {"standard": [], "carla": [("a.drive.speed.speed", "at: end")]}, (
        "a standard speed range is a bound; CARLA's is a target at the end"
    )


def test_carlas_follow_trajectory_is_refused_where_it_is_written_and_its_log_is_never_read(tmp_path):
    log = tmp_path / "ego_logs.csv"
    log.write_text("secret,1,2,3\n")
    text = (
        f'scenario s:\n  a: car\n  do a.drive() with:\n    follow_trajectory(input_file: "{log}", control: "physics")\n'
    )
    report = check_text(text, "t.osc", dialect="carla").report()
    assert "t.osc:4:5: error: not supported: follow_trajectory() replays a recorded log" in report, report
    assert "secret" not in report


PACKAGED_DIALECT = """
from pytest_roadlogic.constructs import STANDARD

# a runner that reads every file as the standard does, under a name of its own
MINE = STANDARD
"""


def test_a_dialect_plugs_in_from_an_installed_package_through_its_entry_point_alone(tmp_path):
    """A package on the path with its module and its metadata only: `--dialect` takes its name
    (the entry points are read for a name that is not built in), and a name nobody registers is
    refused naming every dialect there is."""
    import os
    import subprocess
    import sys

    site = tmp_path / "site"
    (site / "my_runner-1.0.dist-info").mkdir(parents=True)
    (site / "my_runner.py").write_text(PACKAGED_DIALECT)
    (site / "my_runner-1.0.dist-info" / "METADATA").write_text("Metadata-Version: 2.1\nName: my-runner\nVersion: 1.0\n")
    (site / "my_runner-1.0.dist-info" / "entry_points.txt").write_text(
        "[pytest_roadlogic.dialects]\nmine = my_runner:MINE\n"
    )
    env = {**os.environ, "PYTHONPATH": str(site)}

    def check(dialect: str):
        return subprocess.run(
            [
                sys.executable,
                "-m",
                "pytest_roadlogic.cli",
                "check",
                str(ROOT / "scenarios" / "overtake.osc"),
                "--dialect",
                dialect,
            ],
            capture_output=True,
            text=True,
            env=env,
        )

    mine = check("mine")
    assert mine.returncode == 0, mine.stdout + mine.stderr
    assert "1 ok" in mine.stdout
    unknown = check("theirs")
    assert unknown.returncode == 2
    assert "'theirs' is not a dialect; give standard or carla or mine" in unknown.stderr
