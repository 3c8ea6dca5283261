"""Runtime monitor: does a trace satisfy the scenario's automaton, how robustly, and if not, why?

Semantics (the paper's, on a sampled trace with constant interpolation): a run of the automaton
takes its transitions at strictly increasing sample instants, each when its guard holds; while the
run stays in a location, the location's invariant holds at every sample and every actor driving
there makes forward progress (its position increases from each sample to the next; the vehicle
under test is no driver of the automaton it is judged by: ``SymbolicAutomaton.driving_itself``);
a timed phase lasts within its bounds from the transition that starts it to the one that ends it,
and the margin to those bounds (in seconds) counts in the robustness like a guard's. The scenario may
start after the trace does (vehicles start from standstill and need a run-up): the initial location
may be left at any sample up to ``begins_by`` (``monitor``). The trace is accepted when some run
reaches the final location and no incident (collision, off-road) occurred.

One forward pass computes, for every location, the best run into it: the one whose smallest guard
robustness so far is largest. That value at the final location is the verdict's robustness; it is
non-negative exactly when some run meets every guard. The pass costs O(samples x transitions).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

from ..frontend.errors import SourceLocation
from ..logic.automaton import SymbolicAutomaton
from ..logic.guards import Bound, Guard
from ..simulation.trace import Incident, Trace

# the depth-first searches for a run above a floor (``_Witness``) give up after this many states
# per sample of the trace, all together, on a trace whose runs branch more than a run's path does
WITNESS_BUDGET = 20
# of which the climb from the first run found to better ones may spend this many
CLIMB_BUDGET = 3


@dataclass(frozen=True)
class GuardMiss:
    """The guard that stopped the best run, and how close the trace came to meeting it."""

    source: str  # location the run was in
    target: str  # location it could not reach
    guard: str
    events: str
    time: float  # where the guard came closest
    robustness: float
    values: dict[str, float]  # the guard's terms at that time, e.g. {"p(v1) - p(v2)": 3.2}
    locations: tuple[SourceLocation, ...] = ()
    # when the guard did hold but a phase's duration did not allow the transition there: why
    timing: str = ""
    # when the guard did hold but a vehicle of the phase had stopped before it did: which, from when
    progress: str = ""

    def describe(self) -> str:
        values = ", ".join(f"{k} = {v:.2f}" for k, v in self.values.items())
        values = f" where {values}" if values else ""
        where = "".join(f"\n    declared at {loc}" for loc in self.locations)
        if self.progress:
            held = f"held at t = {self.time:.1f} s (robustness {self.robustness:+.2f}){values}"
            return (
                f"stuck in {self.source}: {self.progress} (a vehicle in a drive makes forward progress while "
                f"its phase runs), so no run stayed there until it could take the guard to {self.target} "
                f"({self.events}):\n"
                f"    {self.guard}\n"
                f"    {self.timing + '; the guard ' if self.timing else ''}{held}{where}"
            )
        if self.timing:
            return (
                f"stuck in {self.source}: the guard to {self.target} ({self.events}) held, but not in time:\n"
                f"    {self.guard}\n"
                f"    {self.timing}; the guard held at t = {self.time:.1f} s (robustness {self.robustness:+.2f}){values}{where}"
            )
        return (
            f"stuck in {self.source}: the guard to {self.target} ({self.events}) never held:\n"
            f"    {self.guard}\n"
            f"    closest at t = {self.time:.1f} s (robustness {self.robustness:+.2f}){values}{where}"
        )


@dataclass
class Verdict:
    accepted: bool
    robustness: float
    furthest: str  # the furthest location a run reached with every guard met
    # (time, transition events) of the best run, in order
    run: list[tuple[float, str]] = field(default_factory=list)
    miss: GuardMiss | None = None
    incidents: list[Incident] = field(default_factory=list)

    def explain(self) -> str:
        if self.accepted:
            steps = "; ".join(f"{events} at {t:.1f} s" for t, events in self.run)
            return f"accepted (robustness {self.robustness:+.2f}): {steps}"
        lines = [f"rejected (robustness {self.robustness:+.2f})"]
        lines += [f"  {incident}" for incident in self.incidents]
        if self.miss is not None:
            lines.append("  " + self.miss.describe())
        elif not self.incidents:
            lines.append(f"  furthest location reached: {self.furthest}")
        return "\n".join(lines)

    def to_dict(self) -> dict:
        return {
            "accepted": self.accepted,
            "robustness": self.robustness,
            "furthest": self.furthest,
            "run": [{"time": t, "events": e} for t, e in self.run],
            "miss": None
            if self.miss is None
            else {
                "source": self.miss.source,
                "target": self.miss.target,
                "guard": self.miss.guard,
                "events": self.miss.events,
                "time": self.miss.time,
                "robustness": self.miss.robustness,
                "values": self.miss.values,
                "locations": [str(loc) for loc in self.miss.locations],
            },
            "incidents": [str(i) for i in self.incidents],
            "explanation": self.explain(),
        }


def monitor(
    automaton: SymbolicAutomaton, trace: Trace, floors: tuple[float, ...] | None = None, begins_by: float = math.inf
) -> Verdict:
    """Whether ``trace`` is a run of ``automaton``, with its robustness and, when it is not, why.

    ``begins_by``: the latest time of the trace (s) at which the scenario may begin, that is leave
    its initial location (default: any). A simulation that starts in its plan's first state begins
    the scenario at its first sample (0), as the standard's main scenario accepts the whole trace;
    after a run-up, by the end of the run-up and one planning step. Why it matters beyond meaning:
    a timed phase that may begin at any sample keeps a run per start, and with a second such phase
    (a parallel member that may start late, a repeated one_of of timed serials) a run per pair.

    The search keeps, per location and timed-phase state, the best run so far; what makes it slow
    is keeping runs that cannot matter, so it keeps only the runs at or above a floor and proves
    that the ones it dropped could not have done better (a run's robustness only falls):

    1. Floor 0: the runs that meet every guard. A run into the final location decides acceptance
       and its robustness is exact. The report of a rejected trace (the furthest location, the
       closest miss) reads only these runs.
    2. A rejected trace's robustness, the best of the runs below 0, is bracketed: above by the
       same search with the phases' durations and two-end bounds dropped (``_Untimed``: one
       state per location, vectorised over transitions), below by a run found depth first
       (``_Witness``). When a run keeps every margin at the upper bound, that is the robustness;
       else a search above the lower bound keeps only the runs that could beat it.

    ``floors``: for the tests and the benchmark, which compare with a single pass that keeps every
    run, ``(-math.inf,)``.
    """
    margins = _Margins(automaton, trace, begins_by)
    if floors is not None:
        for floor in floors:
            verdict = _RunSearch(automaton, trace, floor, margins).run().verdict()
            if verdict.robustness >= floor:
                return verdict
        return verdict
    verdict = _RunSearch(automaton, trace, 0.0, margins).run().verdict()
    if verdict.robustness >= 0:
        return verdict
    return dataclasses.replace(verdict, robustness=_rejected_robustness(automaton, trace, margins))


def _rejected_robustness(automaton: SymbolicAutomaton, trace: Trace, margins: _Margins) -> float:
    """The best robustness of any run of a trace no run meets (the largest smallest margin).

    Bounded above by the untimed search; a depth-first search (``_Witness``) looks for a run at
    that bound, which most often exists (what binds is a guard, not a duration), and else for any
    run, whose robustness bounds the answer below, and then for better ones (``_Witness.climb``);
    when none lies above the best, that is the answer. Else the runs that could beat it are
    searched sample by sample. Should the depth-first searches give up, a beam of one gives the
    bound below."""
    untimed = _Untimed(automaton, trace, margins)
    upper = untimed.bound()
    if upper == -math.inf:
        return upper  # not even without the durations does a run reach the end
    ahead = untimed.ahead()
    witness = _Witness(automaton, margins, ahead)
    found = witness.above(upper)
    if found is not None and found >= upper:
        return found
    lower = witness.above(-math.inf) if found is not None else None
    if lower is not None:
        lower, exact = witness.climb(lower, CLIMB_BUDGET * len(trace.times))
        if exact:
            return lower
    else:
        lower = _RunSearch(automaton, trace, -math.inf, margins, beam=1, ahead=ahead).run().best_final
    if lower >= upper:
        return lower
    floor = math.nextafter(lower, math.inf) if lower > -math.inf else -math.inf
    return max(lower, _RunSearch(automaton, trace, floor, margins, ahead=ahead).run().best_final)


class _Witness:
    """Depth-first searches for a run (durations and two-end bounds read, as ``_RunSearch``
    reads them) that keeps every margin at or above a floor into the final location.

    Above a floor, only whether a run's margins stay above it matters, not by how much: so a run
    is its location, sample and timed-phase state, and a state searched once from is never
    searched again. Taking a transition before staying, a search follows one run forward, at the
    cost of its path where the sample-by-sample search steps every location's runs; proving that
    no run keeps above a floor costs every state above it, which the sample-by-sample search does
    better (it keeps one run per state and sample). The searches of one trace share a budget of
    ``WITNESS_BUDGET`` states per sample, after which they give up."""

    def __init__(self, automaton: SymbolicAutomaton, margins: _Margins, ahead: np.ndarray) -> None:
        self.automaton, self.margins = automaton, margins
        self.ahead = ahead.tolist()
        self.budget = WITNESS_BUDGET * len(margins.times)

    def climb(self, lower: float, budget: int) -> tuple[float, bool]:
        """From a run of robustness ``lower``, better runs found one after another, each a higher
        bound below, within ``budget`` more states: (the best robustness found, whether no run lies
        above it). Proving there is none visits every state above the bound, which the search that
        keeps one run per state and sample does better: hence a budget of its own."""
        self.budget = min(self.budget, budget)
        while True:
            better = self.above(math.nextafter(lower, math.inf))
            if better is None:
                return lower, False
            if better == -math.inf:
                return lower, True
            lower = better

    def above(self, floor: float) -> float | None:
        """The robustness of a run that keeps every margin at or above ``floor`` (-inf: none);
        None when the budget ran out."""
        automaton, margins = self.automaton, self.margins
        times, timings, columns = margins.times, automaton.timings, margins.columns
        init, final, samples = automaton.initial, automaton.final, len(times)
        ahead, moved = self.ahead, margins.moved_lists
        guard, invariant = margins.guard, margins.invariant
        # a run to extend: (location, sample, key, its robustness so far, whether it may stay:
        # a fresh run in the initial location only takes a transition at its sample)
        stack = [(init, k, (), math.inf, False) for k in reversed(range(samples)) if margins.begins[k]]
        seen: set[tuple[int, int, tuple]] = set()
        while stack:
            q, k, key, value, stays = stack.pop()
            if q == final:
                return value
            if (q, k, key) in seen:
                continue
            seen.add((q, k, key))
            self.budget -= 1
            if self.budget < 0:
                return None
            if stays:
                # the run stays over (k, k+1]: its drivers progressed and no phase overran
                k += 1
                if k >= samples or not moved[q][k - 1]:
                    continue
                if _overrun(key, k, times, timings) is not None:
                    continue
                held = min(value, invariant[q][k]) if q in invariant else value
                if held >= floor and ahead[q][k] >= floor:
                    stack.append((q, k, key, held, True))
            for (starts, ends), transitions in margins.effects[q]:
                stepped = _advance(key, starts, ends, k, times, timings, columns)
                if stepped is None or isinstance(stepped, _Broken) or stepped[1] < floor:
                    continue
                timed = min(value, stepped[1])
                for transition in transitions:
                    target, margin = transition.target, guard[transition.id][k]
                    if margin >= floor and ahead[target][k] >= floor:
                        stack.append((target, k, stepped[0], min(timed, margin), True))
        return -math.inf


class _Untimed:
    """The search with the phases' durations and two-end bounds dropped: one value per location,
    each sample one vectorised step over the transitions, with the runs' semantics of
    ``_RunSearch.step``. A dropped constraint can only raise a run's robustness, so what it finds
    bounds the timed search's from above."""

    def __init__(self, automaton: SymbolicAutomaton, trace: Trace, margins: _Margins) -> None:
        self.automaton, self.samples = automaton, len(trace.times)
        n_loc = len(automaton.locations)
        self.sources = np.array([t.source for t in automaton.transitions], dtype=int)
        self.targets = np.array([t.target for t in automaton.transitions], dtype=int)
        self.guards = np.array([margins.guard[t.id] for t in automaton.transitions], dtype=float).reshape(
            len(automaton.transitions), self.samples
        )
        self.invariants = np.full((n_loc, self.samples), math.inf)
        for q, series in margins.invariant.items():
            self.invariants[q] = series
        # moved[q, k]: every actor driving in q moved forward over (k, k+1]; the initial location
        # holds a fresh run at every sample the scenario may begin at
        self.moved = margins.moved.copy()
        self.begins = margins.begins
        self.moved[automaton.initial] = True

    def bound(self) -> float:
        """The best robustness of an untimed run into the final location (-inf: none)."""
        init, final = self.automaton.initial, self.automaton.final
        values = np.full(len(self.automaton.locations), -math.inf)
        best = -math.inf
        for k in range(self.samples):
            staying = np.where(self.moved[:, k - 1], values, -math.inf) if k > 0 else np.full_like(values, -math.inf)
            if self.begins[k]:
                staying[init] = math.inf
            values = np.minimum(staying, self.invariants[:, k])
            np.maximum.at(values, self.targets, np.minimum(staying[self.sources], self.guards[:, k]))
            best = max(best, float(values[final]))
        return best

    def ahead(self) -> np.ndarray:
        """ahead[q, k]: the best robustness of what an untimed run in q after sample k still has
        to meet on its way into the final location (+inf in it, -inf where it cannot get there).
        A timed run in q at k whose robustness so far, or this, is below a floor cannot end above it."""
        final = self.automaton.final
        n_loc = len(self.automaton.locations)
        ahead = np.full((n_loc, self.samples), -math.inf)
        ahead[final] = math.inf
        for k in range(self.samples - 2, -1, -1):
            later = ahead[:, k + 1]
            values = np.where(self.moved[:, k], np.minimum(self.invariants[:, k + 1], later), -math.inf)
            taking = np.where(
                self.moved[self.sources, k], np.minimum(self.guards[:, k + 1], later[self.targets]), -math.inf
            )
            np.maximum.at(values, self.sources, taking)
            values[final] = math.inf
            ahead[:, k] = values
        return ahead


