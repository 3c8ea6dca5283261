"""Run with no project above the working folder (``/``, a container's default, or a home folder),
the tool reads only the folder of the file it is given: never ``/``, never the home folder.

Each test runs the ``roadlogic`` command in a separate process with its working folder set to ``/``
or to a home folder, a secret in its environment and a secret file beside the given file's folder,
and checks that neither reaches its output.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from pytest_roadlogic.confinement import ReadRoots, project_root, too_wide

SECRET = "do-not-print-me-4711"
SCENARIO = "scenario s:\n    v1: car\n    do v1.drive(duration: 3s)\n"


def roadlogic(*args: str, cwd: Path | str, home: Path) -> subprocess.CompletedProcess:
    """The command as a user runs it, with a secret in its environment."""
    environment = {**os.environ, "ROADLOGIC_TEST_TOKEN": SECRET, "HOME": str(home)}
    return subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", *args],
        cwd=cwd,
        env=environment,
        capture_output=True,
        text=True,
        timeout=120,  # guards a hang only: the commands take about a second
    )


@pytest.fixture
def outside(tmp_path: Path) -> Path:
    """A folder with no project marker above it: a secret file, and a folder given to the tool."""
    assert project_root(tmp_path) is None, "the test needs a folder outside any project"
    (tmp_path / "secret.osc").write_text(f"TOKEN={SECRET}\n")
    (tmp_path / "given").mkdir()
    return tmp_path


@pytest.mark.parametrize("target", ["/proc/self/environ", "/etc/passwd", "../secret.osc", "/proc/self/environ.osc"])
def test_an_import_from_a_file_checked_from_the_root_folder_reads_nothing_outside_the_files_folder(outside, target):
    given = outside / "given" / "a.osc"
    given.write_text(f'import "{target}"\n{SCENARIO}')
    done = roadlogic("check", str(given), cwd="/", home=outside / "home")
    shown = done.stdout + done.stderr
    assert done.returncode == 1, shown
    assert "a.osc:1:8: error: the imported file" in shown
    assert SECRET not in shown and "root:x:" not in shown and "Traceback" not in shown


@pytest.mark.parametrize("path", ["proc/self/environ", "../secret.osc", "secret.osc", "../../etc/passwd"])
def test_a_case_file_replayed_from_the_root_folder_reads_nothing_outside_its_folder(outside, path):
    case = outside / "given" / "case.json"
    case.write_text(json.dumps({"path": path, "scenario": "s"}))
    done = roadlogic("replay", str(case), "--out", str(outside / "out"), cwd="/", home=outside / "home")
    shown = done.stdout + done.stderr
    assert done.returncode == 2, shown
    assert SECRET not in shown and "root:x:" not in shown and "Traceback" not in shown


def test_a_file_in_the_home_folder_may_not_import_its_neighbours(tmp_path):
    home = tmp_path / "home"
    home.mkdir()
    (home / "notes.osc").write_text(f"TOKEN={SECRET}\n")
    (home / "a.osc").write_text(f'import "notes.osc"\n{SCENARIO}')
    done = roadlogic("check", "a.osc", cwd=home, home=home)
    shown = done.stdout + done.stderr
    assert done.returncode == 1, shown
    assert "is outside the folders the tool reads" in shown and SECRET not in shown


def test_the_root_folder_and_the_home_folder_are_never_read_roots(tmp_path, monkeypatch):
    monkeypatch.setenv("HOME", str(tmp_path))
    assert too_wide(Path("/")) and too_wide(tmp_path)
    assert project_root("/") is None
    (tmp_path / "pyproject.toml").write_text("")  # a marker in the home folder does not make it a project
    assert project_root(tmp_path) is None
    roots = ReadRoots.of("/", tmp_path, tmp_path / "pyproject.toml")
    assert roots.folders == () and roots.files == ((tmp_path / "pyproject.toml").resolve(),)
    assert roots.allows(tmp_path / "pyproject.toml") and not roots.allows(tmp_path / "other.osc")
