"""Stage 2: the symbolic automaton of a scenario (``build_automaton``) and its guard algebra."""

from ..logic.automaton import Location, SymbolicAutomaton, Timing, Transition
from ..logic.guards import LANE, POSITION, SPEED, TRUE, And, Bound, Guard, Not, Or, Term, conjunction
from .construction import build_automaton

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
