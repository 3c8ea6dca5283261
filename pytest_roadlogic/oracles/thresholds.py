"""Where the oracles fail: plain data, read by the run settings without loading numpy."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from ..registries.oracles import ORACLES, ORACLES_BY_NAME


def _defaults() -> dict[str, float]:
    return {oracle.name: oracle.default for oracle in ORACLES}


@dataclass(frozen=True)
class Thresholds:
    """Each oracle's threshold by its name (``registries.oracles.ORACLES``; its default where none
    is given, None: the oracle is off), and how long after a vehicle enters the path of the one
    under test its gap to it is judged from."""

    limits: Mapping[str, float | None] = field(default_factory=_defaults)
    # s: a car that cuts in close is the scenario's doing, what the vehicle under test does next its own
    reaction_time: float = 1.0

    @classmethod
    def given(cls, **limits: float) -> Thresholds:
        """The defaults, with ``limits`` (by oracle name) in their place; an unknown name raises ``KeyError``."""
        unknown = set(limits) - set(ORACLES_BY_NAME)
        if unknown:
            raise KeyError(f"no oracle named {', '.join(sorted(unknown))}; the oracles: {', '.join(ORACLES_BY_NAME)}")
        return cls({**_defaults(), **limits})

    @classmethod
    def of(cls, settings) -> Thresholds:
        """The thresholds a run's ``settings`` (``RunSettings``) set, each oracle's by its option."""
        return cls({oracle.name: getattr(settings, oracle.setting) for oracle in ORACLES})

    def __getitem__(self, oracle: str) -> float | None:
        return self.limits.get(oracle, ORACLES_BY_NAME[oracle].default)

    def by_key(self) -> dict[str, float | None]:
        """Each threshold under its oracle's key (``Oracle.key``), for verdict.json."""
        return {oracle.key: self[oracle.name] for oracle in ORACLES}
