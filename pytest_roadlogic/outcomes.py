"""The words every report uses: how a concrete case ends, and the stages its time is spent in.

The plugin's summary and JUnit properties, the CLI, the bench's tables and the README all use
these, so that "conformant" means one thing everywhere:

- conformant: the monitor accepted a simulation of the case (within the tries a rejection allows);
- non-conformant: the monitor rejected the simulation of every plan tried;
- no plan: the planner found no plan for the case (for a sample: at those values);
- timed out: planning or simulation ran past its time limit.

With a vehicle under test (``dut``), which drives itself, a simulated case is instead:

- passed: the scenario happened (the monitor accepted it) and no oracle failed;
- failed: an oracle failed: the vehicle under test caused a collision, left the road, came closer
  in time or space than a threshold, or braked harder than one (``oracles``);
- not exercised: the scenario did not happen around it (the monitor rejected every try, or
  another vehicle ran into it): nothing was tested, and nothing failed.
"""

from __future__ import annotations

from collections import Counter

CONFORMANT, NON_CONFORMANT, NO_PLAN, TIMED_OUT = "conformant", "non-conformant", "no plan", "timed out"
PASSED, DUT_FAILED, NOT_EXERCISED = "passed", "failed", "not exercised"
CONFORMANCE_OUTCOMES = (CONFORMANT, NON_CONFORMANT, NO_PLAN, TIMED_OUT)
DUT_OUTCOMES = (PASSED, DUT_FAILED, NOT_EXERCISED)
OUTCOMES = (*CONFORMANCE_OUTCOMES, *DUT_OUTCOMES)
# what a case that ends so says about the item: none of these fail it alone (an item whose cases were
# mostly not exercised fails as a whole: ``mostly_not_exercised``)
FINE = (CONFORMANT, PASSED, NOT_EXERCISED)
# the cases whose scenario happened, which coverage counts (one with no plan, or not accepted, exercised nothing)
HAPPENED = (CONFORMANT, PASSED, DUT_FAILED)
STAGES = ("automaton", "planning", "simulation", "monitoring", "artifacts")
# the kinds of failure a report names (``runner.CaseResult.kind``): the scenario cannot be
# instantiated at the values, a limit of the tool binds there, or the simulation was not accepted
CANNOT_INSTANTIATE = "the scenario cannot be instantiated"
TOOL_LIMIT = "a limit of the tool binds"
NOT_ACCEPTED = "the simulation was not accepted"
THE_DUT_FAILED = "the vehicle under test failed"
DID_NOT_HAPPEN = "the scenario did not happen"


def simulated_outcome(accepted: bool, dut=None) -> str:
    """What a simulated case came to, from whether the monitor ``accepted`` it and the oracles'
    verdict on its vehicle under test (``oracles.DutReport``; None: there was none)."""
    if dut is None:
        return CONFORMANT if accepted else NON_CONFORMANT
    if dut.failed:
        return DUT_FAILED
    if dut.hit_by_others or not accepted:
        return NOT_EXERCISED
    return PASSED


def shown(counts) -> tuple[str, ...]:
    """The outcomes a table of ``counts`` (Counters or dicts by outcome) shows: every conformance
    outcome, and those of a vehicle under test where any case had one."""
    counts = list(counts)
    return (*CONFORMANCE_OUTCOMES, *(o for o in DUT_OUTCOMES if any(c.get(o, 0) for c in counts)))


def with_a_vehicle_under_test(outcomes: Counter) -> int:
    """How many of the counted cases were simulated with a vehicle under test driving itself."""
    return sum(outcomes[o] for o in DUT_OUTCOMES)


def mostly_not_exercised(outcomes: Counter) -> bool:
    """Whether most of the simulated cases of an item were not exercised: a test that never
    happened tested nothing, and is a failure of the test."""
    simulated = with_a_vehicle_under_test(outcomes)
    return simulated > 0 and outcomes[NOT_EXERCISED] * 2 > simulated


def key(outcome: str) -> str:
    """An outcome as an identifier (JUnit property names, counters): ``no plan`` -> ``no_plan``."""
    return outcome.replace(" ", "_").replace("-", "_")


class Tally:
    """Cases counted by outcome, and seconds summed by stage."""

    def __init__(self) -> None:
        self.cases = 0
        self.discarded = 0  # samples without a plan set aside (no_plan = discard); among the cases
        # samples whose values each have concrete scenarios, only not together (Runner.refined):
        # outside the logical scenario, so not among the cases; their seconds count
        self.set_aside = 0
        self.outcomes: Counter[str] = Counter()
        self.seconds: Counter[str] = Counter()

    def aside(self, seconds: dict[str, float]) -> None:
        self.set_aside += 1
        for stage in STAGES:
            self.seconds[stage] += seconds.get(stage, 0.0)

    def add(self, outcome: str, seconds: dict[str, float]) -> None:
        self.cases += 1
        self.outcomes[outcome] += 1
        for stage in STAGES:
            self.seconds[stage] += seconds.get(stage, 0.0)