def _effects(automaton: SymbolicAutomaton) -> list[list[tuple[tuple[tuple, tuple], list]]]:
    """Per location, its outgoing transitions grouped by what they do to the timed phases (starts,
    ends). The step of the phases' clocks is the same for the whole group, and a guard's margin is
    the same for every key, so min(value, margin) keeps the order of the values and the best key
    per group is the best key per transition. Why: five_vehicle_minute's 481 transitions all start
    or end a timed phase, 12 of them leave each location with one effect, and stepping every key
    for each of them is far slower (docs/decisions.md)."""
    timings = automaton.timings
    grouped: list[dict[tuple[tuple, tuple], list]] = [{} for _ in automaton.locations]
    for transition in automaton.transitions:
        effect = (
            tuple(sorted(p for p in transition.starts if p in timings)),
            tuple(sorted(p for p in transition.ends if p in timings)),
        )
        grouped[transition.source].setdefault(effect, []).append(transition)
    return [list(groups.items()) for groups in grouped]


class _Margins:
    """What every search of one trace reads, computed once, column-wise: each guard's and
    invariant's robustness at every sample, whether each actor moved forward over each step, the
    columns the phases' two-end bounds read (speed for a mean acceleration, x for a distance), and
    the samples at which the scenario may begin."""

    def __init__(self, automaton: SymbolicAutomaton, trace: Trace, begins_by: float = math.inf) -> None:
        memo: dict = {}  # each bound's series, shared by the guards and invariants that use it
        # begins[k]: the initial location may be left at sample k (the scenario begins by ``begins_by`` s)
        self.begins = (trace.times <= begins_by + 1e-9).tolist()
        guards = [t.guard.robustness_series(trace.actors, memo) for t in automaton.transitions]
        self.guard = dict(zip([t.id for t in automaton.transitions], np.array(guards).tolist(), strict=True))
        held = [q for q in range(len(automaton.locations)) if not automaton.location(q).invariant.is_true]
        invariants = [automaton.location(q).invariant.robustness_series(trace.actors, memo) for q in held]
        self.invariant = dict(zip(held, np.array(invariants).tolist(), strict=True))
        forward = {a: np.diff(trace.actors[a]["x"]) > 0 for a in trace.names}
        self.progress = {a: moved.tolist() for a, moved in forward.items()}
        # moved[q, k]: every actor driving in location q moved forward over (k, k+1] (as an array,
        # and as lists for the searches' sample-by-sample reads)
        self.moved = np.ones((len(automaton.locations), max(len(trace.times) - 1, 0)), dtype=bool)
        for q, location in enumerate(automaton.locations):
            for actor in location.drivers:
                self.moved[q] &= forward[actor]
        self.moved_lists = self.moved.tolist()
        self.columns = {
            column: {a: trace.actors[a][column].tolist() for a in trace.names} for column in _end_columns(automaton)
        }
        self.effects = _effects(automaton)
        self.times = trace.times


