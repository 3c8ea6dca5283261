"""A falsification campaign runs each search, from its own seed, as an independent job: its
outcomes are the serial run's whichever executor ran them, and ``roadlogic falsify`` reports the
first failure with a command that replays it."""

from __future__ import annotations

import json
import shlex
import subprocess
import sys

import pytest

from pytest_roadlogic.evaluation.falsification_campaign import falsify, search_seeds
from pytest_roadlogic.evaluation.scenario_source import ScenarioSource
from pytest_roadlogic.executors import executor
from pytest_roadlogic.settings import RunSettings
from tests.conftest import ROOT

CUT_OUT = ROOT / "scenarios" / "dut" / "cut_out.osc"
LATE = RunSettings(seed=1, search="cross-entropy", dut_driver="late-acc")


def test_the_searches_seeds_are_the_runs_own_then_ones_derived_from_it():
    assert search_seeds(7, 3) == [7, "7-search-1", "7-search-2"]


@pytest.mark.slow  # about 100 s on two cores; the executors themselves are tested by the coverage campaign's
def test_searches_on_two_processes_find_what_the_serial_run_finds_in_its_order():
    def outcomes(where):
        with where:
            return falsify(ScenarioSource(CUT_OUT), LATE, searches=2, budget=4, executor=where)

    serial = outcomes(executor())
    assert outcomes(executor(jobs=2)) == serial
    assert [o.seed for o in serial] == [1, "1-search-1"]
    # a late adaptive cruise control fails the cut-out: the steered search finds it at once
    assert all(o.failure is not None and o.failure.outcome == "failed" for o in serial)


def test_roadlogic_falsify_reports_the_first_failure_and_its_replay_fails_alike(tmp_path):
    command = [sys.executable, "-m", "pytest_roadlogic.cli"]
    found = subprocess.run(
        [
            *command,
            "falsify",
            str(CUT_OUT),
            "--dut-driver",
            "late-acc",
            "--searches",
            "1",
            "--budget",
            "4",
            "--search",
            "cross-entropy",
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=900,
    )
    assert found.returncode == 1, found.stdout + found.stderr
    assert "1 of 1 searches found a failure" in found.stdout
    replay = next(line for line in found.stdout.splitlines() if line.strip().startswith("replay: "))
    values = json.loads(
        next(line for line in found.stdout.splitlines() if line.strip().startswith("values: ")).split("values: ", 1)[1]
    )
    arguments = shlex.split(replay.split("replay: ", 1)[1])
    assert arguments[:2] == ["roadlogic", "replay"] and json.loads(arguments[arguments.index("--values") + 1]) == values
    again = subprocess.run(
        [*command, *arguments[1:], "--artifacts", "none"], capture_output=True, text=True, cwd=ROOT, timeout=900
    )
    assert again.returncode == 1 and "failed after" in again.stdout, again.stdout + again.stderr
