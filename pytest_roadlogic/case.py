"""One concrete test case, exactly reproducible: what the plugin writes for a failure and ``roadlogic replay`` runs.

A run of the pipeline is a function of the scenario file, the sampled parameter values (refined
strategy) or the instance's index among the planner's plans (base strategy), the seed and the
planning settings. A ``Case`` records all of them, so that a failure found by Hypothesis in
``pytest scenarios/`` replays to the same plan and the same trace from one command line.
"""

from __future__ import annotations

import json
import shlex
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

REFINED, BASE = "refined", "base"


class CaseFileError(ValueError):
    """A case file that cannot be read: missing, not JSON, or not a case."""


@dataclass(frozen=True)
class Case:
    path: str
    scenario: str
    seed: int = 1
    strategy: str = REFINED
    values: dict[str, Any] = field(default_factory=dict)  # the sample (refined strategy)
    instance: int = 0  # which of the planner's instances, from 0 (base strategy)
    lanes: int | None = None
    max_horizon: int | None = None
    planning_time_limit: float | None = None
    simulation_time_limit: float | None = None
    max_tries: int = 5

    def settings(self):
        from .planning import PlanningSettings

        overrides = {"max_horizon": self.max_horizon, "time_limit": self.planning_time_limit}
        return PlanningSettings(**{k: v for k, v in overrides.items() if v is not None})

    def run(self, drivers=None):
        """The outcome of this case: the same plan and trace every time."""
        from .frontend import load_file
        from .pipeline import run_instances

        scenario = load_file(self.path, self.lanes).scenario(self.scenario)
        count = self.instance + 1 if self.strategy == BASE else 1
        outcome = None
        for outcome in run_instances(
            scenario, count, seed=self.seed, settings=self.settings(), max_tries=self.max_tries, drivers=drivers, values=self.values or None,
            simulation_time_limit=self.simulation_time_limit,
        ):
            pass
        if outcome is None or outcome.instance != count - 1:
            from .planning import NoPlanError

            raise NoPlanError(f"the planner has fewer than {self.instance + 1} plans for this scenario")
        return outcome

    def to_json(self) -> str:
        return json.dumps(asdict(self), indent=2, sort_keys=True)

    def save(self, path: str | Path) -> Path:
        from .artifacts import write_text

        Path(path).parent.mkdir(parents=True, exist_ok=True)
        return write_text(Path(path), self.to_json())

    @classmethod
    def load(cls, path: str | Path) -> "Case":
        try:
            return cls(**json.loads(Path(path).read_text()))
        except OSError as error:
            raise CaseFileError(f"cannot read the case file ({error.strerror})") from None
        except (json.JSONDecodeError, TypeError) as error:
            raise CaseFileError(f"not a case file written by pytest-roadlogic ({error})") from None

    def command(self, case_file: str | Path | None = None) -> str:
        """The shell command that replays this case: from its case file when there is one."""
        if case_file is not None:
            return f"roadlogic replay {shlex.quote(str(case_file))}"
        parts = ["roadlogic", "replay", self.path, "--scenario", self.scenario, "--seed", str(self.seed)]
        if self.strategy == BASE:
            parts += ["--strategy", BASE, "--instance", str(self.instance)]
        if self.values:
            parts += ["--values", json.dumps(self.values, sort_keys=True)]
        for option, value in (("--lanes", self.lanes), ("--horizon", self.max_horizon), ("--tries", self.max_tries)):
            if value is not None:
                parts += [option, str(value)]
        return shlex.join(parts)

