"""The automaton's drawing as files: DOT text and, when Graphviz is installed, a PNG.

DOT is plain text, so it is always written; the PNG needs Graphviz's ``dot`` program and is
skipped (with a note) when it is not installed, rather than making Graphviz a dependency.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

from ..automaton.dot import to_dot
from ..logic.automaton import SymbolicAutomaton
from .files import write_text


def write_dot(automaton: SymbolicAutomaton, path: str | Path, title: str = "", png: bool = True) -> dict[str, Path]:
    """Write ``path`` (DOT) and, when Graphviz is installed and ``png``, the PNG beside it."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text(path, to_dot(automaton, title))
    written = {"dot": path}
    dot = shutil.which("dot")
    if png and dot is not None:
        image = path.with_suffix(".png")
        subprocess.run([dot, "-Tpng", str(path), "-o", str(image)], check=True, capture_output=True)
        written["png"] = image
    return written
