"""Running the strategies: which concrete cases of a scenario to run, and how each ended.

- base: the planner's first N different plans (``Runner.base``);
- refined: N samples of the logical parameters drawn by Hypothesis (``Runner.refined``), either as
  a property search (the plugin: the loaded Hypothesis profile, the monitor's robustness as
  ``hypothesis.target``, a failure shrunk) or as a plain sample (the bench: generation only);
- replay: one recorded ``Case`` again, to the same plan and trace (``replay``).

The plugin, the CLI and the bench all run cases through here, so they agree on the outcome of a
case (``outcomes``), on the seconds per stage, and on how Hypothesis is set up.
"""

from __future__ import annotations

import contextlib
import math
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

from .blame import Blame
from .case import Case
from .dut import UnderTest
from .frontend import CheckedScenario
from .outcomes import (
    CANNOT_INSTANTIATE,
    CONFORMANT,
    DID_NOT_HAPPEN,
    DUT_FAILED,
    FINE,
    NO_PLAN,
    NON_CONFORMANT,
    NOT_ACCEPTED,
    NOT_EXERCISED,
    PASSED,
    STAGES,
    THE_DUT_FAILED,
    TIMED_OUT,
    TOOL_LIMIT,
    simulated_outcome,
)
from .pipeline import SimulatedInstance, run_instances
from .planning import HorizonTooShort, LimitsBind, NoPlanError, PlanningTimeout, UnsatisfiableScenario, settings_for
from .sampling import Shard
from .settings import BASE, CROSS_ENTROPY, DISCARD, HYPOTHESIS_SEARCH, REFINED, RunSettings
from .simulation import DriverFactory, SimulationTimeout, Simulator


@dataclass
class CaseResult:
    """How one concrete case ended: its outcome, the run (None without a simulation), and why."""

    case: Case
    outcome: str  # one of outcomes.OUTCOMES
    run: SimulatedInstance | None = None
    message: str = ""  # the monitor's explanation, or why there is no plan
    seconds: dict[str, float] = field(default_factory=dict)  # per stage, summed over tries
    error: NoPlanError | None = None  # the planner's, when there is no plan
    # the logical parameter whose sampled value alone has no concrete scenario (the others left to
    # their ranges), when the refined strategy found one (``blame.Blame``)
    culprit: str | None = None
    # no values at all have a plan: the scenario itself cannot be instantiated (``blame.Blame``)
    at_no_values: bool = False

    @property
    def failed(self) -> bool:
        """Whether this case alone fails its item (a case not exercised does not: see ``outcomes``)."""
        return self.outcome not in FINE

    @property
    def kind(self) -> str:
        """Which of the two kinds of failure this is, or neither (the words of reports and JUnit):
        the scenario cannot be instantiated at these values (its constraints clash, or only a plan
        beyond a real car's limits meets them: the message names the limits), a limit of the tool
        binds there (margins, planning step, spacing between cars, horizon, time limit: the message
        names the setting), or the simulation of the vehicles was not accepted."""
        if self.outcome in (CONFORMANT, PASSED):
            return "accepted"
        if self.outcome == NON_CONFORMANT:
            return NOT_ACCEPTED
        if self.outcome == DUT_FAILED:
            return THE_DUT_FAILED
        if self.outcome == NOT_EXERCISED:
            return DID_NOT_HAPPEN
        if isinstance(self.error, UnsatisfiableScenario) or (
            self.outcome == NO_PLAN and self.error is not None and type(self.error) is NoPlanError
        ):
            return CANNOT_INSTANTIATE
        if isinstance(self.error, LimitsBind) and self.error.beyond_a_car:
            return CANNOT_INSTANTIATE  # only plans no car can drive: the values ask too much, not the tool
        return TOOL_LIMIT


