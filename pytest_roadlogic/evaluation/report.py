"""``report.md`` and its figures, from a run's ``results.json`` alone (so a report can be rebuilt)."""

from __future__ import annotations

import json
import math
import os
from pathlib import Path

from ..confinement import safe_name
from ..outcomes import CONFORMANT, NO_PLAN, STAGES, shown
from ..settings import BASE, REFINED
from . import figures
from .bench import PAPER_COUNTS, STRATEGIES, BenchmarkResults
from .summary import StrategySummary, summaries, targets

REPORT_FILE = "report.md"


def write_report(
    results: BenchmarkResults, out: Path, table: dict[tuple[str, str], StrategySummary] | None = None
) -> Path:
    """Write every figure and ``report.md`` into ``out``; returns the report's path. ``table`` is
    ``summaries(results)`` when the caller has it already."""
    table = table if table is not None else summaries(results)
    scenarios = [s for s in results.scenarios if s not in results.errors]
    plots: dict[str, Path] = {}
    if scenarios:
        for strategy in STRATEGIES:
            plots[f"time-{strategy}"] = figures.stage_times(
                table, scenarios, strategy, out / f"rq1-time-{strategy}.png"
            )
            for scenario in scenarios:
                plots[f"{scenario}-{strategy}"] = figures.heatmap(
                    table[scenario, strategy], out / f"rq2-similarity-{safe_name(scenario)}-{strategy}.png"
                )
        plots["overview"] = figures.heatmap_overview(table, scenarios, out / "rq2-similarity.png")
        plots["outcomes"] = figures.outcomes(table, scenarios, REFINED, out / "rq2-outcomes-refined.png")
    path = out / REPORT_FILE
    path.write_text(render(results, table, scenarios, {k: p.name for k, p in plots.items()}), encoding="utf-8")
    return path


def render(
    results: BenchmarkResults,
    table: dict[tuple[str, str], StrategySummary],
    scenarios: list[str],
    plots: dict[str, str],
) -> str:
    s, env = results.settings, results.environment
    lines = [
        "# RoadLogic evaluation",
        "",
        f"Seed {s['seed']}; {s['base']} base and {s['refined']} refined instances per scenario; up to {s['tries']} tries per instance; "
        f"time limits {s['planning_time_limit']:g} s per planning and {s['simulation_time_limit']:g} s per simulation; "
        f"artifacts {'written' if s['artifacts'] else 'not written'}. Wall time {results.seconds / 60:.1f} min.",
        "",
        f"Command: `{' '.join(s['command']) if s.get('command') else 'roadlogic bench'}`",
        "",
        f"Machine: {env['platform']}; {env['processor']}; {env['cpus']} CPUs; {env['memory_gib']} GiB memory; {env['date']}.",
        "",
        "Versions: " + ", ".join(f"{name} {version}" for name, version in env["versions"].items()) + ".",
        "",
        "Raw results: `results.json` (every instance: outcome, tries, seconds per stage, sampled values, occupancy grid).",
        "",
        "## Targets",
        "",
        "| target | met | where |",
        "|---|---|---|",
        *(f"| {t.name} | {'yes' if t.met else 'NO'} | {t.detail} |" for t in targets(results, table)),
        "",
    ]
    if s["base"] < PAPER_COUNTS[0] or s["refined"] < PAPER_COUNTS[1]:
        lines += [
            f"Fewer instances than the paper's {PAPER_COUNTS[0]} and {PAPER_COUNTS[1]}: the targets are set for those; with two base instances a mean similarity rests on one pair.",
            "",
        ]
    if results.errors:
        lines += ["## Scenarios that could not run", ""]
        lines += [f"- {name}: {message.splitlines()[0]}" for name, message in sorted(results.errors.items())]
        lines.append("")
    lines += [
        "## RQ1: effective scenario generation",
        "",
        "unasked: instances whose plan has a lane or speed change that no construct of its vehicle asks for "
        "(docs/language.md, least action).",
        "",
    ]
    for strategy in STRATEGIES:
        lines += [f"### {strategy.capitalize()} strategy", "", *_time_table(table, scenarios, strategy), ""]
        if f"time-{strategy}" in plots:
            lines += [f"![Time per stage, {strategy} strategy]({plots[f'time-{strategy}']})", ""]
    lines += [
        "## RQ2: diversity",
        "",
        "Similarity of two instances: the Jaccard index of the sets of cells (1 lane x 1 m) that any vehicle "
        "occupied at any time; the mean over every pair of instances with a simulation (lower is more diverse).",
        "",
        "| scenario | base | refined | refined lower |",
        "|---|---|---|---|",
    ]
    for scenario in scenarios:
        base, refined = table[scenario, BASE].mean_similarity, table[scenario, REFINED].mean_similarity
        lines.append(
            f"| {scenario} | {_number(base, 3)} | {_number(refined, 3)} | {'yes' if refined < base else 'no'} |"
        )
    lines.append("")
    if "overview" in plots:
        lines += [f"![Similarity heatmaps]({plots['overview']})", ""]
        lines += [
            "Heatmaps per scenario: "
            + ", ".join(f"[{sc} {st}]({plots[f'{sc}-{st}']})" for sc in scenarios for st in STRATEGIES),
            "",
        ]
    lines += ["### Outcomes, refined strategy", "", *_outcome_table(table, scenarios, REFINED), ""]
    if "outcomes" in plots:
        lines += [f"![Outcomes, refined strategy]({plots['outcomes']})", ""]
    lines += _realistic(results, table)
    lines += _unsuccessful(results)
    return "\n".join(lines)


