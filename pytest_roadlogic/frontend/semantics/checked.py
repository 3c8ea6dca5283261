"""What the checker hands on: a checked file, and each checked scenario as one value.

Every stage after the checker takes a ``CheckedScenario``: the scenario model with its actors and
parameters sorted out, its parameter space (domains from ``keep``s, the file's own enums, relations
between parameters), the lane count of its road, and the registry of constructs it was checked
with. Nothing downstream recomputes any of these, so the plugin, the CLI, the bench and a replay
see the same logical parameters.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass, field
from typing import Any, Protocol

from .. import model
from ..errors import Diagnostic, OscError, SourceLocation
from .logical import LogicalParameter
from .parameters import ParameterSpace


class Registry(Protocol):
    """What the checker and the automaton ask of the constructs a scenario may use: each action and
    modifier by name (its signature, check and translation) and the guard of a condition. The
    constructs (``pytest_roadlogic.constructs``) provide it, one registry per dialect
    (``frontend.semantics.dialects``); the front end only names what it needs, so that it sits below them."""

    dialect: str

    def action(self, name: str) -> Any: ...

    def modifier(self, name: str) -> Any: ...

    def translated(self, kind: str) -> list[str]: ...

    def condition(self, expression: Any, env: dict, actors: Collection[str]) -> Any: ...


@dataclass(frozen=True)
class CheckedScenario:
    """One scenario, checked: the model, its parameter space, its road's lanes, its constructs."""

    scenario: model.Scenario
    space: ParameterSpace
    lanes: int
    registry: Registry
    sources: dict[str, str] = field(default_factory=dict, compare=False, repr=False)  # path -> text, for error reports
    # its logical parameters, each once (``frontend.semantics.logical``): what is sampled, planned and reported
    parameters: tuple[LogicalParameter, ...] = field(default=(), compare=False)
    # the road it runs on when it runs on a map (``roads.Route``: set_map or the map option); None:
    # the straight road of ``lanes`` lanes
    route: object = field(default=None, compare=False)
    # with several routes (vehicles that take different ways through a junction): every route,
    # ``route`` first (each route's ``crossers`` are the vehicles that drive it; a vehicle that
    # names none drives ``route``); else ``(route,)`` on a map, () on the straight road
    routes: tuple = field(default=(), compare=False)
    # the ways its paths may take through the map together (``roads.ways.Ways``), when they turn
    # at junctions: ``routes`` are the first; a sample may name others (``sampling.guided``)
    ways: object = field(default=None, compare=False)
    # its cover(...) and record(...) items (``semantics.coverage.CoverItem``), checked
    coverage: tuple = field(default=(), compare=False)

    @property
    def name(self) -> str:
        return self.scenario.name

    @property
    def path(self) -> str | None:
        return self.scenario.path

    @property
    def runnable(self) -> bool:
        """Whether it has a behavior to plan (a library scenario may declare none)."""
        return self.scenario.behavior is not None


@dataclass
class CheckedFile:
    """A file with its imports resolved: the scenarios it declares, checked, and every diagnostic."""

    file: model.OscFile
    diagnostics: list[Diagnostic]
    sources: dict[str, str]
    scenarios: tuple[CheckedScenario, ...] = ()

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == "error"]

    @property
    def warnings(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == "warning"]

    def scenario(self, name: str) -> CheckedScenario:
        """The scenario called ``name`` (KeyError when the file declares none)."""
        for checked in self.scenarios:
            if checked.name == name:
                return checked
        raise KeyError(name)

    def scenario_to_run(self, name: str | None = None) -> CheckedScenario:
        """The scenario called ``name``, or the first one with a behavior (KeyError for an unknown name)."""
        if name is not None:
            return self.scenario(name)
        for checked in self.scenarios:
            if checked.runnable:
                return checked
        raise OscError(
            [Diagnostic(SourceLocation(self.file.path, 1, 1), "the file declares no scenario with a `do` behavior")],
            sources=self.sources,
        )

    def raise_for_errors(self) -> None:
        if self.errors:
            raise OscError(self.errors, sources=self.sources)

    def report(self) -> str:
        return OscError(self.diagnostics, sources=self.sources).report() if self.diagnostics else ""
