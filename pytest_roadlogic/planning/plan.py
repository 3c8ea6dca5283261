"""A high-level plan: every vehicle's discrete state at every planning step."""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..roads.route import Route


@dataclass(frozen=True)
class PlanState:
    """One vehicle at one step, in SI units: longitudinal position of its centre, lane, speed."""

    position: float
    lane: int
    speed: float


@dataclass(frozen=True)
class PlanSnapshot(PlanState):
    """A vehicle at one step as a guard reads it: with the metres travelled since step 0."""

    traveled: float = 0.0


@dataclass
class Plan:
    dt: float
    lanes: int
    # vehicle -> its state at steps 0..horizon
    states: dict[str, list[PlanState]]
    # (step, transition id) for every automaton transition the plan takes, in order
    transitions: list[tuple[int, int]]
    seed: int = 0
    # seconds and acceleration of the run-up from standstill that the plan was made safe for
    runup: float = 7.0
    runup_acceleration: float = 2.0
    index: int = 0  # 0 for the first plan of a solve, 1 for the next one, ...
    stats: dict[str, float] = field(default_factory=dict)
    # vehicles that never move (stationary objects): simulated as standing obstacles
    stationary: tuple[str, ...] = ()
    # vehicles the scenario asks an acceleration of: their plan may step it from one step to the
    # next, and their drivers act on such a step at its instant (simulation.reference's onsets)
    brisk: tuple[str, ...] = ()
    # the route of a map it was planned on and is driven on (its settings' ``route``); None: the
    # straight road
    route: Route | None = field(default=None, compare=False, repr=False)
    # on a map's route: the metres along it of position 0 (asp/continuous/route.lp); None: the
    # straight road, or a plan that does not say
    origin: float | None = None
    # vehicles that drive other routes of the map than ``route`` (different ways through a
    # junction): vehicle -> (its route, the metres along it of its position 0); their positions
    # are along their own routes
    side_routes: dict[str, tuple[Route, float]] = field(default_factory=dict, compare=False, repr=False)

    @property
    def begins_by(self) -> float:
        """The latest time of its simulation's trace (s) at which the scenario begins: 0 without
        a run-up (the simulation starts in the plan's first state); after one, the run-up and one
        step (the vehicles reach their first states only as closely as they track the run-up)."""
        return self.runup + self.dt if self.runup > 0 else 0.0

    @property
    def horizon(self) -> int:
        return len(next(iter(self.states.values()))) - 1

    @property
    def vehicles(self) -> tuple[str, ...]:
        return tuple(self.states)

    def at(self, vehicle: str, step: int) -> PlanState:
        return self.states[vehicle][step]

    def snapshot(self, step: int) -> dict[str, PlanSnapshot]:
        """Every vehicle at ``step``, as the guards of the automaton read it."""
        return {
            v: PlanSnapshot(s[step].position, s[step].lane, s[step].speed, s[step].position - s[0].position)
            for v, s in self.states.items()
        }

    def to_dict(self) -> dict:
        return {
            "dt": self.dt,
            "lanes": self.lanes,
            "seed": self.seed,
            "runup": self.runup,
            "runup_acceleration": self.runup_acceleration,
            "index": self.index,
            "horizon": self.horizon,
            "transitions": [{"step": s, "transition": t} for s, t in self.transitions],
            "states": {v: [asdict(s) for s in states] for v, states in self.states.items()},
            "stats": self.stats,
            "stationary": list(self.stationary),
            **({"brisk": list(self.brisk)} if self.brisk else {}),
            **({"origin": self.origin} if self.origin is not None else {}),
            **(
                {
                    "side_routes": {
                        v: {"route": route.turn or route.name, "origin": origin}
                        for v, (route, origin) in self.side_routes.items()
                    }
                }
                if self.side_routes
                else {}
            ),
        }

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), indent=2)

    def table(self, lane_number=None) -> str:
        """The plan as a text table: one row per step, position/lane/speed per vehicle; lanes as
        ``lane_number(index)`` gives them (the scenario's dialect's numbering; default the
        pipeline's index, 0 the leftmost)."""
        header = ["step", "t[s]"] + [f"{v} pos/lane/speed" for v in self.vehicles]
        rows = [header]
        for step in range(self.horizon + 1):
            row = [str(step), f"{step * self.dt:g}"]
            for v in self.vehicles:
                s = self.at(v, step)
                lane = lane_number(s.lane) if lane_number is not None else s.lane
                row.append(f"{s.position:7.1f} / {lane} / {s.speed:4.1f}")
            rows.append(row)
        widths = [max(len(r[i]) for r in rows) for i in range(len(header))]
        return "\n".join("  ".join(cell.rjust(w) for cell, w in zip(r, widths)) for r in rows)
