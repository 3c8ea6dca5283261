"""What a planner encoding is, as the rest of the tool sees it: its settings, its planner, its name.

An encoding is a folder (``encodings/<name>/``) with its settings, its instance writer, its ``.lp``
files (``asp/<name>/``), its planner and its plan decoder, registered under its name
(``encodings.available()``; ``--roadlogic-encoding NAME``, ini ``roadlogic_encoding``, ``--encoding``
on the CLI). The pipeline, the fallbacks, the sampler and the reports speak only these protocols.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any, ClassVar, Protocol

from ..logic.automaton import SymbolicAutomaton
from .plan import Plan


class PlannerSettings(Protocol):
    """An encoding's settings: plain, frozen data (``dataclasses.replace`` makes variants)."""

    encoding: ClassVar[str]  # the name the encoding is registered under
    dt: float  # seconds per planning step
    max_horizon: int  # steps
    time_limit: float  # seconds for one planning
    explain_unsatisfiable: bool  # find the constraints that clash when there is no plan
    random_start: bool  # the refined strategy's draws from the seed
    position_margin: float  # metres planned inside a position range
    speed_margin: float  # m/s planned inside a speed range

    def resolution(self) -> dict[str | None, float]:
        """How wide a band a sampled value is narrowed to, per physical dimension."""
        ...

    def margins(self) -> dict[str | None, float]:
        """How far inside a range's edges the plan keeps, per physical dimension."""
        ...

    def thinned(self) -> PlannerSettings | None:
        """The settings of a second search with thinner margins, or None when there is none."""
        ...

    def summary(self, lanes: int) -> str:
        """The vehicle limits and bounds on a road of ``lanes`` lanes, for messages that blame them."""
        ...


class Planner(Protocol):
    """Plans for one automaton: lazily, shortest (or a random start's drawn length) first."""

    automaton: SymbolicAutomaton
    settings: PlannerSettings
    seed: int
    stats: dict[str, float]

    def plans(self, limit: int | None = None, deadline: float | None = None) -> Iterator[Plan]:
        """Plans; ``NoPlanError`` (a subclass saying why) when there is none. The first plan is
        due by ``deadline`` (``time.monotonic()``; default: ``settings.time_limit`` from now) or
        ``PlanningTimeout``; each later one has the whole time limit from when it is asked."""
        ...

    def first(self) -> Plan: ...

    def instance_program(self) -> str:
        """The scenario's instance as this encoding writes it (``roadlogic plan --show-asp``)."""
        ...

    def explain(self, deadline: float | None = None) -> tuple | None:
        """A smallest group of the scenario's constraints that no plan meets, or None."""
        ...


@dataclass(frozen=True)
class Encoding:
    """One registered encoding: its name, its settings class (light: no solver is imported with it),
    and ``planner()``, which imports and returns its planner class (with clingo) on first use."""

    name: str
    settings: type
    planner: Callable[[], Callable[[SymbolicAutomaton, Any, int], Planner]]
    description: str
