"""One seed fixes every artifact: two processes with different ``PYTHONHASHSEED`` write the same
files, byte for byte, but for the fields that time a stage (scenario.xml's tags had come in the
order of a set of enums, which the hash seed decides)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import ROOT

# fields that measure how long something took: the only ones two runs may differ in
TIMING = {"seconds", "ground_s", "solve_s"}


def without_timing(data):
    if isinstance(data, dict):
        return {key: without_timing(value) for key, value in data.items() if key not in TIMING}
    if isinstance(data, list):
        return [without_timing(value) for value in data]
    return data


def run(scenario: Path, out: Path, hash_seed: str, *extra: str) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", "run", str(scenario), "--seed", "1", "--out", str(out), *extra],
        env={**os.environ, "PYTHONHASHSEED": hash_seed},
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=600,  # guards a hang only: a run takes seconds
    )
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize(
    "scenario, extra",
    [
        (ROOT / "scenarios" / "overtake.osc", ()),
        (ROOT / "scenarios" / "follow.osc", ("--map", "scenarios/roads/maps/curved_highway.xodr")),
    ],
    ids=["straight road", "on a map"],
)
def test_two_processes_with_different_hash_seeds_write_the_same_artifacts(tmp_path, scenario, extra):
    run(scenario, tmp_path / "one", "1", *extra)
    run(scenario, tmp_path / "other", "3", *extra)
    names = sorted(p.name for p in (tmp_path / "one").iterdir())
    assert names == sorted(p.name for p in (tmp_path / "other").iterdir())
    assert {"plan.json", "trace.csv", "scenario.xml", "scenario.xosc", "road.xodr", "verdict.json"} <= set(names)
    for name in names:
        one, other = (tmp_path / "one" / name), (tmp_path / "other" / name)
        if name.endswith(".json"):
            assert without_timing(json.loads(one.read_text())) == without_timing(json.loads(other.read_text())), name
        else:
            assert one.read_bytes() == other.read_bytes(), name
