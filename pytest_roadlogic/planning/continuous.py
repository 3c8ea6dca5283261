"""The continuous-dynamics encoding (``asp/continuous.lp``): the default planner since issue 17.

Positions, speeds and accelerations are real numbers in linear constraints that ``linear.py``
checks lazily with HiGHS (or clingo-lpx, ``theory="lpx"``, kept to compare); ASP decides the
automaton's run (``asp/automaton.lp``, shared with the grid encoding), lanes, and the order of
vehicles that share a lane. The instance is facts and constants, and one rule set per guard node
as in ``instance.py``, here with ``&sum`` constraints for positions and speeds.

Plans come shortest first, within the window of horizons the durations allow (``window.py``);
each further plan excludes the transition times and lanes of those before it; a random start
draws start lanes and speeds as preferences. A plan has no run-up: the simulation starts in its
first state. A scenario without a plan is explained as the grid planner does it (the diagnosis is
inherited), over the window's horizons.
"""

from __future__ import annotations

import math
import random
from collections.abc import Iterator
from dataclasses import dataclass, replace
from fractions import Fraction

import clingo

from ..logic.automaton import SymbolicAutomaton, Travelled
from ..logic.guards import HEADWAY, LANE, POSITION, SPEED, TRAVELED, And, Bound, Guard, Not, Or
from .errors import HorizonTooShort, NoPlanError, PlanningTimeout
from .instance import atom, bound_rule, guard_nodes, inset, junction_rules, outside_rules, with_automaton
from .linear import THEORY, LazyLinearTheory
from .plan import Plan, PlanState
from .solver import ASP_DIR, Planner, check_satisfiable

ENCODING = "continuous.lp"
# conflicts a random start's search at its drawn horizon may spend before the shortest horizon's
# plans are taken instead: a count, not a time, so that every machine stops at the same point (the
# grid's 50 000 are about 2 s there; each conflict here may cost a linear program)
STRETCH_CONFLICTS = 2_000
SHARED = ("automaton.lp",)
# a random start's vehicle keeps its lane unless the scenario needs a change (the grid's random
# start loads the same file)
KEEP_LANE = "keep_lane.lp"


