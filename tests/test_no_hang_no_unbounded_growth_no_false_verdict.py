"""Issue 38, items 5-18: no hang, no unbounded growth, no false or missing verdict, no usage error
that crashes later, and the README's commands as written. Items 1-4 are in test_security.py. Each
test names the item it checks. A hang is caught by running the command in a subprocess with a
bound far above what it takes (a bound, not a speed target)."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from pytest_roadlogic import cli
from pytest_roadlogic.frontend import OscError, check_text, load_file
from tests.conftest import ROOT

pytest_plugins = ["pytester"]
QUIET = ["-p", "no:cacheprovider", "-p", "no:randomly"]
README = (ROOT / "README.md").read_text()


def roadlogic(*args: str, cwd: Path | None = None, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", *args], capture_output=True, text=True, cwd=cwd, timeout=timeout
    )


def parallel_of(members: int, action: str = "drive() with:\n            speed([10..20]kph)") -> str:
    fields = "".join(f"    v{i}: vehicle\n" for i in range(members))
    body = "".join(f"        v{i}.{action}\n" for i in range(members))
    return f"scenario many:\n{fields}    do parallel(duration: 5s):\n{body}"


# ------------------------------------------------------------------ hangs and resources


def test_item_5_a_parallel_of_thirty_members_checks_without_enumerating_their_product(tmp_path):
    """30 members had never finished: every combination of their moves was made, then filtered."""
    (tmp_path / "many.osc").write_text(parallel_of(30))
    done = roadlogic("check", str(tmp_path / "many.osc"), timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr


def test_item_5_a_parallel_whose_product_is_too_large_is_refused_at_the_composition(tmp_path):
    (tmp_path / "many.osc").write_text(parallel_of(24, "change_lane(side: left)"))
    done = roadlogic("check", str(tmp_path / "many.osc"), timeout=60)
    assert done.returncode == 1
    assert re.search(r"many\.osc:26:8: error: this parallel's automaton grows past 20,000 transitions", done.stdout), (
        done.stdout
    )


def test_item_6_a_horizon_past_the_longest_is_a_usage_error_naming_the_option(capsys):
    with pytest.raises(SystemExit) as ended:
        cli.main(["plan", str(ROOT / "scenarios" / "follow.osc"), "--horizon", "2000000"])
    assert ended.value.code == 2
    assert (
        "argument --horizon: '2000000' is past the longest planning horizon; give a whole number of steps from 1 to 3600"
        in capsys.readouterr().err
    )


def test_item_6_the_plan_timeout_bounds_grounding_too(tmp_path):
    """A 3,500 s scenario of five vehicles had grounded for 55 s (1.7 GB) under a 5 s limit."""
    fields = "".join(f"    v{i}: vehicle\n" for i in range(5))
    body = "".join(f"        v{i}.drive() with:\n            speed([10..20]kph)\n" for i in range(5))
    (tmp_path / "long.osc").write_text(f"scenario long:\n{fields}    do parallel(duration: 3500s):\n{body}")
    done = roadlogic("plan", str(tmp_path / "long.osc"), "--horizon", "3600", "--plan-timeout", "2", timeout=40)
    assert done.returncode == 1
    assert "planning ran out of its time limit (2 s) while grounding step" in done.stderr, done.stderr


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are POSIX")
def test_item_7_a_fifo_named_like_a_scenario_is_skipped_with_a_warning(tmp_path):
    os.mkfifo(tmp_path / "x.osc")
    (tmp_path / "good.osc").write_text("scenario good:\n    v1: car\n    do v1.drive(duration: 3s)\n")
    done = roadlogic("check", str(tmp_path), timeout=30)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "x.osc: warning: skipped: not a regular file (a FIFO)" in done.stderr
    assert "1 files, 1 ok" in done.stdout
    named = roadlogic("check", str(tmp_path / "x.osc"), timeout=30)
    assert named.returncode == 1 and "cannot read the file: not a regular file (a FIFO)" in named.stdout


# ------------------------------------------------------------------ false or missing verdicts

KEEP = """scenario s:
    v1: vehicle
    v2: vehicle
    a: length with:
        keep(it in [15..25]m)
    b: length with:
        keep(it in [15..25]m)
    keep(a + b <= {limit}m)
    do v1.drive(duration: 5s) with:
        position(a, behind: v2, at: start)
