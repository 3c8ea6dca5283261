"""Issue 38, items 1-4: a case file and a scenario file are data. Nothing in them is executed, no
file outside the project is read because of them, nothing is written outside the folder given,
and every command a report prints is safe to paste. Each test names the item it checks."""

from __future__ import annotations

import json
import shlex
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pytest_roadlogic import cli
from pytest_roadlogic.case import Case, CaseFileError
from pytest_roadlogic.frontend import check_file
from tests.conftest import ROOT

pytest_plugins = ["pytester"]
QUIET = ["-p", "no:cacheprovider", "-p", "no:randomly"]
FOLLOW = ROOT / "scenarios" / "follow.osc"
FOLLOW_VALUES = {"start_gap": 20.0, "end_gap": 20.0, "lead_speed": 10.0}
# a module a hostile case file names: importing it leaves a mark
MARKING_MODULE = (
    "from pathlib import Path\nPath(__file__).with_name('IMPORTED').write_text('ran')\nclass Driver:\n    pass\n"
)


def project(tmp_path: Path) -> Path:
    """A project folder (a pyproject.toml marks its root) with the suite's follow scenario."""
    tmp_path.mkdir(parents=True, exist_ok=True)
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'p'\n")
    (tmp_path / "scenarios").mkdir()
    (tmp_path / "scenarios" / "follow.osc").write_text(FOLLOW.read_text())
    return tmp_path


@pytest.mark.parametrize("driver", ["marker:Driver", "sys:exit", "os:abort", "builtins:input"])
def test_item_1_a_replay_never_imports_or_calls_what_a_case_file_names(tmp_path, monkeypatch, capsys, driver):
    root = project(tmp_path)
    (root / "scenarios" / "marker.py").write_text(MARKING_MODULE)  # beside the scenario, as an attacker would put it
    (root / "marker.py").write_text(MARKING_MODULE)  # and in the working folder
    Case(path="scenarios/follow.osc", scenario="follow", values=FOLLOW_VALUES, drivers={"tail": driver}).save(
        root / "case.json"
    )
    monkeypatch.chdir(root)
    assert cli.main(["replay", "case.json", "--out", str(root / "out")]) == cli.EXIT_INPUT
    said = capsys.readouterr().err
    assert f"the case was found with the drivers tail by {driver!r}" in said
    assert "not imported on its word" in said and "--driver VEHICLE=MODULE:CLASS" in said
    assert not list(root.rglob("IMPORTED")), "the module named by the case file ran"
    assert not (root / "out").exists()


def test_item_1_drivers_given_on_the_command_line_other_than_the_cases_are_refused_naming_both(
    tmp_path, monkeypatch, capsys
):
    root = project(tmp_path)
    Case(
        path="scenarios/follow.osc",
        scenario="follow",
        values=FOLLOW_VALUES,
        drivers={"tail": "tests.drivers:NeverChangesLane"},
    ).save(root / "case.json")
    monkeypatch.chdir(root)
    assert (
        cli.main(["replay", "case.json", "--driver", "tail=tests.drivers:Other", "--out", str(root / "out")])
        == cli.EXIT_INPUT
    )
    said = capsys.readouterr().err
    assert "tail by 'tests.drivers:NeverChangesLane'; the command line gives tail by 'tests.drivers:Other'" in said


@pytest.mark.parametrize(
    "path", ["/etc/passwd", "../../../../etc/passwd", "scenarios/../../outside.osc", "", "/proc/self/environ"]
)
def test_item_2_a_case_files_scenario_path_must_be_relative_and_inside_the_project(tmp_path, monkeypatch, capsys, path):
    root = project(tmp_path / "p")
    (tmp_path / "outside.osc").write_text(FOLLOW.read_text())
    Case(path=path, scenario="follow", values=FOLLOW_VALUES).save(root / "case.json")
    monkeypatch.chdir(root)
    assert cli.main(["replay", "case.json", "--out", str(root / "out")]) == cli.EXIT_INPUT
    said = capsys.readouterr().err
    assert (
        "is not a relative path to an .osc file inside the project" in said
        or "is not in the folders the tool reads" in said
    )
    assert "root:" not in said, "nothing of the refused file is shown"


