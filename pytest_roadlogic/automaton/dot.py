"""The automaton as Graphviz DOT text, guards printed as in the paper's Figure 4 (``to_dot``).

Writing it, and the PNG beside it, is an artifact's job (``artifacts/automaton.py``): this stage
only says what the drawing is.
"""

from __future__ import annotations

from ..logic.automaton import SymbolicAutomaton


def _quote(text: str) -> str:
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
    return '"' + escaped + '"'


def to_dot(automaton: SymbolicAutomaton, title: str = "") -> str:
    lines = [
        "digraph automaton {",
        "  rankdir=LR;",
        '  node [shape=circle, fontname="Helvetica"];',
        '  edge [fontname="Helvetica", fontsize=10];',
    ]
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
