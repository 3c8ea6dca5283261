"""Runtime monitor: does a trace satisfy the scenario's automaton, how robustly, and if not, why?

Semantics (the paper's, on a sampled trace with constant interpolation): a run of the automaton
takes its transitions at strictly increasing sample instants, each when its guard holds; while the
run stays in a location, the location's invariant holds at every sample and every actor driving
there makes forward progress (its position increases from each sample to the next). The scenario may start after the trace does (vehicles start from
standstill and need a run-up), so the initial location may be left at any sample. The trace is
accepted when some run reaches the final location and no incident (collision, off-road) occurred.

One forward pass computes, for every location, the best run into it: the one whose smallest guard
robustness so far is largest. That value at the final location is the verdict's robustness; it is
non-negative exactly when some run meets every guard. The pass costs O(samples x transitions).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..automaton.guards import Bound, Guard
from ..automaton.model import SymbolicAutomaton
from ..frontend.errors import SourceLocation
from ..simulation.trace import Incident, Trace


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

    def describe(self) -> str:
        values = ", ".join(f"{k} = {v:.2f}" for k, v in self.values.items())
        where = "".join(f"\n    declared at {loc}" for loc in self.locations)
        return (
            f"stuck in {self.source}: the guard to {self.target} ({self.events}) never held:\n"
            f"    {self.guard}\n"
            f"    closest at t = {self.time:.1f} s (robustness {self.robustness:+.2f}) where {values}{where}"
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
            "miss": None if self.miss is None else {
                "source": self.miss.source, "target": self.miss.target, "guard": self.miss.guard,
                "events": self.miss.events, "time": self.miss.time, "robustness": self.miss.robustness,
                "values": self.miss.values, "locations": [str(loc) for loc in self.miss.locations],
            },
            "incidents": [str(i) for i in self.incidents],
            "explanation": self.explain(),
        }


def monitor(automaton: SymbolicAutomaton, trace: Trace) -> Verdict:
    snapshots = trace.snapshots()
    n_loc = len(automaton.locations)
    drivers = [sorted(loc.drivers) for loc in automaton.locations]
    positions = {a: trace.actors[a]["x"] for a in trace.names}
    init, final = automaton.initial, automaton.final
    NONE = -math.inf
    value = [NONE] * n_loc  # best smallest-robustness of a run in each location, at the current sample
    run: list[tuple] = [()] * n_loc
    first_met = [None] * n_loc  # first sample at which a run with all guards met is in the location
    best_final, best_final_run = NONE, ()
    outgoing = [automaton.outgoing(q) for q in range(n_loc)]
    invariants = [loc.invariant for loc in automaton.locations]
    invariant_locations = [q for q in range(n_loc) if not invariants[q].is_true]
    for k, snapshot in enumerate(snapshots):
        # staying: the run was in q at k-1 and q's drivers progressed over (k-1, k]
        alive = [False] * n_loc
        for q in range(n_loc):
            if q == init:
                alive[q] = True
            elif value[q] != NONE and k > 0 and all(positions[a][k] > positions[a][k - 1] for a in drivers[q]):
                alive[q] = True
        new_value = [value[q] if alive[q] and q != init else NONE for q in range(n_loc)]
        for q in invariant_locations:
            if new_value[q] != NONE:
                # staying in q: its invariant must hold at this sample too
                new_value[q] = min(new_value[q], invariants[q].robustness(snapshot))
        new_value[init] = math.inf
        new_run = list(run)
        for q in range(n_loc):
            if not alive[q]:
                continue
            source_value = math.inf if q == init else value[q]
            for transition in outgoing[q]:
                candidate = min(source_value, transition.guard.robustness(snapshot))
                if candidate > new_value[transition.target]:
                    new_value[transition.target] = candidate
                    new_run[transition.target] = run[q] + ((k, transition.id),)
        value, run = new_value, new_run
        for q in range(n_loc):
            if value[q] >= 0 and first_met[q] is None:
                first_met[q] = k
        if value[final] > best_final:
            best_final, best_final_run = value[final], run[final]

    depth = automaton.depth()
    met = [q for q in range(n_loc) if first_met[q] is not None] or [init]
    furthest = max(met, key=lambda q: (depth.get(q, 0), -(first_met[q] or 0)))
    accepted = best_final >= 0 and not trace.incidents
    times = trace.times
    events = {t.id: t.label for t in automaton.transitions}
    best_run = [(float(times[k]), events[tid]) for k, tid in best_final_run]
    miss = None
    if best_final < 0:
        miss = _closest_miss(automaton, furthest, first_met[furthest] or 0, snapshots, times)
    return Verdict(accepted, float(best_final), automaton.location(furthest).name, best_run, miss, list(trace.incidents))


def _closest_miss(automaton: SymbolicAutomaton, location: int, entered: int, snapshots, times) -> GuardMiss | None:
    best = None
    for transition in automaton.outgoing(location):
        for k in range(entered + 1 if location != automaton.initial else 0, len(snapshots)):
            r = transition.guard.robustness(snapshots[k])
            if best is None or r > best[0]:
                best = (r, k, transition)
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
        values=_term_values(transition.guard, snapshots[k]),
        locations=tuple(dict.fromkeys(b.source for b in transition.guard.atoms() if b.source is not None)),
    )


def _term_values(guard: Guard, snapshot) -> dict[str, float]:
    values: dict[str, float] = {}
    for bound in guard.atoms():
        if isinstance(bound, Bound):
            values[str(bound.term)] = float(bound.term.value(snapshot))
    return values
