"""The planner encodings behind one protocol: found by name, their instances facts only, their
rules in asp/, and a new encoding added without touching the tool."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.pipeline import load_scenario
from pytest_roadlogic.planning import (
    ContinuousSettings,
    Encoding,
    GridSettings,
    UnknownEncoding,
    available,
    encoding,
    planner_for,
    settings_for,
)
from pytest_roadlogic.settings import RunSettings

ROOT = Path(__file__).resolve().parents[2]
PAPER = sorted((ROOT / "scenarios").glob("*.osc"))


def test_every_built_in_encoding_is_found_by_its_name_with_its_settings():
    assert available()[:2] == ["continuous", "grid"]
    assert encoding("continuous").settings is ContinuousSettings
    assert encoding("grid").settings is GridSettings
    assert isinstance(settings_for(RunSettings(encoding="grid")), GridSettings)
    assert settings_for(RunSettings(encoding="continuous", max_horizon=30)).max_horizon == 30


def test_an_unknown_encoding_is_refused_naming_the_known_ones():
    with pytest.raises(UnknownEncoding, match="no planner encoding named 'nosuch'; available: continuous, grid"):
        encoding("nosuch")


@pytest.mark.parametrize("name", ["continuous", "grid"])
@pytest.mark.parametrize("path", PAPER, ids=lambda p: p.stem)
def test_an_instance_is_facts_and_constants_only_every_rule_is_in_asp(path, name):
    """The encoding is readable from asp/ alone: what a scenario adds has no rule, no constraint,
    no theory atom, no heuristic (a random start's draws included)."""
    automaton = build_automaton(load_scenario(path))
    settings = dataclasses.replace(encoding(name).settings(), random_start=True)
    planner = planner_for(automaton, settings, seed=1)
    for text in (planner.instance_program(), planner.preferences):
        statements = [line for line in text.splitlines() if line and not line.startswith(("%", "#program"))]
        assert statements
        for line in statements:
            assert ":-" not in line and "&" not in line and "#heuristic" not in line, line


def test_a_new_encoding_plugs_in_through_the_protocol_alone(monkeypatch):
    """A package's encoding: its settings name it, the registry finds it by that name, and the
    pipeline's settings_for and planner_for use it without knowing it (here, the grid's planner
    under another name)."""
    from importlib import metadata

    from pytest_roadlogic.planning.encodings.grid.planner import GridPlanner

    @dataclasses.dataclass(frozen=True)
    class CoarseSettings(GridSettings):
        encoding = "coarse"  # a class variable, as the protocol has it

    coarse = Encoding("coarse", CoarseSettings, lambda: GridPlanner, "the grid under another name")

    class Point:
        name, value = "coarse", "somewhere:COARSE"

        def load(self):
            return coarse

    real = metadata.entry_points
    monkeypatch.setattr(
        metadata,
        "entry_points",
        lambda **kw: [Point()] if kw.get("group") == "pytest_roadlogic.encodings" else real(**kw),
    )
    assert "coarse" in available()
    settings = settings_for(RunSettings(encoding="coarse"))
    assert isinstance(settings, CoarseSettings)
    plan = planner_for(build_automaton(load_scenario(ROOT / "scenarios" / "follow.osc")), settings, 1).first()
    assert plan.horizon >= 1
