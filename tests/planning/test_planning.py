"""Plans obey the background theory and take the automaton's guards in order.

The checks here are written from the rules, independently of the ASP encoding.
"""

import dataclasses
import math
from pathlib import Path

import pytest

from pytest_roadlogic.logic.automaton import HeldSpeed, MeanAcceleration, ShapedSpeedChange, Travelled
from pytest_roadlogic.planning import GridPlanner, GridSettings

SETTINGS = GridSettings()


def check_plan(plan, automaton, settings=SETTINGS):
    vehicles = plan.vehicles
    for v in vehicles:
        states = plan.states[v]
        if v in automaton.stationary:
            assert all(
                s.speed == 0 and s.position == states[0].position and s.lane == states[0].lane for s in states
            ), f"{v} moved"
            continue
        changes = [k for k in range(1, len(states)) if states[k].lane != states[k - 1].lane]
        for k in range(len(states)):
            s = states[k]
            assert settings.min_speed <= s.speed <= settings.max_speed, f"{v} speed out of bounds at {k}"
            assert 0 <= s.lane < automaton.lanes, f"{v} off the road at {k}"
            if k:
                p = states[k - 1]
                accel = s.speed - p.speed
                assert accel in settings.accelerations, f"{v} acceleration {accel} at step {k}"
                assert s.position == pytest.approx(p.position + (p.speed + s.speed) / 2), f"{v} kinematics at {k}"
                assert abs(s.lane - p.lane) <= 1
        for a, b in zip(changes, changes[1:]):
            assert b - a >= settings.lane_change_gap, f"{v} changes lane at steps {a} and {b}"
    for i, a in enumerate(vehicles):
        for b in vehicles[i + 1 :]:
            for k in range(plan.horizon + 1):
                sa, sb = plan.at(a, k), plan.at(b, k)
                lanes_a = {sa.lane} | ({plan.at(a, k - 1).lane} if k else set())
                lanes_b = {sb.lane} | ({plan.at(b, k - 1).lane} if k else set())
                if lanes_a & lanes_b:
                    assert abs(sa.position - sb.position) >= settings.min_gap, f"{a} and {b} too close at {k}"
    check_run(plan, automaton)


def check_run(plan, automaton):
    """The guards in order, at strictly increasing steps, ending in the final location; every
    invariant at every step spent in its location; every timed phase within its bounds, and its
    actors' mean accelerations (speed at its end minus speed at its start, over its length) within theirs."""
    location = automaton.initial
    last_step = -1
    started = {}
    for step, tid in plan.transitions:
        transition = automaton.transitions[tid]
        assert transition.source == location
        assert step > last_step or (step == 0 and last_step == -1)
        for k in range(last_step + 1, step):
            invariant = automaton.location(location).invariant
            assert invariant.holds(plan.snapshot(k)), f"invariant {invariant} fails at step {k}"
        snapshot = plan.snapshot(step)
        assert transition.guard.holds(snapshot), f"guard {transition.guard} fails at step {step}"
        for phase in transition.starts & automaton.timings.keys():
            started[phase] = step
        for phase in transition.ends & automaton.timings.keys():
            timing = automaton.timings[phase]
            begun = started.pop(phase, step)
            assert timing.admits((step - begun) * plan.dt), f"{timing} broken at step {step}"
            for rate in timing.rates:
                start, end = plan.at(rate.actor, begun), plan.at(rate.actor, step)
                if isinstance(rate, ShapedSpeedChange):
                    check_shape(plan, rate, begun, step)
                    continue
                if isinstance(rate, MeanAcceleration):  # every step's, but a standstill's
                    for k in range(begun + 1, step + 1):
                        before, after = plan.at(rate.actor, k - 1), plan.at(rate.actor, k)
                        value = (after.speed - before.speed) / plan.dt
                        stands = after.speed <= 1e-6 and value <= 0
                        assert value >= rate.low - 1e-6 and (value <= rate.high + 1e-6 or stands), (
                            f"{rate} broken: {value:.2f} at step {k}"
                        )
                    continue
                if isinstance(rate, HeldSpeed):  # every step's speed against the phase's first
                    for k in range(begun, step + 1):
                        strayed = abs(plan.at(rate.actor, k).speed - start.speed)
                        assert strayed <= rate.high + 1e-6, f"{rate} broken: {strayed:.2f} at step {k}"
                    continue
                if isinstance(rate, Travelled):  # metres covered in the phase
                    value = end.position - start.position
                else:  # the speed gained over the phase
                    value = end.speed - start.speed
                assert rate.low - 1e-6 <= value <= rate.high + 1e-6, (
                    f"{rate} broken: {value:.2f} from step {begun} to {step}"
                )
        location, last_step = transition.target, step
    assert location == automaton.final