@dataclass(frozen=True)
class ContinuousSettings:
    """The vehicle limits and planning bounds of the continuous encoding (SI units)."""

    dt: float = 1.0  # seconds per step
    min_acceleration: float = -8.0  # m/s^2: hard braking of a real car
    max_acceleration: float = 4.0  # m/s^2
    max_jerk: float = 2.0  # m/s^3: how much the acceleration may change from one step to the next
    min_speed: float = 0.5  # m/s for a driving vehicle the scenario does not ask to stop
    max_speed: float = 70.0  # m/s
    # m/s at the first step: a scenario that names no speed starts at highway speeds, not at the
    # crawl a vertex of the linear program would pick
    initial_speed: tuple[float, float] = (8.0, 40.0)
    lane_change_speed: float = 5.0  # m/s at least while changing lane
    min_gap: float = 8.0  # m between the centres of two vehicles sharing a lane
    # s: and more, by this many seconds of the speed at which the one behind closes in (a follower
    # 15 m behind at +15 m/s is a collision in the simulation, not a gap)
    closing_time: float = 1.0
    lane_change_gap: int = 3  # steps from one lane change of a vehicle to its next
    spread: float = 300.0  # m from the first vehicle within which the others start
    position_margin: float = 1.5  # m planned inside each side of a position range, when it fits
    speed_margin: float = 0.5  # m/s likewise for speeds
    headway_margin: float = 0.2  # s likewise for time headways
    # m/s^2 likewise for a phase's mean acceleration: the motion planner starts and ends a change
    # of speed late by up to a second (see _speed_lead), which moves the speeds at a 3 s phase's
    # ends by a few tenths of a m/s
    acceleration_margin: float = 0.4
    # s likewise for a sampled duration (the refined strategy's, sampling._band): the motion planner
    # meets a phase's entry condition up to 1.2 s after the plan's step (measured on
    # follow_then_overtake's refined samples: a relative speed the plan reached at the pass's first
    # step, the trace reached 1.2 s later), so a phase planned at its range's shortest (8 s of
    # [8..20] s) was simulated 6.6 s long
    duration_margin: float = 1.0
    # when no plan keeps the margins, a second search keeps this fraction of them: the scenario may
    # have plans nearer its edges than the margins allow (catch_up_band: 0.5 m/s on both speeds over
    # 20 s moved its band's edge 20 m below the true one). Such a plan is simulated and monitored
    # like any other; when none is accepted, the margins are what binds (MarginsBind)
    fallback_margins: float = 0.2
    max_horizon: int = 120  # steps
    time_limit: float = 60.0  # seconds for one solve, all horizons together
    # how the linear constraints are kept: "lazy" checks each complete choice with HiGHS and learns
    # nogoods from its conflicts (planning/linear.py); "lpx" keeps them at every decision with
    # clingo-lpx's exact simplex (measured slower by orders of magnitude on long scenarios)
    theory: str = "lazy"
    lpx_options: tuple[tuple[str, str], ...] = ()  # clingo-lpx's own (propagate-conflicts, select, ...)
    # when no plan exists, find the constraints that cannot hold together (UnsatisfiableScenario)
    explain_unsatisfiable: bool = True
    # seconds the diagnosis may spend deciding whether one constraint can leave the group that
    # clashes; past it the constraint stays. Measured: infeasible_order's duration, once relaxed,
    # leaves every horizon up to the limit to refute, 15 s at 120 steps, for a group that with it
    # names one constraint more (the duration) and is still true
    removal_time_limit: float | None = 1.0
    # a random start (the refined strategy): start lanes and speeds the scenario leaves open are
    # drawn from the seed (as preferences), not left to the solver's and the LP's habits
    random_start: bool = False
    # s: how long a random start's plan may last when it is stretched past the shortest horizon the
    # scenario allows (drawn uniformly up to it, as the grid planner draws its plans' lengths up to
    # its 25-step horizon limit). Measured (roadlogic bench scenarios/ --encoding continuous, seed 1):
    # with every refined plan at its shortest horizon, the refined instances' occupancy was more
    # alike than the grid's on six of seven scenarios (change_lane 0.415 against 0.216)
    stretch_limit: float = 25.0
    # m/s^2: a random start's driving vehicle prefers to accelerate at one of -drift, 0 and +drift,
    # drawn per vehicle, as the grid planner draws one of its accelerations; kept by the linear
    # program where the scenario and drift_speeds leave it free (a preference, never a reason for
    # no plan). Why: see start_preferences
    drift: float = 2.0
    # m/s: the speeds within which a drawn acceleration is kept (the grid's speed range): a vehicle
    # drifting down settles at the low one instead of crawling at min_speed, one drifting up at
    # the high one
    drift_speeds: tuple[float, float] = (2.0, 40.0)

    def resolution(self) -> dict[str | None, float]:
        """How wide a band a sampled value is narrowed to, per physical dimension: positions and
        speeds are real-valued here, so the band is the planning margin's (the plan lies within a
        quarter of it from the sample); durations still count whole steps, time headways do not."""
        return {
            "length": 2 * self.position_margin,
            "speed": 2 * self.speed_margin,
            "time": self.dt,
            "acceleration": 0.5,
            "headway": 2 * self.headway_margin,
        }

    def start_band(self) -> tuple[float, float]:
        """The start speeds (m/s) a driving vehicle is preferred to have where the scenario leaves
        them open: ``initial_speed`` within the speed limits."""
        return max(self.initial_speed[0], self.min_speed), min(self.initial_speed[1], self.max_speed)

    def margins(self) -> dict[str | None, float]:
        """How far inside a range's edges the plan keeps, per physical dimension."""
        return {
            "length": self.position_margin,
            "speed": self.speed_margin,
            "headway": self.headway_margin,
            "acceleration": self.acceleration_margin,
            "time": self.duration_margin,
        }

    def thinned(self) -> ContinuousSettings | None:
        """These settings with ``fallback_margins`` of each margin, or None when there is no such second search."""
        if not 0 <= self.fallback_margins < 1:
            return None
        f = self.fallback_margins
        return replace(
            self,
            position_margin=self.position_margin * f,
            speed_margin=self.speed_margin * f,
            headway_margin=self.headway_margin * f,
            acceleration_margin=self.acceleration_margin * f,
            duration_margin=self.duration_margin * f,
            fallback_margins=1.0,
        )

    def describe_margins(self) -> str:
        return (
            f"speed_margin {self.speed_margin:g} m/s, position_margin {self.position_margin:g} m, "
            f"headway_margin {self.headway_margin:g} s, acceleration_margin {self.acceleration_margin:g} m/s^2, "
            f"duration_margin {self.duration_margin:g} s"
        )

    def summary(self, lanes: int) -> str:
        """The vehicle limits and bounds on a road of ``lanes`` lanes, for messages that blame them."""
        return (
            f"speeds {self.min_speed:g}..{self.max_speed:g} m/s, accelerations {self.min_acceleration:g}..{self.max_acceleration:g} m/s^2, "
            f"{lanes} lanes, {self.min_gap:g} m gaps, at most {self.max_horizon} steps of {self.dt:g} s"
        )


