"""The vehicle-under-test catalogue (scenarios/dut/) tells defective drivers from the good one: the
reference adaptive cruise control passes every test point, and each shipped defective driver fails
at least two of them, each with a named oracle. One case per file at seed 1, as ``roadlogic run``
makes it; the catalogue under pytest samples more."""

from pathlib import Path

import pytest

from pytest_roadlogic.dut import AUTO, UnderTest
from pytest_roadlogic.oracles.thresholds import Thresholds
from pytest_roadlogic.pipeline import load_scenario, run_instances

ROOT = Path(__file__).resolve().parents[2]
CATALOGUE = sorted((ROOT / "scenarios" / "dut").glob("*.osc"))
DEFECTIVE = ("late-acc", "weak-braking-acc", "slow-acquisition-acc")


def outcomes(driver: str) -> dict[str, list[str]]:
    """Per catalogue file, the failures of ``driver`` in its case at seed 1 (empty: passed); a
    case in which the scenario did not happen (not exercised) is ``["not exercised"]``."""
    under_test = UnderTest(AUTO, driver, Thresholds.given())
    found = {}
    for path in CATALOGUE:
        instance = next(run_instances(load_scenario(path), count=1, seed=1, under_test=under_test))
        assert instance.dut is not None, f"{path.name}: no vehicle under test"
        happened = instance.verdict.accepted or instance.dut.failures
        found[path.stem] = instance.dut.failures if happened else ["not exercised"]
    return found


def test_the_catalogue_has_stationary_moving_and_braking_targets_and_the_cut_in_and_out_cases():
    names = {path.stem for path in CATALOGUE}
    assert len(names) >= 6
    assert {"ccr_stationary", "ccr_moving", "ccr_braking", "cut_in", "cut_out", "lead_brake"} <= names


def test_the_reference_driver_passes_every_test_point_of_the_catalogue_and_each_scenario_happens_around_it():
    failed = {name: failures for name, failures in outcomes("acc").items() if failures}
    assert not failed, failed


# one defective driver by default, the others with --run-slow (about a minute each on two cores)
@pytest.mark.parametrize(
    "driver",
    [driver if driver == "weak-braking-acc" else pytest.param(driver, marks=pytest.mark.slow) for driver in DEFECTIVE],
)
def test_each_defective_driver_fails_at_least_two_test_points_each_with_a_named_oracle(driver):
    failed = {name: failures for name, failures in outcomes(driver).items() if failures not in ([], ["not exercised"])}
    assert len(failed) >= 2, f"{driver} fails only {sorted(failed)}"
    for name, failures in failed.items():
        assert any("threshold" in f or "collision" in f for f in failures), (name, failures)
