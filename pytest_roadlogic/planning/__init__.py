"""Stage 3: planning with clingo (``Planner``), from an automaton to ``Plan`` objects.

``Plan`` and ``PlanningSettings`` are plain data and import nothing heavy; the solver (and with it
clingo) is imported on first use of one of its names, so that reading a plan (the simulation, the
monitor, a report) does not load the solver.
"""

from ..settings import CONTINUOUS_HORIZON, DEFAULT_HORIZON, GRID, RunSettings
from .errors import (
    HorizonTooShort,
    LimitsBind,
    MarginsBind,
    NoPlanError,
    PlanningTimeout,
    StepBinds,
    UnsatisfiableScenario,
)
from .instance import PlanningSettings, build_instance
from .plan import Plan, PlanState

_SOLVER_NAMES = ("Planner", "background_theory", "check_satisfiable")


def settings_for(run: RunSettings, explain_unsatisfiable: bool = True):
    """The planner's settings for a run: ``ContinuousSettings`` or the grid's ``PlanningSettings``,
    with the run's horizon limit (the encoding's own when it gives none) and time limit. Here, not
    in ``settings``: the run's settings sit below the planner and must not import it."""
    if run.encoding == GRID:
        return PlanningSettings(
            max_horizon=run.max_horizon or DEFAULT_HORIZON,
            time_limit=run.planning_time_limit,
            explain_unsatisfiable=explain_unsatisfiable,
        )
    from .continuous import ContinuousSettings

    return ContinuousSettings(
        max_horizon=run.max_horizon or CONTINUOUS_HORIZON,
        time_limit=run.planning_time_limit,
        explain_unsatisfiable=explain_unsatisfiable,
    )


def planner_for(automaton, settings, seed: int = 0):
    """The planner of the encoding ``settings`` belong to: ``ContinuousSettings`` (asp/continuous.lp)
    or the grid's ``PlanningSettings`` (asp/dynamics.lp)."""
    from .continuous import ContinuousPlanner, ContinuousSettings
    from .solver import Planner

    if isinstance(settings, ContinuousSettings):
        return ContinuousPlanner(automaton, settings, seed)
    return Planner(automaton, settings, seed)


def __getattr__(name: str):
    if name in _SOLVER_NAMES:
        from . import solver

        return getattr(solver, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "HorizonTooShort",
    "LimitsBind",
    "MarginsBind",
    "NoPlanError",
    "Plan",
    "PlanState",
    "PlanningSettings",
    "PlanningTimeout",
    "StepBinds",
    "UnsatisfiableScenario",
    "build_instance",
    "planner_for",
    "settings_for",
    *_SOLVER_NAMES,
]
