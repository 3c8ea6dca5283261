"""From the README: the CLI and the pytest plugin on the paper's overtake."""

import json
import subprocess
import sys

from tests.conftest import OVERTAKE, ROOT


def run_cli(*args):
    return subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", *args], capture_output=True, text=True, cwd=ROOT
    )


def test_roadlogic_run_writes_every_artifact_and_accepts(tmp_path):
    result = run_cli("run", str(OVERTAKE), "--seed", "1", "--out", str(tmp_path))
    assert result.returncode == 0, result.stdout + result.stderr
    for name in (
        "plan.json",
        "trace.csv",
        "scenario.xml",
        "scenario.xosc",
        "road.xodr",
        "trajectories.png",
        "simulation.gif",
        "verdict.json",
    ):
        assert (tmp_path / name).stat().st_size > 0, name
    assert not [p.name for p in tmp_path.iterdir() if "partial" in p.name], "a temporary file was left behind"
    from PIL import Image

    samples = {line.split(",")[0] for line in (tmp_path / "trace.csv").read_text().splitlines()[1:]}
    with Image.open(tmp_path / "simulation.gif") as gif:
        assert gif.n_frames >= len(samples) // 2, "the animation shows the whole run, a frame every 0.2 s"
    verdict = json.loads((tmp_path / "verdict.json").read_text())
    assert verdict["accepted"] is True
    for stage in ("planning", "simulation", "monitoring"):
        assert stage in result.stdout
    assert "HiGHS" not in result.stdout, "the LP solver's banner is not part of the report"


def test_run_with_essential_artifacts_writes_what_a_replay_needs_and_the_case_replays(tmp_path):
    out = tmp_path / "out"
    result = run_cli("run", str(OVERTAKE.relative_to(ROOT)), "--artifacts", "essential", "--out", str(out))
    assert result.returncode == 0, result.stdout + result.stderr
    assert sorted(p.name for p in out.iterdir()) == ["case.json", "plan.json", "trace.csv", "verdict.json"]
    # the verdict is printed before the artifacts are written
    assert result.stdout.index("accepted (robustness") < result.stdout.index("artifacts")
    again = run_cli("replay", str(out / "case.json"), "--artifacts", "essential", "--out", str(tmp_path / "again"))
    assert again.returncode == 0, again.stdout + again.stderr
    assert (tmp_path / "again" / "trace.csv").read_text() == (out / "trace.csv").read_text()


def test_run_with_no_artifacts_writes_nothing_and_a_bad_level_is_refused(tmp_path):
    result = run_cli("run", str(OVERTAKE), "--artifacts", "none", "--out", str(tmp_path / "out"))
    assert result.returncode == 0, result.stdout + result.stderr
    assert not (tmp_path / "out").exists() and "artifacts" not in result.stdout
    refused = run_cli("run", str(OVERTAKE), "--artifacts", "some", "--out", str(tmp_path / "out"))
    assert refused.returncode == 2 and "--artifacts" in refused.stderr and "Traceback" not in refused.stderr


def test_the_same_seed_gives_the_same_plan_and_trace(tmp_path):
    for run in ("a", "b"):
        assert run_cli("run", str(OVERTAKE), "--seed", "2", "--out", str(tmp_path / run)).returncode == 0
    for name in ("plan.json", "trace.csv"):
        first = (tmp_path / "a" / name).read_text()
        second = (tmp_path / "b" / name).read_text()
        if name == "plan.json":
            first, second = json.loads(first), json.loads(second)
            first.pop("stats"), second.pop("stats")
        assert first == second, f"{name} differs between two runs with seed 2"


def test_a_broken_file_is_a_clear_error_not_a_traceback(tmp_path):
    bad = tmp_path / "bad.osc"
    bad.write_text("scenario s:\n  v1: car\n  do v1.drive() with:\n    position([1..2]m, behind: v9, at: start)\n")
    result = run_cli("run", str(bad), "--out", str(tmp_path / "out"))
    assert result.returncode == 2
    assert f"{bad}:4:31: error: unknown actor 'v9'" in result.stderr
    assert "Traceback" not in result.stderr


