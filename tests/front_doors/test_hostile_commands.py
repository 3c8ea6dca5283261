"""Bad option values, output folders and names from issue 51: a usage error naming the option and
what to do (exit 2), never a traceback, never a file of the user's overwritten, never a terminal
escape sequence echoed from a file."""

from __future__ import annotations

import io

import pytest

from pytest_roadlogic import cli
from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.progress import ProgressBar
from tests.conftest import ROOT

pytest_plugins = ["pytester"]
FOLLOW = ROOT / "scenarios" / "follow.osc"
BENCH = ["bench", str(FOLLOW), "--no-realistic", "--base", "1", "--refined", "0"]


def test_a_bench_with_nothing_to_run_is_a_usage_error(tmp_path, capsys):
    assert cli.main(["bench", str(FOLLOW), "--base", "0", "--refined", "0", "--out", str(tmp_path / "b")]) == 2
    assert "--base 0 and --refined 0 leave nothing to run" in capsys.readouterr().err


def test_a_bench_refuses_a_file_or_a_folder_of_the_users_own_as_its_out_and_leaves_it_as_it_was(tmp_path, capsys):
    (tmp_path / "afile").write_text("mine")
    assert cli.main([*BENCH, "--out", str(tmp_path / "afile")]) == 2
    assert "is a file" in capsys.readouterr().err
    (tmp_path / "notes").mkdir()
    (tmp_path / "notes" / "report.md").write_text("my own report")
    assert cli.main([*BENCH, "--out", str(tmp_path / "notes")]) == 2
    assert "holds files but no results.json" in capsys.readouterr().err
    assert (tmp_path / "notes" / "report.md").read_text() == "my own report"


@pytest.mark.parametrize("command", [["run", str(FOLLOW)], BENCH])
def test_an_out_folder_name_the_system_refuses_is_a_usage_error(tmp_path, capsys, command):
    assert cli.main([*command, "--out", str(tmp_path / ("x" * 300))]) == 2
    said = capsys.readouterr().err
    assert "cannot be a folder (File name too long)" in said and "Traceback" not in said


def test_a_progress_bar_into_a_file_writes_one_line_without_terminal_codes():
    stream = io.StringIO()
    bar = ProgressBar(3, stream=stream)
    for done in (1, 2, 3):
        bar.update(done, "follow base")
    bar.close()
    written = stream.getvalue()
    assert "\r" not in written and "\x1b" not in written
    assert written.count("\n") == 1 and "3/3  follow base" in written


def test_a_line_with_terminal_escape_sequences_is_echoed_with_them_shown_not_sent():
    text = "scenario s:\n    v1: car\n    do v1.drive(duration: 3s) \x1b]0;TITLE\x07\x1b[2J\n"
    from pytest_roadlogic.frontend import OscError

    with pytest.raises(OscError) as raised:
        check_text(text, "e.osc").raise_for_errors()
    report = str(raised.value)
    assert "\x1b" not in report and "\x07" not in report
    assert "\\x1b" in report


def test_more_shards_than_examples_is_a_usage_error(pytester):
    pytester.makefile(".osc", follow=FOLLOW.read_text())
    result = pytester.runpytest_subprocess(
        "--roadlogic-shards", "20", "--roadlogic-examples", "2", "-p", "no:cacheprovider"
    )
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    assert "20 shards share 2 examples" in result.stderr.str()
    assert "Traceback" not in result.stdout.str() + result.stderr.str()


def test_a_vehicle_under_test_no_scenario_has_is_a_usage_error(pytester):
    pytester.makefile(".osc", follow=FOLLOW.read_text())
    result = pytester.runpytest_subprocess("--roadlogic-dut", "ghost", "-p", "no:cacheprovider")
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    assert "no collected scenario has a vehicle 'ghost'" in result.stderr.str()
    assert "During handling" not in result.stdout.str() + result.stderr.str()
