"""The continuous encoding's instance writer: a scenario as constants and facts for ``asp/continuous/``.

Constants and facts (the vehicles, the limits, the start band) for ``asp/continuous/dynamics.lp``,
the automaton (``facts``), each guard node's term and planned range (inset by the settings'
margins) for ``asp/continuous/guards.lp``, and a phase's mean acceleration or distance travelled
for ``asp/continuous/rates.lp``. No rule is written here: the rules are the ``.lp`` files'.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ....logic.automaton import (
    SHAPE_PEAK_OVER_MEAN,
    HeldSpeed,
    MeanAcceleration,
    ShapedSpeedChange,
    SpeedGain,
    SymbolicAutomaton,
    Travelled,
)
from ....logic.guards import HEADWAY, LANE, POSITION, SPEED, TRAVELED, Bound, Guard, Not, required_bounds
from ...facts import atom, guard_nodes, inset, origin, with_automaton
from .settings import ContinuousSettings


def number(value: float) -> str:
    """A rational constant for clingo-lpx: quoted, exact for the decimals we write."""
    fraction = Fraction(value).limit_denominator(10**6)
    text = f"{fraction.numerator}" if fraction.denominator == 1 else f"{float(fraction):.6f}".rstrip("0")
    return f'"{text}"'


def build_continuous_instance(
    automaton: SymbolicAutomaton, settings: ContinuousSettings, relaxable: bool = False
) -> str:
    """The scenario's instance for the continuous encoding; with
    ``relaxable``, every bound and duration of the scenario can be switched off by an external
    ``relaxed(K)``, as in the grid encoding, for the diagnosis of a scenario without a plan."""
    s = settings
    vehicles = automaton.actors
    start_low, start_high = s.start_band()
    first = first_speeds(automaton, s)
    base = [
        "% scenario instance, continuous encoding (generated)",
        f"#const dt = {number(s.dt)}.",
        f"#const half_dt2 = {number(s.dt * s.dt / 2)}.",
        f"#const amin = {number(s.min_acceleration)}.",
        f"#const amax = {number(s.max_acceleration)}.",
        f"#const jerk = {number(s.max_jerk * s.dt)}.",
        f"#const brisk_jerk = {number(max(s.max_jerk, s.brisk_jerk) * s.dt)}.",
        f"#const vmin = {number(s.min_speed)}.",
        f"#const vmax = {number(s.max_speed)}.",
        f"#const v0min = {number(start_low)}.",
        f"#const v0max = {number(start_high)}.",
        f"#const v0floor = {number(start_floor(first, s))}.",
        f"#const gap = {number(spacing(automaton, s))}.",
        f"#const closing_time = {number(s.closing_time)}.",
        f"#const lane_change_speed = {number(s.lane_change_speed)}.",
        f"#const spread = {number(s.spread)}.",
        f"#const first_vehicle = {atom(vehicles[0])}.",
        *(f"vehicle({atom(v)})." for v in vehicles),
        *(f"stationary({atom(v)})." for v in vehicles if v in automaton.stationary),
        *(f"may_stop({atom(v)})." for v in sorted(stopping(automaton, s))),
        *(f"brisk({atom(v)})." for v in sorted(brisk(automaton))),
        *([f"self_driven({atom(s.self_driven)})."] if s.self_driven in vehicles else []),
        *(f"start_speed({atom(v)},{number(x)})." for v, x in sorted(first.items())),
        # CARLA's speed(v): a band driven toward from a phase's start (asp/continuous/toward.lp)
        *(
            f"toward({location.id},{atom(actor)},{number(band.low)},{number(band.high)},{number(band.value)})."
            for location in automaton.locations
            for actor, band in location.targets()
        ),
        # CARLA's position(..., at: end): one speed held over the phase where it can be (dynamics.lp)
        *(f"steady({location.id},{atom(actor)})." for location in automaton.locations for actor in location.steady()),
        *(f"steady_later({q},{atom(actor)},{number(x)})." for q, actor, x in later_targets(automaton)),
        f"#const comfort_up = {number(s.comfortable_acceleration * s.dt)}.",
        f"#const comfort_down = {number(s.comfortable_deceleration * s.dt)}.",
        f"lane_id(0..{automaton.lanes - 1}).",
        "lateral(-1;0;1).",
        f"lane_change_gap({s.lane_change_gap}).",
        *route_facts(s, vehicles, spacing(automaton, s)),
        "",
    ]
    return with_automaton(
        base,
        automaton,
        s.dt,
        relaxable,
        lambda node, guard: node_facts(node, guard, s, automaton),
        lambda relax: rate_facts(automaton, s, relax),
    )


def later_targets(automaton: SymbolicAutomaton) -> list[tuple[int, str, float]]:
    """(Q, V, X) for each location Q where V holds one speed (``Steady``) and every run from Q
    next drives V toward the target X (``Toward.value``): the speed the steady phase must not
    change toward after its first step (``asp/continuous/toward.lp``). A location whose runs meet
    different next targets, or none, has no fact."""
    found = []
    for location in automaton.locations:
        for actor in location.steady():
            values: set[float] = set()
            seen, frontier = {location.id}, [t.target for t in automaton.outgoing(location.id)]
            while frontier:
                q = frontier.pop()
                if q in seen:
                    continue
                seen.add(q)
                band = automaton.location(q).toward(actor)
                if band is not None:
                    values.add(band.value)
                elif q == automaton.final:
                    values.add(math.nan)  # a run with no later target
                else:
                    frontier.extend(t.target for t in automaton.outgoing(q))
            if len(values) == 1 and not math.isnan(x := values.pop()):
                found.append((location.id, actor, x))
    return found


def route_facts(s: ContinuousSettings, vehicles: tuple[str, ...], gap: float) -> list[str]:
    """The facts of the map's routes (asp/continuous/route.lp): route 0 the settings' own, then
    each of ``side_routes``, and where they meet (on a shared stretch, ``gap`` metres between the
    cars of two routes, as between two of one lane); none on the straight road."""
    if s.route_span is None:
        return []
    routes = [(0, s.route_span, s.lane_spans, s.slow_spans, s.junction_span)]
    routes += [(k, r.route_span, r.lane_spans, r.slow_spans, r.junction_span) for k, r in enumerate(s.side_routes, 1)]
    facts = [f"origin_span({number(s.origin_span[0])},{number(s.origin_span[1])})."] if s.origin_span else []
    bend = 0
    for k, span, lane_spans, slow_spans, junction in routes:
        facts.append(f"route_span({k},{number(span[0])},{number(span[1])}).")
        facts += [f"lane_span({k},{lane},{number(first)},{number(last)})." for lane, first, last in lane_spans]
        for first, last, speed in slow_spans:
            facts.append(f"slow_span({k},{bend},{number(first)},{number(last)},{number(speed)}).")
            bend += 1
        if junction is not None:
            facts.append(f"junction_span({k},{number(junction[0])},{number(junction[1])}).")
    crossers = set(s.crossers)
    route_of = dict.fromkeys(vehicles, 0)
    for k, side in enumerate(s.side_routes, 1):
        driven = [v for v in vehicles if v in side.vehicles]
        route_of.update(dict.fromkeys(driven, k))
        facts += [f"route_of({atom(v)},{k})." for v in driven]
        crossers |= set(driven) if side.junction_span is not None else set()
    facts += [f"crosses({atom(v)})." for v in vehicles if v in crossers]
    # routes laid onto each other share one position 0 (the first vehicle's start, dynamics.lp);
    # of every other group of routes, its first vehicle's start is position 0 of its own
    laid = {0, *(a.route for a in s.alignments)}
    facts += [f"aligned({a.route},{a.onto},{number(a.offset)})." for a in s.alignments]
    groups = [laid, *({k} for k in range(1, len(s.side_routes) + 1) if k not in laid)]
    for group in groups:
        first = next((v for v in vehicles if route_of[v] in group), None)
        if first not in (None, vehicles[0]):
            facts.append(f"route_first({atom(first)}).")
    for z, meeting in enumerate(s.meetings):
        facts.append(f"meeting({z},{meeting.kind}).")
        # a crossing widened by the clearance kept between the one through and the next
        widen = s.meeting_clearance if meeting.kind == "crossing" else 0.0
        for route, (first, last) in ((meeting.first, meeting.first_span), (meeting.second, meeting.second_span)):
            facts.append(f"meeting_span({z},{route},{number(first - widen)},{number(last + widen)}).")
        if meeting.kind == "shared":
            facts.append(f"meeting_ahead({z},{meeting.first},{meeting.second},{number(gap + meeting.offset)}).")
            facts.append(f"meeting_ahead({z},{meeting.second},{meeting.first},{number(gap - meeting.offset)}).")
    return facts


def first_speeds(automaton: SymbolicAutomaton, settings: ContinuousSettings) -> dict[str, float]:
    """The speed (m/s) each driving vehicle's first phase asks for, where one does: a bound on its
    own speed at the scenario's start, throughout the first locations or at the end of a phase
    running there, or the speed CARLA's ``speed(v)`` drives toward there; the middle of its range
    within the settings' speeds. A vehicle starts at it rather than at the road's typical speed
    (``asp/continuous/dynamics.lp``): "drive at 10 kph" starts at 10 kph. Only the first phases:
    a speed a later phase asks for is where it goes, not where it starts."""
    found: dict[str, float] = {}
    first = [t.target for t in automaton.outgoing(automaton.initial)]
    guards = [automaton.location(automaton.initial).invariant]
    guards += [t.guard for t in automaton.outgoing(automaton.initial)]
    for location in first:
        guards.append(automaton.location(location).invariant)
        guards += [t.guard for t in automaton.outgoing(location)]
        for actor, band in automaton.location(location).targets():
            found.setdefault(actor, round(min(max(band.value, settings.min_speed), settings.max_speed), 2))
    for bound in (b for guard in guards for b in required_bounds(guard)):
        term = bound.term
        if term.quantity != SPEED or term.reference is not None or term.actor in found:
            continue
        if term.actor in automaton.stationary:
            continue
        low = max(bound.low, settings.min_speed)
        high = min(bound.high, settings.max_speed)
        if low <= high and (math.isfinite(bound.low) or math.isfinite(bound.high)):
            found[term.actor] = round((low + high) / 2, 2)
    return found


def start_floor(first: dict[str, float], settings: ContinuousSettings) -> float:
    """The least speed (m/s) a vehicle whose start speed the scenario leaves open is strongly
    preferred to start at, given ``first``, the start speeds the scenario asks (``first_speeds``):
    the settings' floor (a crawl the motion planner tracks badly), but no
    more than the road's typical speed nor the slowest start speed the scenario asks of another
    vehicle. Why the last: beside a car asked to drive at 20 kph (CARLA's cut-in examples), 20 kph
    is no crawl, and a floor above it makes the other car start faster and brake all phase long to
    keep its position at the phase's end, a change nothing asks for."""
    asked = [speed for speed in first.values() if speed > 0]
    return min(settings.start_floor, settings.start_band()[0], *asked)


def spacing(automaton: SymbolicAutomaton, settings: ContinuousSettings) -> float:
    """The gap (m between centres) the plan keeps between two vehicles sharing a lane: the
    settings' ``min_gap``, or less where a guard requires two vehicles in one lane closer than that
    (a position difference whose whole range lies below it, together with the same lane: "end 5-7
    m behind the lead, in its lane"), down to the near end of that range and never below
    ``closest_gap``.

    Why: the gap is the tool's caution, not the scenario's; a scenario that asks for less had no
    plan until the fallbacks relaxed the gap, after three searches that each proved there was none
    (a follow ending 6 m behind took 16-20 s to plan, and its simulation was accepted)."""
    gap = settings.min_gap
    guards = [transition.guard for transition in automaton.transitions]
    guards += [location.invariant for location in automaton.locations]
    for guard in guards:
        required = required_bounds(guard)
        for bound in required:
            term = bound.term
            if term.quantity != POSITION or term.reference is None or not _one_lane(required, *term.actors):
                continue
            if 0 < bound.low and bound.high < settings.min_gap:
                gap = min(gap, bound.low)
            elif bound.high < 0 and -bound.low < settings.min_gap:
                gap = min(gap, -bound.high)
    return max(gap, min(settings.closest_gap, settings.min_gap))


def _one_lane(bounds: list[Bound], a: str, b: str) -> bool:
    """Whether ``bounds`` put ``a`` and ``b`` in one lane: l(a) = l(b), or both in the same one."""
    lanes: dict[str, tuple[float, float]] = {}
    for bound in bounds:
        term = bound.term
        if term.quantity != LANE:
            continue
        if term.reference is not None and {term.actor, term.reference} == {a, b} and bound.low == bound.high == 0:
            return True
        if term.reference is None and bound.low == bound.high:
            lanes[term.actor] = (bound.low, bound.high)
    return a in lanes and lanes.get(a) == lanes.get(b)


def decimal(value: float) -> str:
    """A decimal as clingo-lpx reads it, unquoted: exact for the decimals we write."""
    fraction = Fraction(value).limit_denominator(10**6)
    return f"{fraction.numerator}" if fraction.denominator == 1 else f"{float(fraction):.6f}".rstrip("0")


def rate_facts(automaton: SymbolicAutomaton, settings: ContinuousSettings, relax: dict) -> list[str]:
    """The bounds over a timed phase (``asp/continuous/rates.lp``), rate R of phase P for vehicle
    V. An acceleration (``MeanAcceleration``), ``mean_acceleration(R,P,V)``: the bound on every
    step of the phase, ``step_at_least(R,X)`` / ``step_at_most(R,X)``, inset by
    ``acceleration_margin``. A speed gain (``SpeedGain``), ``mean_acceleration(R,P,V)`` with, per
    length D the phase may have (up to its upper bound, or to the horizon limit for a phase with
    none), ``gain_at_least(R,D,X)`` / ``gain_at_most(R,D,X)``, inset by ``speed_margin``. A
    distance travelled, ``travelled(R,P,V)`` with ``travelled_at_least(R,X)`` /
    ``travelled_at_most(R,X)``, inset by ``position_margin``. A kept speed (``HeldSpeed``),
    ``held_speed(R,P,V)`` with ``held_within(R,X)``: the speed within X of the phase's first on
    every step, inset by ``speed_margin``. A rate the diagnosis may relax:
    ``relaxable(rate(R),K)``."""
    facts = ["% rates over a phase's two ends (asp/continuous/rates.lp)"]
    rate_id = 0
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
            r, rate_id = rate_id, rate_id + 1
            facts.append(f"% rate {r}: {rate}{origin(automaton, rate)}")
            if rate.source in relax:
                facts.append(f"relaxable(rate({r}),{relax[rate.source]}).")
            actor = atom(rate.actor)
            if isinstance(rate, Travelled):
                low, high = inset(rate.low, rate.high, automaton.planned_margin(rate, settings.position_margin))
                facts.append(f"travelled({r},{phase},{actor}).")
                if math.isfinite(low):
                    facts.append(f"travelled_at_least({r},{number(low)}).")
                if math.isfinite(high):
                    facts.append(f"travelled_at_most({r},{number(high)}).")
                continue
            if isinstance(rate, SpeedGain):  # a gain for every length of the phase
                low, high = inset(rate.low, rate.high, automaton.planned_margin(rate, settings.speed_margin))
                facts.append(f"mean_acceleration({r},{phase},{actor}).")
                if math.isfinite(low) and math.isfinite(high):  # set as the target from the start
                    facts.append(f"gain_target({r},{phase},{actor},{number((low + high) / 2)}).")
                for length in range(shortest, longest + 1):
                    if math.isfinite(low):
                        facts.append(f"gain_at_least({r},{length},{number(low)}).")
                    if math.isfinite(high):
                        facts.append(f"gain_at_most({r},{length},{number(high)}).")
                continue
            if isinstance(rate, HeldSpeed):
                within = inset(-rate.high, rate.high, automaton.planned_margin(rate, settings.speed_margin))[1]
                facts.append(f"held_speed({r},{phase},{actor}).")
                facts.append(f"held_within({r},{number(within)}).")
                continue
            if isinstance(rate, ShapedSpeedChange):
                facts.extend(shape_facts(r, phase, actor, rate, settings, automaton, range(shortest, longest + 1)))
                continue
            low, high = inset(rate.low, rate.high, automaton.planned_margin(rate, settings.acceleration_margin))
            facts.append(f"mean_acceleration({r},{phase},{actor}).")
            if math.isfinite(low):
                facts.append(f"step_at_least({r},{number(low)}).")
            if math.isfinite(high):
                facts.append(f"step_at_most({r},{number(high)}).")
    return facts


# m/s^2: the band below a car's limit in which a change asked at once (dynamics_shape step) is planned
STEP_BAND = 1.0
# m/s: how far a cubic or sinusoidal change's speed may stray from its shape at a step inside it
SHAPE_SLACK = 0.25


def shape_facts(
    r: int, phase: str, actor: str, rate: ShapedSpeedChange, settings: ContinuousSettings, automaton, lengths
) -> list[str]:
    """A shaped speed change's facts (``asp/continuous/rates.lp``): linear, its peak (inset by
    ``acceleration_margin``) on every step; step, a band at the car's limits either way; cubic and
    sinusoidal, per length D the phase may have, the size of the change a peak in the band gives
    over D steps and the speed the shape has at each step inside."""
    if rate.shape in ("step", "linear"):
        if rate.shape == "step":
            up = (settings.max_acceleration - STEP_BAND, settings.max_acceleration)
            down = (-settings.min_acceleration - STEP_BAND, -settings.min_acceleration)
        else:
            up = down = inset(rate.low, rate.high, automaton.planned_margin(rate, settings.acceleration_margin))
        return [
            f"held_rate({r},{phase},{actor}).",
            f"rate_up({r},{number(up[0])},{number(up[1])}).",
            f"rate_down({r},{number(down[0])},{number(down[1])}).",
        ]
    # no margin inside the peak's band: the change lasts whole steps, so the peak a length D gives
    # moves by about peak / D from one length to the next (a cubic stop from 80 kph at 6 m/s^2:
    # 6.7 over 5 s, 5.6 over 6 s), and a band inset by the margin would leave no length
    low, high = rate.low, rate.high
    factor = SHAPE_PEAK_OVER_MEAN[rate.shape]
    facts = [f"shaped({r},{phase},{actor})."]
    for length in lengths:
        seconds = length * settings.dt
        facts.append(f"shape_gain({r},{length},{number(low * seconds / factor)},{number(high * seconds / factor)}).")
        for k in range(1, length):
            share = shape_share(rate.shape, k / length)
            facts.append(f"shape_point({r},{length},{k},{number(share)},{number(1 - share)},{number(SHAPE_SLACK)}).")
    return facts


def shape_share(shape: str, s: float) -> float:
    """How much of its change a cubic or sinusoidal speed change has made at fraction ``s`` of its time."""
    if shape == "cubic":
        return 3 * s**2 - 2 * s**3
    return (1 - math.cos(math.pi * s)) / 2


def brisk(automaton: SymbolicAutomaton) -> set[str]:
    """The vehicles the scenario asks an acceleration of (a phase's mean acceleration: the
    acceleration modifier, a speed change's rate_peak): their own dynamics are the scenario's, so
    their acceleration may change as fast as a car's brakes act (``brisk_jerk``), not at the
    gentle rate every other vehicle keeps."""
    return {
        rate.actor
        for timing in automaton.timings.values()
        for rate in timing.rates
        if isinstance(rate, MeanAcceleration)
    }


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


def _term_facts(node: int, bound: Bound) -> list[str]:
    """The elements of a position, speed or distance bound's term: ``term_p`` (p(V,t)), ``term_v``
    (v(V,t)) and ``term_p0`` (p(V,0), the start of a distance travelled), each with its coefficient."""
    term = bound.term
    variable = "p" if term.quantity in (POSITION, TRAVELED) else "v"
    facts = [f"term_{variable}({node},1,{atom(term.actor)})."]
    if term.quantity == TRAVELED:  # d(a) = p(a,t) - p(a,0)
        facts.append(f"term_p0({node},-1,{atom(term.actor)}).")
    if term.reference is not None:
        facts.append(f"term_{variable}({node},-1,{atom(term.reference)}).")
    return facts


def _margin(bound: Bound, settings: ContinuousSettings) -> float:
    if bound.term.quantity == HEADWAY:
        return settings.headway_margin
    return settings.position_margin if bound.term.quantity in (POSITION, TRAVELED) else settings.speed_margin


def node_facts(node: int, guard: Guard, settings: ContinuousSettings, automaton: SymbolicAutomaton) -> list[str]:
    """One guard node's facts (``asp/continuous/guards.lp``): a bound, ``within(N)`` with its term
    and its range inset by the margin, or its negation, ``outside(N)`` with the range widened by
    the margin (none for a sampled band: ``SymbolicAutomaton.planned_margin``). A time headway ``h(a, b)`` is compared as ``p(a) - p(b) - X*v(b)`` with its offset (0, or
    a car's length for a time gap; the follower never reverses), so its facts carry the
    coefficient -X of each side and the offset."""
    bound = guard.part if isinstance(guard, Not) else guard
    assert isinstance(bound, Bound) and bound.term.quantity != LANE
    margin = _margin(bound, settings)
    headway = bound.term.quantity == HEADWAY
    if isinstance(guard, Not):
        sides = (("under", bound.low - margin, bound.low), ("over", bound.high + margin, bound.high))
        kind = "outside"
    else:
        low, high = inset(bound.low, bound.high, automaton.planned_margin(bound, margin))
        standstill = bound.term.quantity == SPEED and bound.term.reference is None and bound.low <= 0
        if standstill:
            low = 0.0  # no margin below a standstill: no vehicle undershoots it (none reverses)
        sides = (("at_least", low, 0.0 if standstill else low - margin), ("at_most", high, high + margin))
        kind = "within"
    # each side as planned and with the margin's slack (``written_``: what a replan's past and
    # observed steps are held to: the range as written, or a sampled band widened by the margin;
    # the margin is for tracking error still to come, and an observed state has made its own)
    sides = [(name, value, end) for name, value, end in sides if math.isfinite(end)]
    if kind == "outside" and not sides:
        return ["% never holds"]
    if headway:
        ahead, behind = atom(bound.term.actor), atom(bound.term.reference)
        facts = [
            f"{kind}({node}).",
            f"headway({node},{ahead},{behind}).",
            f"headway_gap({node},{number(bound.term.offset)}).",
        ]
        facts += [f"headway_{name}({node},{number(-value)})." for name, value, _ in sides]
        facts += [f"written_headway_{name}({node},{number(-end)})." for name, _, end in sides]
        return facts
    facts = [f"{kind}({node}).", *_term_facts(node, bound)]
    facts += [f"{name}({node},{number(value)})." for name, value, _ in sides]
    facts += [f"written_{name}({node},{number(end)})." for name, _, end in sides]
    if kind == "within" and bound.term.quantity == SPEED:
        facts.append(f"speed_bound({node}).")
    return facts
