"""The local process pool: ``workers`` jobs at once, each in a spawned process of this machine."""

from __future__ import annotations

import multiprocessing
from collections.abc import Iterator, Sequence
from concurrent.futures import Future, ProcessPoolExecutor
from typing import Any

from .protocol import Call, largest_first


class ProcessExecutor:
    name = "processes"

    def __init__(self, workers: int) -> None:
        self._workers = workers
        self._pool: ProcessPoolExecutor | None = None

    def workers(self) -> int:
        return self._workers

    def describe(self) -> str:
        return f"a local pool of {self._workers} processes"

    def results(self, calls: Sequence[Call], sizes: Sequence[float] | None = None) -> Iterator[Any]:
        pool = self._started()
        futures: dict[int, Future] = {
            k: pool.submit(calls[k][0], *calls[k][1]) for k in largest_first(len(calls), sizes)
        }
        try:
            for k in range(len(calls)):
                yield futures[k].result()
        finally:
            for future in futures.values():
                future.cancel()  # an interrupt or a failed job: what has not started does not

    def _started(self) -> ProcessPoolExecutor:
        if self._pool is None:
            # spawned, not forked: a fork of a process whose threads hold locks (a solver's, a test
            # runner's) can hang in the child
            self._pool = ProcessPoolExecutor(max_workers=self._workers, mp_context=multiprocessing.get_context("spawn"))
        return self._pool

    def __enter__(self) -> ProcessExecutor:
        return self

    def __exit__(self, *exc: object) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None
