"""The ``roadlogic`` command: one module per subcommand (``run``, ``check``, ``automaton``, ``plan``,
``replay``, ``bench``, ``cover``, ``falsify``), each with its flags (``add``) and its action; ``common`` holds what they share.

    roadlogic run FILE.osc [--scenario NAME] [--seed S] [--out DIR] [--lanes N] [--tries N] [--instances N | --values JSON]
                  [--encoding continuous|grid] [--horizon N] [--plan-timeout S] [--sim-timeout S] [--simulator NAME]
    roadlogic check PATH... [--syntax-only] [--lanes N]
    roadlogic automaton FILE.osc [--scenario NAME] [--out FILE.dot] [--lanes N]
    roadlogic plan FILE.osc [--scenario NAME] [--plans N] [--seed S] [--lanes N] [--show-asp]
    roadlogic replay CASE.json [--out DIR]
    roadlogic replay FILE.osc [--scenario NAME] [--seed S] [--values JSON | --strategy base --instance K] [--out DIR]
    roadlogic cover FILE.osc [--samples N] [--closure] [--coverage FILE.json] [--jobs N | --ray ADDRESS]
    roadlogic falsify FILE.osc [--searches K] [--budget N] [--search cross-entropy] [--jobs N | --ray ADDRESS]

Exit codes of ``run``: 0 the simulation was accepted; 1 it was rejected (or no plan exists);
2 the input is unusable (a file that does not parse or check, a bad option).
Exit codes of ``check``: 0 every file is fine; 1 some file has an error; 2 a path does not exist.
Exit codes of ``automaton``: 0 written; 2 the input is unusable.
Exit codes of ``plan``: 0 at least one plan; 1 no plan exists; 2 the input is unusable.
Exit codes of ``replay``: as ``run``.
Exit codes of ``cover``: 0 every bucket hit or proved unreachable; 1 some bucket open; 2 the input is unusable.
Exit codes of ``falsify``: 0 no search found a failure; 1 one did; 2 the input is unusable.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import os
import sys

# Light imports only: `roadlogic --help` and argument errors load no command; the command asked
# for adds its flags (cli.<name>), and imports the stages it uses when it runs.
from .commands import EXIT_ACCEPTED, EXIT_INPUT, EXIT_REJECTED, SUMMARIES

__all__ = ["EXIT_ACCEPTED", "EXIT_INPUT", "EXIT_REJECTED", "command", "main"]


def command() -> None:
    """The ``roadlogic`` executable (and ``python -m pytest_roadlogic.cli``): ``main`` on the
    process's arguments, its value the exit code.

    The process then ends as soon as what it owes is done, without the interpreter's teardown:
    every exit handler runs (the interpreter has joined its threads before them) and the standard
    streams are flushed; freeing every module's objects one by one (numpy's, CommonRoad's,
    clingo's) would lengthen every command and change nothing it wrote (docs/decisions.md).
    In a process of its own only: ``main`` returns to a Python caller (a test) as usual."""
    import atexit

    ended = {"code": 1}  # an exception out of main: the traceback is printed, and the exit is 1

    def end_now() -> None:
        # registered first, so it runs last of the exit handlers
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass  # a reader gone away, a stream already closed: nothing more to write
        os._exit(ended["code"])

    atexit.register(end_now)
    try:
        ended["code"] = main()
    except SystemExit as leaving:  # argparse's: 2 for a bad option, 0 after --help
        code = leaving.code
        ended["code"] = code if isinstance(code, int) else 0 if code is None else 1
        raise
    except KeyboardInterrupt:  # before a command began (main answers one during it)
        ended["code"] = 130
        raise
    raise SystemExit(ended["code"])


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="roadlogic", description="Concrete, monitored simulations from OpenSCENARIO DSL scenarios."
    )
    commands = parser.add_subparsers(dest="command", required=True)
    given = list(sys.argv[1:] if argv is None else argv)
    asked = next((word for word in given if not word.startswith("-")), None)
    for name, summary in SUMMARIES.items():
        if name == asked:
            importlib.import_module(f"{__name__}.{name}").add(commands)
        else:
            commands.add_parser(name, help=summary)
    args = parser.parse_args(given)
    args.argv = given
    command = args.action
    try:
        with contextlib.ExitStack() as args.held:  # what a command holds while it runs (its --out folder's claim)
            return command(args)
    except KeyboardInterrupt:
        # Ctrl-C: a line, not the traceback of wherever the solver or the simulation was
        print(f"roadlogic {args.command}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # the reader of our output went away (roadlogic check ... | head): stop quietly, as cat does
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nothing more to flush at exit
        except OSError:
            pass
        return 141
