"""Issue 19 as a user meets it under the default (continuous) planner: a band of values no concrete
scenario meets fails the item at the band's edge, reported as a scenario that cannot be
instantiated, with no other parameter blamed; ``--roadlogic-no-plan discard`` sets such samples
aside instead, and counts them.

``tests/scenarios/close_in.osc``: the ego must close on a lead at 20 m/s to 10 m within 4 s at no
more than 25 m/s. The band's edge: by the file's own arithmetic (exact values) 5 m/s * 4 s + 10 m
= 30 m; with the tolerances a single value is read with (20 +- 0.5 m/s, 10 +- 1.5 m, 4 +- 0.5 s)
5.5 * 4.5 + 11.5 = 36.25 m. A start gap above it has no plan; one below has plans.
"""

import re
import xml.etree.ElementTree as ET

import pytest

from tests.conftest import ROOT

pytest_plugins = ["pytester"]

CLOSE_IN = ROOT / "tests" / "scenarios" / "close_in.osc"
QUIET = ["-p", "no:cacheprovider", "-p", "no:randomly"]
EXACT_EDGE, TOLERANT_EDGE = 30.0, 36.25


def test_a_band_no_plan_meets_fails_at_its_edge_as_a_scenario_that_cannot_be_instantiated(pytester):
    (pytester.path / CLOSE_IN.name).write_text(CLOSE_IN.read_text())
    result = pytester.runpytest_subprocess("--roadlogic-examples", "20", "--junitxml", "junit.xml", *QUIET)
    result.assert_outcomes(failed=1)
    report = result.stdout.str()
    assert "scenario close_in: the scenario cannot be instantiated (no plan) at these values" in report, report
    # The failure section only: on CI (the CI variable set) pytest's short summary repeats the
    # whole message untruncated.
    failure = report.split("short test summary info")[0]
    values = re.findall(r"^  (\S+) = ([\d.]+) m \(line (\d+), ([^)]*)\)$", failure, re.MULTILINE)
    assert [(name, line, kind) for name, _, line, kind in values] == [("start_gap", "7", "declared parameter")], "no other parameter is blamed"
    gap = float(values[0][1])
    assert EXACT_EDGE <= gap <= TOLERANT_EDGE, f"the shrunk start gap {gap} m is not at the band's edge ({EXACT_EDGE}-{TOLERANT_EDGE} m)"
    assert "cannot hold together" in report, "the constraints that clash are named"
    properties = {p.get("name"): p.get("value") for p in ET.parse(pytester.path / "junit.xml").iter("property")}
    assert properties["failure_kind"] == "the scenario cannot be instantiated" and properties["verdict"] == "no plan"


def test_with_no_plan_discard_the_samples_without_a_plan_are_set_aside_and_counted(pytester):
    # the range reaches a little past the edge: most samples have plans, a few do not
    (pytester.path / CLOSE_IN.name).write_text(CLOSE_IN.read_text().replace("[12m..80m]", "[12m..40m]"))
    result = pytester.runpytest_subprocess("--roadlogic-examples", "10", "--roadlogic-no-plan", "discard", "--junitxml", "junit.xml", *QUIET)
    result.assert_outcomes(passed=1)
    properties = {p.get("name"): p.get("value") for p in ET.parse(pytester.path / "junit.xml").iter("property")}
    assert int(properties["discarded"]) >= 1 and int(properties["discarded"]) == int(properties["no_plan"])
    assert "samples without a plan discarded: --roadlogic-no-plan discard" in result.stdout.str()


def test_a_bad_no_plan_value_names_the_option(pytester):
    (pytester.path / CLOSE_IN.name).write_text(CLOSE_IN.read_text())
    result = pytester.runpytest_subprocess("--roadlogic-no-plan", "skip", *QUIET)
    assert result.ret != 0
    result.stderr.fnmatch_lines(["*--roadlogic-no-plan*'skip' is not what to do with a sample without a plan; give fail or discard*"])


@pytest.mark.parametrize(
    "start_gap, error, named",
    [(28.0, "MarginsBind", "speed_margin 0.5 m/s"), (30.0, "StepBinds", "plans in steps of 0.5 s exist")],
    ids=["only-thinner-margins", "only-in-half-steps"],
)
def test_a_case_only_plans_beyond_the_tools_margins_or_step_meet_is_a_tool_limit_when_not_accepted(start_gap, error, named):
    # close_in at 28 m has plans only with thinner margins, at 30 m only in half steps (measured);
    # a vehicle that never goes faster than 15 m/s makes every simulation fail
    from pytest_roadlogic.pipeline import load_scenario
    from pytest_roadlogic.runner import TOOL_LIMIT, Runner
    from pytest_roadlogic.settings import REFINED, RunSettings
    from tests.drivers import NeverChangesLane

    runner = Runner(load_scenario(CLOSE_IN), RunSettings(tries=1), drivers=lambda vehicle: NeverChangesLane() if vehicle == "ego" else None)
    result = runner.run_case(runner.case(strategy=REFINED, values={"start_gap": start_gap}), explain=False)
    assert (result.kind, type(result.error).__name__) == (TOOL_LIMIT, error), result.message
    assert named in result.message and "not accepted" in result.message


def test_a_planning_time_limit_that_runs_out_is_a_tool_limit_naming_the_option():
    from pytest_roadlogic.pipeline import load_scenario
    from pytest_roadlogic.runner import TOOL_LIMIT, Runner
    from pytest_roadlogic.settings import REFINED, RunSettings

    runner = Runner(load_scenario(CLOSE_IN), RunSettings(planning_time_limit=1e-6))
    result = runner.run_case(runner.case(strategy=REFINED, values={"start_gap": 20.0}), explain=False)
    assert (result.outcome, result.kind) == ("timed out", TOOL_LIMIT)
    assert "--roadlogic-plan-timeout" in result.message
