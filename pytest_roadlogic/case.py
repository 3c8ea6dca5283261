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
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from .confinement import ReadRoots, UnreadableFile, project_root, read_bounded, regular_file_problem, shown
from .settings import BASE, OPTIONS, OptionError, RunSettings


class CaseFileError(ValueError):
    """A case file that cannot be read: missing, not JSON, or not a case."""


@dataclass(frozen=True)
class Case:
    """A case: the scenario (``path``, its ``scenario``), what makes it this case among the
    scenario's (``values`` sampled, or the planner's ``instance``), the run settings it was made
    under, the drivers a hook gave, and the versions of what it ran on."""

    path: str
    scenario: str
    settings: RunSettings = field(default_factory=RunSettings)
    values: dict[str, Any] = field(default_factory=dict)  # the sample (refined strategy)
    instance: int = 0  # which of the planner's instances, from 0 (base strategy)
    # vehicle -> "module:QualName" of the driver a pytest_roadlogic_driver hook gave it (the others
    # are the simulator's own): a replay builds the same ones or refuses (simulation/named_drivers.py)
    drivers: dict[str, str] = field(default_factory=dict)
    versions: dict[str, str] = field(default_factory=dict)  # of the packages a run depends on, when written
    # what the case recorded (the scenario's record() items, as reports show them): information for
    # its reader, not part of what a replay runs
    recorded: dict[str, str] = field(default_factory=dict)

    @classmethod
    def of(
        cls, path: str | Path, scenario: str, settings: RunSettings, strategy: str | None = None, **identity
    ) -> Case:
        """The case of ``scenario`` in ``path`` under ``settings``; ``strategy`` (the settings' when
        not given) and ``identity`` give the values (refined) or the instance (base)."""
        if strategy is not None:
            settings = replace(settings, strategy=strategy)
        return cls(path=str(path), scenario=scenario, settings=settings, **identity)

    @property
    def strategy(self) -> str:
        return self.settings.strategy

    @property
    def seed(self) -> int:
        return self.settings.seed

    def within(self, limits: RunSettings) -> Case:
        """This case with its time limits no higher than ``limits``' (the command line's or the
        session's): a case file is data, and ``"planning_time_limit": 1e9`` must not raise what the
        user allows."""
        own = self.settings
        return replace(
            self,
            settings=replace(
                own,
                planning_time_limit=min(own.planning_time_limit, limits.planning_time_limit),
                simulation_time_limit=min(own.simulation_time_limit, limits.simulation_time_limit),
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
        """The case file: its identity, and each run setting a case records (``Option.in_case``)
        under its key, as a number or as the text its option reads back."""
        data = {name: getattr(self, name) for name in IDENTITY if name != "recorded" or self.recorded}
        for option in CASE_OPTIONS:
            value = getattr(self.settings, option.field)
            data[option.key] = value if value is None or option.kind is not str else option.text(value)
        return json.dumps(data, indent=2, sort_keys=True)

    def save(self, path: str | Path) -> Path:
        from .artifacts.files import write_text

        Path(path).parent.mkdir(parents=True, exist_ok=True)
        return write_text(Path(path), self.to_json())

    @classmethod
    def load(cls, path: str | Path) -> Case:
        try:
            data = json.loads(read_bounded(path, MAX_CASE_BYTES).decode("utf-8"))
            known = set(IDENTITY) | {o.key for o in CASE_OPTIONS}
            if not isinstance(data, dict) or not {"path", "scenario"} <= set(data) or set(data) - known:
                raise TypeError(f"expected the keys {', '.join(sorted(known))}")
            identity = _check_kinds(data)
            return cls(settings=_settings_of(data), **identity)
        except UnreadableFile as error:
            raise CaseFileError(f"cannot read the case file: {error}") from None
        except (json.JSONDecodeError, TypeError, UnicodeDecodeError, RecursionError) as error:
            raise CaseFileError(f"not a case file written by pytest-roadlogic ({error})") from None
        except OptionError as error:
            raise CaseFileError(f"a value the tool cannot run with: {error}") from None

    def command(self, case_file: str | Path | None = None) -> str:
        """The shell command that replays this case: from its case file when there is one, else
        from the scenario file with each recorded setting that is not its option's default."""
        if case_file is not None:
            return f"roadlogic replay {shlex.quote(str(case_file))}"
        parts = ["roadlogic", "replay", self.path, "--scenario", self.scenario, "--seed", str(self.seed)]
        if self.strategy == BASE:
            parts += ["--strategy", BASE, "--instance", str(self.instance)]
        if self.values:
            parts += ["--values", json.dumps(self.values, sort_keys=True)]
        for option in REPLAY_OPTIONS:
            value = getattr(self.settings, option.field)
            if value is not None and value != option.default:
                parts += [f"--{option.name}", option.text(value)]
        for vehicle, name in sorted(self.drivers.items()):
            parts += ["--driver", f"{vehicle}={name}"]
        return shlex.join(parts)


# the run settings a case file records, and those its replay command gives as flags (the seed and
# the strategy are the case's identity, written first; the time limits are the replaying user's)
CASE_OPTIONS = tuple(option for option in OPTIONS if option.in_case)
REPLAY_OPTIONS = tuple(
    option for option in CASE_OPTIONS if option.name not in ("seed", "strategy", "plan-timeout", "sim-timeout")
)
IDENTITY = ("path", "scenario", "values", "instance", "drivers", "versions", "recorded")
# sizes past anything the tool writes: a case file is read whole before it is checked, and its
# strings go into messages
MAX_CASE_BYTES = 1_000_000
MAX_TEXT = 1_000  # characters of one string field (a path, a name, a version)
MAX_ENTRIES = 1_000  # entries of ``values``, ``drivers`` or ``versions``
# plans enumerated to reach a base-strategy instance: each costs a planning
MAX_INSTANCE = 999


def _settings_of(data: dict[str, Any]) -> RunSettings:
    """The run settings a case file records, each read and checked by its option, or
    ``TypeError`` / ``OptionError`` naming the field; a field the file lacks is what it meant when
    it was written (``Option.absent``). A case file is data from anywhere: kinds, ranges and sizes
    are checked before anything runs."""
    values = {}
    for option in CASE_OPTIONS:
        value = data.get(option.key)
        if value is None:
            values[option.field] = option.absent
            continue
        name, kind = option.key, option.kind
        if kind is str and not isinstance(value, str):
            raise TypeError(f"{name} must be a string")
        if kind is not str and (
            isinstance(value, bool) or not isinstance(value, (int, float) if kind is float else int)
        ):
            raise TypeError(
                f"{name} must be a {'whole number' if kind is int else 'number'}, not {type(value).__name__}"
            )
        if isinstance(value, str) and len(value) > MAX_TEXT:
            raise TypeError(f"{name} must be at most {MAX_TEXT} characters")
        try:
            values[option.field] = option.parse(str(value))
        except OptionError as error:
            raise OptionError(f"{name}: {error}") from None
    return RunSettings(**values)


def _check_kinds(data: dict[str, Any]) -> dict[str, Any]:
    """The identity of the case in ``data`` (``IDENTITY``), checked, or ``TypeError`` naming the field."""
    for name in ("path", "scenario"):
        if not isinstance(data[name], str) or len(data[name]) > MAX_TEXT:
            raise TypeError(f"{name} must be a string of at most {MAX_TEXT} characters")
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
    for name in ("drivers", "versions", "recorded"):
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
    return {name: data[name] for name in IDENTITY if name in data}


# what a run's plan and trace depend on besides the case (the solvers, the linear programs'
# solver, the motion planner, the sampler): the versions a case file records and a replay compares,
# and those a bench reports
VERSIONED = (
    "pytest-roadlogic",
    "clingo",
    "clingo-dl",
    "clingo-lpx",
    "highspy",
    "scipy",
    "frenetix",
    "commonroad-io",
    "hypothesis",
    "numpy",
)


def installed_versions() -> dict[str, str]:
    """The Python version and each installed package of ``VERSIONED`` by its version."""
    import platform
    from importlib.metadata import PackageNotFoundError, version

    found = {"python": platform.python_version()}
    for name in VERSIONED:
        try:
            found[name] = version(name)
        except PackageNotFoundError:
            pass
    return found
