"""Every entry point runs the scenario the checker checked: the same logical parameters, the file's
own enums included, under the plugin, ``roadlogic run --values``, ``roadlogic replay`` and
``roadlogic bench``."""

import json
import subprocess
import sys

from tests.conftest import ROOT

CHOICE = ROOT / "tests" / "scenarios" / "choice.osc"
VALUES = json.dumps({"how": "overtake", "gap": 20.0, "parallel.duration": 4.0})
QUIET = ["-p", "no:cacheprovider", "-p", "no:randomly"]

pytest_plugins = ["pytester"]


def run_cli(*args, cwd=ROOT):
    return subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", *args], capture_output=True, text=True, cwd=cwd
    )


def test_the_plugin_samples_a_parameter_of_the_files_own_enum(pytester):
    (pytester.path / "choice.osc").write_text(CHOICE.read_text())
    pytester.makeconftest(
        "from pytest_roadlogic.sampling import logical_parameters\n"
        "def pytest_collection_modifyitems(items):\n"
        "    for item in items:\n"
        "        print('PARAMETERS', sorted(p.name for p in logical_parameters(item.scenario)))\n"
    )
    result = pytester.runpytest_subprocess("--collect-only", "-q", "-s", *QUIET)
    result.stdout.fnmatch_lines(["PARAMETERS ['gap', 'how', 'parallel.duration']"])


def test_run_values_accepts_a_value_of_the_files_own_enum(tmp_path):
    result = run_cli("run", str(CHOICE), "--values", VALUES, "--out", str(tmp_path))
    assert result.returncode == 0, result.stdout + result.stderr
    assert "unknown" not in result.stderr


def test_replay_accepts_a_value_of_the_files_own_enum(tmp_path):
    result = run_cli("replay", str(CHOICE), "--values", VALUES, "--out", str(tmp_path))
    assert result.returncode == 0, result.stdout + result.stderr


def test_bench_samples_a_parameter_of_the_files_own_enum(tmp_path):
    result = run_cli("bench", str(CHOICE), "--base", "0", "--refined", "2", "--no-artifacts", "--out", str(tmp_path))
    assert result.returncode in (0, 1), result.stdout + result.stderr  # 1: a target is missed (two samples say little)
    records = json.loads((tmp_path / "results.json").read_text())["instances"]
    assert [sorted(r["values"]) for r in records] == [["gap", "how", "parallel.duration"]] * 2