class Runner:
    """Runs the cases of one checked scenario under one ``RunSettings``.

    ``drivers`` drive chosen vehicles with the user's planners; ``simulator`` is the backend
    (default: the one ``settings.simulator`` names). ``explain`` makes a case without a plan carry
    the constraints that clash (seconds per case); the refined strategy never explains while it
    searches, and ``explain(case)`` asks for the one case reported.
    """

    def __init__(
        self,
        scenario: CheckedScenario,
        settings: RunSettings,
        drivers: DriverFactory | None = None,
        simulator: Simulator | None = None,
        explain: bool = True,
    ) -> None:
        self.scenario = scenario
        self.settings = settings
        self.drivers = drivers
        self._simulator = simulator
        self.explain_no_plan = explain
        self.blame = Blame(scenario, settings)  # which value to blame for a sample without a plan

    @property
    def simulator(self) -> Simulator:
        if self._simulator is None:
            from .simulation.backends import simulator

            self._simulator = simulator(self.settings.simulator)
        return self._simulator

    def case(self, **identity) -> Case:
        return Case.of(self.scenario.path or "<string>", self.scenario.name, self.settings, **identity)

    # ---------------------------------------------------------------- strategies

    def run_case(self, case: Case, explain: bool | None = None, fallbacks: bool = True) -> CaseResult:
        """One case: a sample (refined) or the planner's instance ``case.instance`` (base).
        ``fallbacks``: see ``pipeline.run_instances``."""
        explain = self.explain_no_plan if explain is None else explain
        count = case.instance + 1 if case.strategy == BASE else 1
        started = time.perf_counter()
        last = None
        try:
            for last in self._instances(count, case.values or None, explain, fallbacks):  # noqa: B007 (the last one is what counts)
                pass
        except (NoPlanError, SimulationTimeout) as error:
            return _failure(case, error, started)
        if last is None or last.instance != count - 1:
            error = NoPlanError(f"the planner has fewer than {count} plans for this scenario")
            return _failure(case, error, started)
        return _result(case, last)

    def base(self, count: int | None = None) -> Iterator[CaseResult]:
        """The planner's first ``count`` (default: ``settings.examples``) different plans, each a case.

        A planning failure ends the sequence with one case of that outcome (the planner's search
        is gone with it); a planner that runs out of plans ends it early.
        """
        count = self.settings.examples if count is None else count
        index = 0
        started = time.perf_counter()
        try:
            for outcome in self._instances(count, None, self.explain_no_plan):
                yield _result(self.case(strategy=BASE, instance=outcome.instance), outcome)
                index, started = outcome.instance + 1, time.perf_counter()
        except (NoPlanError, SimulationTimeout) as error:
            yield _failure(self.case(strategy=BASE, instance=index), error, started)

    def refined(
        self,
        each: Callable[[CaseResult], None],
        count: int | None = None,
        search: bool = True,
        key: bytes | None = None,
        discarded: Callable[[CaseResult], None] = lambda result: None,
        set_aside: Callable[[CaseResult], None] = lambda result: None,
        sampling_seed: int | str | None = None,
        shard: Shard | None = None,
        keep_examples: bool = True,
    ) -> None:
        """``count`` (default: ``settings.examples``) samples drawn by Hypothesis, each run and handed to ``each``.

        ``shard``: draw only the samples of one shard of the scenario (``sampling.Shard``), and its
        share of ``count``; every shard draws with the same seed, so that together the shards run
        what one item would draw, split.

        ``search``: a property search, as the plugin runs it: the loaded Hypothesis profile, the
        monitor's robustness fed to ``hypothesis.target``, and a failure that ``each`` raises shrunk
        to the simplest values that still fail (``key`` keeps one example database entry per
        scenario); ``settings.search`` says who draws the samples: Hypothesis, or a backend of
        ``falsification`` (uniformly at random, or steered by cross-entropy from the first sample)
        whose failure Hypothesis then shrinks. With ``settings.no_plan == "discard"``, a sample without a plan goes to
        ``discarded`` and is rejected as ``assume(False)`` rejects one (Hypothesis's health check
        stops an item whose samples mostly have none). Otherwise a sample whose constraints clash
        fails only when one of its values alone has no plan (``CaseResult.culprit``); one whose
        values each have plans, only not together, goes to ``set_aside`` and is rejected too.
        Without ``search``, a plain sample, as the bench draws it: the default profile (a CI
        profile's derandomize would override the seed), generation only, no database; the same seed
        draws the same samples everywhere. ``sampling_seed`` (pytest's ``--hypothesis-seed``) draws the
        samples instead of ``settings.seed``, which still fixes solving and simulation.
        ``keep_examples=False``: a search without the example database (it neither replays nor
        saves a failure: a campaign's searches are fixed by their seeds alone). Each sample's
        outcome, tries and kind of failure are Hypothesis events (``--hypothesis-show-statistics``).
        """
        if count is not None and count < 1:
            return  # nothing to draw (a bench's --refined 0): Hypothesis takes no max_examples of 0
        import hypothesis
        from hypothesis import HealthCheck, Phase

        from .sampling import plain_draw, strategy

        shard = shard or Shard()
        count = shard.examples(self.settings.examples if count is None else count)
        done = 0
        discard = self.settings.no_plan == DISCARD

        def example(values: dict[str, Any]) -> None:
            nonlocal done
            if not search and done >= count:
                return
            done += 1
            if search and discard:
                result = self.run_case(self.case(strategy=REFINED, values=values), explain=False, fallbacks=True)
                _events(result)
                if result.outcome == NO_PLAN:
                    discarded(result)
                    hypothesis.reject()  # as assume(False): the sample does not count, and too many trip the health check
            else:
                result = self.sample(values)
                if search:
                    _events(result)
            if result.kind == CANNOT_INSTANTIATE:
                if search:
                    hypothesis.event(
                        "no plan",
                        "no value alone has a plan"
                        if result.at_no_values
                        else f"{result.culprit} alone has none"
                        if result.culprit
                        else "only the values together have none (set aside)",
                    )
                if set_aside_sample(result):
                    done -= 1
                    set_aside(result)
                    hypothesis.reject()
            if search and result.run is not None and result.run.dut is not None:
                # falsification: steer toward the vehicle under test's failure, the oracle nearest to failing
                hypothesis.target(-result.run.dut.margin(), label="closeness of the vehicle under test to failing")
            elif search and result.run is not None and math.isfinite(result.run.verdict.robustness):
                hypothesis.target(-result.run.verdict.robustness, label="closeness to failure (-robustness)")
            each(result)

        if key is not None:
            # one database entry per scenario, though every scenario runs this same function (the
            # attribute Hypothesis's own pytest integration sets for parametrized tests)
            example._hypothesis_internal_add_digest = key  # type: ignore[attr-defined]
        if search:
            profile = hypothesis.settings()
            if not keep_examples:
                profile = hypothesis.settings(profile, database=None)
            chosen = hypothesis.settings(
                # one failure per item: the report is about its shrunk case, whatever kind it is
                profile,
                max_examples=count,
                deadline=None,
                print_blob=False,
                report_multiple_bugs=False,
                # the explain phase traces every line while shrinking (sys.settrace: each case about
                # five times slower) to say which lines of the test ran: here the tool's own lines,
                # nothing a scenario's author can use
                phases=[phase for phase in profile.phases if phase != Phase.explain],
                # samples discarded for having no plan are what the filter health check is for
                suppress_health_check=[
                    *profile.suppress_health_check,
                    HealthCheck.too_slow,
                    *([] if discard else [HealthCheck.filter_too_much]),
                ],
            )
        else:
            chosen = plain_draw(count)
        seed = self.settings.seed if sampling_seed is None else sampling_seed
        drawing = contextlib.nullcontext()
        if search and self.settings.search != HYPOTHESIS_SEARCH:
            from .falsification import backend, untraced

            # the random or cross-entropy search: a backend of Hypothesis's that draws the choices
            chosen = hypothesis.settings(chosen, backend=backend(seed, self.settings.search == CROSS_ENTROPY))
            drawing = untraced()
        with drawing:
            hypothesis.seed(seed)(chosen(hypothesis.given(strategy(self.scenario, shard))(example)))()

    def sample(self, values: dict[str, Any]) -> CaseResult:
        """One sample of the refined strategy, as the search and the bench run it (a sample
        without a plan is discarded before this where ``no_plan`` says discard): run without its
        explanation; without a plan because its constraints clash, blamed on the value that alone
        has none (``CaseResult.culprit``), if one does (``set_aside_sample`` says whether to set
        it aside)."""
        case = self.case(strategy=REFINED, values=values)
        result = self.run_case(case, explain=False, fallbacks=self.settings.no_plan == DISCARD)
        if result.kind == CANNOT_INSTANTIATE:
            result = self.blame.blamed(case, result, lambda again: self.run_case(again, explain=False))
        return result

    def explained(self, result: CaseResult) -> CaseResult:
        """A case without a plan, run again to say why: the constraints that cannot hold together
        (the pipeline has already tried thinner margins and relaxed vehicle limits, and names
        the limit that binds when only those plans exist: ``LimitsBind``). Other results come back
        as they are."""
        if result.outcome != NO_PLAN:
            return result
        again = self.run_case(result.case, explain=True)
        if again.outcome != NO_PLAN:
            return result
        again.culprit, again.at_no_values = result.culprit, result.at_no_values
        return again

    # ---------------------------------------------------------------- the pipeline

    def _instances(self, count: int, values, explain: bool, fallbacks: bool = True) -> Iterator[SimulatedInstance]:
        return run_instances(
            self.scenario,
            count,
            seed=self.settings.seed,
            settings=settings_for(self.settings, explain),
            max_tries=self.settings.tries,
            drivers=self.drivers,
            values=values,
            simulation_time_limit=self.settings.simulation_time_limit,
            simulator=self.simulator,
            fallbacks=fallbacks,
            under_test=UnderTest.of(self.settings),
        )


