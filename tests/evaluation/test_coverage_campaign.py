"""A coverage campaign runs each sample, proof and closure case as an independent job: its tally
is the serial run's whichever executor ran the jobs, and ``roadlogic cover`` reports it, writes
it for a CI and says when the scenario has nothing to cover."""

from __future__ import annotations

import subprocess
import sys

import pytest

from pytest_roadlogic.evaluation.coverage import read_json
from pytest_roadlogic.evaluation.coverage_campaign import ScenarioSource, cover
from pytest_roadlogic.executors import executor
from pytest_roadlogic.settings import RunSettings
from tests.conftest import ROOT

CATCH_UP = ROOT / "scenarios" / "coverage" / "catch_up_from_behind.osc"


def tally(where) -> dict:
    with where:
        campaign = cover(ScenarioSource(CATCH_UP), RunSettings(seed=4), samples=6, closure=True, executor=where)
    return {
        "coverage": campaign.coverage.to_json(),
        "counts": (campaign.samples, campaign.without_plan, campaign.closure_cases, campaign.outcomes),
    }


@pytest.mark.parametrize("where", ["two processes", "a two-node Ray cluster"])
def test_a_coverage_campaign_elsewhere_tallies_what_the_serial_run_tallies(where, request):
    serial = tally(executor())
    if where == "two processes":
        elsewhere = executor(jobs=2)
    else:
        elsewhere = executor(ray=request.getfixturevalue("two_node_ray_cluster"))
    assert tally(elsewhere) == serial
    items = serial["coverage"]["items"]
    # the closure hit every bucket it could, and the one no car can reach is proved so
    assert items["gap_by_top"]["unreachable"].keys() == {"[80..120] m x [25..35) mps"}
    assert all(hits > 0 for label, hits in items["gap"]["buckets"].items())


def run_cover(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", "cover", *args],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=ROOT,
    )


def test_roadlogic_cover_with_closure_closes_the_scenario_and_writes_the_tally(tmp_path):
    written = tmp_path / "coverage.json"
    result = run_cover(str(CATCH_UP), "--samples", "4", "--closure", "--coverage", str(written), "--seed", "2")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "cover gap_by_top of the cross of gap and top" in result.stdout
    assert "unreachable: no plan exists at these values" in result.stdout
    [coverage] = read_json(written)
    assert coverage.items["top"].covered == coverage.items["top"].reachable == 2


def test_roadlogic_cover_without_closure_exits_1_while_a_bucket_is_open():
    result = run_cover(str(CATCH_UP), "--samples", "1", "--seed", "2")
    assert result.returncode == 1, result.stdout + result.stderr
    assert "not hit" in result.stdout


def test_roadlogic_cover_says_a_scenario_without_cover_items_has_nothing_to_cover():
    result = run_cover(str(ROOT / "scenarios" / "follow.osc"))
    assert result.returncode == 2
    assert "has no cover() or record() item; nothing to cover" in result.stderr
    assert "Traceback" not in result.stderr


def test_roadlogic_cover_refuses_both_a_process_pool_and_a_cluster():
    result = run_cover(str(CATCH_UP), "--jobs", "2", "--ray", "local")
    assert result.returncode == 2
    assert "roadlogic cover: --ray: --jobs runs the jobs on this machine's processes, --ray on a cluster's" in (
        result.stderr
    )
