"""A replan's facts for the continuous encoding (``asp/continuous/replan.lp``): the past as it ran.

In: a ``protocol.Past`` (the observed step, every vehicle's state there, the run so far as seen or
as the driven plan's transitions, the vehicle under test and whether it is predicted). Out: the
facts ``replan.lp`` reads, which pin the past and leave the steps after ``now`` to the planner.
"""

from __future__ import annotations

from ...facts import atom
from ...plan import PlanState
from ...protocol import Past
from .instance import number


def past_facts(past: Past) -> str:
    """``now/1``, ``observed/4``, ``self_driven/1``, ``predicted/1``, and the run so far: ``seen/5``
    at every step before ``now``, or ``kept_run`` with the plan's ``ran/2``."""
    lines = [f"now({past.now})."]
    if past.seen is None:
        lines.append("kept_run.")
        lines += [f"ran({transition},{at})." for transition, at in past.ran]
    else:
        for k in range(past.now):
            for vehicle, state in past.seen[k].items():
                lines.append(f"seen({atom(vehicle)},{k},{_state(state)}).")
    for vehicle, state in past.observed.items():
        lines.append(f"observed({atom(vehicle)},{_state(state)}).")
    lines.append(f"self_driven({atom(past.self_driven)}).")
    if past.predicted:
        lines.append(f"predicted({atom(past.self_driven)}).")
    return "\n".join(lines)


def _state(state: PlanState) -> str:
    return f"{number(state.position)},{number(max(state.speed, 0.0))},{state.lane}"
