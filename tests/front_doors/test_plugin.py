"""The pytest plugin as a user meets it: collection, sampling and shrinking, reports, replay, hooks, xdist.

Each test runs pytest in a subprocess on scenario files in a temporary directory (pytester), with
few examples and a short horizon so that the suite stays quick.
"""

import json
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from pytest_roadlogic.confinement import unique_name
from tests.conftest import ROOT

pytest_plugins = ["pytester"]

SCENARIOS = ROOT / "scenarios"
SQUEEZE = ROOT / "tests" / "scenarios" / "squeeze.osc"
QUIET = ["-p", "no:cacheprovider", "-p", "no:randomly"]


def copy(pytester, *paths):
    for path in paths:
        (pytester.path / path.name).write_text(path.read_text())


def test_collect_only_lists_one_item_per_scenario_and_never_plans(pytester):
    pytester.makefile(
        ".osc",
        two=SQUEEZE.read_text()
        + "\n"
        + SQUEEZE.read_text().replace("scenario traffic.squeeze", "scenario traffic.other"),
    )
    # planning during collection would raise here
    pytester.makeconftest("import pytest_roadlogic.planning.core as s\ns.IncrementalPlanner.__init__ = None\n")
    result = pytester.runpytest_subprocess("--collect-only", "-q", *QUIET)
    assert result.ret == 0, result.stdout.str()
    result.stdout.fnmatch_lines(["two.osc::squeeze", "two.osc::other"])


def test_a_band_of_failing_values_shrinks_to_its_boundary_and_replays(pytester):
    # the middle car fits between back and front (30 m apart, 8 m between centres) only for gaps
    # up to 22.5 m (or from 38 m): Hypothesis must find the band and shrink to its lower edge
    copy(pytester, SQUEEZE)
    pytester.makeini("[pytest]\n")  # a project: the replay below reads the scenario from its root
    # the band's edge is the grid's (8 m gaps); the continuous encoding adds 1 s of closing speed to
    # a gap, which moves it (issue 19 redoes this check for the default encoding)
    result = pytester.runpytest_subprocess(
        "--roadlogic-encoding", "grid", "--roadlogic-horizon", "6", "--roadlogic-examples", "10", *QUIET
    )
    result.assert_outcomes(failed=1)
    report = result.stdout.str()
    gap = float(re.search(r"gap = ([\d.]+) m \(line 7,", report).group(1))
    assert 22.0 <= gap <= 24.0, f"the shrunk gap {gap} m is not at the band's edge (22.5 m):\n{report}"
    assert (
        "the scenario cannot be instantiated (no plan) at these values" in report and "cannot hold together" in report
    )
    assert "gap = " in report and "(line 7, declared parameter)" in report, "each value names its kind"
    case_file = pytester.path / "roadlogic-artifacts" / unique_name("squeeze.osc::squeeze") / "case.json"
    assert f"roadlogic replay {case_file}" in report
    assert json.loads(case_file.read_text())["values"]["gap"] == gap
    replay = subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", "replay", str(case_file), "--out", str(pytester.path / "r")],
        capture_output=True,
        text=True,
    )
    assert replay.returncode == 1, replay.stdout + replay.stderr
    assert f"{gap - 0.5:g} <= p(middle) - p(back)" in replay.stderr, "replay plans the same narrowed scenario"


DRIVER_CONFTEST = f"""
import sys
sys.path.insert(0, {str(ROOT)!r})
from tests.drivers import NeverChangesLane

def pytest_roadlogic_driver(config, scenario, vehicle):
    return NeverChangesLane() if vehicle == "v1" else None
"""


REPLAY_SCRIPT = """
import sys
sys.path.insert(0, {root!r})
from pathlib import Path
from pytest_roadlogic.case import Case
from pytest_roadlogic.runner import replay
from tests.drivers import NeverChangesLane
outcome = replay(Case.load({case!r}), drivers=lambda v: NeverChangesLane() if v == "v1" else None).run
assert not outcome.verdict.accepted
Path({out!r}).mkdir()
Path({out!r}, "plan.json").write_text(outcome.plan.to_json())
Path({out!r}, "trace.csv").write_text(outcome.simulation.trace.to_csv())
"""

