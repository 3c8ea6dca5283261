"""Which values of a scenario are logical parameters (sampled, shrunk, reported) and which are
bounds the planner keeps: a range held at one instant is a parameter, a range a modifier holds
throughout its phase (``at: all``, the standard's default) is a bound."""

from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.sampling import logical_parameters

SCENARIO = """
scenario bands:
    ego: car
    other: car
    gap: length with:
        keep(it in [10..30]m)
    do parallel(duration: [5..10]s):
        other.drive() with:
            speed([20..30]mps)
        ego.drive() with:
            speed([0..36]mps, at: all)
            speed([15..25]mps, at: end)
            position(distance: gap, behind: other, at: start)
            position(distance: [15..25]m, behind: other, at: end)
"""


def test_ranges_held_at_an_instant_are_parameters_and_ranges_held_throughout_are_not():
    checked = check_text(SCENARIO, "bands.osc")
    checked.raise_for_errors()
    checked = checked.scenario_to_run()
    found = {p.name: (p.low, p.high, p.location.line) for p in logical_parameters(checked)}
    assert set(found) == {"gap", "parallel.duration", "ego.drive.speed.speed", "ego.drive.position.distance"}
    assert found["ego.drive.speed.speed"][:2] == (15.0, 25.0), "the at: end speed, not the at: all bound"
    assert found["ego.drive.position.distance"][:2] == (15.0, 25.0)