def _number(value: float) -> str:
    """A rational constant for clingo-lpx: quoted, exact for the decimals we write."""
    fraction = Fraction(value).limit_denominator(10**6)
    text = f"{fraction.numerator}" if fraction.denominator == 1 else f"{float(fraction):.6f}".rstrip("0")
    return f'"{text}"'


def build_continuous_instance(
    automaton: SymbolicAutomaton, settings: ContinuousSettings, relaxable: bool = False
) -> tuple[str, str]:
    """(base program, state(t) program) of the scenario for the continuous encoding; with
    ``relaxable``, every bound and duration of the scenario can be switched off by an external
    ``relaxed(K)``, as in the grid encoding, for the diagnosis of a scenario without a plan."""
    s = settings
    vehicles = automaton.actors
    start_low, start_high = s.start_band()
    base = [
        "% scenario instance, continuous encoding (generated)",
        f"#const dt = {_number(s.dt)}.",
        f"#const half_dt2 = {_number(s.dt * s.dt / 2)}.",
        f"#const amin = {_number(s.min_acceleration)}.",
        f"#const amax = {_number(s.max_acceleration)}.",
        f"#const jerk = {_number(s.max_jerk * s.dt)}.",
        f"#const vmin = {_number(s.min_speed)}.",
        f"#const vmax = {_number(s.max_speed)}.",
        f"#const v0min = {_number(start_low)}.",
        f"#const v0max = {_number(start_high)}.",
        f"#const gap = {_number(s.min_gap)}.",
        f"#const closing_time = {_number(s.closing_time)}.",
        f"#const lane_change_speed = {_number(s.lane_change_speed)}.",
        f"#const spread = {_number(s.spread)}.",
        f"#const first_vehicle = {atom(vehicles[0])}.",
        *(f"vehicle({atom(v)})." for v in vehicles),
        *(f"stationary({atom(v)})." for v in vehicles if v in automaton.stationary),
        *(f"may_stop({atom(v)})." for v in sorted(stopping(automaton, s))),
        f"lane_id(0..{automaton.lanes - 1}).",
        "lateral(-1;0;1).",
        f"lane_change_gap({s.lane_change_gap}).",
        "",
    ]
    return with_automaton(
        base,
        automaton,
        s.dt,
        relaxable,
        lambda node, guard, numbering, switch: _guard_rules(node, guard, numbering, s, switch),
        lambda relax: _rate_rules(automaton, s, relax),
    )


def _rate_rules(automaton: SymbolicAutomaton, settings: ContinuousSettings, relax: dict) -> list[str]:
    """The bounds over a timed phase P's two ends as linear rows. A mean acceleration: one row per
    length D the phase may have (a known length makes the mean linear):
      &sum{ v(V,t); -1*v(V,T) } >= lo*D*dt :- finish(P,t), begin(P,T), T = t-D.   (<= hi*D*dt likewise)
    with lo and hi inset by ``acceleration_margin``; the lengths run up to the phase's upper bound,
    or to the horizon limit for a phase with none. A distance travelled: one row,
      &sum{ p(V,t); -1*p(V,T) } >= lo :- finish(P,t), begin(P,T).
    inset by ``position_margin``."""
    rules = []
    for phase, timing in sorted(automaton.timings.items()):
        if not timing.rates:
            continue
        shortest = max(1, math.ceil(timing.low / settings.dt - 1e-9))
        longest = (
            min(settings.max_horizon, math.floor(timing.high / settings.dt + 1e-9))
            if math.isfinite(timing.high)
            else settings.max_horizon
        )
        for rate in timing.rates:
            rules.append(f"% {rate}")
            switch = f", not relaxed({relax[rate.source]})" if rate.source in relax else ""
            actor = atom(rate.actor)
            if isinstance(rate, Travelled):
                low, high = inset(rate.low, rate.high, settings.position_margin)
                body = f":- finish({phase},t), begin({phase},T){switch}."
                for value, operator in ((low, ">="), (high, "<=")):
                    if math.isfinite(value):
                        rules.append(f"&sum{{ p({actor},t); -1*p({actor},T) }} {operator} {_number(value)} {body}")
                continue
            low, high = inset(rate.low, rate.high, settings.acceleration_margin)
            for length in range(shortest, longest + 1):
                seconds = length * settings.dt
                body = f":- finish({phase},t), begin({phase},T), T = t-{length}{switch}."
                for value, operator in ((low * seconds, ">="), (high * seconds, "<=")):
                    if math.isfinite(value):
                        rules.append(f"&sum{{ v({actor},t); -1*v({actor},T) }} {operator} {_number(value)} {body}")
    return rules


