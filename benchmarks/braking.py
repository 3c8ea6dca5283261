"""A car's own dynamics: how fast and how hard a car asked to brake at 6-8 m/s^2 does so in the
simulation, per seed.

    python benchmarks/braking.py [--seeds 10] [--plot braking.png]

Runs benchmarks/scenarios/emergency_stop.osc (100 kph, then ``acceleration([-8mpsps..-6mpsps])``
to a standstill) as a run does (refined sample, plan, frenetix simulation, monitor) and prints per
seed: when the plan steps into the braking, how long after that the trace first brakes at 6 m/s^2
(target: within 0.5 s), its hardest braking (target: at most 9 m/s^2, the asked 8 and 1), whether it
braked before the step (more than 1.5 m/s^2 in the 0.1 s before it), the monitor's verdict and the
case's seconds. ``--plot``: the plan's and the trace's speed and acceleration at the first seed.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from pytest_roadlogic.pipeline import load_scenario, run_instances  # noqa: E402

SCENARIO = ROOT / "benchmarks" / "scenarios" / "emergency_stop.osc"
ASKED = -6.0  # m/s^2: the gentlest braking asked
HARDEST = -9.0  # m/s^2: the hardest allowed (the asked 8 and 1)


def measure(seed: int):
    started = time.perf_counter()
    instance = next(run_instances(load_scenario(SCENARIO), count=1, seed=seed))
    seconds = time.perf_counter() - started
    plan, trace = instance.plan, instance.simulation.trace
    step = next(k for k, transition in plan.transitions if transition == 1)
    onset = step * plan.dt
    times, acceleration = trace.times, trace.actors["lead"]["acceleration"]
    braking = times[(times >= onset) & (acceleration <= ASKED)]
    delay = float(braking[0] - onset) if len(braking) else float("inf")
    early = bool((acceleration[(times < onset) & (times >= onset - 0.1)] < -1.5).any())
    return instance, onset, delay, float(acceleration.min()), early, seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--plot", type=Path)
    args = parser.parse_args()
    print(
        f"{'seed':>4}  {'step at':>7}  {'6 m/s^2 after':>13}  {'hardest':>8}  {'early':>5}  {'verdict':>8}  {'seconds':>7}"
    )
    delays, peaks = [], []
    for seed in range(1, args.seeds + 1):
        instance, onset, delay, peak, early, seconds = measure(seed)
        delays.append(delay)
        peaks.append(peak)
        verdict = "accepted" if instance.verdict.accepted else "rejected"
        print(
            f"{seed:>4}  {onset:>6.1f}s  {delay:>12.2f}s  {peak:>8.2f}  {str(early):>5}  {verdict:>8}  {seconds:>7.2f}"
        )
        if args.plot and seed == 1:
            plot(instance, args.plot)
    print(
        f"6 m/s^2 reached after the step: median {np.median(delays):.2f} s, worst {max(delays):.2f} s (target 0.5); "
        f"hardest braking: worst {min(peaks):.2f} m/s^2 (target >= {HARDEST:g})"
    )


def plot(instance, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plan, trace = instance.plan, instance.simulation.trace
    steps = np.arange(plan.horizon + 1) * plan.dt
    speeds = np.array([s.speed for s in plan.states["lead"]])
    figure, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    top.plot(trace.times, trace.actors["lead"]["speed"], label="trace")
    top.plot(steps, speeds, "o--", label="plan")
    top.set_ylabel("speed (m/s)")
    top.legend()
    bottom.plot(trace.times, trace.actors["lead"]["acceleration"], label="trace")
    bottom.step(steps[1:], np.diff(speeds) / plan.dt, where="pre", linestyle="--", label="plan")
    bottom.axhspan(-8, -6, alpha=0.15, label="asked")
    bottom.set_ylabel("acceleration (m/s^2)")
    bottom.set_xlabel("time (s)")
    bottom.legend()
    figure.tight_layout()
    figure.savefig(path)
    print(f"plot: {path}")


if __name__ == "__main__":
    main()
