"""One concrete test case, exactly reproducible: what the plugin writes for a failure and ``roadlogic replay`` runs.

A run of the pipeline is a function of the scenario file, the sampled parameter values (refined
strategy) or the instance's index among the planner's plans (base strategy), the seed, the
planning settings and the simulation backend. A ``Case`` records all of them, so that a failure
found by Hypothesis in ``pytest scenarios/`` replays to the same plan and the same trace from one
command line (``runner.replay``). It is plain data: reading one imports nothing heavy.
"""

from __future__ import annotations

import json
import shlex
from dataclasses import asdict, dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from .confinement import ReadRoots, UnreadableFile, project_root, read_bounded, regular_file_problem, shown
from .settings import (
    BASE,
    CONTINUOUS,
    DEFAULT_SIMULATOR,
    DUT_NONE,
    GRID,
    OPTIONS_BY_NAME,
    REFINED,
    STANDARD_DIALECT,
    OptionError,
    RunSettings,
    speed_band,
)


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
    road_map: str | None = None  # the map option's OpenDRIVE file (a scenario's own set_map is in its file)
    road_speed: str | None = None  # "LOW..HIGHmps" (settings.speed_band); None in older case files: the default
    dialect: str = STANDARD_DIALECT
    encoding: str | None = None  # None in case files older than the continuous encoding: the grid's
    max_horizon: int | None = None
    planning_time_limit: float | None = None
    simulation_time_limit: float | None = None
    max_tries: int = 5
    simulator: str = DEFAULT_SIMULATOR
    # vehicle -> "module:QualName" of the driver a pytest_roadlogic_driver hook gave it (the others
    # are the simulator's own): a replay builds the same ones or refuses (simulation/named_drivers.py)
    drivers: dict[str, str] = field(default_factory=dict)
    # the vehicle under test and its oracles (settings.RunSettings.under_test); None in older case files: none
    dut: str | None = None
    dut_driver: str | None = None
    replan_period: float | None = None
    min_ttc: float | None = None
    min_gap: float | None = None
    max_decel: float | None = None
    versions: dict[str, str] = field(default_factory=dict)  # of the packages a run depends on, when written

    @classmethod
    def of(cls, path: str | Path, scenario: str, settings: RunSettings, **identity) -> Case:
        """The case of ``scenario`` in ``path`` under ``settings``; ``identity`` gives the strategy,
        the values (refined) or the instance (base)."""
        return cls(
            path=str(path),
            scenario=scenario,
            road_speed=f"{settings.road_speed[0]!r}..{settings.road_speed[1]!r}mps",
            encoding=settings.encoding,
            max_tries=settings.tries,
            dut=settings.dut,
            **{name: getattr(settings, name) for name in _COPIED},
            **identity,
        )

    @property
    def planning_encoding(self) -> str:
        """The encoding that planned this case (a case file without one predates the continuous one)."""
        return self.encoding or GRID

    def settings(self) -> RunSettings:
        """The run settings this case was made under (defaults where an older case file is silent)."""
        given = {
            "strategy": self.strategy,
            "road_speed": speed_band(self.road_speed) if self.road_speed is not None else None,
            "encoding": self.planning_encoding,
            "tries": self.max_tries,
            # a case file from before vehicles under test drove every vehicle by its plan
            "dut": self.dut if self.dut is not None else DUT_NONE,
            **{name: getattr(self, name) for name in _COPIED},
        }
        return RunSettings(**{k: v for k, v in given.items() if v is not None})

    def within(self, limits: RunSettings) -> Case:
        """This case with its time limits no higher than ``limits``' (the command line's or the
        session's): a case file is data, and ``"planning_time_limit": 1e9`` must not raise what the
        user allows (``--plan-timeout 5`` had not lowered it)."""
        return replace(
            self,
            planning_time_limit=min(self.planning_time_limit or limits.planning_time_limit, limits.planning_time_limit),
            simulation_time_limit=min(
                self.simulation_time_limit or limits.simulation_time_limit, limits.simulation_time_limit
            ),
        )

    def scenario_file(self, case_file: str | Path | None = None, roots: ReadRoots | None = None) -> Path:
        """Where the scenario is: ``path`` relative to the working folder, else to a folder above the
        case file (the plugin records it relative to the rootdir, and writes the case file under it).

        A case file is data from anywhere (a bug report, a pull request): its ``path`` must be
        relative, without ``..``, and lead to a file inside ``roots`` (default: the project's root);
        anything else raises ``CaseFileError`` and is never opened.
        """
        roots = roots or ReadRoots.of(project_root())
        path = Path(self.path)
        if path.is_absolute() or ".." in path.parts or not self.path.strip() or path.suffix != ".osc":
            raise CaseFileError(
                f"the scenario path {shown(repr(self.path[:200]))} is not a relative path to an .osc file inside the "
                "project; a case file names its scenario relative to the rootdir (as pytest wrote it)"
            )
        candidates = [path] + (
            [folder / path for folder in Path(case_file).resolve().parents] if case_file is not None else []
        )
        for candidate in candidates:
            if roots.allows(candidate) and regular_file_problem(candidate) is None:
                return candidate
        raise CaseFileError(
            f"the scenario {shown(repr(self.path[:200]))} is not in the folders the tool reads ({roots.describe()}); run the "
            "replay from the project's folder (one with a pyproject.toml, setup.cfg, tox.ini, pytest.ini or .git: with none "
            "above the working folder only the case file's folder is read), or name the folder that holds it with "
            "--allow-read DIR"
        )

    def version_differences(self) -> list[str]:
        """What differs between the versions this case was written with and the installed ones."""
        now = installed_versions()
        return [
            shown(f"{name[:60]} {was[:60]} (now {now.get(name, 'not installed')})")
            for name, was in sorted(self.versions.items())
            if name in (*VERSIONED, "python") and now.get(name) != was  # only what a replay depends on
        ]

    def to_json(self) -> str:
        return json.dumps(asdict(self), indent=2, sort_keys=True)

    def save(self, path: str | Path) -> Path:
        from .artifacts.files import write_text

        Path(path).parent.mkdir(parents=True, exist_ok=True)
        return write_text(Path(path), self.to_json())

    @classmethod
    def load(cls, path: str | Path) -> Case:
        try:
            data = json.loads(read_bounded(path, MAX_CASE_BYTES).decode("utf-8"))
            known = {f.name for f in fields(cls)}
            if not isinstance(data, dict) or not {"path", "scenario"} <= set(data) or set(data) - known:
                raise TypeError(f"expected the keys {', '.join(sorted(known))}")
            return cls(**_check_kinds(data))
        except UnreadableFile as error:
            raise CaseFileError(f"cannot read the case file: {error}") from None
        except (json.JSONDecodeError, TypeError, UnicodeDecodeError, RecursionError) as error:
            raise CaseFileError(f"not a case file written by pytest-roadlogic ({error})") from None
        except OptionError as error:
            raise CaseFileError(f"a value the tool cannot run with: {error}") from None

    def command(self, case_file: str | Path | None = None) -> str:
        """The shell command that replays this case: from its case file when there is one."""
        if case_file is not None:
            return f"roadlogic replay {shlex.quote(str(case_file))}"
        parts = ["roadlogic", "replay", self.path, "--scenario", self.scenario, "--seed", str(self.seed)]
        if self.strategy == BASE:
            parts += ["--strategy", BASE, "--instance", str(self.instance)]
        if self.values:
            parts += ["--values", json.dumps(self.values, sort_keys=True)]
        for option, value in (
            ("--lanes", self.lanes),
            ("--map", self.road_map),
            ("--road-speed", self.road_speed),
            ("--dialect", None if self.dialect == STANDARD_DIALECT else self.dialect),
            ("--encoding", None if self.planning_encoding == CONTINUOUS else self.planning_encoding),
            ("--horizon", self.max_horizon),
            ("--tries", self.max_tries),
            ("--dut", self.dut),
            ("--dut-driver", self.dut_driver),
            ("--replan-period", self.replan_period),
            ("--min-ttc", self.min_ttc),
            ("--min-gap", self.min_gap),
            ("--max-decel", self.max_decel),
        ):
            if value is not None:
                parts += [option, str(value)]
        if self.simulator != DEFAULT_SIMULATOR:
            parts += ["--simulator", self.simulator]
        for vehicle, name in sorted(self.drivers.items()):
            parts += ["--driver", f"{vehicle}={name}"]
        return shlex.join(parts)


