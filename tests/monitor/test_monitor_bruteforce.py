"""The monitor's verdict equals a brute-force reading of the trace semantics, on every scenario.

The brute force is written from the definitions, with no dynamic programming: enumerate every path
of the automaton from the initial to the final location and every way of placing its transitions
at strictly increasing samples; a placement is a run when, while the run stays in a location
(after entering it, up to and including the sample that leaves it), every actor driving there
moves forward at each sample. Its margin is the smallest of: each guard's robustness at its
sample, and the location's invariant at every sample strictly between entering and leaving (the
instants of entering and leaving are covered by the guards, which include the invariant). A timed
phase must last, from the transition that starts it to the one that ends it, within its bounds,
and its margin to them counts like a guard's. The
trace's robustness is the largest margin of any run (minus infinity without one); it is accepted
when that is at least zero.
"""

import itertools
import math
from math import comb
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pytest_roadlogic.automaton import SymbolicAutomaton, build_automaton
from pytest_roadlogic.frontend import load_file
from pytest_roadlogic.monitor import monitor
from pytest_roadlogic.simulation import Trace

ROOT = Path(__file__).resolve().parents[2]
# The benchmark suite, and corpus files that add what it lacks: waits, durations, one_of, side_of,
# time headways, a distance travelled.
SCENARIOS = sorted((ROOT / "scenarios").glob("*.osc")) + [
    ROOT / "tests" / "corpus" / name
    for name in (
        "16_one_of.osc",
        "19_lane_relative.osc",
        "27_wait.osc",
        "28_durations.osc",
        "46_time_headway.osc",
        "106_traveled_distance_condition.osc",
    )
]
DT = 0.5
# Placements enumerated per example at most: keeps the brute force to about a second.
BUDGET = 40_000


def paths(automaton: SymbolicAutomaton):
    def walk(location, prefix):
        if location == automaton.final:
            yield prefix
            return
        for transition in automaton.outgoing(location):
            yield from walk(transition.target, prefix + [transition])

    return list(walk(automaton.initial, []))


def brute_force_robustness(automaton: SymbolicAutomaton, trace: Trace, begins_by: float = math.inf) -> float:
    snapshots = trace.snapshots()
    x = {name: trace.actors[name]["x"] for name in trace.names}
    best = -math.inf
    for path in paths(automaton):
        for samples in itertools.combinations(range(len(snapshots)), len(path)):
            if trace.times[samples[0]] > begins_by + 1e-9:
                continue  # the scenario begins too late
            margin = math.inf
            is_run = True
            started = {}
            for j, (transition, k) in enumerate(zip(path, samples)):
                margin = min(margin, transition.guard.robustness(snapshots[k]))
                for phase in transition.starts & automaton.timings.keys():
                    started[phase] = k
                for phase in transition.ends & automaton.timings.keys():
                    timing = automaton.timings[phase]
                    seconds = trace.times[k] - trace.times[started.pop(phase, k)]
                    if not timing.admits(seconds):
                        is_run = False
                    margin = min(margin, seconds - timing.low, timing.high - seconds)
                if j + 1 == len(path):
                    break
                location = automaton.location(transition.target)
                leave = samples[j + 1]
                for kk in range(k + 1, leave + 1):
                    if any(x[a][kk] <= x[a][kk - 1] for a in location.drivers):
                        is_run = False
                    if kk < leave and not location.invariant.is_true:
                        margin = min(margin, location.invariant.robustness(snapshots[kk]))
            if is_run:
                best = max(best, margin)
    return best


def max_samples(automaton: SymbolicAutomaton) -> int:
    found = paths(automaton)
    longest = max(len(p) for p in found)
    n = 30
    while n > longest + 1 and len(found) * comb(n, longest) > BUDGET:
        n -= 1
    return n