# A run's state in a location: the samples at which its open timed phases started (empty when the
# scenario has no durations), sorted ((phase, start sample), ...)
Key = tuple


class _RunSearch:
    """The best runs of an automaton through a trace, sample by sample (``step``), and the verdict
    they give (``verdict``). Per location and key, only the run with the largest smallest
    robustness so far is kept: a run is compared with another in the same state only by that."""

    def __init__(
        self,
        automaton: SymbolicAutomaton,
        trace: Trace,
        floor: float,
        margins: _Margins,
        beam: int | None = None,
        ahead: np.ndarray | None = None,
    ) -> None:
        """The search for the runs whose robustness stays at least ``floor`` (-inf: every run);
        with ``beam``, only that many best runs per location are kept at each sample; with
        ``ahead`` (``_Untimed.ahead``), a run that cannot end at or above the floor is dropped
        (only the best robustness is then meant: the report reads runs that need not end)."""
        self.automaton, self.trace, self.floor, self.beam = automaton, trace, floor, beam
        self.ahead = ahead.tolist() if ahead is not None else None
        self.times = trace.times
        self.n_loc = n_loc = len(automaton.locations)
        self.drivers = [sorted(loc.drivers) for loc in automaton.locations]
        self.timings = automaton.timings
        self.effects = margins.effects
        self.invariant_locations = sorted(margins.invariant)
        self.guard_margin, self.invariant_margin = margins.guard, margins.invariant
        self.progress, self.columns = margins.progress, margins.columns
        self.begins = margins.begins
        self.moved = margins.moved_lists
        # the bound over a phase's two ends that came closest to its range where all else held, for
        # the report: (margin, sample, location, rate)
        self.rate_miss: tuple[float, int, int, object] | None = None
        # per location, a guard out of it that held on a run with every guard met so far, where a
        # phase's duration did not allow the transition (too short, or it had overrun): (seconds
        # outside the range, sample, transition, phase, seconds lasted), the least outside kept, for
        # the report of the location the best run got stuck in
        self.timing_miss: dict[int, tuple[float, int, object, int, float]] = {}
        self.overrun: dict[int, tuple[int, int, float]] = {}  # location -> (sample, phase, seconds it had lasted)
        # states[q], for the locations that hold runs: a key -> (smallest robustness so far, run)
        self.states: dict[int, dict[Key, tuple[float, tuple]]] = {}
        self.first_met: list[int | None] = [None] * n_loc  # first sample at which a run with all guards met is in q
        self.met_run: list = [None] * n_loc  # that run's transitions, (sample, transition id)
        self.best_final, self.best_final_run = -math.inf, ()

    def run(self) -> _RunSearch:
        """Itself, searched through the whole trace."""
        for k in range(len(self.times)):
            self.step(k)
        return self

    def step(self, k: int) -> None:
        """The runs after sample ``k``: staying where their drivers progressed, meeting the
        invariants, taking the transitions whose guards hold. Only the locations that hold runs
        are stepped, in the order of their numbers."""
        surviving = self._staying(k)
        new_states = {q: dict(runs) for q, runs in surviving.items()}
        self._invariants(k, new_states)
        for q, runs in surviving.items():
            self._transitions(k, q, runs, new_states)
        if self.ahead is not None:
            for q in [q for q in new_states if self.ahead[q][k] < self.floor]:
                del new_states[q]
        if self.beam is not None:
            for q, runs in new_states.items():
                if len(runs) > self.beam:
                    # the runs that can still end best first (what they have met, and what is ahead)
                    ahead = self.ahead[q][k] if self.ahead is not None else math.inf
                    kept = sorted(runs.items(), key=lambda item: (-min(item[1][0], ahead), item[0]))[: self.beam]
                    new_states[q] = dict(kept)
        self.states = {q: new_states[q] for q in sorted(new_states) if new_states[q]}
        for q, runs in self.states.items():
            if self.first_met[q] is None and max(v for v, _ in runs.values()) >= 0:
                self.first_met[q] = k
                self.met_run[q] = max(runs.values(), key=lambda state: state[0])[1]
        for value, run in self.states.get(self.automaton.final, {}).values():
            if value > self.best_final:
                self.best_final, self.best_final_run = value, run

    def _staying(self, k: int) -> dict[int, dict[Key, tuple[float, tuple]]]:
        """The runs that stay, by location: in q at k-1, q's drivers progressed over (k-1, k], no
        timed phase overran."""
        init, times = self.automaton.initial, self.times
        surviving: dict[int, dict[Key, tuple[float, tuple]]] = {}
        if self.begins[k]:
            surviving[init] = {(): (math.inf, ())}
        if k == 0:
            return surviving
        for q, runs in self.states.items():
            if q == init or not self.moved[q][k - 1]:
                continue
            kept = {}
            for key, entry in runs.items():
                over = _overrun(key, k, times, self.timings)
                if over is None:
                    kept[key] = entry
                elif entry[0] >= 0:
                    # the last run with every guard met that a phase's overrun ended, for the report
                    self.overrun[q] = (k, over, float(times[k - 1] - times[dict(key)[over]]))
            if kept:
                surviving[q] = kept
        return dict(sorted(surviving.items()))

    def _invariants(self, k: int, states: dict[int, dict[Key, tuple[float, tuple]]]) -> None:
        """Each location's invariant at sample ``k``: its robustness bounds its runs', or ends them."""
        for q in self.invariant_locations:
            if q not in states:
                continue
            margin = self.invariant_margin[q][k]
            if margin >= self.floor:
                runs = states[q]
                for key, (value, run) in runs.items():
                    runs[key] = (min(value, margin), run)
            else:
                del states[q]

    def _transitions(self, k: int, q: int, runs: dict, states: dict[int, dict[Key, tuple[float, tuple]]]) -> None:
        """The runs in ``q`` that take one of its transitions at sample ``k``, into ``states``."""
        for (starts, ends), transitions in self.effects[q]:
            # the timed phases after the step, once for every transition with this effect:
            # each key's best value before the guard, per key after the step
            advanced: dict[Key, tuple[float, tuple]] = {}
            for key, (value, run) in runs.items():
                stepped = _advance(key, starts, ends, k, self.times, self.timings, self.columns)
                if isinstance(stepped, _Broken):
                    if value >= 0:
                        for transition in transitions:
                            if self.guard_margin[transition.id][k] >= 0 and (
                                q not in self.timing_miss or stepped.outside < self.timing_miss[q][0]
                            ):
                                self.timing_miss[q] = (stepped.outside, k, transition, stepped.phase, stepped.seconds)
                    continue
                if stepped is None:
                    continue
                next_key, timing_margin, missed = stepped
                if missed is not None and value >= 0 and (self.rate_miss is None or missed[0] > self.rate_miss[0]):
                    self.rate_miss = (missed[0], k, q, missed[1])
                candidate = min(value, timing_margin)
                if candidate < self.floor:
                    continue
                if next_key not in advanced or candidate > advanced[next_key][0]:
                    advanced[next_key] = (candidate, run)
            if not advanced:
                continue
            for transition in transitions:
                margin = self.guard_margin[transition.id][k]
                if margin < self.floor:
                    continue
                target = states.setdefault(transition.target, {})
                for next_key, (value, run) in advanced.items():
                    candidate = min(value, margin)
                    if next_key not in target or candidate > target[next_key][0]:
                        target[next_key] = (candidate, run + ((k, transition.id),))

    def _stood_still(self, location: int, entered: int, held: float) -> str:
        """The vehicle of ``location``'s drive phases that first stood still after the run entered
        it (sample ``entered``) and by ``held`` seconds, and from when: "" when every one of them
        moved on at every sample up to then."""
        stops = [
            (k, actor)
            for actor in self.drivers[location]
            for k in range(entered, len(self.progress[actor]))
            if not self.progress[actor][k] and self.times[k] <= held + 1e-9
        ]
        if not stops:
            return ""
        k, actor = min(stops)
        return f"{actor} stood still from t = {self.times[k]:.1f} s"

    def verdict(self) -> Verdict:
        """Accepted when a run ends in the final location with every guard met and the trace had no
        incident; else the location the best run got furthest to and the closest miss there."""
        automaton, trace, times = self.automaton, self.trace, self.times
        depth = automaton.depth()
        met = [q for q in range(self.n_loc) if self.first_met[q] is not None] or [automaton.initial]
        furthest = max(met, key=lambda q: (depth.get(q, 0), -(self.first_met[q] or 0)))
        accepted = self.best_final >= 0 and not trace.incidents
        events = {t.id: t.label for t in automaton.transitions}
        # a rejected run's report marks only the transitions whose guards held (the best run to the
        # end may mark guards that the explanation says never held)
        shown = self.best_final_run if accepted else (self.met_run[furthest] or [])
        best_run = [(float(times[k]), events[tid]) for k, tid in shown]
        miss = None
        if self.best_final < 0:
            miss = _closest_miss(automaton, furthest, self.first_met[furthest] or 0, self.guard_margin, trace, times)
            # a guard that held where the run could have taken it but for a vehicle that had stopped
            stopped_short = miss is not None and miss.robustness >= 0
            if self.rate_miss is not None and (miss is None or miss.robustness >= 0):
                miss = _rate_miss(automaton, self.rate_miss, self.columns, times)
                stopped_short = False
            if furthest in self.timing_miss and (miss is None or miss.robustness >= 0):
                miss = _timing_miss(automaton, self.timing_miss[furthest], trace, times)
                *_, phase, seconds = self.timing_miss[furthest]
                stopped_short = seconds < automaton.timings[phase].low
            elif furthest in self.overrun and miss is not None and miss.robustness >= 0 and not miss.timing:
                k, phase, seconds = self.overrun[furthest]
                timing = automaton.timings[phase]
                miss = dataclasses.replace(
                    miss,
                    timing=f"{timing} but had lasted {seconds:.1f} s by t = {times[k - 1]:.1f} s, before the guard held",
                    locations=tuple(dict.fromkeys([*miss.locations, *([timing.source] if timing.source else [])])),
                )
                stopped_short = False
            if stopped_short:
                # the guard held, too soon or at a time the run could have taken it: a vehicle of the
                # phase that had stopped making progress by then is why no run stayed there for it
                still = self._stood_still(furthest, self.first_met[furthest] or 0, miss.time)
                if still:
                    miss = dataclasses.replace(miss, progress=still)
        return Verdict(
            accepted,
            float(self.best_final),
            automaton.location(furthest).name,
            best_run,
            miss,
            list(trace.incidents),
        )