def test_pytest_collects_osc_files_runs_them_and_reports_broken_ones(tmp_path):
    (tmp_path / "overtake.osc").write_text(OVERTAKE.read_text())
    (tmp_path / "broken.osc").write_text("scenario s:\n  v1 car\n")
    (tmp_path / "unknown.osc").write_text(
        "scenario u:\n  v1: car\n  do v1.drive() with:\n    lane(same_as: v7, at: end)\n"
    )
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            str(tmp_path),
            "-p",
            "no:cacheprovider",
            "--roadlogic-artifacts",
            str(tmp_path / "art"),
            "-q",
            "--rootdir",
            str(tmp_path),
        ],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert "1 passed" in result.stdout and "2 errors" in result.stdout, result.stdout
    assert "broken.osc:2:" in result.stdout
    assert not (tmp_path / "art").exists(), "artifacts are written for failing cases only"
    # a checker error is reported at collection with the same words as `roadlogic check`
    check = run_cli("check", str(tmp_path / "unknown.osc"))
    first_line = check.stdout.splitlines()[0]
    assert first_line.endswith("unknown.osc:4:19: error: unknown actor 'v7'")
    assert first_line in result.stdout


def test_roadlogic_check_reports_every_bad_file_with_a_summary(tmp_path):
    (tmp_path / "good.osc").write_text(OVERTAKE.read_text())
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "unit.osc").write_text(
        "scenario s:\n  a: car\n  b: car\n  do a.drive() with:\n    position(3s, behind: b, at: end)\n"
    )
    result = run_cli("check", str(tmp_path))
    assert result.returncode == 1
    assert (
        f"{tmp_path / 'sub' / 'unit.osc'}:5:14: error: position() expects a length for distance, got a time"
        in result.stdout
    )
    assert result.stdout.strip().endswith("2 files, 1 ok, 1 with errors")


def test_roadlogic_check_of_the_benchmark_suite_exits_0():
    # the paper's seven; scenarios/realistic/ holds files the front end does not read yet (issue 18)
    result = run_cli("check", *map(str, sorted((ROOT / "scenarios").glob("*.osc"))))
    assert result.returncode == 0, result.stdout
    assert "7 files, 7 ok, 0 with errors" in result.stdout


def test_syntax_only_skips_the_checker(tmp_path):
    (tmp_path / "other.osc").write_text("scenario s:\n  a: car\n  do a.fly()\n")
    assert run_cli("check", str(tmp_path)).returncode == 1
    assert run_cli("check", "--syntax-only", str(tmp_path)).returncode == 0


def test_roadlogic_run_instances_writes_each_instance_with_a_progress_bar(tmp_path):
    result = run_cli("run", str(ROOT / "scenarios" / "follow.osc"), "--instances", "2", "--out", str(tmp_path))
    assert result.returncode == 0, result.stdout + result.stderr
    assert "2 of 2 instances conformant" in result.stdout
    assert "[####################] 2/2" in result.stderr
    for index in (1, 2):
        assert (tmp_path / f"instance-00{index}" / "trace.csv").is_file()
    plans = [(tmp_path / f"instance-00{i}" / "plan.json").read_text() for i in (1, 2)]
    assert plans[0] != plans[1], "each instance is a different plan"


def test_a_run_outside_any_project_writes_no_case_file_that_names_a_path_from_the_root(tmp_path):
    scenario = tmp_path / "overtake.osc"
    scenario.write_text(OVERTAKE.read_text())
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest_roadlogic.cli",
            "run",
            str(scenario),
            "--artifacts",
            "essential",
            "--out",
            "out",
        ],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["plan.json", "trace.csv", "verdict.json"]
