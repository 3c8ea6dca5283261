"""The artifact writer runs the OpenSCENARIO writer in a forked process beside the others
(``writer.beside``): what it writes is there when ``write_artifacts`` returns, and a failure in the
child is the parent's error, not a file silently missing."""

import os
import time

import pytest

from pytest_roadlogic.artifacts.writer import beside


def test_what_the_child_writes_is_there_once_waited_for(tmp_path):
    target = tmp_path / "written.txt"
    wait = beside(lambda: target.write_text("from the child"))
    assert wait() is None
    assert target.read_text() == "from the child"


def test_a_failure_in_the_child_is_raised_in_the_parent_with_its_message(tmp_path):
    def failing():
        raise ValueError("the road has no lanes")

    wait = beside(failing)
    with pytest.raises(OSError, match="ValueError: the road has no lanes"):
        wait()


def test_cancel_stops_the_child_before_it_writes(tmp_path):
    target = tmp_path / "late.txt"

    def slow():
        time.sleep(30)
        target.write_text("too late")

    started = time.perf_counter()
    beside(slow)(cancel=True)
    assert time.perf_counter() - started < 10 and not target.exists()


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the writer runs in turn where there is no fork")
def test_the_child_leaves_without_running_the_parents_exit_handlers(tmp_path, capfd):
    """os._exit in the child: pytest's own atexit work or a buffered print must not run twice."""
    print("buffered in the parent", end="")
    beside(lambda: None)()
    out, _ = capfd.readouterr()
    assert out.count("buffered in the parent") == 1
