"""Stage 3: planning with clingo (``Planner``), from an automaton to ``Plan`` objects."""

from .instance import PlanningSettings, build_instance
from .plan import Plan, PlanState
from .solver import NoPlanError, Planner, PlanningTimeout, UnsatisfiableScenario, background_theory, check_satisfiable

__all__ = [
    "NoPlanError", "Plan", "PlanState", "Planner", "PlanningSettings", "PlanningTimeout", "UnsatisfiableScenario", "background_theory",
    "build_instance", "check_satisfiable",
]