def _overrun(key: Key, k: int, times, timings) -> int | None:
    """The first timed phase of ``key`` (open phases, by start sample) that has run past its
    range by sample ``k``, so that a run staying there is no run; None when none has."""
    return next((p for p, start in key if not timings[p].admits_start(times[k] - times[start])), None)


@dataclass(frozen=True)
class _Broken:
    """A transition a phase's duration does not allow: the phase, how long it had lasted, and by
    how many seconds that is outside its range."""

    phase: int
    seconds: float
    outside: float


def _advance(
    key: tuple, starts: tuple, ends: tuple, k: int, times, timings, columns
) -> tuple[tuple, float, tuple | None] | _Broken | None:
    """The timed-phase state after a transition that starts the timed phases ``starts`` and ends
    ``ends`` at sample ``k``; the smallest margin of the durations (s) and the bounds over their
    two ends (``PhaseBound``, in their units) it ends; and the worst such bound it misses,
    (margin, rate), if any. ``_Broken`` when a duration is broken (that is no run, like a missed
    progress), None when a phase bound cannot be measured; a missed bound is a negative margin,
    as a missed guard is."""
    if not starts and not ends:
        return key, math.inf, None
    started = dict(key)
    margin = math.inf
    missed = None
    for phase in starts:
        started[phase] = k
    for phase in ends:
        timing = timings[phase]
        begun = started.pop(phase, k)
        seconds = times[k] - times[begun]
        if not timing.admits(seconds):
            return _Broken(phase, float(seconds), float(max(timing.low - seconds, seconds - timing.high)))
        if math.isfinite(timing.high):
            margin = min(margin, seconds - timing.low, timing.high - seconds)
        for rate in timing.rates:
            if seconds <= 0:
                return None
            value = rate.measured(columns[rate.column][rate.actor], times, begun, k)
            rate_margin = min(value - rate.low, rate.high - value)
            margin = min(margin, rate_margin)
            if rate_margin < 0 and (missed is None or rate_margin < missed[0]):
                missed = (rate_margin, (rate, begun))
    return tuple(sorted(started.items())), margin, missed


