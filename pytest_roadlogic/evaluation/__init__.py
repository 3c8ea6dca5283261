"""The paper's evaluation as a command (``roadlogic bench``): run every scenario under the base and
the refined strategy, then report time per stage and conformance (RQ1) and diversity (RQ2).

The names below are imported from their modules on first use: a run that needs only one module
of this package (``scenario_source``, ``fidelity``) does not load the benchmark with it."""

from __future__ import annotations

import importlib

# exported name -> the module of this package that defines it
_EXPORTS = {
    "BenchmarkResults": "bench",
    "BenchmarkSettings": "bench",
    "InstanceRecord": "bench",
    "run_benchmark": "bench",
    "Occupancy": "occupancy",
    "jaccard": "occupancy",
    "mean_pairwise": "occupancy",
    "similarity_matrix": "occupancy",
    "write_report": "report",
    "StrategySummary": "summary",
    "summaries": "summary",
    "targets": "summary",
    "targets_met": "summary",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str):
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f".{module}", __name__), name)


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))
