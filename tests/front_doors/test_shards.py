"""One scenario across many workers: ``--roadlogic-shards N`` makes N items of a scenario that draw
disjoint shares of its samples, each shrinking and replaying its own failures."""

import json
import re

import pytest
from hypothesis import HealthCheck, given, seed, settings

from pytest_roadlogic.confinement import unique_name
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.sampling import Shard, strategy
from tests.conftest import ROOT

pytest_plugins = ["pytester"]

SQUEEZE = ROOT / "tests" / "scenarios" / "squeeze.osc"
QUIET = ["-p", "no:cacheprovider", "-p", "no:randomly"]


def drawn(shard: Shard | None, count: int = 40) -> list[dict]:
    """The first ``count`` samples of squeeze.osc that ``shard`` draws, with one fixed seed."""
    samples: list[dict] = []

    @seed(7)
    @settings(max_examples=count, database=None, derandomize=False, suppress_health_check=list(HealthCheck))
    @given(strategy(load_scenario(SQUEEZE), shard))
    def keep(values):
        samples.append(values)

    keep()
    return samples


def test_every_sample_belongs_to_exactly_one_shard_and_the_shares_add_up_to_the_examples():
    for values in drawn(None):
        assert sum(Shard(index, 3).holds(values) for index in range(3)) == 1, values
    for total in (0, 1, 7, 10, 200):
        shares = [Shard(index, 4).examples(total) for index in range(4)]
        assert sum(shares) == total and max(shares) - min(shares) <= 1, shares


def test_each_shard_draws_only_its_own_samples_so_shards_never_run_the_same_sample():
    first, second = Shard(0, 2), Shard(1, 2)
    ones, twos = drawn(first), drawn(second)
    assert all(first.holds(v) for v in ones) and all(second.holds(v) for v in twos)
    assert not {json.dumps(v, sort_keys=True) for v in ones} & {json.dumps(v, sort_keys=True) for v in twos}


@pytest.mark.slow  # two workers shrinking a failure: about 2 minutes
def test_a_scenario_split_over_two_xdist_workers_names_the_failing_shard_and_its_case_replays(pytester):
    # squeeze's gaps of 22.5..38 m have no plan: with 10 examples in two shards, both find some
    (pytester.path / "squeeze.osc").write_text(SQUEEZE.read_text())
    options = ["--roadlogic-encoding", "grid", "--roadlogic-horizon", "6", "--roadlogic-examples", "10", *QUIET]
    result = pytester.runpytest_subprocess(
        "--roadlogic-shards", "2", "--dist", "load", "--tx", "2*popen", "-v", *options
    )
    report = result.stdout.str()
    assert re.search(r"\[gw0\].*squeeze\.osc::squeeze\[\dof2\]", report), report
    assert re.search(r"\[gw1\].*squeeze\.osc::squeeze\[\dof2\]", report), "both workers ran a shard"
    failed = re.findall(r"FAILED squeeze\.osc::squeeze\[(\d)of2\]", report)
    assert failed, report
    shard = failed[0]
    assert f"shard {shard} of 2" in report, "the failure report names the shard"
    case_file = pytester.path / "roadlogic-artifacts" / unique_name(f"squeeze.osc::squeeze[{shard}of2]") / "case.json"
    if not case_file.is_file():  # the folder is the node id made safe; find it by its shard
        [case_file] = [p for p in (pytester.path / "roadlogic-artifacts").glob(f"*{shard}of2*/case.json")]
    command = f"pytest 'squeeze.osc::squeeze[{shard}of2]' --roadlogic-replay {case_file} --roadlogic-shards 2"
    assert command in report, report
    values = json.loads(case_file.read_text())["values"]
    assert Shard(int(shard) - 1, 2).holds(values), "the shrunk case is still the shard's own"

    again = pytester.runpytest_subprocess(
        f"squeeze.osc::squeeze[{shard}of2]", "--roadlogic-replay", str(case_file), "--roadlogic-shards", "2", *options
    )
    again.assert_outcomes(failed=1)
    assert "1 examples" in again.stdout.str()


def test_shards_with_the_base_strategy_are_a_usage_error_that_says_what_to_give(pytester):
    (pytester.path / "squeeze.osc").write_text(SQUEEZE.read_text())
    result = pytester.runpytest_subprocess("--roadlogic-shards", "2", "--roadlogic-strategy", "base", *QUIET)
    assert result.ret == 4, result.stdout.str()
    assert "--roadlogic-shards" in result.stderr.str() and "--roadlogic-strategy refined" in result.stderr.str()
    bad = pytester.runpytest_subprocess("--roadlogic-shards", "0", *QUIET)
    assert "give a whole number from 1 up" in bad.stderr.str()