def check_shape(plan, rate, begun: int, step: int) -> None:
    """A speed change in the standard's shape. Linear (and step): one way, at the peak (step: at
    least its least) on every step but the last, where the car reaches its target, and those after
    a standstill. Cubic and sinusoidal: at each step inside, the share of the change the curve
    has made there (within a quarter m/s), the change's peak (the curve's factor times its mean)
    within the band."""
    speeds = [plan.at(rate.actor, k).speed for k in range(begun, step + 1)]
    rates = [(b - a) / plan.dt for a, b in zip(speeds, speeds[1:])]
    if rate.shape in ("linear", "step"):
        sign = 1.0 if speeds[-1] >= speeds[0] else -1.0
        for k, value in enumerate(rates):
            size = sign * value
            assert -1e-6 <= size <= rate.high + 1e-6, f"{rate} broken: {value:.2f} at step {begun + k + 1}"
            last = k == len(rates) - 1 or speeds[k + 1] <= 1e-6
            assert last or size >= rate.low - 1e-6, f"{rate} broken: {value:.2f} at step {begun + k + 1}"
        return
    length = len(rates)
    for k in range(1, length):
        s = k / length
        share = 3 * s**2 - 2 * s**3 if rate.shape == "cubic" else (1 - math.cos(math.pi * s)) / 2
        assert abs(speeds[k] - (speeds[0] + share * (speeds[-1] - speeds[0]))) <= 0.25 + 1e-4, (
            f"{rate} broken: off its curve at step {begun + k}"
        )
    factor = 1.5 if rate.shape == "cubic" else math.pi / 2
    peak = factor * abs(speeds[-1] - speeds[0]) / (length * plan.dt)
    assert rate.low - 1e-6 <= peak <= rate.high + 1e-6, f"{rate} broken: peak {peak:.2f}"


BENCHMARK = sorted((Path(__file__).resolve().parents[2] / "scenarios").glob("*.osc"))
BENCHMARK_BY_NAME = {path.stem: path for path in BENCHMARK}


@pytest.mark.parametrize("path", BENCHMARK, ids=[p.stem for p in BENCHMARK])
def test_thirty_plans_of_every_benchmark_scenario_obey_the_rules_and_the_guards(path):
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import load_file

    automaton = build_automaton(load_file(path).scenarios[0])
    checked = 0
    for seed in (1, 2, 3):
        for plan in GridPlanner(automaton, seed=seed).plans(limit=10):
            check_plan(plan, automaton)
            checked += 1
    assert checked == 30


@pytest.mark.parametrize("seed", range(1, 11))
def test_overtake_plans_obey_the_rules_and_the_guards(overtake_automaton, seed):
    plan = GridPlanner(overtake_automaton, seed=seed).first()
    check_plan(plan, overtake_automaton)


def test_next_plans_differ_and_also_obey_the_rules(overtake_automaton):
    plans = list(GridPlanner(overtake_automaton, seed=1).plans(limit=5))
    assert len(plans) == 5
    signatures = {tuple((s.position, s.lane) for v in p.vehicles for s in p.states[v]) for p in plans}
    assert len(signatures) == 5
    for plan in plans:
        check_plan(plan, overtake_automaton)


