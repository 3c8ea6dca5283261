"""The ``roadlogic`` command.

    roadlogic run FILE.osc [--scenario NAME] [--seed S] [--out DIR] [--lanes N] [--tries N]

Exit codes: 0 the simulation was accepted; 1 it was rejected (or no plan exists);
2 the input is unusable (a file that does not parse or check, a bad option).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from .frontend import OscError
from .planning import NoPlanError, PlanningSettings

EXIT_ACCEPTED, EXIT_REJECTED, EXIT_INPUT = 0, 1, 2


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="roadlogic", description="Concrete, monitored simulations from OpenSCENARIO DSL scenarios.")
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("run", help="plan, simulate and monitor one scenario; write the artifacts")
    run.add_argument("file", type=Path, help="an .osc file")
    run.add_argument("--scenario", help="the scenario to run when the file declares several (default: the first)")
    run.add_argument("--seed", type=int, default=1, help="fixes planning and simulation (default 1)")
    run.add_argument("--out", type=Path, default=Path("out"), help="artifact directory (default out/)")
    run.add_argument("--lanes", type=int, default=3, help="lanes of the road (default 3)")
    run.add_argument("--tries", type=int, default=5, help="plans to try when the monitor rejects (default 5)")
    args = parser.parse_args(argv)
    return _run(args)


def _run(args: argparse.Namespace) -> int:
    from .artifacts import write_artifacts
    from .pipeline import load_scenario, run_scenario

    try:
        scenario = load_scenario(args.file, args.scenario)
        outcome = run_scenario(scenario, seed=args.seed, settings=PlanningSettings(lanes=args.lanes), max_tries=args.tries)
    except OscError as error:
        print(error.report(), file=sys.stderr)
        return EXIT_INPUT
    except KeyError as error:
        print(f"{args.file}: error: no scenario named {error.args[0]!r} in the file", file=sys.stderr)
        return EXIT_INPUT
    except NoPlanError as error:
        print(f"{args.file}: no plan: {error}", file=sys.stderr)
        return EXIT_REJECTED
    started = time.perf_counter()
    paths = write_artifacts(outcome, args.out)
    outcome.seconds["artifacts"] = time.perf_counter() - started
    print(f"scenario {scenario.name} (seed {args.seed}): {outcome.tries} tr{'y' if outcome.tries == 1 else 'ies'}")
    for stage, seconds in outcome.seconds.items():
        print(f"  {stage:<11} {seconds:7.3f} s")
    print(outcome.verdict.explain())
    for kind, path in paths.items():
        print(f"  {kind:<11} {path}")
    return EXIT_ACCEPTED if outcome.verdict.accepted else EXIT_REJECTED


if __name__ == "__main__":
    raise SystemExit(main())