def test_item_2_a_case_file_kept_outside_the_project_finds_its_scenario_inside_it(tmp_path, monkeypatch):
    root = project(tmp_path / "p")
    (tmp_path / "downloads").mkdir()
    (tmp_path / "downloads" / "scenarios").mkdir()
    (tmp_path / "downloads" / "scenarios" / "follow.osc").write_text("a file beside the case, outside the project")
    case = Case(path="scenarios/follow.osc", scenario="follow")
    monkeypatch.chdir(root)
    assert (
        case.scenario_file(tmp_path / "downloads" / "case.json").resolve()
        == (root / "scenarios" / "follow.osc").resolve()
    )
    from pytest_roadlogic.confinement import ReadRoots

    with pytest.raises(CaseFileError, match="not in the folders the tool reads"):
        Case(path="elsewhere.osc", scenario="follow").scenario_file(
            tmp_path / "downloads" / "case.json", ReadRoots.of(root)
        )


@pytest.mark.parametrize("target", ["/etc/passwd", "/proc/self/environ", "../secret.osc"])
def test_item_2_an_import_outside_the_project_is_refused_at_the_import_and_never_shown(tmp_path, monkeypatch, target):
    (tmp_path / "secret.osc").write_text("TOKEN=do-not-print-me\n")
    root = project(tmp_path / "p")
    (root / "a.osc").write_text(f'import "{target}"\nscenario s:\n    v1: car\n    do v1.drive(duration: 3s)\n')
    monkeypatch.chdir(root)
    checked = check_file(root / "a.osc")
    report = checked.report()
    refused = "is outside the folders the tool reads" if target.endswith(".osc") else "is not an .osc file"
    assert f"a.osc:1:8: error: the imported file {target!r} {refused}" in report
    assert "TOKEN" not in report and "root:x:" not in report


def test_item_2_a_symbolic_link_inside_the_project_to_a_file_outside_is_refused(tmp_path, monkeypatch):
    (tmp_path / "secret.osc").write_text("TOKEN=do-not-print-me\n")
    root = project(tmp_path / "p")
    (root / "lib.osc").symlink_to(tmp_path / "secret.osc")
    (root / "a.osc").write_text('import "lib.osc"\nscenario s:\n    v1: car\n    do v1.drive(duration: 3s)\n')
    monkeypatch.chdir(root)
    report = check_file(root / "a.osc").report()
    assert "is outside the folders the tool reads" in report and "TOKEN" not in report


def test_item_2_a_folder_named_with_allow_read_may_be_imported_from(tmp_path, monkeypatch, capsys):
    (tmp_path / "shared").mkdir()
    (tmp_path / "shared" / "lib.osc").write_text("enum colour: [red, blue]\n")
    root = project(tmp_path / "p")
    (root / "a.osc").write_text('import "../shared/lib.osc"\nscenario s:\n    v1: car\n    do v1.drive(duration: 3s)\n')
    monkeypatch.chdir(root)
    assert cli.main(["check", "a.osc"]) == 1
    assert cli.main(["check", "a.osc", "--allow-read", str(tmp_path / "shared")]) == 0
    assert "1 ok" in capsys.readouterr().out


def test_item_2_under_pytest_an_import_outside_the_rootdir_is_a_collection_error(pytester):
    pytester.makefile(
        ".osc",
        a='import "/proc/self/environ"\nimport "/etc/x.osc"\nscenario s:\n    v1: car\n    do v1.drive(duration: 3s)\n',
    )
    result = pytester.runpytest_subprocess(*QUIET)
    result.assert_outcomes(errors=1)
    assert "'/proc/self/environ' is not an .osc file" in result.stdout.str()
    assert "'/etc/x.osc' is outside the folders the tool reads" in result.stdout.str()
    assert "PATH=" not in result.stdout.str() and "HOME=" not in result.stdout.str()


def test_item_3_a_quoted_scenario_name_does_not_lead_a_written_file_out_of_the_working_folder(
    tmp_path, monkeypatch, capsys
):
    work = tmp_path / "a" / "b" / "c"
    work.mkdir(parents=True)
    (work / "x.osc").write_text("scenario |../../../x|:\n    v1: car\n    do v1.drive(duration: 3s)\n")
    monkeypatch.chdir(work)
    assert cli.main(["automaton", "x.osc"]) == 0
    assert not (tmp_path / "x.dot").exists()
    assert [p.name for p in work.glob("*.dot")] == ["x.dot"]
    assert "x.dot" in capsys.readouterr().out