def start_preferences(automaton: SymbolicAutomaton, settings: ContinuousSettings, draw: random.Random) -> str:
    """A random start's draws, in a fixed order so that one seed gives one set: per vehicle a
    preferred lane (a heuristic) and, for a driving one, a preferred start speed (a preference of
    the linear program, which a scenario's own speeds override).

    A driving vehicle that changes lane prefers to end the plan in its drawn lane as well: one the
    scenario moves out of its lane (a dodge, an overtake) does not always go to the nearest lane,
    and one the scenario leaves in its lane is not pulled out of it. Measured (roadlogic bench
    scenarios/ --encoding continuous, seed 1), refined mean similarity with the start lane alone
    -> with this: dodge_obstacle 0.569 -> 0.470 (its ego had always dodged into the next lane),
    overtake_obstacle 0.494 -> 0.456, overtake_fixed_lane 0.296 -> 0.282, change_lane 0.217 ->
    0.224, follow 0.209 -> 0.206, overtake 0.238 -> 0.251, overtake_third_actor 0.242 -> 0.244.
    Preferred by every vehicle, not only those that change lane, it pulled coupled vehicles out
    of their lanes for nothing (follow's lead and tail changed lane in 34 of 50 samples, against
    10 without and 17 with this; follow 0.210, overtake_third_actor 0.276); drawn apart from the
    start lane, follow 0.233.

    And, as the grid planner's random start does (asp/preferences.lp), a driving vehicle keeps
    one drawn acceleration (-drift, 0 or +drift, an ``&drift`` preference of the linear program,
    within ``drift_speeds``) and keeps its lane unless the scenario needs a change (asp/keep_lane.lp).
    Without them the smoothest plan held every vehicle the scenario leaves free at its start
    speed, and the solver's random signs moved vehicles across lanes and back for nothing (follow,
    seeds 1-30: a lane change in 11 first plans, 8 with this; both cars kept the middle lane in 2,
    8 with this: pairs in different lanes share no cell). Measured
    (roadlogic bench scenarios/ --encoding continuous, seeds 1, 2 and 3), refined mean similarity
    before -> after: change_lane 0.224/0.251/0.231 -> 0.185/0.189/0.180, dodge_obstacle
    0.470/0.463/0.532 -> 0.527/0.522/0.451, follow 0.206/0.239/0.255 -> 0.197/0.181/0.181, overtake
    0.251/0.279/0.255 -> 0.228/0.216/0.219, overtake_fixed_lane 0.282/0.291/0.288 ->
    0.283/0.306/0.280, overtake_obstacle 0.456/0.419/0.441 -> 0.419/0.441/0.440,
    overtake_third_actor 0.244/0.243/0.246 -> 0.224/0.213/0.220; mean over the seven 0.305/0.312/
    0.321 -> 0.295/0.295/0.282, and refined below base on all seven at each seed (before, follow
    and overtake missed it at seed 2, follow and overtake_third_actor at seed 3). The drift alone
    (seed 1): follow 0.217; drawn from -2..+2 instead of three values, 0.224, and that kept within
    the start band (8-40 m/s), 0.226. Lanes kept only by
    vehicles the scenario never moves across lanes: change_lane 0.228 (its v1 wove again). A lane
    change at a drawn step, or each transition's sign drawn (eager or late): neither better over
    the seven (0.305, 0.315 at seed 1).

    And a transition whose guard pins a driving vehicle to a place (``pins``: dodge_obstacle's
    end, 5-20 m past the parked car) is tried at its earliest step first. Every other transition
    is tried as late as it can fire (a free guard is tried false first), so a plan stretched to
    its drawn length met such a guard only at its last step, and the vehicle covered the same
    distance over the whole plan: dodge_obstacle's ego crawled towards the car at 2-4 m/s for up
    to 25 s, where the grid's dodges end by step 4-10 and its ego drives on. Measured (refined
    mean similarity of dodge_obstacle, seeds 1/2/3; no other of the seven has such a guard):
    0.527/0.522/0.451 -> 0.424/0.411/0.379, the grid's 0.475/0.471/0.461. Tried early in a drawn
    share of the samples only: a third 0.502/0.439/0.412, a half 0.480/0.426/0.405, two thirds
    0.451/0.410/0.383 (the late samples are the ones alike). Every transition tried early in every
    sample: change_lane 0.324 and overtake_fixed_lane 0.453 at seed 1, above their base strategy
    (each squeezed into the plan's first steps); every transition with a position or headway in
    its guard (follow's end gap, the overtakes' ends), in a drawn third: overtake_third_actor
    0.248/0.229/0.251, above its base strategy at seed 3, and follow no better (0.190/0.182/0.188)."""
    low, high = settings.start_band()
    rules, ends, drifts = [], [], []
    for vehicle in automaton.actors:
        name = atom(vehicle)
        lane = draw.randrange(automaton.lanes)
        rules.append(f"#heuristic lane({name},{lane},0). [2,true]")
        if vehicle not in automaton.stationary:
            rules.append(f"&nudge{{ v({name},0) }} = {_number(round(draw.uniform(low, high), 1))}.")
            ends.append(f"#heuristic lane({name},{lane},t) : query(t), changed({name},t). [3,true]")
    # drawn after the lanes and start speeds, which a seed therefore gives as it did before drifts
    slow, fast = settings.drift_speeds
    for vehicle in automaton.actors:
        if vehicle not in automaton.stationary and settings.drift:
            name = atom(vehicle)
            aim = draw.choice((-settings.drift, 0.0, settings.drift))
            drifts += [
                f"&drift{{ a({name},t) }} = {_number(aim)}.",
                f"&drift{{ v({name},t) }} >= {_number(slow)}.",
                f"&drift{{ v({name},t) }} <= {_number(fast)}.",
            ]
    # the last step's lane atoms exist once that step is grounded, and query(t) says which is last;
    # changed(V,t): V has changed lane by step t
    keep_lane = (ASP_DIR / KEEP_LANE).read_text(encoding="utf-8")
    # a transition that pins a driving vehicle to a place is tried at its earliest step first (a
    # decision order, latest step last; a heuristic's level must be positive)
    top = settings.max_horizon + 1
    early = [
        f"#heuristic fire({transition.id},t) : t < {top}. [{top}-t,true]"
        for transition in automaton.transitions
        if transition.source != automaton.initial
        and any(pins(bound, automaton.stationary) for bound in transition.guard.atoms())
    ]
    return (
        "\n".join(
            [
                *rules,
                "#program dynamics(t).",
                *drifts,
                keep_lane,
                "#program dynamics(t).",
                "changed(V,t) :- changing(V,t).",
                "changed(V,t) :- changed(V,t-1), t > 1.",
                "#program check(t).",
                *ends,
                "#program state(t).",
                *early,
                "#program base.",
            ]
        )
        + "\n"
    )