"""


def test_item_8_a_keep_that_no_values_of_the_ranges_meet_is_a_located_error():
    with pytest.raises(OscError) as refused:
        check_text(KEEP.format(limit=20), "keep.osc").raise_for_errors()
    first = refused.value.errors[0]
    assert (first.location.line, first.location.column) == (8, 5)
    assert first.message == "no values of the parameters' ranges meet this constraint"
    check_text(KEEP.format(limit=40), "keep.osc").raise_for_errors()  # some values meet it: kept


def test_item_8_values_that_break_a_keep_relating_parameters_are_refused_where_they_enter(tmp_path, capsys):
    (tmp_path / "keep.osc").write_text(KEEP.format(limit=40))
    assert (
        cli.main(["run", str(tmp_path / "keep.osc"), "--values", '{"a": 16, "b": 25}', "--out", str(tmp_path / "o")])
        == cli.EXIT_INPUT
    )
    assert "a = 16, b = 25 break the constraint at keep.osc:8:5" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_item_8_under_pytest_a_keep_no_values_meet_is_one_collection_error_not_a_hypothesis_traceback(pytester):
    pytester.makefile(".osc", keep=KEEP.format(limit=20))
    result = pytester.runpytest_subprocess(*QUIET)
    result.assert_outcomes(errors=1)
    assert "keep.osc:8:5: error: no values of the parameters' ranges meet this constraint" in result.stdout.str()
    assert "Unsatisfiable" not in result.stdout.str() and "Traceback" not in result.stdout.str()


RECURSIVE = """scenario a:
    v1: vehicle
    do serial:
        v1.drive(duration: 3s)
        b()

scenario b:
    v1: vehicle
    do serial:
        v1.drive(duration: 3s)
        a()
