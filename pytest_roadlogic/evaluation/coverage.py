"""What a run covered of each scenario's ``cover``/``record`` items (``ScenarioCoverage``): per
cover item, how many cases fell in each bucket, outside them all, were ignored or illegal; per
record item, the values recorded. It counts the cases whose scenario happened (``HAPPENED``: a
case with no plan, or one the monitor rejected, exercised nothing). Tallies are plain data: they
travel as JSON from pytest-xdist workers, merge across items and runs (``merged``), and are
written for a CI to diff (``write_json``) and read back (``read_json``).
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..frontend.semantics.coverage import CROSS
from ..outcomes import HAPPENED

FORMAT = 1  # the JSON file's format, written into it


@dataclass
class ItemCoverage:
    """One item's tally: ``buckets`` (label -> cases), and for a record the values seen (as shown)."""

    name: str
    kind: str
    parameter: str
    text: str = ""
    target: int = 1
    buckets: dict[str, int] = field(default_factory=dict)
    outside: int = 0
    ignored: int = 0
    illegal: list[str] = field(default_factory=list)
    recorded: list[str] = field(default_factory=list)
    crossed: list[str] = field(default_factory=list)  # a cross's items
    # buckets no case can reach, with why (``coverage.reach``): label -> the reason
    unreachable: dict[str, str] = field(default_factory=dict)

    @property
    def covered(self) -> int:
        return sum(1 for label, hits in self.buckets.items() if hits >= self.target and label not in self.unreachable)

    @property
    def reachable(self) -> int:
        return sum(1 for label in self.buckets if label not in self.unreachable)


@dataclass
class ScenarioCoverage:
    """The coverage of one scenario (``scenario``: its file and name, as reports name it)."""

    scenario: str
    cases: int = 0
    items: dict[str, ItemCoverage] = field(default_factory=dict)
    # of the file the cases ran on (``coverage_db.fingerprint``): a database adds up only the
    # tallies of one file
    fingerprint: str = ""

    @classmethod
    def of(cls, scenario: str, items: Iterable, fingerprint: str = "") -> ScenarioCoverage:
        """An empty tally of ``items`` (``semantics.coverage.CoverItem``)."""
        return cls(
            scenario,
            0,
            {
                item.name: ItemCoverage(
                    item.name,
                    item.kind,
                    item.parameter,
                    item.text,
                    item.target,
                    {b.label: 0 for b in item.buckets},
                    crossed=list(item.crossed),
                )
                for item in items
            },
            fingerprint,
        )

    def add(self, items: Iterable, values: dict[str, Any], outcome: str, run=None) -> None:
        """Count one case if its scenario happened: its sampled ``values`` (parameter -> SI value),
        and the values its ``run`` (``pipeline.SimulatedInstance``) took at the items' events."""
        if outcome not in HAPPENED:
            return
        counted = False
        landed: dict[str, str] = {}  # cover item -> the bucket this case fell in
        for item in items:
            if item.crossed:
                continue
            value = _value(item, values, run)
            if value is None:
                continue
            counted = True
            tally = self.items[item.name]
            if item.ignored(value):
                tally.ignored += 1
                continue
            if item.illegal_value(value):
                tally.illegal.append(item.shown(value))
            if item.kind == "record":
                tally.recorded.append(item.shown(value))
                continue
            bucket = next((b for b in item.buckets if b.holds(value)), None)
            if bucket is None:
                tally.outside += 1
            else:
                tally.buckets[bucket.label] += 1
                landed[item.name] = bucket.label
        for item in items:
            if item.crossed and counted:
                tally = self.items[item.name]
                if all(name in landed for name in item.crossed):
                    tally.buckets[CROSS.join(landed[name] for name in item.crossed)] += 1
                else:
                    tally.outside += 1
        self.cases += counted

    def to_json(self) -> dict:
        return asdict(self)

    @classmethod
    def from_json(cls, data: dict) -> ScenarioCoverage:
        return cls(
            data["scenario"],
            data["cases"],
            {k: ItemCoverage(**v) for k, v in data["items"].items()},
            data.get("fingerprint", ""),
        )


def recorded_values(items: Iterable, values: dict[str, Any], run=None) -> dict[str, str]:
    """What one case records (its case file, verdict.json, the CLI's report): each ``record``
    item's value in it, as the report shows it (in the item's unit), by the item's name: a
    logical parameter's sampled value, or the value the run took at the item's event. An item
    without a value in this case (a base case's parameter, an event the run did not meet) is left
    out."""
    found = {}
    for item in items:
        if item.kind == "record" and not item.crossed:
            value = _value(item, values, run)
            if value is not None:
                found[item.name] = item.shown(value)
    return found


