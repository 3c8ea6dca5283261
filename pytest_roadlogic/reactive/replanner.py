"""The rest of a scenario planned again from an observed state (``Replanner``).

A replan pins every vehicle's state at the observed step and plans the steps after it; the steps
before are the past, which no vehicle limit or kinematics binds (``asp/continuous/replan.lp``).
The run of the automaton so far is the monitor's: any run through the states the simulation had
at the past steps (the planner finds it, through the same guards); when there is none at the
steps (a guard that held only between two of them), the run the plan being driven took. How the
past is written for a planner is its encoding's (``Planner.replan``, ``planning.protocol.Past``). The
vehicle under test is not planned but predicted: it holds its observed speed and lane; when no
plan exists so, it is planned as any car could drive, and when none exists either, the scenario
cannot go on from here: the replan says so.
"""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass

from ..planning.plan import Plan, PlanState
from ..planning.protocol import Past
from ..simulation.interface import Replan

# seconds one replan may take, all its ways together: a replan that takes longer is no reaction
REPLAN_TIME_LIMIT = 5.0


@dataclass(frozen=True)
class _Mode:
    """One way to replan: the run so far through what was seen (else the plan's), the vehicle under
    test predicted (else planned), and the plan at least its old length (else any length)."""

    seen: bool
    predicted: bool
    full_length: bool


# every way a replan tries; Replanner.replan orders them: a phase keeping the end it was planned
# with first, then the run through what was seen before the old plan's (which only stands in for
# it), then the vehicle under test as the last replan that found a plan had it (predicted, else
# planned)
MODES = (
    _Mode(True, True, True),
    _Mode(True, False, True),
    _Mode(False, True, True),
    _Mode(False, False, True),
    _Mode(True, False, False),
    _Mode(False, False, False),
)
# the modes that ask least of a replan, one for each run so far: a plan of any other mode is a
# plan of one of these (the vehicle under test predicted is one way it may drive; a plan of the
# old length is a plan of some length)
WIDEST = frozenset(m for m in MODES if not m.predicted and not m.full_length)


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
        # the modes that found no plan from a step, and why, by whether the states there were
        # predicted (from an instant before the step) or observed at it: a later replan from the
        # same step does not try them again, unless it observes what an earlier one predicted (a
        # prediction carries the tracking's wobble a step ahead)
        self.failed: dict[tuple[int, bool], set[_Mode]] = {}
        self.why: dict[int, str] = {}
        self.stuck = False  # whether the last replan found no plan

    def replan(
        self,
        plan: Plan,
        step: int,
        observed: dict[str, PlanState],
        seen: dict[int, dict[str, PlanState]] | None = None,
        at: float | None = None,
    ) -> Replan:
        """The plan from ``step`` on, the vehicles as ``observed`` there (each vehicle's position along
        the road, lane and speed, as a plan states them) at the time ``at`` (default: the step's).
        ``seen``: the vehicles' states at the steps before (step -> vehicle -> state), every one of
        them, for the monitor's run; without them, or when no run goes through them, the run so far
        is ``plan``'s."""
        from ..planning import NoPlanError, PlanningTimeout, planner_for

        started = time.perf_counter()
        at = step * plan.dt if at is None else at
        why = self.why.get(step, "")
        complete = seen is not None and all(k in seen for k in range(step))
        failed = self.failed.setdefault((step, abs(at - step * plan.dt) > 1e-6), set())
        found_by: dict[_Mode, Plan] = {}

        def attempt(mode: _Mode) -> Plan | None:
            """The plan ``mode`` finds (None: none), remembered; ``failed`` keeps a mode without one,
            ``proved`` one that has none at all (not one that ran out of time)."""
            nonlocal why
            if mode in found_by:
                return found_by[mode]
            settings = dataclasses.replace(self.settings, time_limit=min(self.settings.time_limit, left))
            planner = planner_for(self.automaton, settings, self.seed)
            past = Past(
                step,
                observed,
                seen if mode.seen else None,
                tuple((transition, k) for k, transition in plan.transitions if k < step),
                self.dut,
                mode.predicted,
            )
            try:
                found = planner.replan(past, max(step + 1, plan.horizon) if mode.full_length else step + 1)
            except NoPlanError as error:
                why = self.why[step] = str(error)
                failed.add(mode)
                if not isinstance(error, PlanningTimeout):
                    proved.add(mode)
                return None
            if found is None:
                failed.add(mode)
            else:
                found_by[mode] = found
            return found

        order = sorted(MODES, key=lambda m: (not m.full_length, not m.seen, m.predicted != self.predicting))
        proved: set[_Mode] = set()
        if self.stuck:
            # the last replan found no plan: most likely none exists from here either, which the
            # widest modes alone prove (every other mode asks more of the same plan); when one of
            # them finds a plan, the order still decides which plan is taken
            widest = [m for m in order if m in WIDEST and not (m.seen and not complete) and m not in failed]
            for mode in widest:
                left = REPLAN_TIME_LIMIT - (time.perf_counter() - started)
                if left <= 0.05 or attempt(mode) is not None:
                    break
            if widest and proved >= set(widest):
                failed.update(MODES)
        for mode in order:
            if (mode.seen and not complete) or mode in failed:
                continue
            left = REPLAN_TIME_LIMIT - (time.perf_counter() - started)
            if left <= 0.05:
                why = why or f"no plan within the replanning time limit ({REPLAN_TIME_LIMIT:g} s)"
                break
            found = attempt(mode)
            if found is not None:
                self.predicting, self.stuck = mode.predicted, False
                return Replan(at, time.perf_counter() - started, found, mode.predicted, seen=mode.seen)
        self.stuck = True
        return Replan(
            at,
            time.perf_counter() - started,
            None,
            False,
            f"from the state at t={at:g} s the scenario cannot go on, even with {self.dut} driving as any car could: {why}",
            seen=False,
        )