def pins(bound: Bound, stationary: frozenset[str]) -> bool:
    """Whether ``bound`` pins a driving vehicle to a place on the road: a distance travelled, or a
    position that is absolute or taken from a stationary object. Met at a later step, such a
    bound leaves the vehicle the same distance for more time; one between two driving vehicles
    does not (they may drive on at any speed together)."""
    if bound.term.quantity == TRAVELED:
        return True
    return bound.term.quantity == POSITION and sum(actor not in stationary for actor in bound.term.actors) == 1


def farthest(points: list[float], low: float, high: float) -> float:
    """The value in [low, high] farthest from every one of ``points`` (the lowest of ties)."""
    inside = sorted(min(max(p, low), high) for p in points)
    candidates = [low, high] + [(a + b) / 2 for a, b in zip(inside, inside[1:])]
    return max(candidates, key=lambda c: (min(abs(c - p) for p in inside), -c)) if inside else low


def stopping(automaton: SymbolicAutomaton, settings: ContinuousSettings) -> set[str]:
    """The vehicles the scenario lets stop: a speed bound of theirs reaches below the speed every
    other driving vehicle keeps (``speed(0kph)``, ``change_speed(target: 0kph)``). The paper's
    no-stop rule, scoped: whoever the scenario does not ask to stop keeps moving."""
    _, numbering = guard_nodes(automaton)  # every guard and invariant, and every part of one
    return {
        node.term.actor
        for node in numbering
        if isinstance(node, Bound)
        and node.term.quantity == SPEED
        and node.term.reference is None
        and node.low < settings.min_speed
    }


def _terms(bound: Bound) -> tuple[str, str]:
    """The variable of a position or speed bound's quantity, and the &sum elements of its term."""
    variable = "p" if bound.term.quantity in (POSITION, TRAVELED) else "v"
    term = bound.term
    elements = f"{variable}({atom(term.actor)},t)"
    if term.quantity == TRAVELED:  # d(a) = p(a,t) - p(a,0)
        elements += f"; -1*p({atom(term.actor)},0)"
    if term.reference is not None:
        elements += f"; -1*{variable}({atom(term.reference)},t)"
    return variable, elements


def _margin(bound: Bound, settings: ContinuousSettings) -> float:
    if bound.term.quantity == HEADWAY:
        return settings.headway_margin
    return settings.position_margin if bound.term.quantity in (POSITION, TRAVELED) else settings.speed_margin


def _compared(bound: Bound, value: float) -> tuple[str, str]:
    """(&sum elements, right-hand side) that compare a bound's term with ``value`` in a linear
    row: the row's ``<=`` (``>=``) holds exactly when the term is at most (at least) ``value``.
    A headway ``h(a, b)`` is compared as ``gap - value * v(b)`` with 0 (the follower never
    reverses); a position or speed as the term itself with ``value``."""
    if bound.term.quantity == HEADWAY:
        ahead, behind = atom(bound.term.actor), atom(bound.term.reference)
        return f"p({ahead},t); -1*p({behind},t); {_number(-value)}*v({behind},t)", "0"
    return _terms(bound)[1], _number(value)