def _realistic(results: BenchmarkResults, table: dict[tuple[str, str], StrategySummary]) -> list[str]:
    """The realistic suite beside the paper's seven: outcomes and time per stage, no targets (they
    are the paper's). Two of its files are infeasible on purpose: "no plan" is their right answer."""
    scenarios = [s for s in results.realistic if s not in results.errors]
    suite = results.settings.get("realistic")
    if not suite or not scenarios:
        return []
    lines = [
        "## Realistic scenarios",
        "",
        f"`{os.path.commonpath(suite['paths']) if suite['paths'] else ''}`: {len(scenarios)} scenarios written the way testing "
        f"engineers write them (kph, timed phases, headways, events, braking to a stop, up to five vehicles); "
        f"{suite['base']} base and {suite['refined']} refined instances each, {suite['encoding']} encoding. "
        "The files named infeasible_* are infeasible on purpose: their right outcome is no plan, with the clashing constraints named.",
        "",
    ]
    for strategy in STRATEGIES:
        lines += [
            f"### {strategy.capitalize()} strategy",
            "",
            *_time_table(table, scenarios, strategy),
            "",
            *_outcome_table(table, scenarios, strategy),
            "",
        ]
    return lines


def _time_table(table, scenarios: list[str], strategy: str) -> list[str]:
    lines = [
        "| scenario | instances | conformant | unasked | tries | "
        + " | ".join(f"{stage} s" for stage in STAGES)
        + " | total s | all instances min |",
        "|---" * (7 + len(STAGES)) + "|",
    ]
    for scenario in scenarios:
        summary = table[scenario, strategy]
        stages = " | ".join(_number(summary.mean_seconds[stage], 2) for stage in STAGES)
        total = sum(summary.mean_seconds.values())
        lines.append(
            f"| {scenario} | {summary.instances} | {_percent(summary.conformant)} | {summary.unasked} | {_number(summary.mean_tries, 2)} | {stages} | "
            f"{_number(total, 2)} | {_number(summary.total_seconds / 60, 2)} |"
        )
    return lines


def _outcome_table(table, scenarios: list[str], strategy: str) -> list[str]:
    columns = shown(table[scenario, strategy].outcomes for scenario in scenarios)
    lines = ["| scenario | " + " | ".join(columns) + " |", "|---" * (1 + len(columns)) + "|"]
    for scenario in scenarios:
        counts = table[scenario, strategy].outcomes
        lines.append(f"| {scenario} | " + " | ".join(str(counts[o]) for o in columns) + " |")
    return lines


def _unsuccessful(results: BenchmarkResults) -> list[str]:
    failed = [r for r in results.instances if r.outcome != CONFORMANT]
    if not failed:
        return ["## Instances that did not conform", "", "None.", ""]
    lines = ["## Instances that did not conform", ""]
    for r in failed:
        where = f" (artifacts: `{r.artifacts}`)" if r.artifacts else ""
        values = f" at {'; '.join(r.described)} (values {json.dumps(r.values)})" if r.values else ""
        reason = " / ".join(line.strip() for line in r.message.splitlines()[:3]) or r.outcome
        lines.append(f"- {r.scenario} {r.strategy} #{r.index + 1}: {r.outcome}{values}{where}: {reason}")
    if any(r.outcome == NO_PLAN for r in failed):
        lines += [
            "",
            "Replay a sample with `roadlogic replay FILE --values JSON --seed S`; without a plan it prints the conflicting constraints.",
        ]
    return lines + [""]


def _number(value: float, digits: int) -> str:
    return "-" if math.isnan(value) else f"{value:.{digits}f}"


def _percent(value: float) -> str:
    return "-" if math.isnan(value) else f"{100 * value:.1f}%"
