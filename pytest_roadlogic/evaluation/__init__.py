"""The paper's evaluation as a command (``roadlogic bench``): run every scenario under the base and
the refined strategy, then report time per stage and conformance (RQ1) and diversity (RQ2)."""

from .bench import BenchmarkResults, BenchmarkSettings, InstanceRecord, run_benchmark
from .occupancy import Occupancy, jaccard, mean_pairwise, similarity_matrix
from .report import write_report
from .summary import StrategySummary, summaries, targets, targets_met

__all__ = [
    "BenchmarkResults",
    "BenchmarkSettings",
    "InstanceRecord",
    "Occupancy",
    "StrategySummary",
    "jaccard",
    "mean_pairwise",
    "run_benchmark",
    "similarity_matrix",
    "summaries",
    "targets",
    "targets_met",
    "write_report",
]
