"""What the road tests share: the project's test maps' folder, and writing a map or a scenario a
test makes."""

from __future__ import annotations

import textwrap
from pathlib import Path

MAPS = Path(__file__).resolve().parents[2] / "scenarios" / "roads" / "maps"


def write(path: Path, text: str) -> Path:
    """``text``, dedented, as the file ``path``; the path."""
    path.write_text(textwrap.dedent(text).lstrip())
    return path
