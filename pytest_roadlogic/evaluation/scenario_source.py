"""Where a campaign's job finds its scenario (``ScenarioSource``): plain data that travels to a
worker, which reads and checks the file itself, once per process however many of the scenario's
jobs it runs, and runs them with one ``runner.Runner`` per run settings, as a serial run does."""

from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..frontend.semantics.checked import CheckedScenario


@dataclass(frozen=True)
class ScenarioSource:
    """What ``pipeline.load_scenario`` takes: the file, the scenario's name (default: the first),
    a lane count, the dialect, the folders it may read (``confinement.ReadRoots``) and a map."""

    path: Path
    name: str | None = None
    lanes: int | None = None
    dialect: str | None = None
    roots: Any = None
    road_map: Path | None = None

    def load(self) -> CheckedScenario:
        """The checked scenario (``OscError`` when the file does not parse or check)."""
        return _loaded(self)

    def runner(self, settings: Any):
        """The ``runner.Runner`` of this scenario under ``settings`` (``RunSettings``), without
        explanations (a campaign counts a case without a plan; it does not explain it)."""
        return _runner(self, settings)


@functools.lru_cache(maxsize=8)
def _loaded(source: ScenarioSource) -> CheckedScenario:
    from ..pipeline import load_scenario

    return load_scenario(source.path, source.name, source.lanes, source.dialect, source.roots, source.road_map)


@functools.lru_cache(maxsize=8)
def _runner(source: ScenarioSource, settings: Any):
    from ..runner import Runner

    return Runner(source.load(), settings, explain=False)
