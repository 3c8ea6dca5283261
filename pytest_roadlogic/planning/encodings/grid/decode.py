"""The grid encoding's plan decoder: a model's atoms (cells, cells per step, steps) to a ``Plan``."""

from __future__ import annotations

import clingo

from ...plan import Plan, PlanState


def decode_plan(
    symbols: list[clingo.Symbol], horizon: int, index: int, automaton, settings, seed: int, stats: dict[str, float]
) -> Plan:
    """The plan in a model's shown atoms: ``pos``/``lane``/``vel`` per vehicle and step in cells,
    ``fire`` per transition, ``runup_time`` in steps, turned into metres, m/s and seconds."""
    s = settings
    cells: dict[tuple[str, int], dict[str, int]] = {}
    transitions: list[tuple[int, int]] = []
    runup_steps = 0
    for symbol in symbols:
        if symbol.name == "runup_time":
            runup_steps = symbol.arguments[0].number
        elif symbol.name in ("pos", "lane", "vel"):
            vehicle, value, step = symbol.arguments
            name = vehicle.string if vehicle.type == clingo.SymbolType.String else vehicle.name
            cells.setdefault((name, step.number), {})[symbol.name] = value.number
        elif symbol.name == "fire":
            transitions.append((symbol.arguments[1].number, symbol.arguments[0].number))
    states = {
        v: [
            PlanState(
                position=cells[(v, k)]["pos"] * s.grid,
                lane=cells[(v, k)]["lane"],
                speed=cells[(v, k)]["vel"] * s.grid / s.dt,
            )
            for k in range(horizon + 1)
        ]
        for v in automaton.actors
    }
    transitions.sort()
    stats = dict(stats)
    stats["horizon"] = horizon
    return Plan(
        dt=s.dt,
        lanes=automaton.lanes,
        states=states,
        transitions=transitions,
        seed=seed,
        index=index,
        stats=stats,
        runup=runup_steps * s.dt,
        runup_acceleration=s.runup_acceleration,
        stationary=tuple(v for v in automaton.actors if v in automaton.stationary),
    )
