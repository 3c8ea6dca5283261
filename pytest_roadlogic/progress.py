"""A one-line progress bar on stderr, for commands that run many instances."""

from __future__ import annotations

import sys
import time
from typing import TextIO


class ProgressBar:
    """``[#####     ] 12/70  overtake refined  conformant 12  1:05 left``, redrawn in place.

    On stderr, so that a command's output (stdout) stays clean for pipes and files.
    """

    def __init__(self, total: int, width: int = 20, stream: TextIO | None = None) -> None:
        self.total, self.width = total, width
        self.stream = stream or sys.stderr
        self.started = time.monotonic()

    def update(self, done: int, text: str = "") -> None:
        bar = "#" * round(self.width * done / self.total) if self.total else ""
        elapsed = time.monotonic() - self.started
        left = f"  {_clock(elapsed * (self.total - done) / done)} left" if 0 < done < self.total else ""
        print(f"\r[{bar:<{self.width}}] {done}/{self.total}  {text}{left}\033[K", end="", file=self.stream, flush=True)

    def close(self) -> None:
        print(file=self.stream, flush=True)


def _clock(seconds: float) -> str:
    minutes, seconds = divmod(int(seconds), 60)
    return f"{minutes}:{seconds:02d}"
