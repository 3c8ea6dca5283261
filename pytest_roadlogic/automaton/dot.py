"""The automaton as a Graphviz drawing, guards printed as in the paper's Figure 4.

DOT is plain text, so it is always written; the PNG needs Graphviz's ``dot`` program and is
skipped (with a note) when it is not installed, rather than making Graphviz a dependency.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

from ..artifacts.files import write_text
from .model import SymbolicAutomaton


def _quote(text: str) -> str:
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
    return '"' + escaped + '"'


def to_dot(automaton: SymbolicAutomaton, title: str = "") -> str:
    lines = ["digraph automaton {", "  rankdir=LR;", '  node [shape=circle, fontname="Helvetica"];', '  edge [fontname="Helvetica", fontsize=10];']
    if title:
        lines.append(f"  label={_quote(title)}; labelloc=t;")
    lines.append('  start [shape=point, label=""];')
    for location in automaton.locations:
        label = location.name
        if not location.invariant.is_true:
            label += f"\ninv: {location.invariant}"
        if location.drivers:
            label += f"\ndrive: {', '.join(sorted(location.drivers))}"
        shape = "doublecircle" if location.id == automaton.final else ("circle" if "\n" not in label else "ellipse")
        lines.append(f"  q{location.id} [label={_quote(label)}, shape={shape}];")
    lines.append(f"  start -> q{automaton.initial};")
    for transition in automaton.transitions:
        guard = str(transition.guard)
        lines.append(f"  q{transition.source} -> q{transition.target} [label={_quote(guard)}];")
    lines.append("}")
    return "\n".join(lines) + "\n"


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
