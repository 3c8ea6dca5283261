"""A vehicle under test under pytest: its outcomes (passed, failed, not exercised), what a failure
says and records, how it replays, and the options that choose it and judge it."""

from __future__ import annotations

import json
from collections import Counter

import pytest

from pytest_roadlogic.case import Case, CaseFileError
from pytest_roadlogic.oracles import ORACLES
from pytest_roadlogic.outcomes import DUT_FAILED, NOT_EXERCISED, PASSED, mostly_not_exercised
from pytest_roadlogic.registries.drivers import BUILT_IN
from pytest_roadlogic.settings import RunSettings
from tests.conftest import ROOT

pytest_plugins = ["pytester"]

DUT = ROOT / "scenarios" / "dut"
QUIET = ["-p", "no:cacheprovider", "-p", "no:randomly"]
# one plan, one try: no sampling and no shrinking, so that each run is one simulation
ONE = ["--roadlogic-strategy", "base", "--roadlogic-examples", "1", "--roadlogic-tries", "1", *QUIET]


def copy(pytester, name: str) -> None:
    (pytester.path / name).write_text((DUT / name).read_text())


def junit_properties(path) -> dict[str, str]:
    import xml.etree.ElementTree as ET

    return {p.get("name"): p.get("value") for p in ET.parse(path).iter("property")}


def test_the_reference_vehicle_passes_the_cut_out_and_the_one_that_reacts_late_fails_naming_the_oracle(pytester):
    copy(pytester, "cut_out.osc")
    good = pytester.runpytest_subprocess(*ONE, "--junitxml", "good.xml")
    good.assert_outcomes(passed=1)
    properties = junit_properties(pytester.path / "good.xml")
    assert properties["passed"] == "1" and properties["vehicle_under_test"] == "dut.car"
    assert float(properties["dut_min_gap_m"]) >= 2.0

    late = pytester.runpytest_subprocess(
        *ONE, "--roadlogic-dut-driver", "late-acc", "--html", "report.html", "--self-contained-html"
    )
    late.assert_outcomes(failed=1)
    page = (pytester.path / "report.html").read_text()
    assert "roadlogic-oracles" in page and "least time to collision" in page, "the HTML report shows every oracle"
    report = late.stdout.str()
    assert "scenario cut_out: the vehicle under test failed (failed)" in report
    assert "the vehicle under test failed after 1 plans tried: dut.car: " in report
    assert any(oracle in report for oracle in ("ran into wreck ahead", "time to collision", "gap ")), report
    verdict = json.loads(next(pytester.path.glob("roadlogic-artifacts/*/verdict.json")).read_text())
    assert verdict["vehicle_under_test"]["failures"] and verdict["replans"], "the oracles and the replans are recorded"
    case = Case.load(next(pytester.path.glob("roadlogic-artifacts/*/case.json")))
    assert (
        case.settings.dut == "auto" and case.settings.dut_driver == "late-acc" and case.settings.replan_period == 0.25
    )

    # the case replays to the same failure under pytest, with the recorded reference driver
    again = pytester.runpytest_subprocess(
        "--roadlogic-replay", str(next(pytester.path.glob("roadlogic-artifacts/*/case.json"))), *QUIET
    )
    again.assert_outcomes(failed=1)
    assert "the vehicle under test failed" in again.stdout.str()