def test_the_same_seed_gives_the_same_plan(overtake_automaton):
    first = GridPlanner(overtake_automaton, seed=7).first()
    again = GridPlanner(overtake_automaton, seed=7).first()
    assert first.to_dict()["states"] == again.to_dict()["states"]


def test_instance_program_lists_the_automaton_and_its_guards(overtake_automaton):
    program = GridPlanner(overtake_automaton).instance_program()
    assert "transition(0,0,1)." in program
    # v1 starts 10-20 m behind v2, planned 1.5 m inside the range, as a fact that asp/grid/guards.lp
    # turns into a difference constraint per side
    assert "position_within(1,v2,v1,12,18)." in program
    assert "&diff" not in program and ":-" not in program, "the instance is facts: the rules are in asp/"


@pytest.mark.parametrize("seed", range(1, 6))
@pytest.mark.parametrize("quantity, low, high, margin", [("position", 0.0, 30.0, 1.5), ("speed", -3.0, 3.0, 0.5)])
def test_a_negated_guard_puts_the_value_outside_the_range_with_a_margin(seed, quantity, low, high, margin):
    """``not (a within [low, high] of b)``: positions are solver variables, not atoms, and bounds
    are planned with a margin inside; the negation must force the value out of the range, with
    the margin outside it, not merely leave the range unenforced."""
    from pytest_roadlogic.logic.automaton import Location, SymbolicAutomaton, Transition
    from pytest_roadlogic.logic.guards import Bound, Not, Term

    near = Bound(Term(quantity, "a", "b"), low, high)
    automaton = SymbolicAutomaton(
        locations=[Location(0, "init"), Location(1, "end")],
        transitions=[Transition(0, 0, 1, Not(near))],
        initial=0,
        final=1,
        actors=("a", "b"),
    )
    plan = GridPlanner(automaton, seed=seed).first()
    check_plan(plan, automaton)
    step = plan.transitions[0][0]
    difference = getattr(plan.at("a", step), quantity) - getattr(plan.at("b", step), quantity)
    assert not low - margin <= difference <= high + margin, f"a - b = {difference}: the negated range is not kept clear"


def test_an_impossible_scenario_has_no_plan():
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import check_text
    from pytest_roadlogic.planning import NoPlanError

    text = "scenario s:\n  a: car\n  do a.drive() with:\n    speed([50..60]mps, at: end)\n"
    automaton = build_automaton(check_text(text).scenarios[0])
    with pytest.raises(NoPlanError):
        GridPlanner(automaton, GridSettings(max_horizon=6)).first()


def test_timed_phases_last_as_long_as_their_durations_allow():
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import load_file

    automaton = build_automaton(
        load_file(Path(__file__).resolve().parents[1] / "corpus" / "28_durations.osc").scenarios[0]
    )
    plan = GridPlanner(automaton, seed=3).first()
    fired = {tid: step for step, tid in plan.transitions}
    for timing in automaton.timings.values():
        begin = [step for tid, step in fired.items() if timing.phase in automaton.transitions[tid].starts]
        end = [step for tid, step in fired.items() if timing.phase in automaton.transitions[tid].ends]
        assert len(begin) == len(end) == 1, timing
        assert timing.low <= (end[0] - begin[0]) * plan.dt <= timing.high, timing


def plan_text(tmp_path, name: str, text: str) -> tuple[int, Path]:
    """``roadlogic plan`` on ``text`` written as ``name`` in ``tmp_path``: (exit code, the file)."""
    from pytest_roadlogic.cli import main

    path = tmp_path / name
    path.write_text(text)
    return main(["plan", str(path)]), path


