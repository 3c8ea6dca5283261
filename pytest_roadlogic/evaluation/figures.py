"""The evaluation's plots, as the paper draws them: stacked stage times (RQ1), similarity heatmaps
on one colour scale and the refined strategy's outcomes (RQ2)."""

from __future__ import annotations

from pathlib import Path

from ..outcomes import (
    CONFORMANT,
    DUT_FAILED,
    NO_PLAN,
    NON_CONFORMANT,
    NOT_EXERCISED,
    PASSED,
    STAGES,
    TIMED_OUT,
    shown,
)
from .bench import STRATEGIES
from .summary import StrategySummary

STAGE_COLOURS = {
    "automaton": "tab:purple",
    "planning": "tab:orange",
    "simulation": "tab:blue",
    "monitoring": "tab:green",
    "artifacts": "tab:grey",
}
OUTCOME_COLOURS = {
    CONFORMANT: "tab:blue",
    NON_CONFORMANT: "tab:orange",
    TIMED_OUT: "tab:grey",
    NO_PLAN: "tab:red",
    PASSED: "tab:green",
    DUT_FAILED: "tab:pink",
    NOT_EXERCISED: "tab:olive",
}
COLOUR_MAP = "viridis"


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def stage_times(table: dict[tuple[str, str], StrategySummary], scenarios: list[str], strategy: str, path: Path) -> Path:
    """Mean seconds per instance, one bar per scenario, stacked by pipeline stage."""
    series = {stage: [table[s, strategy].mean_seconds[stage] for s in scenarios] for stage in STAGES}
    return _stacked_bars(
        scenarios,
        series,
        STAGE_COLOURS,
        "seconds per instance (mean)",
        f"Time per pipeline stage, {strategy} strategy",
        path,
    )


def _stacked_bars(
    scenarios: list[str],
    series: dict[str, list[float]],
    colours: dict[str, str],
    ylabel: str,
    title: str,
    path: Path,
    legend: str = "best",
) -> Path:
    plt = _pyplot()
    figure, axes = plt.subplots(figsize=(max(6, 1.3 * len(scenarios)), 4.2))
    bottoms = [0.0] * len(scenarios)
    for label, heights in series.items():
        axes.bar(scenarios, heights, bottom=bottoms, label=label, color=colours[label])
        bottoms = [b + h for b, h in zip(bottoms, heights)]
    axes.set_ylabel(ylabel)
    axes.set_title(title)
    axes.legend(loc=legend)
    axes.tick_params(axis="x", rotation=30)
    for label in axes.get_xticklabels():
        label.set_horizontalalignment("right")
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return path


def heatmap(summary: StrategySummary, path: Path) -> Path:
    """The pairwise similarity of one scenario's instances under one strategy (scale 0..1)."""
    plt = _pyplot()
    figure, axes = plt.subplots(figsize=(4.6, 4))
    image = axes.imshow(summary.similarity or [[float("nan")]], vmin=0.0, vmax=1.0, cmap=COLOUR_MAP)
    axes.set_title(
        f"{summary.scenario} ({summary.strategy})\nmean pairwise similarity {summary.mean_similarity:.2f}", fontsize=9
    )
    axes.set_xlabel("instance")
    axes.set_ylabel("instance")
    figure.colorbar(image, ax=axes, label="Jaccard index")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)
    return path


def heatmap_overview(table: dict[tuple[str, str], StrategySummary], scenarios: list[str], path: Path) -> Path:
    """Every scenario's heatmaps side by side (base, refined), sharing one colour bar."""
    plt = _pyplot()
    figure, grid = plt.subplots(len(scenarios), 2, figsize=(6, 2.8 * len(scenarios)), squeeze=False)
    image = None
    for row, scenario in enumerate(scenarios):
        for column, strategy in enumerate(STRATEGIES):
            summary = table[scenario, strategy]
            axes = grid[row][column]
            image = axes.imshow(summary.similarity or [[float("nan")]], vmin=0.0, vmax=1.0, cmap=COLOUR_MAP)
            axes.set_title(f"{scenario} ({strategy[0]}): {summary.mean_similarity:.2f}", fontsize=8)
            axes.set_xticks([])
            axes.set_yticks([])
    if image is not None:
        figure.colorbar(image, ax=grid, label="Jaccard index (occupancy grid)", shrink=0.6)
    figure.savefig(path, dpi=100)
    plt.close(figure)
    return path


def outcomes(table: dict[tuple[str, str], StrategySummary], scenarios: list[str], strategy: str, path: Path) -> Path:
    """How the instances of each scenario ended, stacked (the paper's success-rate bars): its three
    categories, and instances without a plan only when there were some."""
    counts = [table[s, strategy].outcomes for s in scenarios]
    series = {outcome: [c[outcome] for c in counts] for outcome in shown(counts)}
    if not any(series[NO_PLAN]):
        del series[NO_PLAN]
    return _stacked_bars(
        scenarios, series, OUTCOME_COLOURS, "instances", f"Outcomes, {strategy} strategy", path, legend="lower right"
    )
