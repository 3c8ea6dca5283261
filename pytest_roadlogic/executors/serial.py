"""The serial executor: each job in this process, one after another (each job's seconds are
measured alone)."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import Any

from .protocol import Call


class SerialExecutor:
    name = "serial"

    def workers(self) -> int:
        return 1

    def describe(self) -> str:
        return "serial, in this process"

    def results(self, calls: Sequence[Call], sizes: Sequence[float] | None = None) -> Iterator[Any]:
        for function, arguments in calls:
            yield function(*arguments)

    def __enter__(self) -> SerialExecutor:
        return self

    def __exit__(self, *exc: object) -> None:
        return None