def test_an_impossible_scenario_is_reported_with_both_conflicting_modifiers(tmp_path, capsys):
    code, path = plan_text(
        tmp_path,
        "impossible.osc",
        "scenario s:\n  a: car\n  b: car\n  do parallel:\n    b.drive()\n    a.drive() with:\n"
        "      position([30..40]m, ahead_of: b, at: end)\n      position([10..20]m, behind: b, at: end)\n",
    )
    assert code == 1
    err = capsys.readouterr().err
    # each constraint with the logical parameter behind it: the inline range's name (two
    # position ranges in one modifier list, told apart by their lines)
    assert (
        f"{path}:7:7: error: 30 <= p(a) - p(b) <= 40 (parameter a.drive.position.distance@7) cannot hold together with "
        "10 <= p(b) - p(a) <= 20 (line 8; parameter a.drive.position.distance@8)"
    ) in err
    assert f"{path}:8:7: error:" in err and "Traceback" not in err


SWAP = """\
scenario s:
  a: car
  b: car
  do serial:
    p1: parallel:
      b.drive()
      a.drive() with:
        position([30..40]m, ahead_of: b, at: end)
    p2: parallel(duration: [1s..2s]):
      b.drive() with:
        speed([10..12]mps)
      a.drive() with:
        speed([10..12]mps)
        position([10..20]m, behind: b, at: end)
"""


def test_constraints_that_conflict_across_phases_are_named_by_an_unsatisfiable_core(tmp_path, capsys):
    """a cannot fall from 30 m ahead of b to 10 m behind it within 2 s while b keeps 10-12 m/s:
    the report names exactly those four constraints (not a's own speed, which is not needed for
    the contradiction), each at its line and column."""
    from pytest_roadlogic.cli import main

    path = tmp_path / "swap.osc"
    path.write_text(SWAP)
    # the grid's accelerations (+-2 m/s^2) make a's speed bound needless; with the continuous
    # encoding's (-8..+4, jerk-limited) the group it names differs, and is checked there
    assert main(["plan", str(path), "--encoding", "grid"]) == 1
    err = capsys.readouterr().err
    named = {line.split(": error:")[0] for line in err.splitlines() if ": error:" in line}
    assert named == {f"{path}:8:9", f"{path}:9:18", f"{path}:11:9", f"{path}:14:9"}, err
    assert "30 <= p(a) - p(b) <= 40 (parameter a.drive.position.distance@8) cannot hold together with" in err
    assert "p2 lasts 1..2 s (line 9; parameter p2.duration)" in err
    assert "Traceback" not in err


def test_a_constraint_the_domain_rules_forbid_is_named_with_those_rules():
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import check_text
    from pytest_roadlogic.planning import UnsatisfiableScenario

    text = "scenario s:\n  a: car\n  do a.drive() with:\n    speed([50..60]mps, at: end)\n"
    automaton = build_automaton(check_text(text, "fast.osc").scenarios[0])
    with pytest.raises(UnsatisfiableScenario) as caught:
        GridPlanner(automaton, GridSettings(max_horizon=8)).first()
    report = caught.value.report()
    assert (
        "fast.osc:4:5: error: 50 <= v(a) <= 60 (parameter a.drive.speed.speed) cannot hold in any plan under the "
        "domain rules (speeds 2..40 m/s" in report
    )


def test_roadlogic_plan_prints_each_plan_as_a_table_and_the_instance_on_request(capsys):
    from pytest_roadlogic.cli import main

    assert (
        main(
            [
                "plan",
                str(Path(__file__).resolve().parents[2] / "scenarios" / "overtake.osc"),
                "--plans",
                "2",
                "--show-asp",
            ]
        )
        == 0
    )
    out = capsys.readouterr().out
    assert "#program base." in out and "transition(0," in out
    assert "plan 1 of scenario overtake" in out and "plan 2 of scenario overtake" in out
    assert "v1 pos/lane/speed" in out and "2 plans in" in out


