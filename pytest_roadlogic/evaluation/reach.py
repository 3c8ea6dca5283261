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
from ..frontend.semantics.coverage import Bucket, CoverItem, held


def open_questions(checked: CheckedScenario, coverage) -> list[tuple[CoverItem, list[str]]]:
    """Each cover item of ``checked`` with the labels of its buckets no case of ``coverage``
    (``coverage.ScenarioCoverage``) hit: what ``unreachable`` may be asked. A cross with a value
    of the run is left out: its combinations are not asked of the planner."""
    items = {i.name: i for i in checked.coverage}
    questions = []
    for item in checked.coverage:
        if item.crossed and any(items[name].observed is not None for name in item.crossed):
            continue
        missed = [label for label, hits in coverage.items[item.name].buckets.items() if hits == 0]
        if item.kind == "cover" and missed:
            questions.append((item, missed))
    return questions


def unreachable(checked: CheckedScenario, item: CoverItem, labels: list[str], settings, seed: int) -> dict[str, str]:
    """Of ``item``'s buckets named in ``labels`` (those no case hit), the ones no case can reach,
    each with why: outside a parameter's range, or the planner's proof that no plan exists with
    the parameter (a cross: each of its items' parameters) in the bucket (``settings``: the run's
    ``RunSettings``, ``seed``: its seed)."""
    items = {i.name: i for i in checked.coverage}
    found = {}
    for bucket in item.buckets:
        if bucket.label not in labels:
            continue
        if item.observed is not None:
            why = _no_plan_observed(checked, item, bucket, settings, seed)
            if why:
                found[bucket.label] = why
            continue
        holds = held(item, bucket, items)
        why = next(filter(None, (_outside(checked, part, b) for part, b in holds)), "")
        why = why or _no_plan(checked, holds, settings, seed)
        if why:
            found[bucket.label] = why
    return found


OPEN_END = 1e-3  # how much less an open end of a bucket is widened (metres, m/s)


def _observed_bounds(expression, low: float, high: float):
    """(guard term, low, high) that hold exactly when the value an item reads lies in [low, high]:
    a vehicle's position or speed, the difference of two vehicles', or ``a.space_gap(b)`` (their
    centres' distance, shifted by a car's length where the gap is not zero); None for any other."""
    from ..dimensions import CAR_LENGTH
    from ..frontend.semantics.coverage import space_gap_actors
    from ..logic.guards import POSITION, Term

    pair = space_gap_actors(expression)
    if pair is not None:
        reference, other = pair
        # the gap is 0 while the centres are less than a car's length apart
        return (
            Term(POSITION, other, reference),
            low + CAR_LENGTH if low > 0 else low - CAR_LENGTH,
            high - CAR_LENGTH if high < 0 else high + CAR_LENGTH,
        )
    term = _observed_term(expression)
    return (term, low, high) if term is not None else None


def _observed_term(expression):
    """The guard term (``logic.guards.Term``) of a value of the run an item reads: a vehicle's
    position or speed, or the difference of two vehicles'; None for any other."""
    from ..frontend import model
    from ..logic.guards import POSITION, SPEED, Term

    quantities = {"position": POSITION, "speed": SPEED}

    def split(name: model.Name) -> tuple[str, str | None]:
        actor, _, quantity = name.name.rpartition(".")
        return actor, quantities.get(quantity)

    if isinstance(expression, model.Name):
        actor, quantity = split(expression)
        return Term(quantity, actor) if quantity else None
    if (
        isinstance(expression, model.Binary)
        and expression.operator == "-"
        and isinstance(expression.left, model.Name)
        and isinstance(expression.right, model.Name)
    ):
        (actor, quantity), (reference, other) = split(expression.left), split(expression.right)
        return Term(quantity, actor, reference) if quantity and quantity == other else None
    return None


def _no_plan_observed(checked: CheckedScenario, item: CoverItem, bucket: Bucket, settings, seed: int) -> str:
    """The planner's proof that no plan puts the value ``item`` reads in ``bucket`` at its event:
    the bucket is one more bound of the guards of the transitions at that event ("" when a plan
    exists, none was proved absent, or the value is not one a guard can state)."""
    import dataclasses

    from ..automaton import build_automaton
    from ..logic.guards import POSITION, Bound, conjunction
    from ..planning import settings_for

    bounds = _observed_bounds(item.observed, bucket.low, bucket.high)
    if bounds is None:
        return ""
    automaton = build_automaton(checked)
    at = {t.id for t in automaton.transitions_at(*item.event)}
    if not at:
        return ""
    term, low, high = bounds
    # the planner plans inside every range by its margin, this bound's and the scenario's own
    # alike: widened by twice the thinnest margin it falls back to, the bucket loses no value a
    # run could take at the edge of a range the scenario gives, so "no plan" stays a proof; an
    # open end (the bucket's high, but for the last) by a hair less, so that a range the
    # scenario starts at that end proves the bucket below it out of reach
    thinnest = settings_for(settings).thinned() or settings_for(settings)
    margin = 2 * (thinnest.position_margin if term.quantity == POSITION else thinnest.speed_margin)
    bound = Bound(term, low - margin, high + margin - (0 if bucket.closed else OPEN_END), item.location)
    automaton.transitions = [
        dataclasses.replace(t, guard=conjunction([t.guard, bound])) if t.id in at else t for t in automaton.transitions
    ]
    return _proof(checked, automaton, settings, seed)


def _parameter(checked: CheckedScenario, item: CoverItem):
    return next(p for p in checked.parameters if p.name == item.parameter)


def _outside(checked: CheckedScenario, item: CoverItem, bucket: Bucket) -> str:
    parameter = _parameter(checked, item)
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


def _no_plan(checked: CheckedScenario, held: list[tuple[CoverItem, Bucket]], settings, seed: int) -> str:
    """The planner's proof that no plan exists with each parameter in its bucket (``held``), as
    its message says it ("" when a plan exists, or none was proved absent)."""
    from ..automaton import build_automaton
    from ..frontend.semantics.logical import WAY
    from ..sampling import UnknownParameter, guided, on_ways, within

    narrowed, declared = checked, {}
    try:
        for item, bucket in held:
            parameter = _parameter(checked, item)
            if parameter.kind == WAY:
                narrowed = on_ways(narrowed, {item.parameter: bucket.choice})
            elif bucket.choice is not None:
                narrowed, more = guided(narrowed, {item.parameter: bucket.choice}, {}, {})
                declared.update(more)
            else:
                narrowed, more = within(narrowed, item.parameter, bucket.low, bucket.high)
                declared.update(more)
    except UnknownParameter as error:  # the value breaks a keep() of the scenario, or the ways do not go together
        return str(error)
    return _proof(narrowed, build_automaton(narrowed, values=declared), settings, seed)


def _proof(checked: CheckedScenario, automaton, settings, seed: int) -> str:
    """The planner's proof that ``automaton`` (``checked`` asked more of) has no plan, as its
    message says it: "" when it has one, or when the planner ran out of time or a limit of the
    tool binds (no proof)."""
    from ..planning import HorizonTooShort, NoPlanError, PlanningTimeout, settings_for
    from ..planning.fallbacks import planned

    planner_settings = settings_for(settings)
    if checked.route is not None:
        planner_settings = planner_settings.on_route(checked.route, checked.routes[1:])
    try:
        next(planned(lambda _: automaton, planner_settings, seed, 1))
    except (PlanningTimeout, HorizonTooShort):
        return ""
    except NoPlanError as error:
        return " ".join(str(error).split())
    return ""
