"""Falsification: a search that spends its samples where the vehicle under test comes closest to failing.

Hypothesis draws a scenario's logical parameters favouring each range's ends and steers toward its
``target()`` only once half its examples are spent (its target phase): on a rare failure away
from the ends it is no faster than random. ``CrossEntropyProvider`` is a Hypothesis backend (a
``PrimitiveProvider``: Hypothesis's extension point for what draws the choices) that steers from
the first sample. Its first ``CORNERS`` samples probe the corners of the space, every choice (one
per logical parameter, ``sampling.strategy``) at one of its ends: a physical failure most often
lies at an extreme (fastest, closest, hardest), and probing them is boundary-value testing. Then,
in the manner of VerifAI's cross-entropy sampler, each choice is split into ``BUCKETS`` buckets; a
bucket is drawn and a value uniformly inside it. After each sample, the next ones follow the elite (the
share ``ELITE`` of the samples so far that came closest to failing, read from the ``target()`` the
runner reports, a failure closest of all): with a probability growing to ``MOST_FOLLOWED``, a
choice takes the bucket of an elite sample or a bucket next to it (so that the search moves past
the best seen, toward a failure beyond them), else any bucket (so that none is ruled out).

Everything else is Hypothesis's: the failure it finds is replayed on Hypothesis's own backend,
shrunk and saved to the example database as any other, so it replays exactly. The provider's
own random draws come from the seed its backend name carries (``backend(seed)``), so one seed
fixes the search as it fixes sampling. ``backend(seed, steered=False)`` is the uniform random
search it is measured against (``benchmarks/falsification.py``).
"""

from __future__ import annotations

import contextlib
import math
import random
import zlib
from collections.abc import Iterator
from typing import Any, ClassVar

from hypothesis.internal.conjecture.providers import AVAILABLE_PROVIDERS, PrimitiveProvider

BUCKETS = 10  # per choice, as VerifAI's cross-entropy sampler splits each range
ELITE = 0.1  # the share of samples so far whose buckets the next samples favour
# how likely a choice follows the elite once there are n samples: MOST_FOLLOWED * n / (n + SETTLE),
# so that the first samples are close to uniform and the search sharpens as evidence comes in
# (tuned on synthetic rare failures: docs/evaluation.md)
SETTLE = 1.0
MOST_FOLLOWED = 0.9
CORNERS = 8  # samples probing the corners first: all of them for up to 3 parameters
TARGET = "target"  # how Hypothesis names a target() value among an observation's features ("target:label")

Key = tuple[int, int]  # (the choice's position in the sample, its number of buckets)