def test_enumerated_plans_are_spread_out_not_near_neighbours(overtake_automaton):
    import itertools
    import statistics

    plans = list(GridPlanner(overtake_automaton, seed=1).plans(limit=10))
    cells = [{(v, k, s.lane, round(s.position)) for v in p.vehicles for k, s in enumerate(p.states[v])} for p in plans]
    similarity = statistics.mean(len(a & b) / len(a | b) for a, b in itertools.combinations(cells, 2))
    assert similarity < 0.3, f"mean pairwise Jaccard similarity of occupied cells is {similarity:.2f}"


RANDOM_START = GridSettings(random_start=True)


@pytest.mark.parametrize("path", BENCHMARK, ids=[p.stem for p in BENCHMARK])
def test_a_random_start_still_obeys_the_rules_and_the_guards(path):
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import load_file

    automaton = build_automaton(load_file(path).scenarios[0])
    for seed in range(1, 6):
        plan = GridPlanner(automaton, RANDOM_START, seed=seed).first()
        check_plan(plan, automaton, RANDOM_START)


def test_a_random_start_is_fixed_by_its_seed_and_varies_with_it(overtake_automaton):
    """The refined strategy's samples are independent random plans: one seed, one plan; other
    seeds give other start speeds, lanes and lengths, and some plans last longer than the shortest."""
    plans = [GridPlanner(overtake_automaton, RANDOM_START, seed=seed).first() for seed in range(1, 11)]
    again = GridPlanner(overtake_automaton, RANDOM_START, seed=1).first()
    assert again.to_dict()["states"] == plans[0].to_dict()["states"]
    starts = {tuple((p.states[v][0].speed, p.states[v][0].lane) for v in p.vehicles) for p in plans}
    assert len(starts) >= 8, "random starts should rarely coincide"
    shortest = GridPlanner(overtake_automaton, seed=1).first().horizon
    assert max(p.horizon for p in plans) > shortest, "no plan was stretched past the shortest horizon"
    assert min(p.horizon for p in plans) >= shortest


def test_a_random_start_drives_a_free_vehicle_as_preferred():
    """A vehicle the scenario says nothing about (overtake_third_actor's v3) nearly always takes its
    random acceleration where the speed limits allow it, and keeps its lane. Preferences the solver
    ignores (chance would follow a third of them) leave it weaving at random, and such plans all
    cover the same cells. Preferences may yield to the scenario and the other vehicles, hence the margins."""
    import re

    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import load_file

    automaton = build_automaton(load_file(BENCHMARK_BY_NAME["overtake_third_actor"]).scenarios[0])
    settings = dataclasses.replace(RANDOM_START, max_horizon=12)  # long enough to show a habit, and quick
    followed = steps = kept_lane = 0
    for seed in range(1, 13):
        planner = GridPlanner(automaton, settings, seed=seed)
        preferred = (
            int(re.search(r"preferred_acc\(v3,(-?\d+)\)", planner.preferences).group(1)) * settings.grid / settings.dt
        )
        states = planner.first().states["v3"]
        possible = [
            (a.speed, b.speed)
            for a, b in zip(states, states[1:])
            if settings.min_speed <= a.speed + preferred <= settings.max_speed
        ]
        followed += sum(after - before == preferred for before, after in possible)
        steps += len(possible)
        kept_lane += len({s.lane for s in states}) == 1
    assert followed >= 0.85 * steps, f"v3 took its preferred acceleration at {followed} of {steps} steps where it could"
    assert kept_lane >= 10, f"v3 kept its lane in {kept_lane} of 12 plans"