"""


@pytest.mark.parametrize(
    "text, where, cycle",
    [
        (
            "scenario s:\n    v1: vehicle\n    do serial:\n        v1.drive(duration: 3s)\n        s()\n",
            (5, 9),
            "s -> s",
        ),
        (RECURSIVE, (5, 9), "b -> a -> b"),
    ],
)
def test_item_9_a_scenario_that_calls_itself_is_a_located_error(text, where, cycle):
    with pytest.raises(OscError) as refused:
        check_text(text, "r.osc").raise_for_errors()
    messages = [(d.location.line, d.location.column, d.message) for d in refused.value.errors]
    assert (*where, f"scenario '{cycle.split()[0]}' calls itself ({cycle})") in messages
    assert not any("unknown action" in m for _, _, m in messages), "the call is not reported twice"


def test_item_9_under_pytest_a_recursive_scenario_is_a_collection_error(pytester):
    pytester.makefile(".osc", r=RECURSIVE)
    result = pytester.runpytest_subprocess(*QUIET)
    result.assert_outcomes(errors=1)
    assert "calls itself (b -> a -> b)" in result.stdout.str()


@pytest.mark.parametrize("modifier", ["speed(-20kph)", "speed([-5..20]kph)", "speed(-2kph, faster_than: v2)"])
def test_item_10_a_negative_speed_is_a_check_error_at_its_place(modifier):
    text = f"scenario s:\n    v1: vehicle\n    v2: vehicle\n    do v1.drive(duration: 3s) with:\n        {modifier}\n"
    with pytest.raises(OscError) as refused:
        check_text(text, "s.osc").raise_for_errors()
    first = refused.value.errors[0]
    assert (first.location.line, first.location.column, first.message) == (5, 15, "a speed must not be negative")


@pytest.mark.parametrize("action", ["change_speed(target: -3kph)", "assign_speed(target: -1mps)"])
def test_item_10_a_negative_target_speed_is_a_check_error(action):
    with pytest.raises(OscError, match="a speed must not be negative"):
        check_text(f"scenario s:\n    v1: vehicle\n    do v1.{action}\n", "s.osc").raise_for_errors()


def test_item_11_a_rejected_verdict_marks_only_the_transitions_whose_guards_held(overtake_automaton):
    """A run stuck in A had been shown with marks for B and C, whose guards never held."""
    from pytest_roadlogic.monitor import monitor
    from tests.monitor.test_monitor import overtake_trace

    trace = overtake_trace()
    trace.actors["v1"]["lane"][:] = 1  # v1 never leaves v2's lane: stuck in A
    verdict = monitor(overtake_automaton, trace)
    assert not verdict.accepted and verdict.furthest == "A"
    events = [events for _, events in verdict.run]
    assert events and all("B" not in e and "C" not in e for e in events), events
    assert verdict.to_dict()["run"] == [{"time": t, "events": e} for t, e in verdict.run]


def test_item_12_a_replay_that_matches_no_collected_item_is_a_usage_error(pytester):
    pytester.makefile(".osc", good="scenario good:\n    v1: car\n    do v1.drive(duration: 3s)\n")
    (pytester.path / "case.json").write_text(json.dumps({"path": "other.osc", "scenario": "other"}))
    result = pytester.runpytest_subprocess("--roadlogic-replay", "case.json", *QUIET)
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    assert "no collected scenario is other.osc::other" in result.stderr.str()


def test_item_12_a_replay_with_a_value_of_the_wrong_kind_fails_with_one_line_under_pytest(pytester):
    pytester.path.joinpath("follow.osc").write_text((ROOT / "scenarios" / "follow.osc").read_text())
    case = {"path": "follow.osc", "scenario": "follow", "values": {"start_gap": "abc"}}
    (pytester.path / "case.json").write_text(json.dumps(case))
    result = pytester.runpytest_subprocess("--roadlogic-replay", "case.json", *QUIET)
    result.assert_outcomes(failed=1)
    assert "start_gap = 'abc' is not a number" in result.stdout.str()
    # it had been a 946-line traceback through pluggy and the runner
    assert len(result.stdout.lines) < 40 and "HookCallError" not in result.stdout.str(), result.stdout.str()
    assert "another exception occurred" not in result.stdout.str()


# ------------------------------------------------------------------ usage errors that crashed later


@pytest.mark.parametrize("seed", ["-5", "99999999999"])
def test_item_13_a_seed_clingo_cannot_take_is_a_usage_error(pytester, capsys, seed):
    pytester.makefile(".osc", good="scenario good:\n    v1: car\n    do v1.drive(duration: 3s)\n")
    result = pytester.runpytest_subprocess("--roadlogic-seed", seed, *QUIET)
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    assert (
        f"--roadlogic-seed (ini roadlogic_seed): '{seed}' is not a seed; give a whole number from 0 to 4294967295"
        in result.stderr.str()
    )
    with pytest.raises(SystemExit):
        cli.main(["plan", str(ROOT / "scenarios" / "follow.osc"), "--seed", seed])
    assert "is not a seed" in capsys.readouterr().err


def test_item_14_an_artifacts_option_naming_a_file_stops_the_session_at_its_start(pytester):
    pytester.makefile(".osc", good="scenario good:\n    v1: car\n    do v1.drive(duration: 3s)\n")
    (pytester.path / "taken").write_text("a file")
    result = pytester.runpytest_subprocess("--roadlogic-artifacts", "taken", *QUIET)
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    assert (
        "--roadlogic-artifacts (ini roadlogic_artifacts):" in result.stderr.str() and "is a file" in result.stderr.str()
    )


def test_item_14_run_with_an_out_folder_that_cannot_be_made_stops_before_running(capsys):
    assert cli.main(["run", str(ROOT / "scenarios" / "follow.osc"), "--out", "/proc/x/out"]) == cli.EXIT_INPUT
    said = capsys.readouterr()
    assert "roadlogic run: --out: cannot make a folder in /proc" in said.err and "scenario follow" not in said.out


def test_item_15_what_a_killed_run_left_is_removed_and_the_folder_gets_the_umasks_mode(tmp_path):
    from pytest_roadlogic.artifacts.files import replaced_directory
    from pytest_roadlogic.artifacts.writer import ARTIFACT_NAMES

    dead = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True
    ).stdout.strip()
    left = tmp_path / f".out.{dead}.k2j3.partial"
    left.mkdir()
    (left / "plan.json").write_text("{}")
    previous = os.umask(0o022)
    try:
        with replaced_directory(tmp_path / "out", ARTIFACT_NAMES) as staging:
            (staging / "plan.json").write_text("{}")
    finally:
        os.umask(previous)
    assert not left.exists(), "the killed run's staging folder stays"
    assert (tmp_path / "out").stat().st_mode & 0o777 == 0o755
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_item_15_a_second_run_into_an_out_folder_another_run_holds_is_refused(tmp_path):
    from pytest_roadlogic.artifacts.files import FolderBusy, claimed

    # the claim is a lock the system holds per open file: a second process is refused as a second open is
    other = subprocess.Popen(
        [
            sys.executable,
            "-c",
            f"""
