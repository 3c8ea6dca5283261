"""The continuous encoding's random start: draws from the seed as preferences of the search and
the linear program (the refined strategy's samples are independent instances, not the solver's habits)."""

from __future__ import annotations

import random

from ....logic.automaton import SymbolicAutomaton
from ....logic.guards import POSITION, TRAVELED, Bound
from ...facts import atom
from .instance import number
from .settings import ContinuousSettings


def start_preferences(automaton: SymbolicAutomaton, settings: ContinuousSettings, draw: random.Random) -> str:
    """A random start's draws as facts for ``asp/continuous/start.lp``, in a fixed order so that one
    seed gives one set: per vehicle a preferred lane (a heuristic) and, for a driving one, a
    preferred start speed (a preference of the linear program, which a scenario's own speeds
    override).

    A driving vehicle that changes lane prefers to end the plan in its drawn lane as well: one the
    scenario moves out of its lane (a dodge, an overtake) does not always go to the nearest lane,
    and one the scenario leaves in its lane is not pulled out of it.

    As the grid planner's random start does (asp/grid/preferences.lp), a driving vehicle keeps one
    drawn acceleration (-drift, 0 or +drift, an ``&drift`` preference of the linear program, within
    ``drift_speeds``) where it may change its speed (a construct of its own asks for a speed, or
    no plan holds it to what it is asked), and keeps its lane unless the scenario needs a change
    (asp/keep_lane.lp): else the smoothest plan holds every such vehicle at its start speed, and
    the solver's random signs move vehicles across lanes and back for nothing. A vehicle holding
    its speed that may brake for a vehicle ahead brakes only as much as that asks, not at its
    drawn rate.

    A transition whose guard pins a driving vehicle to a place (``pins``: dodge_obstacle's end,
    5-20 m past the parked car) is tried at its earliest step first; every other transition is
    tried as late as it can fire, so a plan stretched to its drawn length would meet such a guard
    only at its last step, the vehicle crawling towards it all the while.

    What each draw was measured to do, and the variants tried: docs/decisions.md."""
    low, high = settings.start_band()
    facts, drifts = ["% a random start's draws (asp/continuous/start.lp)"], []
    for vehicle in automaton.actors:
        name = atom(vehicle)
        facts.append(f"preferred_lane({name},{draw.randrange(automaton.lanes)}).")
        if vehicle not in automaton.stationary:
            facts.append(f"preferred_speed({name},{number(round(draw.uniform(low, high), 1))}).")
    # drawn after the lanes and start speeds, which a seed therefore gives as it did before drifts
    for vehicle in automaton.actors:
        if vehicle not in automaton.stationary and settings.drift:
            aim = draw.choice((-settings.drift, 0.0, settings.drift))
            drifts.append(f"drift({atom(vehicle)},{number(aim)}).")
    if drifts:
        slow, fast = settings.drift_speeds
        drifts.append(f"drift_speeds({number(slow)},{number(fast)}).")
    early = [
        f"pins({transition.id})."
        for transition in automaton.transitions
        if transition.source != automaton.initial
        and any(pins(bound, automaton.stationary) for bound in transition.guard.atoms())
    ]
    if early:
        early.append(f"pin_levels({settings.max_horizon + 1}).")
    return "\n".join([*facts, *drifts, *early]) + "\n"


def pins(bound: Bound, stationary: frozenset[str]) -> bool:
    """Whether ``bound`` pins a driving vehicle to a place on the road: a distance travelled, or a
    position that is absolute or taken from a stationary object. Met at a later step, such a
    bound leaves the vehicle the same distance for more time; one between two driving vehicles
    does not (they may drive on at any speed together)."""
    if bound.term.quantity == TRAVELED:
        return True
    return bound.term.quantity == POSITION and sum(actor not in stationary for actor in bound.term.actors) == 1


def farthest(points: list[float], low: float, high: float) -> float:
    """The value in [low, high] farthest from every one of ``points`` (the lowest of ties)."""
    inside = sorted(min(max(p, low), high) for p in points)
    candidates = [low, high] + [(a + b) / 2 for a, b in zip(inside, inside[1:])]
    return max(candidates, key=lambda c: (min(abs(c - p) for p in inside), -c)) if inside else low