def _guard_rules(
    node: int, guard: Guard, numbering: dict[Guard, int], settings: ContinuousSettings, switch: str = ""
) -> list[str]:
    """The rules of one guard node; ``switch`` is a body condition (``, not relaxed(K)``) under
    which a bound's linear constraints apply."""
    head = f"g({node},t)"
    if isinstance(guard, (And, Or)):
        return junction_rules(node, guard, numbering)
    if isinstance(guard, Not):
        bound = guard.part
        assert isinstance(bound, Bound)
        if bound.term.quantity == LANE:
            return outside_rules(node, bound, None)  # lanes: the grid's rules, which need no settings
        return _outside(node, bound, settings, switch)
    assert isinstance(guard, Bound)
    if guard.term.quantity == LANE:
        return bound_rule(head, guard, None)
    low, high = inset(guard.low, guard.high, _margin(guard, settings))
    if guard.term.quantity == SPEED and guard.term.reference is None and guard.low <= 0:
        low = 0.0  # no margin below a standstill: no vehicle undershoots it (none reverses)
    # a free guard is tried false first: set at random, it would add linear constraints at steps
    # where no transition or invariant needs it
    rules = [f"{{ {head} }}.", f"#heuristic {head}. [1,false]"]
    for value, operator in ((high, "<="), (low, ">=")):
        if math.isfinite(value):
            elements, right = _compared(guard, value)
            rules.append(f"&sum{{ {elements} }} {operator} {right} :- {head}{switch}.")
    if guard.term.quantity == SPEED:
        rules += _speed_lead(node, _terms(guard)[1], low, high)
    return rules


def _speed_lead(node: int, elements: str, low: float, high: float) -> list[str]:
    """A speed bound that holds at a step is preferred to hold at the steps next to it too.

    Why: the motion planner rounds off the plan's changes of speed, starting them late and ending
    them early (measured on follow_then_overtake's refined samples: a relative speed the plan
    reached at a phase's first step, the trace reached 1.2 s later, past the 0.5 s a sampled
    duration allows). Holding the bound a step either side is a preference of the smoothing
    program, never a reason for no plan.
    """
    before, after = elements.replace(",t)", ",S)"), elements
    rules = []
    for bound, operator in ((high, "<="), (low, ">=")):
        if math.isfinite(bound):
            rules.append(f"&prefer{{ {before} }} {operator} {_number(bound)} :- g({node},t), S = t-1, t > 0.")
            rules.append(f"&prefer{{ {after} }} {operator} {_number(bound)} :- g({node},S), S = t-1.")
    return rules


def _outside(node: int, bound: Bound, settings: ContinuousSettings, switch: str = "") -> list[str]:
    """``not bound``: below the range or above it, with the margin outside."""
    margin = _margin(bound, settings)
    head = f"g({node},t)"
    sides = []
    rules = []
    if bound.low != -math.inf:
        sides.append(f"below({node},t)")
        elements, right = _compared(bound, bound.low - margin)
        rules.append(f"&sum{{ {elements} }} <= {right} :- below({node},t).")
    if bound.high != math.inf:
        sides.append(f"above({node},t)")
        elements, right = _compared(bound, bound.high + margin)
        rules.append(f"&sum{{ {elements} }} >= {right} :- above({node},t).")
    if not sides:
        return [f"% {head} never holds"]
    return [
        f"{{ {head} }}.",
        f"#heuristic {head}. [1,false]",
        f"{{ {'; '.join(sides)} }} = 1 :- {head}{switch}.",
        *rules,
    ]


