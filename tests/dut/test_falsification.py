"""Falsification: the cross-entropy search steers toward a failure from its first samples, is fixed by
its seed, and a failure it finds is shrunk and replays exactly under pytest."""

from __future__ import annotations

import re
import statistics

import pytest
from hypothesis import HealthCheck, Phase, given, settings, target
from hypothesis import seed as seeded
from hypothesis import strategies as st

from pytest_roadlogic.case import Case
from pytest_roadlogic.falsification import backend
from tests.conftest import ROOT

pytest_plugins = ["pytester"]

QUIET = ["-p", "no:cacheprovider", "-p", "no:randomly"]


class Found(Exception):
    pass


def corner(x: int, y: int) -> tuple[float, bool]:
    """How close a sample came to a rare failure at a corner of the space (higher: closer), and
    whether it failed: low ``x`` and high ``y``, 0.5% of the space."""
    return -(max(x - 20, 0) / 281 + max(37 - y, 0) / 41), x < 20 and y > 37


def inside(x: int, y: int) -> tuple[float, bool]:
    """The same for a rare failure inside the space, away from every range's end: a disc around
    (200, 10) covering 0.5% of it."""
    distance = ((x - 200) / 281) ** 2 + ((y - 10) / 41) ** 2
    return -distance, distance < 0.04**2


def samples_to_failure(seed: int, search: str, failure, budget: int = 400) -> int:
    """Samples a property search needs to reach ``failure`` (the budget when it does not)."""
    count, first = 0, None

    @seeded(seed)
    @settings(
        max_examples=budget,
        database=None,
        deadline=None,
        phases=[Phase.generate],
        suppress_health_check=list(HealthCheck),
        backend=backend(seed, steered=search == "cross-entropy"),
    )
    @given(st.integers(0, 280), st.integers(0, 40))
    def search_for_it(x: int, y: int) -> None:
        nonlocal count, first
        count += 1
        closeness, failed = failure(x, y)
        target(closeness)
        if failed:
            first = count if first is None else first
            raise Found()

    try:
        search_for_it()
    except Found:
        pass
    return first or budget


def test_the_cross_entropy_search_probes_the_corners_first_and_so_finds_a_failure_at_one_within_five_samples():
    # Hypothesis's simplest sample, then the four corners of two parameters
    assert all(samples_to_failure(seed, "cross-entropy", corner) <= 5 for seed in range(10))


def test_the_cross_entropy_search_reaches_a_rare_failure_inside_the_space_in_a_third_of_the_samples_random_needs():
    steered = [samples_to_failure(seed, "cross-entropy", inside) for seed in range(20)]
    uniform = [samples_to_failure(seed, "random", inside) for seed in range(20)]
    assert statistics.median(steered) * 3 <= statistics.median(uniform), (steered, uniform)


def test_one_seed_draws_the_same_samples_and_another_seed_other_ones():
    def drawn(seed: int) -> list[int]:
        values = []

        @seeded(seed)
        @settings(max_examples=30, database=None, phases=[Phase.generate], backend=backend(seed))
        @given(st.integers(0, 1000))
        def collect(x: int) -> None:
            values.append(x)
            target(float(x))

        collect()
        return values

    assert drawn(3) == drawn(3)
    assert drawn(3) != drawn(4)
    assert backend("a text seed") == backend("a text seed"), "pytest's --hypothesis-seed may be a text"


def test_a_failure_the_cross_entropy_search_finds_is_shrunk_and_its_case_replays_to_the_same_failure(pytester):
    # a car braking ahead, which a driver braking at most 3 m/s^2 fails at some values; the car
    # ahead does not react to the vehicle under test, so it follows its first plan (replan period 0)
    scenario = ROOT / "benchmarks" / "scenarios" / "rear_braking_rare.osc"
    (pytester.path / "rear_braking_rare.osc").write_text(scenario.read_text())
    options = [
        "--roadlogic-search",
        "cross-entropy",
        "--roadlogic-dut-driver",
        "weak-braking-acc",
        "--roadlogic-replan-period",
        "0",
        "--roadlogic-examples",
        "20",
        "--roadlogic-tries",
        "1",
        *QUIET,
    ]
    found = pytester.runpytest_subprocess(*options)
    found.assert_outcomes(failed=1)
    assert "the vehicle under test failed" in found.stdout.str()
    assert re.search(r"dut\.car: (time to collision|gap|time headway|ran into)", found.stdout.str()), (
        "the oracle is named"
    )
    assert "Traceback" not in found.stdout.str() + found.stderr.str()
    case_file = next(pytester.path.glob("roadlogic-artifacts/*/case.json"))
    case = Case.load(case_file)
    assert case.settings.dut_driver == "weak-braking-acc" and case.values, "the shrunk values are recorded"
    again = pytester.runpytest_subprocess("--roadlogic-replay", str(case_file), *QUIET)
    again.assert_outcomes(failed=1)
    assert "the vehicle under test failed" in again.stdout.str()


def test_a_search_the_tool_does_not_have_is_a_usage_error_naming_the_option(pytester):
    pytester.makefile(".osc", empty="")
    result = pytester.runpytest_subprocess("--roadlogic-search", "annealing", *QUIET)
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    assert (
        "--roadlogic-search (ini roadlogic_search): 'annealing' is not a search; give hypothesis or random or "
        "cross-entropy" in result.stderr.str()
    )
