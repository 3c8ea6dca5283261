"""A failing scenario in pytest-html's report: its plot and animation inline, and the commands that
replay it, as the report's "extras" (pytest-html is an optional extra: ``pip install -e ".[html]"``).

The pictures are embedded as base64 (pytest-html writes them as files beside the report unless it
is ``--self-contained-html``); the case's artifact folder keeps the originals.
"""

from __future__ import annotations

import base64
import html
from pathlib import Path


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
    commands = "\n".join(html.escape(line) for line in replay)
    # wrapped: one replay line is wider than a screen and would push the pictures out of view
    result.append(
        extras.html(
            f'<div class="roadlogic-replay"><p>replay this case:</p><pre style="white-space: pre-wrap; overflow-wrap: anywhere">{commands}</pre></div>'
        )
    )
    return result


def _base64(path: Path) -> str:
    return base64.b64encode(Path(path).read_bytes()).decode("ascii")