class ContinuousPlanner(Planner):
    """Plans for one automaton with the continuous encoding; ``plans()`` yields the first plan.

    A ``Planner`` with another instance and another theory (clingo-lpx instead of clingo-dl): the
    diagnosis of a scenario without a plan (``explain``) is the grid planner's, unchanged.
    """

    def __init__(self, automaton: SymbolicAutomaton, settings: ContinuousSettings | None = None, seed: int = 0) -> None:
        super().__init__(automaton, settings or ContinuousSettings(), seed)  # type: ignore[arg-type]

    def _instance(self, settings, relaxable: bool = False) -> tuple[str, str]:
        return build_continuous_instance(self.automaton, settings, relaxable)

    def _start_preferences(self, draw: random.Random) -> str:
        return start_preferences(self.automaton, self.settings, draw)

    def _widened(self):
        return None  # every start speed the settings allow is tried at once

    def _control(self, base_program: str, state_program: str):
        from clingo.ast import ProgramBuilder, parse_string

        control = self._new_control()
        program = "\n".join((ASP_DIR / name).read_text(encoding="utf-8") for name in (*SHARED, ENCODING))
        program += (
            "\n#program base.\n" + base_program + "\n" + self.preferences + "\n#program state(t).\n" + state_program
        )
        if self.settings.theory == "lpx":
            from clingolpx import ClingoLPXTheory

            theory = ClingoLPXTheory()
            # clingo-lpx has no preferences: the encoding's bind, a random start's nudges and drifts go
            program = program.replace("&prefer{", "&sum{")
            program = "\n".join(line for line in program.splitlines() if not line.startswith(("&nudge", "&drift")))
            for key, value in self.settings.lpx_options:
                theory.configure(key, value)
        else:
            theory = LazyLinearTheory()
            program = THEORY + program
        theory.register(control)
        self._theories[control] = theory
        with ProgramBuilder(control) as builder:
            parse_string(program, lambda statement: theory.rewrite_ast(statement, builder.add))
        return control

    def plans(self, limit: int | None = None) -> Iterator[Plan]:
        """Plans, shortest horizon first; each next one differs from all before it in when a
        transition fires or in a lane (the linear program then gives its smoothest motion)."""
        check_satisfiable(self.automaton)
        deadline = self._renewed()
        found = 0
        places: list[float] = []  # where in the start band each plan after the first was steered
        try:
            window = self.window(deadline)
            # the search starts at the automaton's floor, where every scenario measured can end
            # (planning/window.py); the window's own solver is asked when no plan ends there, or
            # when the floor is past the horizon limit (measured: five_vehicle_minute's first
            # plan 0.98 s with the window asked first at the floor, 0.77 s without)
            checked = window.floor > self.settings.max_horizon
            earliest = self._earliest(deadline, window) if checked else window.floor
            control = self._control(self.base_program, self.state_program)
            self._advance_to(control, earliest)
            horizon = earliest
            # a random start's plans come from a search of their own at a drawn, longer horizon as
            # long as it answers within STRETCH_CONFLICTS (as the grid planner's do: _plans)
            stretched = None  # (control, horizon)
            while limit is None or found < limit:
                if stretched is not None:
                    answer = self._model(stretched[0], deadline, f"at horizon {stretched[1]}", STRETCH_CONFLICTS)
                    if answer is None:
                        stretched = None
                        continue
                    source, plan_horizon = stretched
                else:
                    answer = self._model(control, deadline, f"at horizon {horizon}")
                    if answer is None and not checked:
                        checked, grounded = True, horizon
                        earliest = horizon = max(horizon, self._earliest(deadline, window))
                        if horizon > grounded:
                            self._advance_to(control, horizon, grounded)
                            continue
                    if answer is None:
                        # one question, not the whole window's bisection (5 solves, a fifth of
                        # change_lane's first plan): open_at is monotone, so a run not under way at
                        # this horizon is under way at no later one
                        if horizon >= self.settings.max_horizon or window.past_end(horizon + 1):
                            break  # no run of the automaton lasts longer: no longer plan either
                        horizon += 1
                        self._advance(control, horizon)
                        continue
                    source, plan_horizon = control, horizon
                    target = self._stretch_target(horizon)
                    if found == 0 and target > horizon and window.open_at(target):
                        longer = self._control(self.base_program, self.state_program)
                        self._advance_to(longer, target)
                        longer_answer = self._model(longer, deadline, f"at horizon {target}", STRETCH_CONFLICTS)
                        if longer_answer is not None:
                            answer, source, plan_horizon = longer_answer, longer, target
                            stretched = (longer, target)
                symbols, values = answer
                self.stats["horizon"] = plan_horizon
                yield self._continuous_plan(symbols, values, plan_horizon, found)
                deadline = self._renewed()
                window.wait = self._waiter(deadline)
                found += 1
                self._exclude(source, symbols, found, self._steering(places, found))
            if found:
                return
            last_open = window.last_open(self.settings.max_horizon)
            if last_open is None:
                raise NoPlanError(
                    f"no plan satisfies the scenario within {self.settings.max_horizon} steps ({self.settings.max_horizon * self.settings.dt:g} s)"
                )
            dt, longest = self.settings.dt, last_open + 1
            lengths = f"{earliest * dt:g} s" if longest <= earliest else f"{earliest * dt:g}..{longest * dt:g} s"
            raise NoPlanError(f"no plan satisfies the scenario in any length its durations allow ({lengths})")
        except (PlanningTimeout, HorizonTooShort):
            raise
        except NoPlanError as error:
            if not self.settings.explain_unsatisfiable:
                raise
            self._explain(error, deadline, window)

    def _earliest(self, deadline: float, window) -> int:
        """The first horizon the durations allow (``needed_horizon``); ``NoPlanError`` when none does."""
        earliest = self.needed_horizon(deadline, window)
        if earliest is None:
            raise NoPlanError(
                f"the phases' durations cannot all hold at any length, in steps of {self.settings.dt:g} s"
            )
        return earliest

    def _stretch_target(self, shortest: int, longest: int | None = None) -> int:
        """As the grid planner's, but never past ``stretch_limit``."""
        cap = min(self.settings.max_horizon, math.floor(self.settings.stretch_limit / self.settings.dt + 1e-9))
        return super()._stretch_target(shortest, cap if longest is None else min(longest, cap))

    def _model(
        self, control, deadline: float, where: str, conflicts: int | None = None
    ) -> tuple[list, dict[str, object]] | None:
        """(shown symbols, the linear program's values) of the next model; None when there is none,
        or none within ``conflicts``."""

        def answer(model, theory) -> tuple[list, dict[str, object]]:
            return list(model.symbols(shown=True)), {
                str(key): value for key, value in theory.assignment(model.thread_id)
            }

        return self._next_model(control, deadline, f" {where}", answer, conflicts)

    def _exclude(self, control, symbols, count: int, steering: list[str] = ()) -> None:
        """Never these transition times and lanes together again; the next plan follows
        ``steering`` (``_steering``) instead of the steering before it."""
        self._forbid(control, [s for s in symbols if s.name in ("fire", "lane")], count, steering)
        if steering:
            control.assign_external(clingo.Function("steer", [clingo.Number(count)]), True)
            if count > 1:
                control.assign_external(clingo.Function("steer", [clingo.Number(count - 1)]), False)

    def _steering(self, places: list[float], count: int) -> list[str]:
        """Rules that steer the next plan's start speeds away from those of the plans before it,
        as the grid planner's base strategy steered its choices away from every earlier plan's:
        every driving vehicle is nudged to one place of its start band (``initial_speed``), the
        place farthest from those of the plans before (``farthest``: the first plan's is the
        band's low end, then the high end, the middle, the quarters...). A nudge of the linear
        program, so a scenario's own speeds decide where they bind; switched on by
        ``steer(count)`` for this plan only. ``places`` is the places so far, and grows.

        Why: exclusion alone changes a plan's transition times and lanes, and the linear program
        then gives every plan the same smoothest values: the base strategy's ten plans of
        overtake all started at 8 m/s, alike but for their lanes (mean similarity 0.507 against
        the grid's 0.391). One place for all vehicles, not one each: the scenario often ties their
        speeds together (an overtaker faster than the one it passes), which places drawn apart
        would pull against each other. Places are not moved by what a plan reached: a speed the
        scenario caps in one plan (dodge_obstacle's ego, at most 20 m/s at 4 steps) may be free in
        the next, and bands shrunk to the speeds reached ended overtake's plans at 8 m/s."""
        if self.settings.theory != "lazy":
            return []  # clingo-lpx has no preferences
        low, high = self.settings.start_band()
        place = farthest([0.0, *places], 0.0, 1.0)  # the first plan, unsteered, starts low
        places.append(place)
        rules = [f"#external steer({count})."]
        for vehicle in self.automaton.actors:
            if vehicle not in self.automaton.stationary:
                rules.append(
                    f"&nudge{{ v({atom(vehicle)},0) }} = {_number(round(low + place * (high - low), 1))} :- steer({count})."
                )
        return rules

    def _continuous_plan(self, symbols, values: dict[str, object], horizon: int, index: int = 0) -> Plan:
        lanes: dict[tuple[str, int], int] = {}
        transitions = []
        for symbol in symbols:
            if symbol.name == "lane":
                vehicle, lane, step = symbol.arguments
                name = vehicle.string if vehicle.type.name == "String" else vehicle.name
                lanes[(name, step.number)] = lane.number
            elif symbol.name == "fire":
                transitions.append((symbol.arguments[1].number, symbol.arguments[0].number))

        def value(variable: str, vehicle: str, step: int) -> float:
            raw = values.get(f"{variable}({atom(vehicle)},{step})")
            return float(Fraction(str(raw).strip('"'))) if raw is not None else 0.0

        states = {
            v: [
                PlanState(position=value("p", v, k), lane=lanes[(v, k)], speed=value("v", v, k))
                for k in range(horizon + 1)
            ]
            for v in self.automaton.actors
        }
        return Plan(
            dt=self.settings.dt,
            lanes=self.automaton.lanes,
            states=states,
            transitions=sorted(transitions),
            seed=self.seed,
            index=index,
            stats=dict(self.stats),
            runup=0.0,
            stationary=tuple(v for v in self.automaton.actors if v in self.automaton.stationary),
        )
