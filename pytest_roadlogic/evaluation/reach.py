"""Which buckets of a scenario's cover items no case can reach, and why (``unreachable``).

A bucket no sample hit is either not yet sampled or out of reach: its values lie outside the
range the scenario gives the parameter, or no plan meets the scenario with the parameter held to
the bucket. The second is a planning problem like any other (``sampling.within`` narrows the
parameter, the planner and its fallbacks answer), and its answer is a proof only when the planner
proves that no plan exists: a planner that ran out of time, or a limit of the tool that binds,
leaves the bucket merely not hit.
"""

from __future__ import annotations

from pathlib import Path

from ..frontend.semantics.checked import CheckedScenario
from ..frontend.semantics.coverage import Bucket, CoverItem


def unreachable(checked: CheckedScenario, item: CoverItem, labels: list[str], settings, seed: int) -> dict[str, str]:
    """Of ``item``'s buckets named in ``labels`` (those no case hit), the ones no case can reach,
    each with why: outside the parameter's range, or the planner's proof that no plan exists there
    (``settings``: the run's ``RunSettings``, ``seed``: its seed)."""
    parameter = next(p for p in checked.parameters if p.name == item.parameter)
    found = {}
    for bucket in item.buckets:
        if bucket.label not in labels:
            continue
        why = _outside(parameter, bucket, item) or _no_plan(checked, item, bucket, settings, seed)
        if why:
            found[bucket.label] = why
    return found


def _outside(parameter, bucket: Bucket, item: CoverItem) -> str:
    if bucket.choice is not None:
        if parameter.choices or parameter.low <= bucket.choice <= parameter.high:
            return ""
    elif bucket.high > parameter.low + 1e-9 and bucket.low < parameter.high + 1e-9:
        if bucket.low < parameter.high - 1e-9 or bucket.closed:
            return ""
    where = parameter.location
    return (
        f"outside the range of {parameter.name}, {item.shown(parameter.low)} to {item.shown(parameter.high)} "
        f"({Path(where.path).name}:{where.line})"
    )


def _no_plan(checked: CheckedScenario, item: CoverItem, bucket: Bucket, settings, seed: int) -> str:
    """The planner's proof that no plan exists with the parameter in ``bucket``, as its message
    says it ("" when a plan exists, or none was proved absent)."""
    from ..automaton import build_automaton
    from ..frontend.semantics.logical import WAY
    from ..planning import HorizonTooShort, NoPlanError, PlanningTimeout, settings_for
    from ..planning.fallbacks import planned
    from ..sampling import UnknownParameter, guided, on_ways, within

    parameter = next(p for p in checked.parameters if p.name == item.parameter)
    try:
        if parameter.kind == WAY:
            narrowed, declared = on_ways(checked, {item.parameter: bucket.choice}), {}
        elif bucket.choice is not None:
            narrowed, declared = guided(checked, {item.parameter: bucket.choice}, {}, {})
        else:
            narrowed, declared = within(checked, item.parameter, bucket.low, bucket.high)
    except UnknownParameter as error:  # the value breaks a keep() of the scenario, or the ways do not go together
        return str(error)
    planner_settings = settings_for(settings)
    if narrowed.route is not None:
        planner_settings = planner_settings.on_route(narrowed.route, narrowed.routes[1:])
    automaton = build_automaton(narrowed, values=declared)
    try:
        next(planned(lambda _: automaton, planner_settings, seed, 1))
    except (PlanningTimeout, HorizonTooShort):
        return ""
    except NoPlanError as error:
        return " ".join(str(error).split())
    return ""
