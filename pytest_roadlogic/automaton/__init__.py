"""Stage 2: the symbolic automaton of a scenario (``build_automaton``) and its guard algebra."""

from .construction import build_automaton
from .guards import LANE, POSITION, SPEED, TRUE, And, Bound, Guard, Not, Or, Term, conjunction
from .model import Location, SymbolicAutomaton, Timing, Transition

__all__ = [
    "LANE",
    "POSITION",
    "SPEED",
    "TRUE",
    "And",
    "Bound",
    "Guard",
    "Location",
    "Not",
    "Or",
    "SymbolicAutomaton",
    "Term",
    "Timing",
    "Transition",
    "build_automaton",
    "conjunction",
]