def test_an_item_whose_cases_mostly_did_not_happen_fails_saying_it_tested_nothing_with_the_last_cases_artifacts(
    pytester,
):
    # open loop (no replanning) the npc cuts in where the plan expected the vehicle under test, not
    # where it is: at these values the cut-in does not happen (tests/simulation/test_reactive.py)
    from tests.simulation.test_reactive import VALUES

    copy(pytester, "cut_in.osc")
    # a vehicle under test set 15% below the speed it starts at: its plan holds the speed
    pytester.makeconftest(
        "from pytest_roadlogic.dut.reference_drivers import AdaptiveCruiseControl\n\n"
        "class Cautious(AdaptiveCruiseControl):\n"
        "    def start(self, vehicle, reference, road, dt):\n"
        "        super().start(vehicle, reference, road, dt)\n"
        "        self.set_speed *= 0.85\n\n"
        "def pytest_roadlogic_driver(config, scenario, vehicle):\n"
        "    return Cautious() if vehicle == 'dut.car' else None\n"
    )
    settings = RunSettings(replan_period=0.0, tries=1)
    case = Case.of("cut_in.osc", "cut_in", settings, values=VALUES, drivers={"dut.car": "conftest:Cautious"})
    case = case.save(pytester.path / "case.json")
    result = pytester.runpytest_subprocess("--roadlogic-replay", str(case), *QUIET)
    result.assert_outcomes(failed=1)
    report = result.stdout.str()
    assert "1 of 1 cases were not exercised (the scenario did not happen around the vehicle under test" in report
    # reported as a failing case is: its values, its artifacts and how to replay it
    assert "the scenario did not happen (not exercised)" in report and "artifacts:" in report
    assert "replay: pytest" in report and "roadlogic replay" in report


def test_none_scripts_every_vehicle_and_a_vehicle_the_scenario_lacks_is_a_usage_error(pytester):
    copy(pytester, "cut_out.osc")
    scripted = pytester.runpytest_subprocess(*ONE, "--roadlogic-dut", "none", "--junitxml", "none.xml")
    scripted.assert_outcomes(passed=1)
    properties = junit_properties(pytester.path / "none.xml")
    assert properties["conformant"] == "1" and "vehicle_under_test" not in properties
    missing = pytester.runpytest_subprocess(*ONE, "--roadlogic-dut", "hero")
    assert missing.ret == pytest.ExitCode.USAGE_ERROR
    assert "--roadlogic-dut (ini roadlogic_dut): no collected scenario has a vehicle 'hero'" in missing.stderr.str()
    assert "Traceback" not in missing.stdout.str() + missing.stderr.str()


@pytest.mark.parametrize(
    "option, value",
    [
        ("dut-driver", "perfect"),
        ("min-ttc", "-1"),
        ("min-gap", "x"),
        ("max-decel", "0"),
        ("replan-period", "-2"),
        ("replan-period", "0.05"),
    ],
)
def test_a_bad_value_of_an_oracle_or_driver_option_is_a_usage_error_naming_the_option(pytester, option, value):
    copy(pytester, "cut_out.osc")
    result = pytester.runpytest_subprocess(f"--roadlogic-{option}={value}", *QUIET)
    assert result.ret != 0
    assert f"--roadlogic-{option}" in result.stderr.str() + result.stdout.str()
    assert "Traceback" not in result.stderr.str() + result.stdout.str()


def test_a_case_file_keeps_who_was_under_test_and_refuses_a_crafted_value(tmp_path):
    settings = RunSettings(dut="ego", dut_driver="weak-braking-acc", min_ttc=2.0, replan_period=0.0)
    case = Case.of("s.osc", "s", settings)
    again = Case.load(case.save(tmp_path / "case.json")).settings
    assert (again.dut, again.dut_driver, again.min_ttc, again.replan_period) == ("ego", "weak-braking-acc", 2.0, 0.0)
    data = json.loads((tmp_path / "case.json").read_text())
    data["dut_driver"] = "os:system"
    (tmp_path / "crafted.json").write_text(json.dumps(data))
    with pytest.raises(CaseFileError, match="reference driver"):
        Case.load(tmp_path / "crafted.json")
    # a case file from before vehicles under test scripted every vehicle, and still does
    del data["dut"], data["dut_driver"]
    (tmp_path / "old.json").write_text(json.dumps(data))
    assert Case.load(tmp_path / "old.json").settings.dut == "none"


def test_an_item_fails_when_most_of_its_simulated_cases_were_not_exercised():
    assert mostly_not_exercised(Counter({NOT_EXERCISED: 3, PASSED: 2}))
    assert not mostly_not_exercised(Counter({NOT_EXERCISED: 2, PASSED: 2}))
    assert not mostly_not_exercised(Counter({NOT_EXERCISED: 1, DUT_FAILED: 1, PASSED: 1}))
    assert not mostly_not_exercised(Counter())


