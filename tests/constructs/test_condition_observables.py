"""What a condition reads beyond speeds and gaps. The distance travelled: ``a.traveled_distance()``
is d(a) = p(a) - p(a at the run's first instant). The planner writes it as p(a,t) - p(a,0), the monitor measures x - x[0]
on the trace; both read the one Bound of the guard algebra. The relative lane:
``a.relative_lane(reference: b)``, the lanes a is to the left of b."""

import numpy as np
import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import OscError, check_text
from pytest_roadlogic.logic.guards import TRAVELED, Bound, Term
from pytest_roadlogic.planning import ContinuousPlanner, GridPlanner, GridSettings
from tests.planning.test_planning_continuous import check_continuous_plan

# the follower is not the vehicle at position 0, so its start position is not 0 in the plan
FOLLOW_THEN_PASS = """\
scenario s:
    lead: car
    ego: car
    do serial:
        follow: parallel:
            lead.drive() with:
                lane(1)
                speed([20mps..22mps])
            ego.drive() with:
                lane(1)
                position([25m..40m], behind: lead, at: start)
                until ego.traveled_distance() >= 120m and ego.traveled_distance() <= 140m
        ego.change_lane(side: left, duration: [3s..4s])
"""


def automaton(text):
    checked = check_text(text, "t.osc")
    assert not checked.errors, checked.report()
    return build_automaton(checked.scenarios[0])


def test_the_condition_is_a_bound_on_the_distance_travelled_of_its_actor():
    assert "d(ego) >= 120 and d(ego) <= 140" in automaton(FOLLOW_THEN_PASS).describe()


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_a_plan_ends_the_phase_where_the_follower_has_covered_120_to_140_m_from_its_own_start(seed):
    a = automaton(FOLLOW_THEN_PASS)
    plan = ContinuousPlanner(a, seed=seed).first()
    check_continuous_plan(plan, a)
    (end_step,) = [
        step
        for step, tid in plan.transitions
        if a.location(a.transitions[tid].target).name.startswith("ego.change_lane")
    ]
    covered = plan.at("ego", end_step).position - plan.at("ego", 0).position
    assert 120 <= covered <= 140
    assert plan.at("ego", 0).position != 0, "the test means something only when the ego does not start at 0"


def test_the_monitor_measures_from_the_first_sample_not_from_the_origin():
    bound = Bound(Term(TRAVELED, "a"), 100.0)
    margins = bound.robustness_series({"a": {"x": np.array([500.0, 550.0, 620.0])}})
    assert margins.tolist() == [-100.0, -50.0, 20.0]


def test_the_grid_encoding_refuses_it_at_its_place():
    with pytest.raises(OscError) as error:
        GridPlanner(automaton(FOLLOW_THEN_PASS), GridSettings(), seed=1).first()
    (diagnostic,) = error.value.diagnostics
    assert (diagnostic.location.line, "a distance travelled") == (12, diagnostic.message[:20])


def test_it_is_a_length_compared_with_a_length():
    checked = check_text(FOLLOW_THEN_PASS.replace(">= 120m", ">= 12s"), "t.osc")
    assert any("traveled_distance is a length, compared here with a time" in d.message for d in checked.errors), (
        checked.report()
    )


def test_relative_lane_counts_the_lanes_to_the_left_of_the_reference_in_either_dialect():
    text = "scenario s:\n    a: car\n    b: car\n    do a.drive() with:\n        until a.relative_lane(reference: b) >= 1\n"
    (guard,) = [t.guard for t in automaton(text).transitions if t.label.endswith("end")]

    class At:  # lanes counted from the left, as the guard algebra counts them
        def __init__(self, lane):
            self.position, self.lane, self.speed, self.traveled = 0.0, lane, 10.0, 0.0

    assert guard.holds({"a": At(0), "b": At(1)}), "a in the leftmost lane is one lane left of b"
    assert not guard.holds({"a": At(1), "b": At(1)})
    assert not guard.holds({"a": At(2), "b": At(1)})
