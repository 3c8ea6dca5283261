"""Stage 5b: did the vehicle under test fail? Oracles over a trace, apart from the monitor's
"did the scenario happen" (``judge``: a ``Trace`` and the vehicle in, a ``DutReport`` out).
``ORACLES`` (one record per oracle) and ``Thresholds`` are plain data; the rest loads numpy on
first use."""

from importlib import import_module

from ..registries.oracles import ORACLES, ORACLES_BY_NAME, Oracle
from .thresholds import Thresholds

_HOMES = {"Closest": "measures", "Collision": "verdict", "DutReport": "verdict", "judge": "verdict"}


def __getattr__(name: str):
    if name in _HOMES:
        return getattr(import_module(f".{_HOMES[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["ORACLES", "ORACLES_BY_NAME", "Closest", "Collision", "DutReport", "Oracle", "Thresholds", "judge"]