def _rate_miss(automaton: SymbolicAutomaton, found: tuple, columns, times) -> GuardMiss:
    """A bound over a phase's two ends (a mean acceleration, a distance travelled) that no run
    met, where it came closest (all else met up to there)."""
    margin, k, location, (rate, begun) = found
    series = columns[rate.column][rate.actor]
    value = rate.measured(series, times, begun, k)
    k = rate.span(series, begun, k)
    name = "v" if rate.column == "speed" else rate.column
    return GuardMiss(
        source=automaton.location(location).name,
        target=f"the end of {rate.phase}" if rate.phase else "the phase's end",
        guard=str(rate),
        events=f"{times[begun]:.1f} s to {times[k]:.1f} s",
        time=float(times[k]),
        robustness=float(margin),
        values={
            f"{rate.symbol}({rate.actor})": float(value),
            f"{name}({rate.actor}) at start": float(series[begun]),
            f"{name}({rate.actor}) at end": float(series[k]),
        },
        locations=(rate.source,) if rate.source is not None else (),
    )


def _timing_miss(automaton: SymbolicAutomaton, found: tuple, trace: Trace, times) -> GuardMiss:
    """A guard that held where the run could not take it, because a phase it ends would have
    lasted too short or too long: the values it printed meet the guard, and this says why they
    were not enough (an explanation must not be contradicted by its own values)."""
    outside, k, transition, phase, seconds = found
    timing = automaton.timings[phase]
    return GuardMiss(
        source=automaton.location(transition.source).name,
        target=automaton.location(transition.target).name,
        guard=str(transition.guard),
        events=transition.label,
        time=float(times[k]),
        robustness=float(transition.guard.robustness(trace.snapshot(k))),
        values=_term_values(transition.guard, trace.snapshot(k)),
        locations=tuple(
            dict.fromkeys(
                [
                    *(b.source for b in transition.guard.atoms() if b.source is not None),
                    *([timing.source] if timing.source is not None else []),
                ]
            )
        ),
        timing=f"{timing} but had lasted {seconds:.1f} s there ({outside:.1f} s {'short' if seconds < timing.low else 'over'})",
    )


