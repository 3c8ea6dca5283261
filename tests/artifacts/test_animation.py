"""Issue 21: the animation is quick to draw and still shows what a person needs: every vehicle in
its own colour in every frame, the lanes, and a frame every 0.2 s of the run at its real pace."""

import pytest
from PIL import Image

from pytest_roadlogic.artifacts.animation import FIRST_VEHICLE, PALETTE, animate_simulation
from pytest_roadlogic.pipeline import load_scenario, run_scenario
from tests.conftest import ROOT


@pytest.fixture(scope="module")
def outcome():
    return run_scenario(load_scenario(ROOT / "scenarios" / "overtake_third_actor.osc"), seed=1)


def test_every_frame_shows_every_vehicle_in_its_colour_at_the_runs_pace(outcome, tmp_path):
    path = animate_simulation(
        outcome.simulation, outcome.verdict, tmp_path / "simulation.gif", title="overtake_third_actor"
    )
    trace = outcome.simulation.trace
    colours = [PALETTE[FIRST_VEHICLE + k] for k in range(len(trace.actors))]
    with Image.open(path) as gif:
        assert gif.n_frames == len(range(0, len(trace), 2)) + (len(trace) % 2 == 0), (
            "a frame every 0.2 s, and the last sample"
        )
        for index in range(gif.n_frames):
            gif.seek(index)
            assert gif.info["duration"] == 200, "played at the run's pace"
            present = {colour for _, colour in gif.convert("RGB").getcolors(maxcolors=1 << 16)}
            missing = [name for name, colour in zip(trace.actors, colours) if colour not in present]
            assert not missing, f"frame {index}: no box of {missing}"


def test_a_scenario_without_a_verdict_is_drawn_too(outcome, tmp_path):
    """The phase line needs the monitor's run; without one the frames show the time alone."""
    path = animate_simulation(outcome.simulation, None, tmp_path / "plain.gif")
    with Image.open(path) as gif:
        assert gif.n_frames > 10 and gif.size[0] == 1000


def test_the_plots_title_says_the_cases_outcome_a_vehicle_under_tests_failure_naming_its_oracle():
    from types import SimpleNamespace

    from pytest_roadlogic.artifacts.plot import status_line

    accepted, rejected = (
        SimpleNamespace(accepted=True, robustness=0.5),
        SimpleNamespace(accepted=False, robustness=-0.2),
    )
    failed = SimpleNamespace(failed=True, hit_by_others=[], failures=["gap 0.55 m (threshold 2 m) behind wreck"])
    fine = SimpleNamespace(failed=False, hit_by_others=[], failures=[])
    assert status_line(accepted) == "conformant (robustness +0.50)"
    assert status_line(rejected) == "NON-CONFORMANT (robustness -0.20)"
    assert status_line(accepted, failed).startswith("vehicle under test FAILED: gap 0.55 m"), "not REJECTED"
    assert status_line(accepted, fine) == "passed (robustness +0.50)"
    assert status_line(rejected, fine) == "not exercised (robustness -0.20)"
