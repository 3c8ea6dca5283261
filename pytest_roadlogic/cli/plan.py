"""``roadlogic plan``: solve a scenario's planning problem and print the plans as tables.

Exit codes: 0 at least one plan; 1 no plan exists; 2 the input is unusable."""

from __future__ import annotations

import argparse
import functools
import itertools
import time

from .commands import SUMMARIES
from .common import load_automaton, print_unasked, reporting_input_errors, run_settings, scenario_command, setting_flags


def add(commands) -> None:
    """The ``plan`` command's flags, and its action."""
    plan = scenario_command(commands, "plan", SUMMARIES["plan"])
    plan.add_argument("--plans", type=int, default=1, help="how many plans to enumerate (default 1)")
    setting_flags(plan, ("seed", "road-speed", "encoding", "horizon", "plan-timeout", "dut"))
    plan.add_argument("--show-asp", action="store_true", help="also print the generated instance program")
    plan.set_defaults(action=_plan)


def _plan(args: argparse.Namespace) -> int:
    from ..dut import UnderTest
    from ..planning import planner_for, settings_for
    from ..planning.fallbacks import fallback_needed, planned

    def solve():
        scenario, automaton = load_automaton(args)
        settings = run_settings(args)
        planner_settings = settings_for(settings)
        if scenario.route is not None:  # as a run plans: on the map's route (CannotPlanOnMap from the grid)
            planner_settings = planner_settings.on_route(scenario.route, scenario.routes[1:])
        # as a run plans: the vehicle under test drives itself (planned as braking as a car can)
        dut = UnderTest.of(settings).vehicle(automaton.actors)
        if dut is not None:
            planner_settings = planner_settings.with_self_driven(dut)
        planner = planner_for(automaton, planner_settings, settings.seed)
        if args.show_asp:
            print(planner.instance_program())
        started = time.perf_counter()
        # as a run plans: before "no plan", thinner margins, a finer step and relaxed limits (a plan
        # that needs one says so below); the constraints named when none has one clash for those too
        plans = planned(lambda _: automaton, planner_settings, settings.seed, args.plans)
        plans = list(itertools.islice(plans, args.plans))
        return scenario, automaton, plans, time.perf_counter() - started, planner_settings, settings.seed

    solved = reporting_input_errors(args, solve)
    if isinstance(solved, int):
        return solved
    scenario, automaton, plans, seconds, planner_settings, seed = solved
    events = {t.id: t.label for t in automaton.transitions}
    for plan in plans:
        print(
            f"plan {plan.index + 1} of scenario {scenario.name} (seed {plan.seed}): horizon {plan.horizon} steps of {plan.dt:g} s"
        )
        print(plan.table(functools.partial(scenario.registry.lane_number, lanes=plan.lanes)))
        if plan.route is not None and plan.origin is not None:
            # where the table's positions are: metres along each vehicle's route less its origin
            print(f"  route: {plan.route.turn or plan.route.name}; position 0 at {plan.origin:.1f} m along it")
            for vehicle, (route, origin) in plan.side_routes.items():
                print(f"  {vehicle}'s route: {route.turn or route.name}; its position 0 at {origin:.1f} m along it")
        for step, transition in plan.transitions:
            print(f"  step {step}: {events[transition]}")
        needed = fallback_needed(plan, lambda _: automaton, planner_settings, seed)
        if needed:
            print(f"  {needed}")
        print_unasked(plan, automaton, scenario.registry, indent="  ")
    print(f"{len(plans)} plan{'s' if len(plans) != 1 else ''} in {seconds:.3f} s")
    return 0
