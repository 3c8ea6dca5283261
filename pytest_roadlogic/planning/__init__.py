"""Stage 3: planning with clingo, from an automaton to ``Plan`` objects.

One protocol (``protocol``: ``PlannerSettings``, ``Planner``, ``Encoding``), one core the encodings
share (``core``: the incremental horizon loop; ``diagnosis``: why there is no plan; ``facts``: the
automaton as facts; ``window``: the horizons the durations allow), one folder per encoding
(``encodings/continuous``, the default, and ``encodings/grid``), and the fallback policy
(``fallbacks``). ``Plan``, the settings and the errors are plain data and import nothing heavy; a
planner (and with it clingo) is imported on first use, so that reading a plan (the simulation, the
monitor, a report) does not load the solver.
"""

from ..settings import RunSettings
from .encodings import UnknownEncoding, available, encoding, of_settings
from .encodings.continuous import ContinuousSettings
from .encodings.grid import GridSettings
from .errors import (
    CannotPlanOnMap,
    CannotReplan,
    HorizonTooShort,
    LimitsBind,
    MarginsBind,
    NoPlanError,
    PlanningTimeout,
    StepBinds,
    UnsatisfiableScenario,
)
from .plan import Plan, PlanState
from .protocol import Encoding, Limit, Past, Planner, PlannerSettings


def settings_for(run: RunSettings, explain_unsatisfiable: bool = True) -> PlannerSettings:
    """The settings of the run's encoding, with the run's horizon limit (the encoding's own when it
    gives none) and time limit. Here, not in ``settings``: the run's settings sit below the
    planner and must not import it."""
    settings = encoding(run.encoding).settings(
        time_limit=run.planning_time_limit, explain_unsatisfiable=explain_unsatisfiable
    )
    import dataclasses

    if run.max_horizon:
        settings = dataclasses.replace(settings, max_horizon=run.max_horizon)
    return settings.with_road_speed(run.road_speed)


def planner_for(automaton, settings: PlannerSettings, seed: int = 0) -> Planner:
    """The planner of the encoding ``settings`` belong to."""
    return of_settings(settings).planner()(automaton, settings, seed)


def __getattr__(name: str):
    # the planners by class, for Python users and tests; each imports clingo
    if name in ("GridPlanner", "ContinuousPlanner"):
        return encoding(name.removesuffix("Planner").lower()).planner()
    if name == "check_satisfiable":
        from .diagnosis import check_satisfiable

        return check_satisfiable
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "CannotPlanOnMap",
    "CannotReplan",
    "ContinuousPlanner",
    "ContinuousSettings",
    "Encoding",
    "GridPlanner",
    "GridSettings",
    "HorizonTooShort",
    "Limit",
    "LimitsBind",
    "MarginsBind",
    "NoPlanError",
    "Past",
    "Plan",
    "PlanState",
    "Planner",
    "PlannerSettings",
    "PlanningTimeout",
    "StepBinds",
    "UnknownEncoding",
    "UnsatisfiableScenario",
    "available",
    "check_satisfiable",
    "encoding",
    "planner_for",
    "settings_for",
]
