"""``roadlogic automaton``: write a scenario's symbolic automaton as Graphviz DOT (and PNG when dot
is installed). Exit codes: 0 written; 2 the input is unusable."""

from __future__ import annotations

import argparse
from pathlib import Path

from .commands import SUMMARIES
from .common import load_automaton, reporting_input_errors, scenario_command


def add(commands) -> None:
    """The ``automaton`` command's flags, and its action."""
    automaton = scenario_command(commands, "automaton", SUMMARIES["automaton"])
    automaton.add_argument("--out", type=Path, default=None, help="the DOT file to write (default: <scenario>.dot)")
    automaton.set_defaults(action=_automaton)


def _automaton(args: argparse.Namespace) -> int:
    from ..artifacts.automaton import write_dot

    loaded = reporting_input_errors(args, lambda: load_automaton(args))
    if isinstance(loaded, int):
        return loaded
    scenario, automaton = loaded
    from ..confinement import safe_name

    # the name is the scenario's, which may be quoted (|../../../x|): it must not lead out of the working folder
    written = write_dot(
        automaton, args.out or Path(f"{safe_name(scenario.name)}.dot"), title=f"{scenario.name} ({args.file})"
    )
    print(automaton.describe())
    print(f"{len(automaton.locations)} locations, {len(automaton.transitions)} transitions")
    for kind, path in written.items():
        print(f"  {kind:<4} {path}")
    if "png" not in written:
        print("  (no PNG: Graphviz's dot is not installed)")
    return 0
