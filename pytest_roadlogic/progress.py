"""A one-line progress bar on stderr, for commands that run many instances."""

from __future__ import annotations

import sys
import time
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from typing import TextIO


class ProgressBar:
    """``[#####     ] 12/70  overtake refined  conformant 12  1:05 left``, redrawn in place.

    On stderr, so that a command's output (stdout) stays clean for pipes and files; redrawn only on
    a terminal: into a file or a pipe (``roadlogic bench ... 2> log``) it writes one line when it is
    closed, not carriage returns and erase-line codes.
    """

    def __init__(self, total: int, width: int = 20, stream: TextIO | None = None) -> None:
        self.total, self.width = total, width
        self.stream = stream or sys.stderr
        self.started = time.monotonic()
        self.live = _is_terminal(self.stream)
        self.last = ""

    def update(self, done: int, text: str = "") -> None:
        bar = "#" * round(self.width * done / self.total) if self.total else ""
        elapsed = time.monotonic() - self.started
        left = f"  {_clock(elapsed * (self.total - done) / done)} left" if 0 < done < self.total else ""
        self.last = f"[{bar:<{self.width}}] {done}/{self.total}  {text}"
        if self.live:
            print(f"\r{self.last}{left}\033[K", end="", file=self.stream, flush=True)

    def close(self) -> None:
        if self.live:
            print(file=self.stream, flush=True)
        elif self.last:
            print(f"{self.last}  in {_clock(time.monotonic() - self.started)}", file=self.stream, flush=True)


def _is_terminal(stream: TextIO) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):  # a closed or a stream-like object
        return False


def _clock(seconds: float) -> str:
    minutes, seconds = divmod(int(seconds), 60)
    return f"{minutes}:{seconds:02d}"