PROFILE = """
from hypothesis import Phase, settings
settings.register_profile("quick", max_examples=2, phases=[Phase.explicit, Phase.reuse, Phase.generate])
"""


def overtake_driven_by(pytester, conftest: str):
    """overtake.osc under pytest with ``conftest``'s drivers and the quick profile (a Hypothesis
    profile is respected: two examples, no shrinking, each would be a simulation), one try."""
    copy(pytester, SCENARIOS / "overtake.osc")
    pytester.makeconftest(conftest + PROFILE)
    return pytester.runpytest_subprocess("--hypothesis-profile", "quick", "--roadlogic-tries", "1", *QUIET)


def test_the_driver_hook_drives_the_vehicle_under_test_and_a_bad_one_fails_with_a_replayable_report(pytester):
    result = overtake_driven_by(pytester, DRIVER_CONFTEST)
    result.assert_outcomes(failed=1)
    report = result.stdout.str()
    assert "scenario overtake: the simulation was not accepted (non-conformant) at these values" in report
    assert "A.position.distance = " in report, "the failing values are listed"
    assert "rejected (robustness" in report, "the monitor's explanation is shown"
    artifacts = pytester.path / "roadlogic-artifacts" / unique_name("overtake.osc::overtake")
    for name in ("plan.json", "trace.csv", "scenario.xml", "trajectories.png", "simulation.gif", "case.json"):
        assert (artifacts / name).is_file(), name
    assert f"pytest overtake.osc::overtake --roadlogic-replay {artifacts / 'case.json'}" in report

    assert "closest at t =" in report, "the monitor says when the run came closest"

    # the case replays exactly, with the same driver: same plan, same trace (in a fresh process:
    # pytester restores sys.modules after a test, which frenetix's extension does not survive)
    replay = REPLAY_SCRIPT.format(
        root=str(ROOT), case=str(artifacts / "case.json"), out=str(pytester.path / "replayed")
    )
    done = subprocess.run([sys.executable, "-c", replay], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    replayed = pytester.path / "replayed"
    assert (
        json.loads((replayed / "plan.json").read_text())["states"]
        == json.loads((artifacts / "plan.json").read_text())["states"]
    )
    assert (replayed / "trace.csv").read_text() == (artifacts / "trace.csv").read_text()

    again = pytester.runpytest_subprocess(
        "--roadlogic-replay", str(artifacts / "case.json"), "--roadlogic-tries", "1", *QUIET
    )
    again.assert_outcomes(failed=1)
    assert "1 examples" in again.stdout.str()

    # issue 20, item 5: the case names its drivers and its scenario relative to the rootdir, and the
    # printed command line replays it with the same driver (it had replayed as accepted, exit 0)
    case = json.loads((artifacts / "case.json").read_text())
    assert case["path"] == "overtake.osc" and case["drivers"] == {"v1": "tests.drivers:NeverChangesLane"}, case
    assert "--driver v1=tests.drivers:NeverChangesLane" in report
    # issue 38: the drivers come from the command line, never from the case file's word; the scenario
    # is read inside the project (the pytester folder, named with --allow-read from this checkout)
    replay = [
        sys.executable,
        "-m",
        "pytest_roadlogic.cli",
        "replay",
        str(artifacts / "case.json"),
        "--out",
        str(pytester.path / "cli"),
    ]
    replay += ["--allow-read", str(pytester.path)]
    refused = subprocess.run(replay, capture_output=True, text=True, cwd=ROOT)
    assert refused.returncode == 2 and "not imported on its word" in refused.stderr, refused.stderr
    cli = subprocess.run(
        [*replay, "--driver", "v1=tests.drivers:NeverChangesLane"], capture_output=True, text=True, cwd=ROOT
    )
    assert cli.returncode == 1, cli.stdout + cli.stderr
    assert (pytester.path / "cli" / "trace.csv").read_text() == (artifacts / "trace.csv").read_text()

    # a session with other drivers does not pass the case off as replayed
    (pytester.path / "conftest.py").write_text(PROFILE)
    other = pytester.runpytest_subprocess(
        "--roadlogic-replay", str(artifacts / "case.json"), "--roadlogic-tries", "1", *QUIET
    )
    other.assert_outcomes(failed=1)
    assert (
        "the case was found with the drivers v1: tests.drivers:NeverChangesLane, this session drives with the simulator's own only"
        in other.stdout.str()
    )


def test_pytest_html_shows_a_failing_scenarios_plot_animation_and_replay_command(pytester):
    """Issue 21: with pytest-html (the html extra), the report embeds the failing case's pictures."""
    pytest.importorskip("pytest_html")
    copy(pytester, SCENARIOS / "overtake.osc")
    pytester.makeconftest(DRIVER_CONFTEST + PROFILE)
    result = pytester.runpytest_subprocess(
        "--hypothesis-profile",
        "quick",
        "--roadlogic-tries",
        "1",
        "--html",
        "report.html",
        "--self-contained-html",
        *QUIET,
    )
    result.assert_outcomes(failed=1)
    report = (pytester.path / "report.html").read_text()
    assert "data:image/png;base64,iVBORw0KGgo" in report, "the plot (a PNG) is embedded"
    assert "data:image/gif;base64,R0lGOD" in report, "the animation (a GIF) is embedded"
    assert "--roadlogic-replay" in report and "roadlogic replay" in report, "the replay commands are shown"


def test_a_replay_that_cannot_build_the_cases_drivers_says_so_and_runs_nothing(tmp_path, capsys, monkeypatch):
    from pytest_roadlogic.case import Case
    from pytest_roadlogic.cli import main

    case = Case(
        path="scenarios/follow.osc",
        scenario="follow",
        values={"start_gap": 20.0, "end_gap": 20.0, "lead_speed": 10.0},
        drivers={"tail": "nowhere.to.be.found:Planner"},
    )
    case.save(tmp_path / "case.json")
    monkeypatch.chdir(ROOT)
    assert (
        main(
            [
                "replay",
                str(tmp_path / "case.json"),
                "--out",
                str(tmp_path / "out"),
                "--driver",
                "tail=nowhere.to.be.found:Planner",
            ]
        )
        == 2
    )
    said = capsys.readouterr().err
    assert "error: the driver of tail, nowhere.to.be.found:Planner, does not load here (ModuleNotFoundError" in said
    assert not (tmp_path / "out").exists()


def test_ini_options_the_base_strategy_the_summary_and_junit_properties(pytester):
    copy(pytester, SCENARIOS / "follow.osc")
    pytester.makeini("[pytest]\nroadlogic_strategy = base\nroadlogic_examples = 2\n")
    result = pytester.runpytest_subprocess("--junitxml", "junit.xml", *QUIET)
    result.assert_outcomes(passed=1)
    result.stdout.fnmatch_lines(
        ["*1 scenarios, 2 examples: 2 conformant, 0 non-conformant, 0 no plan, 0 timed out*", "time per stage: *"]
    )
    properties = {p.get("name"): p.get("value") for p in ET.parse(pytester.path / "junit.xml").iter("property")}
    assert properties["strategy"] == "base" and properties["examples"] == "2" and properties["conformant"] == "2"


def test_an_error_inside_one_example_fails_that_item_only(pytester):
    copy(pytester, SCENARIOS / "follow.osc", SCENARIOS / "change_lane.osc")
    pytester.makeconftest(
        "def pytest_roadlogic_driver(config, scenario, vehicle):\n"
        "    if scenario.name == 'follow':\n"
        "        raise RuntimeError('the driver under test crashed')\n"
    )
    result = pytester.runpytest_subprocess("--roadlogic-examples", "1", *QUIET)
    result.assert_outcomes(failed=1, passed=1)
    assert "the driver under test crashed" in result.stdout.str()


@pytest.mark.slow  # the suite twice, serial and on two workers: about 2 minutes
def test_pytest_xdist_gives_the_same_outcomes_as_a_serial_run(pytester):
    copy(pytester, SCENARIOS / "follow.osc", SCENARIOS / "change_lane.osc")
    # every gap of this range is infeasible: a failing item whose examples are quick
    pytester.makefile(".osc", squeeze=SQUEEZE.read_text().replace("keep(it in [10..40]m)", "keep(it in [25..35]m)"))
    options = ["--roadlogic-examples", "3", "--roadlogic-horizon", "6", "-rA", *QUIET]
    serial = pytester.runpytest_subprocess(*options)
    case_file = pytester.path / "roadlogic-artifacts" / unique_name("squeeze.osc::squeeze") / "case.json"
    serial_case = case_file.read_text()
    shutil.rmtree(pytester.path / ".hypothesis")  # the second run must not start from the first one's failures
    parallel = pytester.runpytest_subprocess("-n", "2", *options)
    assert case_file.read_text() == serial_case, "a failure found under -n 2 is the same case (it replays the same)"

    def outcomes(result):
        lines = result.stdout.lines
        verdicts = sorted(line.split(" - ")[0] for line in lines if line.startswith(("PASSED", "FAILED")))
        summary = [line for line in lines if " scenarios, " in line]
        return verdicts, summary

    assert outcomes(serial) == outcomes(parallel)
    assert outcomes(serial)[0] == [
        "FAILED squeeze.osc::squeeze",
        "PASSED change_lane.osc::change_lane",
        "PASSED follow.osc::follow",
    ]


def test_the_strategy_is_public_for_ordinary_given_tests():
    from hypothesis import given, settings

    import pytest_roadlogic

    @settings(max_examples=25, deadline=None)
    @given(pytest_roadlogic.parameters(SCENARIOS / "overtake.osc"))
    def check(values):
        assert set(values) == {"A.position.distance", "B.position.distance", "C.position.distance"}
        assert 10 <= values["A.position.distance"] <= 20
        assert 8 <= values["C.position.distance"] <= 13

    check()


def test_a_scenario_with_many_vehicles_is_marked_slow(pytester):
    copy(pytester, ROOT / "benchmarks" / "scenarios" / "platoon_overtake_merge.osc", SCENARIOS / "follow.osc")
    result = pytester.runpytest_subprocess("--collect-only", "-q", "-m", "slow", *QUIET)
    result.stdout.fnmatch_lines(["platoon_overtake_merge.osc::*", "*1/2 tests collected (1 deselected)*"])


SIMULATOR_CONFTEST = """
from pathlib import Path
from pytest_roadlogic.simulation.frenetix import FrenetixSimulator

class Counting(FrenetixSimulator):
    name = "counting"

    def simulate(self, plan, limits, drivers=None):
        with Path("simulations.txt").open("a") as record:
            record.write(f"{limits.dt} {limits.time_limit}\\n")
        return super().simulate(plan, limits, drivers)

def pytest_roadlogic_simulator(config, scenario):
    return Counting()
"""


def test_a_simulator_from_the_hook_simulates_every_case(pytester):
    copy(pytester, SCENARIOS / "follow.osc")
    pytester.makeconftest(SIMULATOR_CONFTEST)
    result = pytester.runpytest_subprocess(
        "--roadlogic-strategy", "base", "--roadlogic-examples", "2", "--roadlogic-sim-timeout", "90", *QUIET
    )
    result.assert_outcomes(passed=1)
    assert (pytester.path / "simulations.txt").read_text().splitlines() == ["0.1 90.0", "0.1 90.0"], (
        "one simulation per case, with the session's limits"
    )


PLAN_RECORDING_CONFTEST = """
import hashlib
import json
from pathlib import Path
from pytest_roadlogic.simulation.frenetix import FrenetixSimulator

class Recording(FrenetixSimulator):
    def simulate(self, plan, limits, drivers=None):
        with Path("plans.txt").open("a") as record:
            states = json.dumps(json.loads(plan.to_json())["states"])  # not its timing statistics
            record.write(hashlib.sha256(states.encode()).hexdigest()[:12] + "\\n")
        return super().simulate(plan, limits, drivers)

def pytest_roadlogic_simulator(config, scenario):
    return Recording()
"""


def test_hypothesis_seed_draws_the_samples_and_the_statistics_show_the_projects_events(pytester):
    """Issue 20, item 9: --hypothesis-seed had been ignored (seeds 5 and 6 drew the same values) and
    --hypothesis-show-statistics printed an empty section for scenario items."""
    copy(pytester, SCENARIOS / "follow.osc")
    pytester.makeconftest(PLAN_RECORDING_CONFTEST)

    def plans(seed: str) -> list[str]:
        record = pytester.path / "plans.txt"
        record.unlink(missing_ok=True)
        shutil.rmtree(
            pytester.path / ".hypothesis", ignore_errors=True
        )  # the example database replays earlier runs' samples first
        result = pytester.runpytest_subprocess(
            "--hypothesis-seed", seed, "--roadlogic-examples", "3", "--hypothesis-show-statistics", *QUIET
        )
        result.assert_outcomes(passed=1)
        statistics = result.stdout.str().split("Hypothesis Statistics")[1]
        assert (
            "follow.osc::follow:" in statistics
            and "outcome: conformant" in statistics
            and "plans tried: 1" in statistics
        ), statistics
        return record.read_text().splitlines()

    five = plans("5")
    assert plans("5") == five, "one seed, the same samples"
    assert plans("6") != five, "another seed, other samples"


def test_a_bad_option_value_stops_the_session_with_a_message_naming_the_option(pytester):
    copy(pytester, SCENARIOS / "follow.osc")
    for option, value, message in (
        (
            "--roadlogic-examples",
            "abc",
            "--roadlogic-examples (ini roadlogic_examples): 'abc' is not a number of examples; give a whole number from 1 up",
        ),
        ("--roadlogic-seed", "x", "--roadlogic-seed (ini roadlogic_seed): 'x' is not a seed"),
        (
            "--roadlogic-plan-timeout",
            "-1",
            "--roadlogic-plan-timeout (ini roadlogic_plan_timeout): '-1' is not a time limit",
        ),
        ("--roadlogic-simulator", "nope", "no simulator named 'nope'; available: frenetix"),
    ):
        result = pytester.runpytest_subprocess(option, value, *QUIET)
        assert result.ret == pytest.ExitCode.USAGE_ERROR, (option, result.stdout.str())
        assert message in result.stderr.str(), (option, result.stderr.str())
        assert "Traceback" not in result.stderr.str() + result.stdout.str()


def test_a_conftest_reads_a_folder_in_carlas_dialect_and_the_items_run_accepted(pytester):
    carla = SCENARIOS / "realistic" / "carla_dialect"
    copy(pytester, carla / "lib.osc", carla / "slow_cut_in.osc")
    pytester.makeconftest("def pytest_roadlogic_dialect(config, path):\n    return 'carla'\n")
    result = pytester.runpytest_subprocess("--roadlogic-examples", "1", "--junitxml", "j.xml", *QUIET)
    result.assert_outcomes(passed=1)
    properties = {p.get("name"): p.get("value") for p in ET.parse(pytester.path / "j.xml").iter("property")}
    assert properties["conformant"] == "1", properties


def test_a_dialect_hook_that_names_no_dialect_is_a_collection_error_of_that_file(pytester):
    copy(pytester, SCENARIOS / "change_lane.osc")
    pytester.makeconftest("def pytest_roadlogic_dialect(config, path):\n    return 'carl'\n")
    result = pytester.runpytest_subprocess("--collect-only", "-q", *QUIET)
    result.stdout.fnmatch_lines(
        ["*change_lane.osc: pytest_roadlogic_dialect: 'carl' is not a dialect; give standard or carla*"]
    )


def test_a_folders_conftest_hooks_apply_to_that_folders_files_only(pytester):
    # a_carla/ is collected before b.osc: the folder's dialect and driver hooks must not reach b.osc
    # (they did when the plugin asked config.hook: every conftest.py collected so far)
    folder = pytester.mkdir("a_carla")
    (folder / "conftest.py").write_text(
        "import pathlib\n"
        "def pytest_roadlogic_dialect(config, path):\n"
        "    pathlib.Path(str(config.rootpath), 'asked.txt').open('a').write(path.name + '\\n')\n"
        "    return 'carla'\n"
    )
    (folder / "x.osc").write_text(SQUEEZE.read_text())
    (pytester.path / "b.osc").write_text(SQUEEZE.read_text())
    result = pytester.runpytest_subprocess("--collect-only", "-q", *QUIET)
    assert result.ret == 0, result.stdout.str()
    assert (pytester.path / "asked.txt").read_text().split() == ["x.osc"]


def test_the_summary_and_junit_say_which_vehicle_had_to_do_what_nothing_asked_which_vehicle_had_to_do_what_nothing_asked(
    pytester,
):
    from tests.constructs.test_asked_per_instant import FOLLOW_THEN_OVERTAKE_EXACT

    pytester.makefile(".osc", exact=FOLLOW_THEN_OVERTAKE_EXACT)
    pytester.makeini("[pytest]\nroadlogic_strategy = base\nroadlogic_examples = 1\n")
    result = pytester.runpytest_subprocess("--junitxml", "junit.xml", *QUIET)
    result.assert_outcomes(passed=1)
    result.stdout.fnmatch_lines(["*1 examples needed changes nothing in their scenario asks for*"])
    properties = {p.get("name"): p.get("value") for p in ET.parse(pytester.path / "junit.xml").iter("property")}
    assert properties["unasked"] == "1"
    assert properties["unasked_changes"].startswith("slow changes speed from"), properties["unasked_changes"]


def test_every_option_is_a_run_setting_and_unless_it_says_how_cases_are_drawn_a_case_field_and_a_replay_flag(
    tmp_path, capsys
):
    import dataclasses

    from pytest_roadlogic.case import CASE_OPTIONS, REPLAY_OPTIONS, Case
    from pytest_roadlogic.cli import main
    from pytest_roadlogic.oracles import ORACLES
    from pytest_roadlogic.settings import OPTIONS, RunSettings

    assert [f.name for f in dataclasses.fields(RunSettings)] == [o.field for o in OPTIONS]
    assert all(getattr(RunSettings(), o.field) == o.default for o in OPTIONS)
    assert {o.option for o in ORACLES} <= {o.name for o in CASE_OPTIONS}, "each oracle's threshold is recorded"
    with pytest.raises(SystemExit):
        main(["replay", "--help"])
    flags = set(re.findall(r"--[a-z-]+", capsys.readouterr().out))
    assert {f"--{option.name}" for option in REPLAY_OPTIONS} <= flags, "replay takes every flag a case's command gives"
    # a case records a setting away from its default, and its replay command gives it back
    settings = RunSettings(min_gap=3.0, tries=2, road_speed=(20.0, 30.0), dut_driver="late-acc")
    case = Case.of("s.osc", "s", settings, strategy="base", instance=1)
    again = Case.load(case.save(tmp_path / "case.json"))
    assert again.settings == settings.__class__(**{**dataclasses.asdict(settings), "strategy": "base"})
    command = case.command()
    assert "--min-gap 3.0" in command and "--tries 2" in command and "--road-speed 20.0..30.0mps" in command
    assert "--dut-driver late-acc" in command and "--encoding" not in command, "defaults are not repeated"


FLAKY_CONFTEST = f"""
import sys
sys.path.insert(0, {str(ROOT)!r})
from tests.drivers import NeverChangesLane

calls = []

def pytest_roadlogic_driver(config, scenario, vehicle):
    if vehicle != "v1":
        return None
    calls.append(vehicle)
    return NeverChangesLane() if len(calls) == 1 else None
"""


def test_a_failure_that_does_not_come_again_when_rerun_is_reported_as_it_happened_without_a_traceback(pytester):
    # as a simulation over its wall-clock limit on a loaded machine: Hypothesis reruns the failing
    # values, they pass, and it raises its FlakyFailure (an exception group)
    result = overtake_driven_by(pytester, FLAKY_CONFTEST)
    result.assert_outcomes(failed=1)
    report = result.stdout.str()
    assert "Traceback" not in report + result.stderr.str(), report
    assert "it did not fail again when rerun at the same values" in report
    assert "scenario overtake: the simulation was not accepted (non-conformant) at these values" in report
