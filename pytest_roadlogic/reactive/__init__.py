"""Reactive execution: the vehicle under test drives itself, and the scenario's other vehicles are
replanned from what it really does while the simulation runs (``ReactiveExecution``), each replan
the rest of the scenario solved again from the observed state (``Replanner``,
``asp/continuous/replan.lp``). Between planning and simulation: it asks the planner, and the
lockstep loop asks it."""

from .execution import ReactiveExecution, execution_for, replanning_seconds
from .replanner import Replan, Replanner

__all__ = ["ReactiveExecution", "Replan", "Replanner", "execution_for", "replanning_seconds"]
