"""The rest of a scenario planned again from an observed state (``Replanner``).

A replan keeps the run of the automaton so far (the transitions the plan being driven fired before
the observed step), pins every vehicle's observed position, speed and lane at that step, and plans
the steps after it; the steps before are the past, which no vehicle limit binds
(``asp/continuous/replan.lp``). The vehicle under test is not planned but predicted: it holds its
observed speed and lane; when no plan exists so, it is planned as any car could drive, and when
none exists either, the scenario cannot go on from here: the replan says so.
"""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass

from ..planning.encodings.continuous.instance import number
from ..planning.facts import atom
from ..planning.plan import Plan, PlanState

# seconds one replan may take: a replan that takes longer is no reaction
REPLAN_TIME_LIMIT = 5.0


@dataclass(frozen=True)
class Replan:
    """One replanning: when (the observed step's time), how long it took, the plan found (None:
    none), and how: the vehicle under test predicted at its speed, or planned as any car; why none."""

    time: float
    seconds: float
    plan: Plan | None
    predicted: bool = True
    why: str = ""


class Replanner:
    """Replans one scenario (its planning ``automaton`` and planner ``settings``) for the vehicle under test ``dut``."""

    def __init__(self, automaton, settings, seed: int, dut: str) -> None:
        self.automaton = automaton
        # a replan starts from what was observed: no random start of its own, and no time to explain
        self.settings = dataclasses.replace(
            settings,
            random_start=False,
            explain_unsatisfiable=False,
            time_limit=min(settings.time_limit, REPLAN_TIME_LIMIT),
        )
        self.seed = seed
        self.dut = dut
        self.predicting = True  # whether the last replan found a plan with the vehicle under test predicted

    def replan(self, plan: Plan, step: int, observed: dict[str, PlanState]) -> Replan:
        """The plan from ``step`` on, the run before it as ``plan``'s, the vehicles as ``observed``
        there (each vehicle's position along the road, lane and speed, as a plan states them)."""
        from ..planning import NoPlanError, planner_for

        started = time.perf_counter()
        why = ""
        # the plan's own length or longer first (a phase keeps the end it was planned with), the
        # vehicle under test predicted, unless the last replan had to plan it; then any length
        length = max(step + 1, plan.horizon)
        modes = [(True, length), (False, length)] if self.predicting else [(False, length), (True, length)]
        for predicted, shortest in dict.fromkeys([*modes, (False, step + 1)]):
            planner = planner_for(self.automaton, self.settings, self.seed)
            planner.instance += "\n" + self.facts(plan, step, observed, predicted)
            planner.shortest = shortest
            try:
                found = next(planner.plans(limit=1), None)
            except NoPlanError as error:
                why = str(error)
                continue
            if found is not None:
                self.predicting = predicted
                return Replan(step * plan.dt, time.perf_counter() - started, found, predicted)
        return Replan(
            step * plan.dt,
            time.perf_counter() - started,
            None,
            False,
            f"from the state at t={step * plan.dt:g} s the scenario cannot go on, even with {self.dut} driving as any car could: {why}",
        )

    def facts(self, plan: Plan, step: int, observed: dict[str, PlanState], predicted: bool) -> str:
        """The replan's facts (``asp/continuous/replan.lp``)."""
        lines = [f"now({step})."]
        lines += [f"ran({transition},{at})." for at, transition in plan.transitions if at < step]
        for vehicle, state in observed.items():
            lines.append(
                f"observed({atom(vehicle)},{number(state.position)},{number(max(state.speed, 0.0))},{state.lane})."
            )
        lines.append(f"self_driven({atom(self.dut)}).")
        if predicted:
            lines.append(f"predicted({atom(self.dut)}).")
        return "\n".join(lines)