def test_a_random_start_prefers_and_never_forces():
    """The preferences are domain heuristics: a scenario whose start speed is pinned still plans."""
    import random

    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import check_text
    from pytest_roadlogic.planning.encodings.grid.instance import start_preferences

    automaton = build_automaton(
        check_text("scenario s:\n  v1: car\n  do v1.drive() with:\n    speed(9mps, at: start)\n").scenarios[0]
    )
    facts = start_preferences(automaton, RANDOM_START, random.Random(1))
    assert facts and all(line.startswith(("%", "preferred_")) for line in facts.splitlines()), (
        "only the facts the heuristics of asp/grid/preferences.lp read"
    )
    for seed in range(1, 6):
        plan = GridPlanner(automaton, RANDOM_START, seed=seed).first()
        assert 8.0 <= plan.states["v1"][0].speed <= 10.0


def test_a_horizon_limit_that_binds_is_named_not_the_scenarios_durations():
    # two phases of at least 15 s cannot end within 25 steps: the setting binds, and the message
    # must say so (before, the diagnosis blamed the two durations for clashing)
    from pytest_roadlogic.automaton import build_automaton
    from pytest_roadlogic.frontend import check_text
    from pytest_roadlogic.planning import HorizonTooShort

    text = "scenario s:\n  a: car\n  do serial:\n    first: a.drive(duration: [15s..20s])\n    second: a.drive(duration: [15s..20s])\n"
    automaton = build_automaton(check_text(text, "long.osc").scenarios[0])
    with pytest.raises(HorizonTooShort) as refused:
        GridPlanner(automaton, SETTINGS, 1).first()
    message = str(refused.value)
    assert (
        "horizon limit of 25 steps (25 s)" in message
        and "at least 30 s" in message
        and "--roadlogic-horizon" in message
    )
    assert GridPlanner(automaton, dataclasses.replace(SETTINGS, max_horizon=32), 1).first().horizon >= 30, (
        "with the limit raised it plans"
    )


KEEP_AND_CHANGE = """\
scenario s:
  a: car
  b: car
  do serial:
    p1: parallel(duration: 3s):
      b.drive() with:
        lane(1)
      a.drive() with:
        lane(2)
        speed(20mps)
    p2: parallel(duration: 3s):
      b.drive() with:
        keep_lane()
      a.drive() with:
        keep_speed()
        speed(30mps, at: end)
"""


def test_a_kept_speed_that_cannot_hold_is_named_as_the_file_writes_it_with_only_the_files_speeds(tmp_path, capsys):
    """A message names keep_speed() and what it holds, and only speeds the file asks: never a band
    of starting speeds the file never wrote (``0 <= v(a) <= 0.5``)."""
    code, _ = plan_text(tmp_path, "keep.osc", KEEP_AND_CHANGE)
    assert code == 1
    err = capsys.readouterr().err
    assert "keep_speed() of a over a.drive: its speed within 1.5 m/s of the phase's first" in err, err
    import re

    bands = set(re.findall(r"([\d.]+) <= v\(a\) <= ([\d.]+)", err))
    assert bands <= {("19.5", "20.5"), ("29.5", "30.5")}, f"only the file's speeds (with their tolerance): {bands}"
    assert "Traceback" not in err


def test_roadlogic_plan_tries_the_runs_fallbacks_before_no_plan_and_names_what_a_fallback_plan_needs(tmp_path, capsys):
    """From 10 to 30 m/s in 2 s is beyond a car: ``plan`` had said the speeds cannot hold together
    under its own margins and limits only, where ``run`` went on to its fallbacks; it now plans as
    ``run`` does and says which limits the plan needs, and whose they are."""
    code, _ = plan_text(
        tmp_path,
        "jump.osc",
        "scenario jump:\n  a: car\n  do serial:\n    p1: a.drive(duration: 2s) with:\n"
        "      speed(10mps, at: start)\n      speed(30mps, at: end)\n",
    )
    assert code == 0
    out = capsys.readouterr().out
    assert "no plan exists within the planner's vehicle limits: this one needs" in out, out
    assert "max_acceleration 4 m/s^2 relaxed to 12" in out and "beyond a real car's" in out