def _value(item, values: dict[str, Any], run) -> Any:
    """The value ``item`` reads in one case: its parameter's sampled value, or the run's at its
    event (``_observed``); None without one."""
    if item.observed is not None:
        return _observed(item, run)
    return values.get(item.parameter)


def _observed(item, run) -> float | None:
    """The value ``item`` reads in ``run`` at its event: the trace's first sample at or after the
    time the monitor's run met it (None without a run, or a run that did not meet it)."""
    if run is None:
        return None
    automaton, verdict, trace = run.automaton, run.verdict, run.simulation.trace
    label, end = item.event
    if not verdict.run or not len(trace.times):
        return None
    if not label:
        time = verdict.run[0][0] if end == "start" else verdict.run[-1][0]
    else:
        marks = {t.label for t in automaton.transitions_at(label, end)}
        times = [time for time, events in verdict.run if events in marks]
        if not times:
            return None
        time = times[0]
    index = min(int(np.searchsorted(trace.times, time - 1e-9)), len(trace.times) - 1)
    state = {actor: {column: float(values[index]) for column, values in c.items()} for actor, c in trace.actors.items()}
    return item.value_of(state)


def merged(coverages: Iterable[ScenarioCoverage]) -> list[ScenarioCoverage]:
    """One tally per scenario, adding up those of the same scenario (workers, shards, runs)."""
    by_scenario: dict[str, ScenarioCoverage] = {}
    for coverage in coverages:
        into = by_scenario.get(coverage.scenario)
        if into is None:
            by_scenario[coverage.scenario] = ScenarioCoverage.from_json(json.loads(json.dumps(coverage.to_json())))
            continue
        into.cases += coverage.cases
        for name, item in coverage.items.items():
            mine = into.items.setdefault(
                name,
                ItemCoverage(item.name, item.kind, item.parameter, item.text, item.target, crossed=list(item.crossed)),
            )
            for label, hits in item.buckets.items():
                mine.buckets[label] = mine.buckets.get(label, 0) + hits
            mine.outside += item.outside
            mine.ignored += item.ignored
            mine.illegal += item.illegal
            mine.recorded += item.recorded
            mine.unreachable.update(item.unreachable)
    return [by_scenario[k] for k in sorted(by_scenario)]


def text_lines(coverages: list[ScenarioCoverage]) -> list[str]:
    """The terminal's coverage report: per scenario and item, buckets hit of those reachable,
    each bucket's count, the buckets not hit, and those no case can reach with why."""
    lines = []
    for coverage in coverages:
        lines.append(f"{coverage.scenario}: {coverage.cases} cases")
        for item in coverage.items.values():
            about = f" ({item.text})" if item.text else ""
            if item.kind == "record":
                shown = ", ".join(item.recorded[:8]) + (" ..." if len(item.recorded) > 8 else "")
                of = item.parameter or "a value of the run"
                lines.append(f"  record {item.name} of {of}{about}: {len(item.recorded)} values: {shown}")
                continue
            target = f", target {item.target}" if item.target > 1 else ""
            of = item.parameter or (
                "the cross of " + " and ".join(item.crossed) if item.crossed else "a value of the run"
            )
            lines.append(f"  cover {item.name} of {of}{about}: {item.covered} of {item.reachable} buckets{target}")
            for label, hits in item.buckets.items():
                why = item.unreachable.get(label)
                mark = f"unreachable: {why}" if why else ("not hit" if hits == 0 else str(hits))
                lines.append(f"    {label:<24}  {mark}")
            extra = [
                f"{item.outside} outside the buckets" if item.outside else "",
                f"{item.ignored} ignored" if item.ignored else "",
                f"{len(item.illegal)} illegal ({', '.join(item.illegal[:4])})" if item.illegal else "",
            ]
            if any(extra):
                lines.append("    " + "; ".join(e for e in extra if e))
    return lines


def write_json(coverages: list[ScenarioCoverage], path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps({"format": FORMAT, "scenarios": [c.to_json() for c in coverages]}, indent=1) + "\n")


def read_json(path: Path) -> list[ScenarioCoverage]:
    """The tallies a ``write_json`` wrote; ``ValueError`` saying why a file is not one."""
    try:
        data = json.loads(path.read_text())
        if data.get("format") != FORMAT:
            raise ValueError(f"not a coverage file of format {FORMAT}")
        return [ScenarioCoverage.from_json(s) for s in data["scenarios"]]
    except (OSError, json.JSONDecodeError, KeyError, TypeError, AttributeError) as error:
        raise ValueError(f"not a coverage file: {error}") from None
