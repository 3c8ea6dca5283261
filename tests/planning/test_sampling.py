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


def test_a_sampled_time_headway_is_narrowed_to_the_headway_band_not_a_durations_step():
    """position(time: [1.5s..2.5s], at: start) is a time like a duration, but the planner places it
    to tenths of a second, not whole steps: its sample is planned within +-0.1 s (a band one
    headway margin wide, which the planner plans as given), where a duration's sample gets +-0.5 s."""
    from pytest_roadlogic.planning import ContinuousSettings
    from pytest_roadlogic.sampling import guided

    checked = check_text(
        """
scenario headway:
    ego: car
    lead: car
    do parallel(duration: [5..8]s):
        lead.drive()
        ego.drive() with:
            lane(same_as: lead)
            position(time: [1.5s..2.5s], behind: lead, at: start)
""",
        "headway.osc",
    )
    checked.raise_for_errors()
    checked = checked.scenario_to_run()
    parameters = {p.name: p for p in logical_parameters(checked)}
    assert parameters["ego.drive.position.time"].sampled_as == "headway"
    settings = ContinuousSettings()
    narrowed, _ = guided(
        checked, {"ego.drive.position.time": 2.0, "parallel.duration": 6.0}, settings.resolution(), settings.margins()
    )
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.logic.guards import HEADWAY

    automaton = build_automaton(narrowed)
    bounds = {(b.low, b.high) for t in automaton.transitions for b in t.guard.atoms() if b.term.quantity == HEADWAY}
    assert [(round(low, 9), round(high, 9)) for low, high in bounds] == [(1.9, 2.1)], bounds
    assert {(t.low, t.high) for t in automaton.timings.values()} == {(5.5, 6.5)}


def test_values_given_in_part_fix_a_parameter_their_relations_determine_as_the_sampler_draws_it():
    """``far: length = near + 10m`` with only ``near`` given (``roadlogic run --values``): ``far``
    is 10 m more, not anywhere in its range; the planner reads ranges, not relations."""
    from pytest_roadlogic.frontend.semantics.values import Interval
    from pytest_roadlogic.planning import ContinuousSettings
    from pytest_roadlogic.sampling import guided

    checked = check_text(
        """
scenario spaced:
    ego: car
    npc: car
    near: length with:
        keep(it in [10m..20m])
    far: length = near + 10m
    do parallel(duration: 5s):
        ego.drive()
        npc.drive() with:
            position(far, ahead_of: ego, at: start)
""",
        "spaced.osc",
    )
    checked.raise_for_errors()
    checked = checked.scenario_to_run()
    settings = ContinuousSettings()
    _, declared = guided(checked, {"near": 12.0}, settings.resolution(), settings.margins())
    assert isinstance(declared["far"], Interval) and declared["far"].low <= 22.0 <= declared["far"].high
    assert declared["far"].high - declared["far"].low < 2.0, declared["far"]
