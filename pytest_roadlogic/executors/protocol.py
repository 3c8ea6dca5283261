"""What a campaign's independent jobs run on: the protocol every executor answers.

A campaign (the bench's runs and samples, a coverage campaign's cases) is a list of calls, each of
a module-level function (pickled by its name) on picklable arguments, each fixed by its arguments
and the run's seed alone. An executor runs them, as many at once as it has workers, and
hands back each job's result in the order of the list, so that a campaign records what the serial
run records whichever executor ran it. A job that raises raises the same exception from
``results`` at its turn.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from typing import Any, Protocol

Job = tuple[Any, ...]  # the arguments of one call
Call = tuple[Callable[..., Any], Job]  # a function and its arguments


class ExecutorError(Exception):
    """An executor cannot be set up or cannot go on (its option names the cause and what to do)."""


class Executor(Protocol):
    """Runs jobs; a context manager that releases its workers on exit (an interrupt too)."""

    name: str  # as the record of a run names it: "serial", "processes", "ray"

    def workers(self) -> int:
        """How many jobs run at once."""
        ...

    def describe(self) -> str:
        """One line for a run's record: what ran the jobs (the cluster's nodes and CPUs)."""
        ...

    def results(self, calls: Sequence[Call], sizes: Sequence[float] | None = None) -> Iterator[Any]:
        """``function(*arguments)`` for each call, yielded in the order of ``calls``; ``sizes``
        (the expected cost of each) starts the largest first, so that no worker is left with a
        long one at the end."""
        ...

    def __enter__(self) -> Executor: ...

    def __exit__(self, *exc: object) -> None: ...


def largest_first(count: int, sizes: Sequence[float] | None) -> list[int]:
    """The jobs' indices in the order to start them: the largest first, ties in list order."""
    if sizes is None:
        return list(range(count))
    return sorted(range(count), key=lambda k: -sizes[k])