@pytest.mark.parametrize(
    "name, safe",
    [
        ("../../../x", "x"),
        ("a/b\\c", "a_b_c"),
        ("..", "scenario"),
        (".hidden", "hidden"),
        ("ok_name-1.2", "ok_name-1.2"),
    ],
)
def test_item_3_a_name_from_a_scenario_becomes_one_file_name_inside_its_folder(name, safe):
    from pytest_roadlogic.confinement import safe_name

    assert safe_name(name) == safe
    assert "/" not in safe_name(name) and not safe_name(name).startswith(".")


def test_item_4_the_printed_pytest_replay_line_is_shell_quoted(pytester):
    """A file named a'$(touch P)'b.osc: the printed command ran touch P when pasted."""
    name = "a'$(touch P)'b"
    (pytester.path / f"{name}.osc").write_text((ROOT / "scenarios" / "overtake.osc").read_text())
    pytester.makeconftest(DRIVER_CONFTEST)  # a vehicle under test that never changes lane: the overtake fails
    result = pytester.runpytest_subprocess(
        "--roadlogic-strategy", "base", "--roadlogic-examples", "1", "--roadlogic-tries", "1", *QUIET
    )
    result.assert_outcomes(failed=1)
    lines = [line for line in result.stdout.lines if line.startswith("replay: pytest ")]
    assert lines, result.stdout.str()
    command = lines[0][len("replay: ") :].split("   (with")[0]
    words = shlex.split(command)
    assert words[:2] == ["pytest", f"{name}.osc::overtake"], words
    # pasted into a shell, the line runs only pytest: echo stands in for it
    done = subprocess.run(
        ["bash", "-c", "echo " + command[len("pytest ") :]], cwd=pytester.path, capture_output=True, text=True
    )
    assert done.returncode == 0 and not (pytester.path / "P").exists()


DRIVER_CONFTEST = f"""
import sys
sys.path.insert(0, {str(ROOT)!r})
from tests.drivers import NeverChangesLane

def pytest_roadlogic_driver(config, scenario, vehicle):
    return NeverChangesLane() if vehicle == "v1" else None
"""


def test_every_printed_replay_command_of_a_case_is_shell_quoted():
    case = Case(path="a'$(touch P)'b.osc", scenario="s", values={"x": 1.0}, drivers={"v1": "m:C"})
    words = shlex.split(case.command())
    assert words[2] == "a'$(touch P)'b.osc"
    assert json.loads(words[words.index("--values") + 1]) == {"x": 1.0}
    assert shlex.split(case.command(Path("out dir/case.json"))) == ["roadlogic", "replay", "out dir/case.json"]


@pytest.mark.parametrize(
    "field, value, said",
    [
        ("seed", "abc", "seed must be a whole number, not str"),
        ("seed", -5, "is not a seed"),
        ("lanes", "4", "lanes must be a whole number, not str"),
        ("planning_time_limit", "30", "planning_time_limit must be a number, not str"),
        ("max_tries", "2", "max_tries must be a whole number, not str"),
        ("max_tries", 10**6, "is not a number of tries"),
        ("planning_time_limit", 1e300, "is past the longest time limit"),
        ("instance", 1_000_000, "instance must be a whole number from 0 to"),
        ("versions", {"numpy": "x" * 100_000}, "versions must map"),
        ("path", "scenarios/follow.txt" * 100, "path must be a string of at most"),
        ("seed", 2**40, "is not a seed"),
        ("max_tries", 0, "is not a number of tries"),
        ("values", {"start_gap": [1, 2]}, "values must map"),
        ("drivers", {"tail": 3}, "drivers must map"),
        ("strategy", "evil", "is not a strategy"),
        ("road_speed", "fast", "is not a speed band"),
        ("road_speed", "0..900kph", "is not a speed band a car drives at"),
        ("path", 3, "path must be a string"),
        ("instance", -1, "instance must be"),
    ],
)
def test_a_crafted_case_file_is_refused_when_it_is_read_naming_the_field(tmp_path, field, value, said):
    data = json.loads(Case(path="scenarios/follow.osc", scenario="follow").to_json())
    data[field] = value
    (tmp_path / "case.json").write_text(json.dumps(data))
    with pytest.raises(CaseFileError, match=said):
        Case.load(tmp_path / "case.json")


