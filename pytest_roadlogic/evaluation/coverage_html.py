"""The coverage report as a picture for pytest-html's summary (``html``): per scenario, each cover
item as horizontal bars (one per bucket, its length the cases in it), each cross of two or more
items as a grid (rows the first item's buckets, columns the others'), each record item as its
values. Colours say the state: hit its target, hit fewer times, not hit, proved unreachable (the
reason in the cell's tooltip). Plain HTML and inline styles, every text from a scenario escaped:
a report is opened in a browser, and a scenario's names are data."""

from __future__ import annotations

import html
import itertools

from ..frontend.semantics.coverage import CROSS
from .coverage import ItemCoverage, ScenarioCoverage

HIT, SHORT, MISSED, UNREACHABLE = "#4caf50", "#ffb74d", "#e57373", "#bdbdbd"
BAR_PIXELS = 240  # the longest bar


def html_summary(coverages: list[ScenarioCoverage]) -> str:
    """The section for the HTML report's summary ("" without coverage)."""
    if not coverages:
        return ""
    parts = ["<h2>Coverage</h2>", _legend()]
    for coverage in coverages:
        parts.append(f"<h3>{_e(coverage.scenario)}: {coverage.cases} cases</h3>")
        for item in coverage.items.values():
            parts.append(_item(item, coverage))
    return '<div class="roadlogic-coverage">' + "".join(parts) + "</div>"


def _item(item: ItemCoverage, coverage: ScenarioCoverage) -> str:
    about = f" ({_e(item.text)})" if item.text else ""
    if item.kind == "record":
        values = ", ".join(_e(v) for v in item.recorded) or "none"
        return f"<p><b>record {_e(item.name)}</b>{about}: {values}</p>"
    head = f"<p><b>cover {_e(item.name)}</b>{about}: {item.covered} of {item.reachable} buckets</p>"
    gridded = item.crossed and all(name in coverage.items for name in item.crossed)
    return head + (_grid(item, coverage) if gridded else _bars(item))


def _bars(item: ItemCoverage) -> str:
    most = max(item.buckets.values(), default=0) or 1
    rows = []
    for label, hits in item.buckets.items():
        colour, state = _state(item, label, hits)
        width = 0 if label in item.unreachable else max(2, round(BAR_PIXELS * hits / most)) if hits else 0
        bar = f'<div style="background:{colour};width:{width}px;height:12px"></div>' if width else ""
        rows.append(
            f'<tr title="{_e(state)}"><td>{_e(label)}</td><td style="width:{BAR_PIXELS}px">{bar}</td>'
            f'<td style="background:{colour}">{_e(state)}</td></tr>'
        )
    return '<table class="roadlogic-coverage-bars">' + "".join(rows) + "</table>"


def _grid(item: ItemCoverage, coverage: ScenarioCoverage) -> str:
    first, *others = [list(coverage.items[name].buckets) for name in item.crossed]
    columns = [CROSS.join(c) for c in itertools.product(*others)]
    head = "<tr><th></th>" + "".join(f"<th>{_e(c)}</th>" for c in columns) + "</tr>"
    rows = []
    for row in first:
        cells = []
        for column in columns:
            label = CROSS.join((row, column))
            hits = item.buckets.get(label, 0)
            colour, state = _state(item, label, hits)
            shown = "unreachable" if label in item.unreachable else str(hits)
            cells.append(f'<td style="background:{colour}" title="{_e(state)}">{shown}</td>')
        rows.append(f"<tr><th>{_e(row)}</th>{''.join(cells)}</tr>")
    return '<table class="roadlogic-coverage-grid">' + head + "".join(rows) + "</table>"


def _state(item: ItemCoverage, label: str, hits: int) -> tuple[str, str]:
    """(colour, words) of one bucket."""
    if label in item.unreachable:
        return UNREACHABLE, f"unreachable: {item.unreachable[label]}"
    if hits >= item.target:
        return HIT, f"{hits} case{'s' * (hits != 1)}"
    if hits:
        return SHORT, f"{hits} of the target {item.target}"
    return MISSED, "not hit"


def _legend() -> str:
    keys = ((HIT, "hit"), (SHORT, "hit fewer times than its target"), (MISSED, "not hit"), (UNREACHABLE, "unreachable"))
    return "<p>" + " ".join(f'<span style="background:{c};padding:0 6px">{w}</span>' for c, w in keys) + "</p>"


def _e(text: object) -> str:
    return html.escape(str(text), quote=True)
