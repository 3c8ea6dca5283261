"""A failing scenario in pytest-html's report: its plot and animation inline, and the commands that
replay it, as the report's "extras" (pytest-html is an optional extra: ``pip install -e ".[html]"``).

The pictures are embedded as base64 (pytest-html writes them as files beside the report unless it
is ``--self-contained-html``); the case's artifact folder keeps the originals.
"""

from __future__ import annotations

import base64
import html
from pathlib import Path

from ..registries.oracles import ORACLES


def report_extras(paths: dict[str, Path], replay: list[str]) -> list[dict]:
    """pytest-html extras for one failing case: plot, animation, replay commands."""
    from pytest_html import extras

    result = []
    if "plot" in paths:
        result.append(extras.png(_base64(paths["plot"]), name="trajectories"))
    if "animation" in paths:
        result.append(
            extras.image(_base64(paths["animation"]), name="simulation", mime_type="image/gif", extension="gif")
        )
    table = _oracle_table(paths.get("verdict"))
    if table:
        result.append(extras.html(table))
    commands = "\n".join(html.escape(line) for line in replay)
    # wrapped: one replay line is wider than a screen and would push the pictures out of view
    result.append(
        extras.html(
            f'<div class="roadlogic-replay"><p>replay this case:</p><pre style="white-space: pre-wrap; overflow-wrap: anywhere">{commands}</pre></div>'
        )
    )
    return result


def _oracle_table(verdict: Path | None) -> str:
    """The oracles' values of the vehicle under test (``verdict.json``), as an HTML table; "" without one."""
    import json

    if verdict is None or not Path(verdict).is_file():
        return ""
    values = json.loads(Path(verdict).read_text()).get("vehicle_under_test")
    if not values:
        return ""
    rows = [
        (oracle.title, values.get(oracle.value_key), oracle.unit, values["thresholds"].get(oracle.key))
        for oracle in ORACLES
        if values["thresholds"].get(oracle.key) is not None  # off, or a verdict written before the oracle existed
    ]
    cells = "".join(
        f"<tr><td>{name}</td><td>{'none ahead' if value is None else f'{value:g} {unit}'}</td><td>{threshold:g} {unit}</td></tr>"
        for name, value, unit, threshold in rows
    )
    failures = "".join(f"<li>{html.escape(line)}</li>" for line in values["failures"])
    return (
        f'<div class="roadlogic-oracles"><p>vehicle under test {html.escape(values["vehicle"])}:</p>'
        f"<table><tr><th>oracle</th><th>value</th><th>threshold</th></tr>{cells}</table>"
        + (f"<ul>{failures}</ul>" if failures else "")
        + "</div>"
    )


def _base64(path: Path) -> str:
    return base64.b64encode(Path(path).read_bytes()).decode("ascii")
