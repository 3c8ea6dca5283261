"""Ours beside Scenic, the peer measured side by side: seconds and simulations per valid concrete scenario.

    pip install -e ".[peers]"       # Scenic 3.1 (its Newtonian simulator)
    python benchmarks/peers.py [--valid 20] [--seed 1] [--only overtake cut_in follow close_follow] [--simulator kinematic]

Each row is one logical scenario written twice, by us: an .osc file for ours and a Scenic program
for Scenic (``benchmarks/peers/*.scenic``, driving with ``peers/scenic_support.py``), on the same
straight road of three 3.5 m lanes. Both run in this process, interleaved (one valid scenario of
ours, one of Scenic's, and again), until each side has ``--valid`` valid concrete scenarios:

- ours: a sample of the logical parameters drawn as the refined strategy draws it, then planned,
  simulated and monitored, with the pipeline's retries (a rejected simulation takes the next plan);
  a sample without a plan or without an accepted simulation is followed by the next sample;
- Scenic: a scene generated from the program, then simulated; its requirements (the monitor of the
  scenario's phases, no collision) reject a run, and a rejected run is followed by a new scene.

``--simulator kinematic`` compares at equal fidelity: our kinematic backend (a bicycle model
tracking the plan) against Scenic's Newtonian simulator; the default, frenetix, is ours as it is.

"Seconds per valid scenario" is the wall time from the end of the previous valid one (reading the
.osc file and compiling the Scenic program are left out on both sides; one warm-up run each is not
counted). "Simulations per valid" counts every simulation run, the rejected ones too.
"""

from __future__ import annotations

import argparse
import random
import statistics
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PEERS = Path(__file__).resolve().parent / "peers"
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(PEERS))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from driver import samples  # noqa: E402  (benchmarks/driver.py: samples drawn as the refined strategy draws them)
from scenic_support import write_road  # noqa: E402

from pytest_roadlogic.pipeline import load_scenario, run_scenario  # noqa: E402
from pytest_roadlogic.planning import NoPlanError  # noqa: E402
from pytest_roadlogic.simulation import SimulationTimeout  # noqa: E402

# (row, our .osc file, the Scenic program)
PAIRS = {
    "overtake": (ROOT / "scenarios" / "overtake.osc", PEERS / "overtake.scenic"),
    "cut_in": (ROOT / "scenarios" / "realistic" / "cut_in.osc", PEERS / "cut_in.scenic"),
    "follow": (ROOT / "scenarios" / "follow.osc", PEERS / "follow.scenic"),
    "close_follow": (ROOT / "benchmarks" / "scenarios" / "follow_close.osc", PEERS / "close_follow.scenic"),
}
STAGES = ("planning", "simulation", "monitoring")


@dataclass
class Side:
    """One tool's tally on one scenario."""

    seconds: list[float] = field(default_factory=list)  # per valid scenario
    simulations: int = 0
    attempts: int = 0  # samples (ours) or scenes (Scenic) tried
    stages: dict[str, float] = field(default_factory=lambda: dict.fromkeys(STAGES, 0.0))

    @property
    def valid(self) -> int:
        return len(self.seconds)

    def cell(self) -> str:
        if not self.seconds:
            return "none valid"
        return f"{statistics.median(self.seconds):6.3f} / {max(self.seconds):6.3f}"

    def per_valid(self) -> str:
        return f"{self.simulations / self.valid:.1f}" if self.valid else "-"


class Ours:
    """Our pipeline on one .osc file, one sample after another."""

    def __init__(self, path: Path, seed: int, count: int, backend: str) -> None:
        from pytest_roadlogic.simulation.backends import simulator

        self.scenario = load_scenario(path)
        self.seed = seed
        self.samples = iter(samples(self.scenario, count, seed))
        self.simulator = simulator(backend)

    def valid_one(self, side: Side) -> None:
        """Samples until one gives an accepted simulation; adds its seconds to ``side``."""
        started = time.perf_counter()
        for values in self.samples:
            side.attempts += 1
            try:
                outcome = run_scenario(self.scenario, seed=self.seed, values=values, simulator=self.simulator)
            except (NoPlanError, SimulationTimeout):
                continue
            side.simulations += outcome.tries
            for stage in STAGES:
                side.stages[stage] += outcome.seconds[stage]
            if outcome.verdict.accepted:
                side.seconds.append(time.perf_counter() - started)
                return
        raise RuntimeError("ran out of samples before a valid scenario: raise --draws")


class Scenic:
    """A Scenic program: scene after scene, each simulated, until one is not rejected."""

    def __init__(self, path: Path, seed: int) -> None:
        import numpy
        import scenic
        from scenic.simulators.newtonian import NewtonianSimulator

        random.seed(seed)
        numpy.random.seed(seed)
        self.scenario = scenic.scenarioFromFile(str(path), mode2D=True)
        self.simulator = NewtonianSimulator()

    def valid_one(self, side: Side, limit: int = 500) -> None:
        started = time.perf_counter()
        for _ in range(limit):
            scene, _ = self.scenario.generate(verbosity=0)
            side.attempts += 1
            side.simulations += 1
            run = self.simulator.simulate(scene, maxSteps=600, maxIterations=1, verbosity=0)
            if run is not None:
                side.seconds.append(time.perf_counter() - started)
                return
        raise RuntimeError(f"no valid Scenic run in {limit} scenes")


def interleaved(name: str, valid: int, seed: int, draws: int, backend: str) -> tuple[Side, Side]:
    osc, program = PAIRS[name]
    ours, peer = Ours(osc, seed, draws, backend), Scenic(program, seed)
    ours.valid_one(Side())  # warm-up: imports, caches
    peer.valid_one(Side())
    mine, theirs = Side(), Side()
    for _ in range(valid):
        ours.valid_one(mine)
        peer.valid_one(theirs)
    return mine, theirs


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--valid", type=int, default=20, help="valid concrete scenarios per side and scenario")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--draws", type=int, default=400, help="samples of ours drawn at most per scenario")
    parser.add_argument("--only", nargs="*", choices=sorted(PAIRS), default=list(PAIRS))
    parser.add_argument(
        "--simulator", default="frenetix", help="our backend: frenetix (as it is) or kinematic (Scenic's fidelity)"
    )
    args = parser.parse_args(argv)
    try:
        import scenic  # noqa: F401
    except ImportError:
        print("Scenic is not installed: pip install -e '.[peers]'", file=sys.stderr)
        return 2
    write_road(PEERS / "road.xodr")
    print(
        f"{args.valid} valid concrete scenarios per side, seed {args.seed}, interleaved in one process; "
        f"ours simulated by {args.simulator}, Scenic's by its Newtonian simulator"
    )
    header = (
        f"{'scenario':<10} {'ours: s per valid, median / max':>32} {'Scenic':>17} "
        f"{'simulations per valid, ours / Scenic':>38} {'ours: planning / simulation / monitoring, s per valid':>56}"
    )
    print(header)
    for name in args.only:
        mine, theirs = interleaved(name, args.valid, args.seed, args.draws, args.simulator)
        stages = " / ".join(f"{mine.stages[s] / max(mine.valid, 1):.3f}" for s in STAGES)
        ratio = (
            f"  ours/Scenic {statistics.median(mine.seconds) / statistics.median(theirs.seconds):.2f}"
            if mine.seconds and theirs.seconds
            else ""
        )
        print(
            f"{name:<10} {mine.cell():>32} {theirs.cell():>17} {mine.per_valid() + ' / ' + theirs.per_valid():>38} {stages:>56}{ratio}",
            flush=True,
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