def test_a_conftest_judges_one_scenario_by_its_own_thresholds_and_a_bad_one_is_named(pytester):
    copy(pytester, "cut_out.osc")
    # a gap of 50 m is more than the reference keeps to the stopped car: its own threshold fails it
    pytester.makeconftest(
        "def pytest_roadlogic_oracles(config, scenario):\n"
        "    return {'min-gap': 50} if scenario.name == 'cut_out' else None\n"
    )
    strict = pytester.runpytest_subprocess(*ONE)
    strict.assert_outcomes(failed=1)
    assert "(threshold 50 m)" in strict.stdout.str()
    pytester.makeconftest("def pytest_roadlogic_oracles(config, scenario):\n    return {'min_ttc': 'soon'}\n")
    bad = pytester.runpytest_subprocess(*ONE)
    options = ", ".join(oracle.option for oracle in ORACLES)
    assert f"pytest_roadlogic_oracles gave 'min_ttc' for scenario cut_out; give {options}" in (bad.stdout.str())


def test_roadlogic_run_prints_a_gap_of_zero_as_zero_and_no_one_ahead_as_inf():
    from pytest_roadlogic.cli.common import oracle_line
    from pytest_roadlogic.oracles import Closest, DutReport, Thresholds

    line = oracle_line(DutReport("dut.car", Thresholds(), measured={"gap": Closest(0.0, 1.0, "npc")}), replans=3)
    assert "least time to collision inf s" in line and "least gap 0.0 m" in line and "3 replans" in line


PACKAGED_DRIVER = '''
from pathlib import Path

from pytest_roadlogic.dut.reference_drivers import AdaptiveCruiseControl


class Cautious(AdaptiveCruiseControl):
    """An adaptive cruise control that leaves itself a second more."""

    def start(self, vehicle, reference, road, dt):
        Path("CAUTIOUS_DROVE").write_text(vehicle)
        super().start(vehicle, reference, road, dt)
'''


def test_a_reference_driver_plugs_in_from_an_installed_package_through_its_entry_point_alone(pytester, monkeypatch):
    # a package on the path with nothing but its module and its metadata: no hook, no conftest
    site = pytester.path / "site"
    (site / "cautious_acc-1.0.dist-info").mkdir(parents=True)
    (site / "cautious_acc.py").write_text(PACKAGED_DRIVER)
    (site / "cautious_acc-1.0.dist-info" / "METADATA").write_text(
        "Metadata-Version: 2.1\nName: cautious-acc\nVersion: 1.0\n"
    )
    (site / "cautious_acc-1.0.dist-info" / "entry_points.txt").write_text(
        "[pytest_roadlogic.drivers]\ncautious = cautious_acc:Cautious\nbroken = broken_acc:Driver\n"
    )
    (site / "broken_acc.py").write_text("import a_module_nobody_installed\n")
    monkeypatch.setenv("PYTHONPATH", str(site))
    copy(pytester, "cut_in.osc")
    result = pytester.runpytest_subprocess(*ONE, "--roadlogic-dut-driver", "cautious")
    result.assert_outcomes(passed=1)
    assert (pytester.path / "CAUTIOUS_DROVE").read_text() == "dut.car", (
        "the package's driver drove the vehicle under test"
    )

    broken = pytester.runpytest_subprocess(*ONE, "--roadlogic-dut-driver", "broken")
    assert "the entry point broken_acc:Driver for the reference driver 'broken' cannot be loaded" in broken.stderr.str()
    assert "Traceback" not in broken.stderr.str() + broken.stdout.str()

    unknown = pytester.runpytest_subprocess(*ONE, "--roadlogic-dut-driver", "reckless")
    names = " or ".join([*BUILT_IN, "cautious", "broken"])
    assert f"'reckless' is not a reference driver of the vehicle under test; give {names}" in unknown.stderr.str()
