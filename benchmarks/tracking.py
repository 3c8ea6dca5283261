"""How closely the simulated vehicles follow their plans: the figures the planner's margins rest on.

For every scenario file and seed, the first plan of the continuous encoding is simulated (frenetix,
the default driver) and compared with the plan at its steps:

- position error: the trace's position minus the plan's, per vehicle and step (m);
- gap error: the same for the distance between two vehicles, which is what a relative position
  guard (``position(..., ahead_of: x)``) reads (m);
- speed error (m/s);
- lane-change lag: when the vehicle's centre crossed into its new lane, against the plan's step at
  which it is in that lane (s; positive: later than the plan says).

    python benchmarks/tracking.py [--seeds 5] [FILES...]     (default: the paper's seven and the
                                                                 realistic files the front end reads)

Prints one row per file (median, 95th percentile and maximum of each error) and the same over all
files. The planner keeps ``position_margin``/``speed_margin`` inside every range: those settings
are set from these figures (planning/encodings/continuous/settings.py cites them).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from pytest_roadlogic.automaton import build_automaton  # noqa: E402
from pytest_roadlogic.frontend import OscError, check_file  # noqa: E402
from pytest_roadlogic.planning import (  # noqa: E402
    ContinuousPlanner,
    ContinuousSettings,
    NoPlanError,  # noqa: E402
)
from pytest_roadlogic.simulation import simulate  # noqa: E402


def errors(plan, trace) -> dict[str, list[float]]:
    """Position, gap and speed errors at the plan's steps and lane-change lags, of one simulation."""
    found: dict[str, list[float]] = {"position": [], "gap": [], "speed": [], "lag": []}
    times = trace.times
    moving = [v for v in plan.vehicles if v not in plan.stationary]
    for step in range(plan.horizon + 1):
        t = plan.runup + step * plan.dt
        if t > times[-1] + 1e-9:
            break
        index = int(np.argmin(np.abs(times - t)))
        offset = {}
        for vehicle in moving:
            state, column = plan.at(vehicle, step), trace.actors[vehicle]
            offset[vehicle] = float(column["x"][index]) - state.position
            found["position"].append(abs(offset[vehicle]))
            found["speed"].append(abs(float(column["speed"][index]) - state.speed))
        found["gap"] += [abs(offset[a] - offset[b]) for i, a in enumerate(moving) for b in moving[i + 1 :]]
    for vehicle in moving:
        lanes = trace.actors[vehicle]["lane"]
        for step in range(1, plan.horizon + 1):
            before, after = plan.at(vehicle, step - 1).lane, plan.at(vehicle, step).lane
            if before == after:
                continue
            start = plan.runup + (step - 1) * plan.dt
            crossed = [t for t, lane in zip(times, lanes) if t >= start - 1e-9 and int(lane) == after]
            if crossed:
                found["lag"].append(float(crossed[0]) - (plan.runup + step * plan.dt))
    return found


def summary(values: list[float]) -> str:
    if not values:
        return f"{'-':>20}"
    array = np.array(values)
    return f"{np.median(array):6.2f} {np.percentile(array, 95):6.2f} {array.max():6.2f}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path)
    parser.add_argument("--seeds", type=int, default=5)
    args = parser.parse_args()
    files = args.files or [
        *sorted((ROOT / "scenarios").glob("*.osc")),
        *sorted((ROOT / "scenarios" / "realistic").glob("*.osc")),
    ]
    columns = ("position", "gap", "speed", "lag")
    print(f"{'scenario':<22} {'plans':>5}  " + "  ".join(f"{c + ' (med p95 max)':<20}" for c in columns))
    total: dict[str, list[float]] = {c: [] for c in columns}
    for path in files:
        try:
            checked = check_file(path)
            if checked.errors:
                continue
            automaton = build_automaton(checked.scenario_to_run())
        except OscError:
            continue
        found: dict[str, list[float]] = {c: [] for c in columns}
        plans = 0
        for seed in range(1, args.seeds + 1):
            try:
                plan = ContinuousPlanner(automaton, ContinuousSettings(), seed).first()
            except NoPlanError:
                break
            plans += 1
            for key, values in errors(plan, simulate(plan).trace).items():
                found[key] += values
        if not plans:
            continue
        for key in columns:
            total[key] += found[key]
        print(f"{path.stem:<22} {plans:>5}  " + "  ".join(f"{summary(found[c]):<20}" for c in columns), flush=True)
    print(f"{'all':<22} {'':>5}  " + "  ".join(f"{summary(total[c]):<20}" for c in columns))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