def set_aside_sample(result: CaseResult) -> bool:
    """Whether a sample is set aside rather than counted: each of its values has concrete
    scenarios, only not together (no plan, and no value alone to blame): a combination outside the
    logical scenario, drawn by independent sampling and set aside as rejection sampling sets one
    aside (the README's rule)."""
    return (
        bool(result.case.values)
        and result.kind == CANNOT_INSTANTIATE
        and result.culprit is None
        and not result.at_no_values
    )


def replay(
    case: Case, drivers: DriverFactory | None = None, simulator: Simulator | None = None, roots=None
) -> CaseResult:
    """Run a recorded case again: the same plan and the same trace (with the same drivers).
    ``roots`` (``confinement.ReadRoots``): where the scenario's imports may be read from."""
    from .frontend import load_file

    settings = case.settings
    scenario = load_file(
        case.path, settings.lanes, dialect=settings.dialect, roots=roots, road_map=settings.road_map
    ).scenario(case.scenario)
    return Runner(scenario, settings, drivers, simulator).run_case(case)


def _events(result: CaseResult) -> None:
    """A sample's outcome for Hypothesis's statistics: what a tester reads to see where the examples went."""
    import hypothesis

    hypothesis.event("outcome", result.outcome)
    if result.run is not None:
        hypothesis.event("plans tried", str(result.run.tries))
    elif result.failed:
        hypothesis.event("without a simulation", result.kind)


