"""Why there is no plan: the planner's exceptions, importable without the solver (and clingo).

``NoPlanError``: none up to the horizon limit; ``PlanningTimeout``: the time limit ran out first (a
plan may still exist); ``HorizonTooShort``: the horizon limit, a setting, is what forbids a plan;
``UnsatisfiableScenario``: the scenario's own constraints cannot hold
together, with the groups that clash, each at its place in the file.
"""

from __future__ import annotations

from ..logic.guards import LANE, Bound


class NoPlanError(Exception):
    """No plan exists up to the horizon limit, or none was found within the time limit."""


class CannotPlanOnMap(NoPlanError):
    """An encoding that plans one straight road only was asked to plan on a map's route."""


class CannotReplan(NoPlanError):
    """An encoding that does not replan from an observed state was asked to."""


class PlanningTimeout(NoPlanError):
    """The time limit ran out before a plan was found (a plan may still exist)."""


class PlanningTooLarge(PlanningTimeout):
    """Grounding grew the process past the planner's memory limit: a limit of the tool, reported as
    a time limit is (the outcome "timed out"), with the memory named."""


class HorizonTooShort(NoPlanError):
    """The scenario's phases cannot all end within the horizon limit: a setting of the tool binds,
    not the scenario's constraints. The message names the setting and how to raise it."""

    def __init__(self, limit_steps: int, dt: float, needed_steps: int | None) -> None:
        from ..settings import MAX_HORIZON

        needed = (
            f"at least {needed_steps * dt:g} s" if needed_steps is not None else f"more than {4 * limit_steps * dt:g} s"
        )
        if (
            needed_steps is not None
            and needed_steps <= MAX_HORIZON
            or needed_steps is None
            and limit_steps < MAX_HORIZON
        ):
            what = "raise the limit with --roadlogic-horizon N (ini roadlogic_horizon) or --horizon N of roadlogic run, plan, replay and bench"
        else:  # past the longest horizon the tool plans: no setting helps
            what = f"the tool plans at most {MAX_HORIZON} steps: shorten the scenario's phases or split it"
        super().__init__(
            f"no plan within the horizon limit of {limit_steps} steps ({limit_steps * dt:g} s): the scenario's phases need {needed} together; {what}"
        )
        self.limit_steps, self.needed_steps = limit_steps, needed_steps


class MarginsBind(NoPlanError):
    """No plan keeps the planner's margins inside the scenario's ranges, and the plans that keep
    less of them were not accepted in simulation: a setting of the tool binds, not the scenario's
    constraints (which a plan meets at these values). The message names the settings."""

    def __init__(self, margins: str, thinned: str, explanation: str) -> None:
        super().__init__(
            f"no plan keeps the planner's margins inside the scenario's ranges ({margins}); plans with "
            f"{thinned} exist, so the scenario itself can be met at these values, but their simulation was "
            f"not accepted: the vehicles cannot track the scenario's edges that closely. This is the tool's "
            f"limit, not the scenario's: move the values off the edges of their ranges, or widen the ranges.\n"
            f"last simulation: {explanation}"
        )


class StepBinds(NoPlanError):
    """No plan in the planner's steps (``dt``), plans in half those steps exist, and their simulation
    was not accepted: the planning step binds (a setting of the tool), not the scenario's constraints."""


class LimitsBind(NoPlanError):
    """No plan exists within the planner's vehicle limits, one does with some of them relaxed, and
    its simulation was not accepted. ``limits`` names each setting with its value and the value it
    was relaxed to. ``beyond_a_car``: among them a real car's (jerk, accelerations, top speed), so
    no concrete scenario a car can drive has these values: the scenario cannot be instantiated here
    (with these settings, which the report names). Otherwise only the planner's spacing between
    cars binds: a setting of the tool."""

    def __init__(self, limits: list[str], explanation: str = "", beyond_a_car: bool = True) -> None:
        self.limits = limits
        self.beyond_a_car = beyond_a_car
        relaxed = " and ".join(limits)
        if beyond_a_car:
            text = (
                f"no concrete scenario within a real car's limits has these values: plans exist only with {relaxed}, "
                "beyond what a car can do (ContinuousSettings fields; their defaults are a real car's)"
            )
        else:
            text = (
                f"no plan within the planner's spacing between cars at these values, but one exists with {relaxed}: "
                "the scenario itself can be met here, a setting of the tool binds (a ContinuousSettings field)"
            )
        super().__init__(text + (f"; that plan's simulation was not accepted: {explanation}" if explanation else ""))