# the run settings a case keeps under their own names (the others: road_speed as text, encoding,
# tries as max_tries, dut; strategy with the case's identity)
_COPIED = (
    "seed",
    "lanes",
    "road_map",
    "dialect",
    "max_horizon",
    "planning_time_limit",
    "simulation_time_limit",
    "simulator",
    "dut_driver",
    "replan_period",
    "min_ttc",
    "min_gap",
    "max_decel",
)
# the case's fields that are run settings, by the option (settings.OPTIONS) that reads and checks them
_SETTING_OPTIONS = {
    "seed": "seed",
    "strategy": "strategy",
    "lanes": "lanes",
    "road_map": "map",
    "road_speed": "road-speed",
    "dialect": "dialect",
    "encoding": "encoding",
    "max_horizon": "horizon",
    "planning_time_limit": "plan-timeout",
    "simulation_time_limit": "sim-timeout",
    "max_tries": "tries",
    "simulator": "simulator",
    "dut": "dut",
    "dut_driver": "dut-driver",
    "replan_period": "replan-period",
    "min_ttc": "min-ttc",
    "min_gap": "min-gap",
    "max_decel": "max-decel",
}


# the case's fields the options read that hold numbers (whole numbers where the option reads one);
# the other setting fields hold text
_NUMBERS = {
    "seed": int,
    "lanes": int,
    "max_horizon": int,
    "max_tries": int,
    "planning_time_limit": float,
    "simulation_time_limit": float,
    "replan_period": float,
    "min_ttc": float,
    "min_gap": float,
    "max_decel": float,
}
# sizes past anything the tool writes: a case file is read whole before it is checked, and a
# 100 MB string in ``versions`` had gone to stderr in a warning
MAX_CASE_BYTES = 1_000_000
MAX_TEXT = 1_000  # characters of one string field (a path, a name, a version)
MAX_ENTRIES = 1_000  # entries of ``values``, ``drivers`` or ``versions``
# plans enumerated to reach a base-strategy instance: ``"instance": 1000000`` had run past 120 s
MAX_INSTANCE = 999