@st.composite
def traces(draw, actors: tuple[str, ...], stationary: frozenset[str], n_max: int) -> Trace:
    """Small traces in which scenarios are sometimes met: each actor cruises at its own pace (so
    that overtakes happen), with noise, stalls and occasional lane changes."""
    n = draw(st.integers(2, n_max))
    columns = {}
    for actor in actors:
        start = 5 * draw(st.integers(-6, 6))
        if actor in stationary:
            steps = [0] * (n - 1)
            speed = [draw(st.sampled_from([0.0, 0.05, 0.5]))] * n
        else:
            pace = draw(st.integers(1, 6))
            steps = [
                pace + d
                for d in draw(
                    st.lists(st.sampled_from([0, 0, 0, 1, -1, -pace, -pace - 1]), min_size=n - 1, max_size=n - 1)
                )
            ]
            speed = [pace / DT + draw(st.sampled_from([0.0, 0.5, -0.5, 2.0]))] * n
        x = np.cumsum([start, *steps]).astype(float)
        lane = [draw(st.integers(0, 2))]
        for _ in range(n - 1):
            lane.append(min(2, max(0, lane[-1] + draw(st.sampled_from([0, 0, 0, 0, -1, 1])))))
        columns[actor] = {
            "x": x,
            "y": np.zeros(n),
            "heading": np.zeros(n),
            "speed": np.array(speed),
            "acceleration": np.zeros(n),
            "lane": np.array(lane),
        }
    return Trace(np.arange(n) * DT, columns)


def plan_trace(plan) -> Trace:
    """A plan read as a trace (one sample per plan step): it meets the scenario by construction."""
    n = plan.horizon + 1
    columns = {}
    for vehicle, states in plan.states.items():
        columns[vehicle] = {
            "x": np.array([s.position for s in states]),
            "y": np.zeros(n),
            "heading": np.zeros(n),
            "speed": np.array([s.speed for s in states]),
            "acceleration": np.zeros(n),
            "lane": np.array([s.lane for s in states]),
        }
    return Trace(np.arange(n) * plan.dt, columns)


@st.composite
def perturbed(draw, base: Trace, n_max: int) -> Trace:
    """A planned trace, cropped and nudged: near the boundary between accepted and rejected."""
    n = len(base)
    first = draw(st.integers(0, max(0, n - n_max)))
    last = min(n, first + n_max)
    columns = {}
    for actor, c in base.actors.items():
        x = c["x"][first:last] + np.array(
            draw(
                st.lists(
                    st.sampled_from([0.0, 0.0, 0.0, 0.5, -0.5, 2.0, -2.0, -9.0]),
                    min_size=last - first,
                    max_size=last - first,
                )
            )
        )
        lane = c["lane"][first:last] + np.array(
            draw(st.lists(st.sampled_from([0, 0, 0, 0, 0, 0, 1, -1]), min_size=last - first, max_size=last - first))
        )
        columns[actor] = {**{k: v[first:last] for k, v in c.items()}, "x": x, "lane": np.clip(lane, 0, 2)}
    return Trace(base.times[first:last] - base.times[first], columns)


@pytest.mark.parametrize("path", SCENARIOS, ids=[p.stem for p in SCENARIOS])
def test_the_monitor_agrees_with_the_brute_force_semantics(path):
    from pytest_roadlogic.planning import ContinuousPlanner, ContinuousSettings

    scenario = load_file(path).scenarios[0]
    automaton = build_automaton(scenario)
    n_max = max_samples(automaton)
    planned = plan_trace(ContinuousPlanner(automaton, ContinuousSettings(), 1).first())  # the default encoding
    assert monitor(automaton, planned).accepted, "a plan, read as a trace, meets its scenario"

    @settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(
        st.one_of(traces(automaton.actors, automaton.stationary, n_max), perturbed(planned, n_max)),
        st.sampled_from([math.inf, 0.0, 2 * DT]),  # the scenario begins at any sample, the first, or by the third
    )
    def check(trace, begins_by):
        expected = brute_force_robustness(automaton, trace, begins_by)
        verdict = monitor(automaton, trace, begins_by=begins_by)
        if expected == -math.inf:
            assert verdict.robustness == -math.inf
        else:
            assert verdict.robustness == pytest.approx(expected)
        assert verdict.accepted == (expected >= 0)
        if verdict.robustness > 0:
            assert verdict.accepted
        if verdict.robustness < 0:
            assert not verdict.accepted
        # the monitor's passes with a floor drop runs below it: the verdict is the one that keeps them all
        every_run = monitor(automaton, trace, floors=(-math.inf,), begins_by=begins_by)
        assert (verdict.furthest, verdict.run, verdict.miss) == (every_run.furthest, every_run.run, every_run.miss)

    check()


def test_a_plan_without_a_run_up_begins_its_scenario_at_the_first_sample_and_one_with_a_run_up_by_its_end():
    from pytest_roadlogic.planning.plan import Plan

    assert Plan(dt=1.0, lanes=3, states={}, transitions=[], runup=0.0).begins_by == 0.0
    assert Plan(dt=1.0, lanes=3, states={}, transitions=[], runup=7.0).begins_by == 8.0