class UnsatisfiableScenario(NoPlanError):
    """The scenario cannot be met by any plan. ``conflicts`` holds groups of the scenario's
    constraints (bounds, durations) that cannot hold together, each with its source location; a
    group of one cannot hold on its own under the domain rules (speed limits, lanes, no collision).
    ``parameters``: the logical parameters used at each place (``SymbolicAutomaton.parameters``),
    so that a constraint is named with the parameters behind it. ``lanes``: the road's driving lanes,
    said with a group of lanes that no placement on them meets; ``on_the_map``, said with every
    group: where the map's routes let the vehicles be (``PlannerSettings.on_the_map``), which a
    group of speeds and durations may need more room than."""

    def __init__(
        self,
        message: str,
        conflicts: list[tuple],
        rules: str = "",
        parameters: dict | None = None,
        lanes: int | None = None,
        on_the_map: str = "",
    ) -> None:
        super().__init__(message)
        self.conflicts = conflicts
        self.rules = rules
        self.parameters = parameters or {}
        self.lanes = lanes
        self.on_the_map = on_the_map

    def _named(self, constraint) -> str:
        return _named(self.parameters.get(constraint.source, ()))

    def _alone(self, constraint) -> str:
        """A constraint with the parameters behind it: ``10 <= p(a) <= 20 (parameter gap)``."""
        named = self._named(constraint)
        return f"{constraint.as_written} ({named[2:]})" if named else constraint.as_written

    def report(self) -> str:
        """Each conflicting modifier as ``path:line:col: error:`` with its line and a caret."""
        from ..frontend.errors import Diagnostic, OscError

        diagnostics = []
        for group in self.conflicts:
            for member in group:
                if member.source is None:
                    continue
                others = [o for o in group if o is not member]
                if others:
                    together = ", ".join(
                        f"{o.as_written} (line {o.source.line}{self._named(o)})" if o.source else o.as_written
                        for o in others
                    )
                    message = f"{self._alone(member)} cannot hold together with {together}"
                else:
                    message = f"{self._alone(member)} cannot hold in any plan under the domain rules" + (
                        f" ({self.rules})" if self.rules else ""
                    )
                hint = None
                if member is group[0]:
                    hint = "the scenario can never be met; widen or remove one of them"
                    if self.lanes is not None and any(_places_in_a_lane(other) for other in group):
                        hint += f"; the road has {self.lanes} driving lane{'' if self.lanes == 1 else 's'}"
                    if self.on_the_map:
                        hint += f"; on the map, {self.on_the_map}"
                    if any(_numbers_a_lane(other) for other in group):
                        hint += f"; {LANE_NUMBERS}"
                diagnostics.append(Diagnostic(member.source, message, hint))
        return OscError(diagnostics).report() if diagnostics else str(self)


# a lane number's meaning depends on the dialect the file is read in: the hint for a clash of lanes
LANE_NUMBERS = (
    "lane numbers are read in the file's dialect: the standard's lane(1) is the rightmost lane, "
    "CARLA's (--dialect carla) the leftmost"
)


def _places_in_a_lane(constraint) -> bool:
    """Whether ``constraint`` is about a vehicle's lane (its number, or one beside another's)."""
    return isinstance(constraint, Bound) and constraint.term.quantity == LANE


def _numbers_a_lane(constraint) -> bool:
    """Whether ``constraint`` places a vehicle in a lane by its number (``lane(1)``)."""
    return _places_in_a_lane(constraint) and constraint.term.reference is None


def conflict_message(conflicts: list[tuple], parameters: dict | None = None) -> str:
    """The groups of constraints that cannot hold together, each at its place and with the logical
    parameters behind it (``parameters``: ``SymbolicAutomaton.parameters``, by place)."""
    parameters = parameters or {}
    lines = ["the scenario can never be met: these constraints cannot hold at the same time"]
    for group in conflicts:
        lines.append(
            "  " + " and ".join(f"{c.as_written} (at {c.source}{_named(parameters.get(c.source, ()))})" for c in group)
        )
    return "\n".join(lines)


def _named(names: tuple[str, ...]) -> str:
    """``; parameter start_gap`` after a constraint's place, or nothing when no parameter is behind it."""
    return f"; {'parameter' if len(names) == 1 else 'parameters'} {', '.join(names)}" if names else ""