def _check_kinds(data: dict[str, Any]) -> dict[str, Any]:
    """``data`` with each setting read by its option, or ``TypeError`` / ``OptionError`` naming the
    field: a case file is data from anywhere, checked (kinds, ranges, sizes) before anything runs (a
    non-numeric seed had been a traceback under pytest, ``"lanes": "4"`` a ``TypeError``)."""
    checked = dict(data)
    for name in ("path", "scenario"):
        if not isinstance(data[name], str) or len(data[name]) > MAX_TEXT:
            raise TypeError(f"{name} must be a string of at most {MAX_TEXT} characters")
    for name, option in _SETTING_OPTIONS.items():
        value = data.get(name)
        if value is None:
            continue
        kind = _NUMBERS.get(name)
        if kind is None and not isinstance(value, str):
            raise TypeError(f"{name} must be a string")
        if kind is not None and (
            isinstance(value, bool) or not isinstance(value, (int, float) if kind is float else int)
        ):
            raise TypeError(
                f"{name} must be a {'whole number' if kind is int else 'number'}, not {type(value).__name__}"
            )
        if isinstance(value, str) and len(value) > MAX_TEXT:
            raise TypeError(f"{name} must be at most {MAX_TEXT} characters")
        try:
            parsed = OPTIONS_BY_NAME[option].parse(str(value))
        except OptionError as error:
            raise OptionError(f"{name}: {error}") from None
        checked[name] = parsed if name != "road_speed" else value
    instance = data.get("instance", 0)
    if not isinstance(instance, int) or isinstance(instance, bool) or not 0 <= instance <= MAX_INSTANCE:
        raise TypeError(f"instance must be a whole number from 0 to {MAX_INSTANCE}")
    values = data.get("values", {})
    if (
        not isinstance(values, dict)
        or len(values) > MAX_ENTRIES
        or not all(
            len(k) <= MAX_TEXT and isinstance(v, (str, int, float, bool)) and len(str(v)) <= MAX_TEXT
            for k, v in values.items()
        )
    ):
        raise TypeError(f"values must map at most {MAX_ENTRIES} parameter names to numbers, names or booleans")
    for name in ("drivers", "versions"):
        given = data.get(name, {})
        if (
            not isinstance(given, dict)
            or len(given) > MAX_ENTRIES
            or not all(
                isinstance(k, str) and isinstance(v, str) and len(k) <= MAX_TEXT and len(v) <= MAX_TEXT
                for k, v in given.items()
            )
        ):
            raise TypeError(f"{name} must map at most {MAX_ENTRIES} names to strings of at most {MAX_TEXT} characters")
    return checked


# what a replay depends on besides the case: a different solver or motion planner may plan or drive otherwise
VERSIONED = ("pytest-roadlogic", "clingo", "clingo-lpx", "frenetix", "commonroad-io", "hypothesis", "numpy", "scipy")


def installed_versions() -> dict[str, str]:
    import platform
    from importlib.metadata import PackageNotFoundError, version

    found = {"python": platform.python_version()}
    for name in VERSIONED:
        try:
            found[name] = version(name)
        except PackageNotFoundError:
            pass
    return found
