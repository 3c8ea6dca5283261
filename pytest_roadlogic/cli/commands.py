"""The ``roadlogic`` subcommands and the line ``roadlogic --help`` gives each: the one table the top-level
parser is built from without importing a command (each module, ``cli.<name>``, adds its own flags when it
is the command asked for)."""

from __future__ import annotations

SUMMARIES = {
    "run": "plan, simulate and monitor one scenario; write the artifacts",
    "replay": "run one case again exactly: from the case.json of a failure, or from a file and values",
    "check": "parse and check .osc files and folders; print every problem",
    "automaton": "write a scenario's symbolic automaton as Graphviz DOT (and PNG when dot is installed)",
    "plan": "solve a scenario's planning problem and print the plans as tables",
    "bench": "the paper's evaluation (RQ1 time and conformance, RQ2 diversity): results, plots and report.md",
    "cover": "a coverage campaign: samples, proofs of unreachable buckets, closure; on a cluster too",
    "falsify": "search for a failing case from several seeds at once; on a cluster too",
}

# what each command exits with
EXIT_ACCEPTED, EXIT_REJECTED, EXIT_INPUT = 0, 1, 2