@pytest.mark.parametrize("kind", ["fifo", "device", "huge"])
def test_a_case_file_that_is_not_a_small_regular_file_is_refused_without_reading_it_all(tmp_path, kind):
    import os

    case = tmp_path / "case.json"
    if kind == "fifo":
        os.mkfifo(case)
    elif kind == "device":
        case.symlink_to("/dev/zero")
    else:
        case.write_text(json.dumps({"path": "a.osc", "scenario": "s", "values": {"x": "y" * 2_000_000}}))
    with pytest.raises(CaseFileError, match="not a regular file|more than"):
        Case.load(case)


def test_a_case_files_time_limits_never_exceed_the_command_lines(tmp_path):
    from pytest_roadlogic.settings import RunSettings

    case = Case(path="a.osc", scenario="s", settings=RunSettings(planning_time_limit=3000.0, simulation_time_limit=2.0))
    bounded = case.within(RunSettings(planning_time_limit=5.0)).settings
    assert bounded.planning_time_limit == 5.0 and bounded.simulation_time_limit == 2.0


if sys.platform == "win32":  # pragma: no cover - the project runs on POSIX systems
    pytestmark = pytest.mark.skip("POSIX paths and shells")


def test_two_scenarios_whose_safe_names_are_equal_never_share_an_artifacts_folder():
    from pytest_roadlogic.confinement import safe_name, unique_name

    pairs = [("ä.osc::plain", "ö.osc::plain"), ("a" * 120 + "::x", "a" * 120 + "::y")]
    for one, other in pairs:
        assert safe_name(one) == safe_name(other)
        assert unique_name(one) != unique_name(other)
        assert unique_name(one) == unique_name(one) and "/" not in unique_name(one)


HOSTILE_VALUES = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(2**70), 2**70),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=30),
    st.sampled_from(["4", "1e308", "../../etc/passwd", "proc/self/environ", "a.osc", "\x1b[2J", "0..900kph", "acc"]),
    st.lists(st.integers(), max_size=3),
    st.dictionaries(
        st.text(max_size=5), st.one_of(st.integers(), st.text(max_size=5), st.lists(st.none())), max_size=3
    ),
)


@st.composite
def hostile_case(draw) -> dict:
    """A case the tool wrote, with some of its fields replaced by values of any kind."""
    data = json.loads(Case(path="scenarios/follow.osc", scenario="follow", values=FOLLOW_VALUES).to_json())
    for name in draw(st.lists(st.sampled_from(sorted(data)), max_size=5, unique=True)):
        data[name] = draw(HOSTILE_VALUES)
    if draw(st.booleans()):
        data[draw(st.text(min_size=1, max_size=8))] = draw(HOSTILE_VALUES)
    return data


def _loaded_or_refused(folder: Path, data: dict) -> None:
    from pytest_roadlogic.settings import RunSettings

    (folder / "case.json").write_text(json.dumps(data))
    try:
        case = Case.load(folder / "case.json")
    except CaseFileError as error:
        assert "Traceback" not in str(error) and len(str(error)) < 2_000
        return
    settings = case.within(RunSettings()).settings  # any other exception fails with this input
    assert settings.planning_time_limit <= RunSettings().planning_time_limit
    try:
        case.scenario_file(folder / "case.json")
    except CaseFileError:
        pass


@settings(max_examples=200, deadline=None, derandomize=True, database=None, suppress_health_check=list(HealthCheck))
@given(hostile_case())
def test_a_case_file_with_fields_of_any_kind_is_loaded_or_refused_never_a_traceback(tmp_path_factory, data):
    _loaded_or_refused(tmp_path_factory.mktemp("case"), data)


@pytest.mark.slow
@settings(max_examples=5_000, deadline=None, derandomize=True, database=None, suppress_health_check=list(HealthCheck))
@given(hostile_case())
def test_five_thousand_hostile_case_files_are_loaded_or_refused(tmp_path_factory, data):
    _loaded_or_refused(tmp_path_factory.mktemp("case"), data)


def test_a_diagnostic_reads_at_most_what_the_front_end_reads_of_a_file():
    from pytest_roadlogic.frontend.errors import SHOWN_FILE_BYTES
    from pytest_roadlogic.frontend.syntax.limits import MAX_BYTES

    assert SHOWN_FILE_BYTES == 4 * MAX_BYTES  # a character is at most 4 bytes of UTF-8