class CrossEntropyProvider(PrimitiveProvider):
    """A Hypothesis backend that draws integer choices from a cross-entropy distribution steered
    by the samples' ``target()`` values (higher: closer to failing). Other kinds of choice (the
    refined strategy draws none) are drawn uniformly. ``seed`` is set by ``backend``."""

    lifetime = "test_function"
    add_observability_callback = True
    seed: ClassVar[int] = 0
    steered: ClassVar[bool] = True  # False: every bucket uniformly (the random search it is measured against)

    def __init__(self, conjecturedata: Any, /) -> None:
        super().__init__(conjecturedata)
        self._random = random.Random(self.seed)
        self._drawn: list[tuple[Key, int]] = []  # this sample's (choice, bucket)
        self._history: list[tuple[float, list[tuple[Key, int]]]] = []  # (score, choices) per observed sample
        self._samples = 0  # samples drawn so far, those rejected too
        self._following: list[list[tuple[Key, int]]] = []  # this sample's elite (``_elite``), for every choice
        self._flips: list[bool] = []  # per choice: whether the corners' order starts at its highest value

    # ------------------------------------------------------------ Hypothesis's protocol

    def per_test_case_context_manager(self) -> contextlib.AbstractContextManager:
        return self._sample()

    @contextlib.contextmanager
    def _sample(self) -> Iterator[None]:
        self._drawn = []
        self._following = self._elite() if self.steered else []
        try:
            yield
        finally:
            self._samples += 1

    def on_observation(self, observation: Any) -> None:
        """Learn from one sample: its score is its ``target()`` value (a failure scores above all)."""
        if observation.status == "gave_up" or not self._drawn:
            return  # rejected (no plan, set aside): it says nothing about closeness to failing
        if observation.status == "failed":
            score = math.inf
        else:
            scores = [
                v
                for k, v in observation.features.items()
                if (k == TARGET or k.startswith(TARGET + ":")) and isinstance(v, int | float)
            ]
            if not scores:
                return
            score = float(max(scores))
        self._history.append((score, list(self._drawn)))

    def draw_integer(
        self,
        min_value: int | None = None,
        max_value: int | None = None,
        *,
        weights: dict[int, float] | None = None,
        shrink_towards: int = 0,
    ) -> int:
        # ``weights`` (Hypothesis's nudge toward a range's ends) is not followed: the buckets decide
        low = min_value if min_value is not None else (max_value - 2**16 if max_value is not None else -(2**16))
        high = max_value if max_value is not None else low + 2**17
        size = high - low + 1
        key = (len(self._drawn), min(BUCKETS, size))
        corner = self._corner(key[0])
        if corner is not None:
            self._drawn.append((key, key[1] - 1 if corner else 0))
            return high if corner else low
        bucket = self._bucket(key)
        self._drawn.append((key, bucket))
        first = low + (size * bucket) // key[1]
        last = low + (size * (bucket + 1)) // key[1] - 1
        return self._random.randint(first, max(first, last))

    def draw_boolean(self, p: float = 0.5) -> bool:
        return self._random.random() < p

    def draw_float(
        self,
        *,
        min_value: float = -math.inf,
        max_value: float = math.inf,
        allow_nan: bool = True,
        smallest_nonzero_magnitude: float,
    ) -> float:
        low = min_value if math.isfinite(min_value) else -1e6
        high = max_value if math.isfinite(max_value) else 1e6
        return self._random.uniform(low, high)

    def draw_string(self, intervals: Any, *, min_size: int = 0, max_size: int = 8) -> str:
        size = self._random.randint(min_size, min(max_size, min_size + 8))
        return "".join(chr(intervals[self._random.randrange(len(intervals))]) for _ in range(size)) if intervals else ""

    def draw_bytes(self, min_size: int = 0, max_size: int = 8) -> bytes:
        size = self._random.randint(min_size, min(max_size, min_size + 8))
        return bytes(self._random.randrange(256) for _ in range(size))

    # ------------------------------------------------------------ the cross-entropy distribution

    def _corner(self, position: int) -> bool | None:
        """While the search probes the corners of the space (its first ``CORNERS`` samples), which
        end the choice at ``position`` takes (True: its highest value): the sample's number in
        binary, each bit one choice's end, so that the first 2^d samples visit every corner of d
        choices, in an order the seed shuffles. None after, or for the random search."""
        probe = self._samples
        if not self.steered or probe >= CORNERS:
            return None
        if position >= len(self._flips):
            self._flips.extend(self._random.random() < 0.5 for _ in range(position + 1 - len(self._flips)))
        return bool((probe >> position) & 1) != self._flips[position]

    def _bucket(self, key: Key) -> int:
        """A bucket of choice ``key``: with probability ``followed``, an elite sample's bucket or one
        next to it (so that the search moves past the best buckets seen, toward a failure beyond
        them), else uniformly."""
        buckets = key[1]
        if self._following:
            followed = MOST_FOLLOWED * len(self._history) / (len(self._history) + SETTLE)
            if self._random.random() < followed:
                used = [bucket for choices in self._following for k, bucket in choices if k == key]
                if used:
                    bucket = self._random.choice(used) + self._random.choice((-1, 0, 0, 1))
                    return min(buckets - 1, max(0, bucket))
        return self._random.randrange(buckets)

    def _elite(self) -> list[list[tuple[Key, int]]]:
        """The choices of the samples so far that came closest to failing (at least one)."""
        if not self._history:
            return []
        count = max(1, math.ceil(ELITE * len(self._history)))
        ranked = sorted(self._history, key=lambda entry: -entry[0])
        return [choices for _, choices in ranked[:count]]


@contextlib.contextmanager
def untraced() -> Iterator[None]:
    """Hypothesis's observability without its line coverage while a search runs: the provider
    needs each sample's ``target()`` (``on_observation``), not which lines ran, and tracing every
    line of planning and simulation made each sample about five times slower (Python 3.11's
    ``sys.settrace``). Hypothesis reads this switch at each test case and supports setting it."""
    from hypothesis.internal import observability

    before = observability.OBSERVABILITY_COLLECT_COVERAGE
    observability.OBSERVABILITY_COLLECT_COVERAGE = False
    try:
        yield
    finally:
        observability.OBSERVABILITY_COLLECT_COVERAGE = before


def backend(seed: int | str, steered: bool = True) -> str:
    """The name of the cross-entropy backend (``steered=False``: the uniform random search, each
    choice's buckets equally likely, as VerifAI's random sampler) whose random draws ``seed`` fixes
    (a text seed, as pytest's ``--hypothesis-seed`` may be, is read as its CRC-32), registered
    with Hypothesis for ``settings(backend=...)``."""
    number = seed if isinstance(seed, int) else zlib.crc32(str(seed).encode())
    name = f"roadlogic-{'cross-entropy' if steered else 'random'}-{number}"
    if name not in AVAILABLE_PROVIDERS:
        AVAILABLE_PROVIDERS[name] = type(
            "SeededCrossEntropyProvider", (CrossEntropyProvider,), {"seed": number, "steered": steered}
        )
    return name
