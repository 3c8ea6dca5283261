"""The standard's gap actions: keep_space_gap / keep_time_gap hold a gap to a reference ahead
throughout the phase; change_space_gap / change_time_gap reach one by its end. A kept range is a
bound, not a sampled parameter; a target is one instant's value, so it is a parameter."""

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.planning import ContinuousPlanner
from pytest_roadlogic.sampling import logical_parameters
from tests.planning.test_planning_continuous import check_continuous_plan

GAPS = """\
scenario s:
    ego: car
    lead: car
    do parallel:
        lead.drive() with:
            lane(1)
            speed([20mps..22mps])
        serial:
            ego.keep_time_gap({kept}, reference: lead, duration: [4s..6s]) with:
                lane(1)
            ego.change_space_gap({target}, reference: lead, duration: [5s..8s]) with:
                lane(1)
"""


def checked(text):
    result = check_text(text, "g.osc")
    assert not result.errors, result.report()
    return result.scenarios[0]


def test_a_kept_gap_holds_throughout_and_a_changed_gap_holds_at_the_end():
    described = build_automaton(checked(GAPS.format(kept="2s", target="15m"))).describe()
    assert (
        "lead.drive | ego.keep_time_gap invariant: l(lead) = 2 and 20 <= v(lead) <= 22 and 1.8 <= h(lead, ego) <= 2.2"
        in described
    )
    assert "-> fin: l(lead) = 2 and 20 <= v(lead) <= 22 and 14 <= p(lead) - p(ego) <= 16" in described
    assert (
        "lead.drive | ego.change_space_gap invariant: l(lead) = 2 and 20 <= v(lead) <= 22 and l(ego) = 2\n" in described
    )


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_plans_keep_the_time_gap_and_reach_the_space_gap(seed):
    automaton = build_automaton(checked(GAPS.format(kept="2s", target="15m")))
    check_continuous_plan(ContinuousPlanner(automaton, seed=seed).first(), automaton)


def test_a_kept_range_is_a_bound_while_a_target_range_and_the_durations_are_parameters():
    names = [p.name for p in logical_parameters(checked(GAPS.format(kept="[1.5s..2.5s]", target="[10m..20m]")))]
    assert names == ["ego.keep_time_gap.duration", "ego.change_space_gap.target", "ego.change_space_gap.duration"]


@pytest.mark.parametrize(
    "kept, message",
    [
        ("2s, direction: lateral", "not supported: keep_time_gap(direction: lateral)"),
        ("-1s", "a time gap must not be negative"),
        ("20m", "expects a time"),
    ],
)
def test_what_a_gap_action_cannot_mean_is_an_error_at_its_place(kept, message):
    result = check_text(GAPS.format(kept=kept, target="15m"), "g.osc")
    errors = list(result.errors)
    if not errors:  # refused when the automaton is built, at the same place
        with pytest.raises(Exception) as raised:
            build_automaton(result.scenarios[0])
        errors = raised.value.diagnostics
    assert errors[0].location.line == 9 and message in errors[0].message, [e.message for e in errors]


def test_a_gap_needs_its_reference():
    result = check_text(GAPS.format(kept="2s", target="15m").replace("2s, reference: lead", "2s"), "g.osc")
    (error,) = result.errors
    assert error.location.line == 9 and "reference" in error.message, error.message
