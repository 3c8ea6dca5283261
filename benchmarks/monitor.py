"""Monitor speed: the time to judge a 60 s trace sampled at 0.1 s, per benchmark scenario (the
paper's seven and the realistic files whose automaton builds).

    python benchmarks/monitor.py

The traces are synthetic (no simulation needed): every actor cruises in its lane, the first one
faster, changing lanes now and then, so that runs get deep into the automaton. The target is
under 50 ms for three actors; the automaton's size is printed too, since the monitor's cost is
linear in samples x transitions, times the start instants a timed phase can have (its duration's
range over the sample period: five_vehicle_minute's phases of 15-25 s keep up to 100 of them).
A scenario whose first judgement takes over a second is judged once, not REPEATS times.

Each row prints the monitor beside the same monitor keeping every run (one pass with no floor:
the monitor before its floors and bounds), and the monitor as the pipeline judges a trace of a
plan without a run-up: the scenario begins at the first sample (``begins_by=0``). The synthetic traces are all rejected: a rejected trace
is where the monitor must be as quick as on an accepted one (a failing case is shrunk on it).
``--simulated`` adds, per realistic scenario, the trace of its first accepted simulation at seed 1
and the ratio of the synthetic rejected trace's time to it (target: at most 10), whole and per
sample: the simulated traces are shorter than the synthetic 60 s, and the monitor's cost grows
with the samples, so only the per-sample ratio compares a rejected trace with an accepted one of
the same length.
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import OscError, load_file
from pytest_roadlogic.monitor import monitor
from pytest_roadlogic.simulation import Trace

ROOT = Path(__file__).resolve().parent.parent
DURATION, DT, REPEATS = 60.0, 0.1, 15


def synthetic_trace(actors: tuple[str, ...], stationary: frozenset[str]) -> Trace:
    times = np.arange(0.0, DURATION + DT / 2, DT)
    n = len(times)
    columns = {}
    for index, actor in enumerate(actors):
        speed = 0.0 if actor in stationary else 20.0 - 2.0 * index
        x = -15.0 * index + speed * times if actor not in stationary else np.full(n, 300.0)
        lane = np.where((times // 10).astype(int) % 3 == 1, 0, 1) if index == 0 else np.full(n, 1 + index % 2)
        columns[actor] = {
            "x": x,
            "y": np.zeros(n),
            "heading": np.zeros(n),
            "speed": np.full(n, speed),
            "acceleration": np.zeros(n),
            "lane": lane,
        }
    return Trace(times, columns)


def timed(judge, automaton, trace) -> tuple[float, object]:
    """Median milliseconds of ``judge`` on ``trace`` (once when the first takes over a second)."""
    samples, verdict = [], None
    for _ in range(REPEATS):
        started = time.perf_counter()
        verdict = judge(automaton, trace)
        samples.append((time.perf_counter() - started) * 1000)
        if samples[0] > 1000:
            break
    return statistics.median(samples), verdict


def row(name: str, automaton, trace, rejected_ms: float | None = None) -> float:
    """Print one row; the monitor's milliseconds on ``trace``."""
    after, verdict = timed(monitor, automaton, trace)
    before, _ = timed(lambda a, t: monitor(a, t, floors=(-math.inf,)), automaton, trace)
    first, _ = timed(lambda a, t: monitor(a, t, begins_by=0.0), automaton, trace)
    ratio = ""
    if rejected_ms is not None:
        per_sample = (rejected_ms / (int(DURATION / DT) + 1)) / (after / len(trace.times))
        ratio = f" {rejected_ms / after:14.1f} {per_sample:11.1f} {len(trace.times):8d}"
    print(
        f"{name:24} {len(automaton.actors):6d} {len(automaton.locations):9d} {len(automaton.transitions):11d} "
        f"{'accepted' if verdict.accepted else 'rejected':>9} {before:12.1f} {after:10.1f} {first:14.1f}{ratio}"
    )
    return after


HEADER = (
    f"{'scenario':24} {'actors':>6} {'locations':>9} {'transitions':>11} {'verdict':>9} {'every run ms':>12} "
    f"{'monitor ms':>10} {'from 1st ms':>14}"
)


def main() -> int:
    print(
        f"monitor on a synthetic {DURATION:.0f} s trace at {DT} s ({int(DURATION / DT) + 1} samples), median of {REPEATS}"
    )
    print(HEADER)
    rejected: dict[str, float] = {}
    for path in sorted((ROOT / "scenarios").glob("*.osc")) + sorted((ROOT / "scenarios" / "realistic").glob("*.osc")):
        try:
            automaton = build_automaton(load_file(path).scenarios[0])
        except (OscError, IndexError):
            continue  # not read yet (issue 18), or a library without a scenario
        rejected[path.stem] = row(path.stem, automaton, synthetic_trace(automaton.actors, automaton.stationary))
    if "--simulated" in sys.argv[1:]:
        from pytest_roadlogic.pipeline import load_scenario, run_scenario
        from pytest_roadlogic.planning.errors import NoPlanError

        print("\nmonitor on each realistic scenario's simulated trace (seed 1)")
        print(HEADER + f" {'rejected/this':>14} {'per sample':>11} {'samples':>8}")
        for path in sorted((ROOT / "scenarios" / "realistic").glob("*.osc")):
            try:
                outcome = run_scenario(load_scenario(path), seed=1)
            except (OscError, NoPlanError):
                continue  # the infeasible ones
            row(path.stem, outcome.automaton, outcome.simulation.trace, rejected.get(path.stem))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