def _end_columns(automaton: SymbolicAutomaton) -> set[str]:
    return {rate.column for timing in automaton.timings.values() for rate in timing.rates}


def _closest_miss(
    automaton: SymbolicAutomaton, location: int, entered: int, guard_margin: dict, trace: Trace, times
) -> GuardMiss | None:
    """The guard out of ``location`` that came closest to holding after the run entered it."""
    best = None
    for transition in automaton.outgoing(location):
        margins = guard_margin[transition.id]
        for k in range(entered + 1 if location != automaton.initial else 0, len(times)):
            if best is None or margins[k] > best[0]:
                best = (margins[k], k, transition)
    if best is None:
        return None
    r, k, transition = best
    return GuardMiss(
        source=automaton.location(location).name,
        target=automaton.location(transition.target).name,
        guard=str(transition.guard),
        events=transition.label,
        time=float(times[k]),
        robustness=float(r),
        values=_term_values(transition.guard, trace.snapshot(k)),
        locations=tuple(dict.fromkeys(b.source for b in transition.guard.atoms() if b.source is not None)),
    )


def _term_values(guard: Guard, snapshot) -> dict[str, float]:
    values: dict[str, float] = {}
    for bound in guard.atoms():
        if isinstance(bound, Bound):
            values[str(bound.term)] = float(bound.term.value(snapshot))
    return values