def _result(case: Case, outcome: SimulatedInstance) -> CaseResult:
    seconds = {stage: outcome.seconds.get(stage, 0.0) for stage in STAGES}
    report = outcome.dut
    word = simulated_outcome(outcome.verdict.accepted, report)
    if word == DUT_FAILED:
        why = f"{report.vehicle}: " + "; ".join(report.failures)
    elif word == NOT_EXERCISED and report.hit_by_others:
        why = f"another vehicle ran into {report.vehicle}: " + "; ".join(str(c) for c in report.hit_by_others)
    elif word in (NON_CONFORMANT, NOT_EXERCISED):
        why = "\n".join(filter(None, (outcome.verdict.explain(), outcome.simulation.unfollowed())))
    else:
        why = ""
    return CaseResult(case, word, outcome, why, seconds)


def _failure(case: Case, error: Exception, started: float) -> CaseResult:
    """A case that ended without a verdict; its time counts as planning (where it was spent, but
    for a simulation that timed out)."""
    elapsed = time.perf_counter() - started
    seconds = {stage: 0.0 for stage in STAGES}
    if isinstance(error, SimulationTimeout):
        seconds["simulation"] = elapsed
        return CaseResult(
            case,
            TIMED_OUT,
            message=f"simulation timed out: {error} (a limit of the tool: raise it with --roadlogic-sim-timeout, or --sim-timeout on the command line)",
            seconds=seconds,
        )
    seconds["planning"] = elapsed
    if isinstance(error, PlanningTimeout):
        return CaseResult(
            case,
            TIMED_OUT,
            message=f"planning timed out: {error} (a limit of the tool, not the scenario: raise it with --roadlogic-plan-timeout, or --plan-timeout on the command line)",
            seconds=seconds,
            error=error,
        )
    if isinstance(error, UnsatisfiableScenario):
        return CaseResult(case, NO_PLAN, message=error.report(), seconds=seconds, error=error)
    if isinstance(error, HorizonTooShort):
        return CaseResult(case, NO_PLAN, message=str(error), seconds=seconds, error=error)
    return CaseResult(case, NO_PLAN, message=f"no plan: {error}", seconds=seconds, error=error)
