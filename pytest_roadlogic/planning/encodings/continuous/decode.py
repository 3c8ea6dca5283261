"""The continuous encoding's plan decoder: a model's atoms and the linear program's values to a ``Plan``."""

from __future__ import annotations

from fractions import Fraction

from ...facts import atom
from ...plan import Plan, PlanState
from .instance import brisk


def decode_plan(
    symbols,
    values: dict[str, object],
    horizon: int,
    index: int,
    automaton,
    settings,
    seed: int,
    stats: dict[str, float],
) -> Plan:
    """The plan in a model: lanes and transitions from its shown atoms, positions and speeds from
    the linear program's values (``values``: variable -> value), in metres and m/s."""
    lanes: dict[tuple[str, int], int] = {}
    transitions = []
    for symbol in symbols:
        if symbol.name == "lane":
            vehicle, lane, step = symbol.arguments
            name = vehicle.string if vehicle.type.name == "String" else vehicle.name
            lanes[(name, step.number)] = lane.number
        elif symbol.name == "fire":
            transitions.append((symbol.arguments[1].number, symbol.arguments[0].number))

    def value(variable: str, vehicle: str, step: int) -> float:
        raw = values.get(f"{variable}({atom(vehicle)},{step})")
        return float(Fraction(str(raw).strip('"'))) if raw is not None else 0.0

    states = {
        v: [
            PlanState(position=value("p", v, k), lane=lanes[(v, k)], speed=value("v", v, k)) for k in range(horizon + 1)
        ]
        for v in automaton.actors
    }
    return Plan(
        dt=settings.dt,
        lanes=automaton.lanes,
        states=states,
        transitions=sorted(transitions),
        seed=seed,
        index=index,
        stats=dict(stats),
        runup=0.0,
        stationary=tuple(v for v in automaton.actors if v in automaton.stationary),
        brisk=tuple(v for v in automaton.actors if v in brisk(automaton)),
        route=settings.route,
        origin=float(Fraction(str(values["origin"]).strip('"'))) if "origin" in values else None,
        side_routes={
            v: (side.route, float(Fraction(str(values.get(f"origin({k})", 0)).strip('"'))))
            for k, side in enumerate(settings.side_routes, 1)
            for v in automaton.actors
            if v in side.vehicles
        },
    )