import time
from pathlib import Path
from pytest_roadlogic.artifacts.files import claimed
with claimed(Path({str(tmp_path / "out")!r})):
    print('held', flush=True)
    time.sleep(5)
""",
        ],
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert other.stdout.readline().strip() == "held"
        with pytest.raises(FolderBusy, match="another run is writing"):
            with claimed(tmp_path / "out"):
                pass
    finally:
        other.kill()
        other.wait()
    with claimed(tmp_path / "out"):  # the other run is gone: its claim went with it
        pass
    assert not (tmp_path / ".out.lock").exists(), "the claim leaves nothing behind"


# ------------------------------------------------------------------ the README, in a new shell


def commands_after(heading: str) -> str:
    """The first fenced block after a line of the README."""
    return README.split(heading, 1)[1].split("```\n", 2)[1].strip()


def test_item_16_both_commands_of_the_readme_work_without_an_activated_environment():
    install = commands_after("Install and run the scenario suite")
    tests = commands_after("Run the project's own tests")
    assert install == 'python3 -m venv .venv && .venv/bin/pip install -e ".[test]" && .venv/bin/pytest scenarios/'
    assert tests == ".venv/bin/python -m pytest tests/ -q -n auto"
    assert "activate" not in install + tests
    ci = (ROOT / ".ci" / "run").read_text().strip().splitlines()
    assert ci[-1] == tests, "CI runs exactly the README's test command"


def test_item_17_the_project_has_its_own_language_reference_and_links_nothing_of_the_teams():
    reference = ROOT / "docs" / "language.md"
    assert reference.is_file() and "(docs/language.md)" in README
    text = reference.read_text()
    for subject in (
        "## What is read",
        "Refused, by name",
        "## Values that mean nothing are errors",
        "## Files an `.osc` file may import",
    ):
        assert subject in text
    shipped = [
        README,
        text,
        *(p.read_text() for p in (ROOT / "pytest_roadlogic").rglob("*.py") if "generated" not in p.parts),
    ]
    assert not any("os2-subset.md" in t or "../shared" in t for t in shipped)


def test_item_18_the_frontend_benchmark_reads_a_file_that_declares_its_own_units():
    done = subprocess.run(
        [
            sys.executable,
            str(ROOT / "benchmarks" / "frontend.py"),
            str(ROOT / "tests" / "corpus" / "49_carla_style.osc"),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    assert "49_carla_style.osc" in done.stdout and "Traceback" not in done.stderr


def test_item_18_the_readme_counts_the_corpus_as_it_is():
    count = len(list((ROOT / "tests" / "corpus").rglob("*.osc")))
    assert f"`tests/corpus/`, {count} `.osc` files" in README.replace("\n", " ")


def test_item_18_each_option_names_one_default_in_its_help(pytester):
    result = pytester.runpytest_subprocess("--help")
    text = " ".join(result.stdout.str().split())
    help_of_horizon = text.split("--roadlogic-horizon=ROADLOGIC_HORIZON", 1)[1].split("--roadlogic-", 1)[0]
    assert help_of_horizon.count("default") == 1, help_of_horizon
    assert "default the encoding's: 120 continuous, 25 grid" in help_of_horizon


def test_a_scenario_read_from_python_confines_its_imports_as_the_commands_do(tmp_path, monkeypatch):
    (tmp_path / "pyproject.toml").write_text("")
    (tmp_path / "a.osc").write_text(
        'import "/etc/hostname.osc"\nscenario s:\n    v1: car\n    do v1.drive(duration: 3s)\n'
    )
    monkeypatch.chdir(tmp_path)
    with pytest.raises(OscError, match="outside the folders the tool reads"):
        load_file(tmp_path / "a.osc")
