"""How a run is set up: one ``RunSettings``, built once from pytest options and ini keys, CLI flags, or Python.

``OPTIONS`` is the one table of what a user can set: each option's name, how its text is read
(with a message that says what to give instead), its default and its help. The pytest plugin
turns it into ``--roadlogic-<name>`` options and ``roadlogic_<name>`` ini keys, the CLI into
``--<name>`` flags, so that a default or a check is written once. Nothing heavy is imported here:
the plugin loads this module in every pytest session.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, make_dataclass
from dataclasses import field as dataclass_field
from typing import Any

from .registries.drivers import BUILT_IN as BUILT_IN_DRIVERS
from .registries.drivers import DEFAULT as DEFAULT_DUT_DRIVER
from .registries.drivers import driver_names
from .registries.entry_points import registered_names
from .registries.oracles import ORACLES

REFINED, BASE = "refined", "base"
STRATEGIES = (REFINED, BASE)
CONTINUOUS, GRID = "continuous", "grid"
ENCODINGS = (CONTINUOUS, GRID)  # the built-in planner encodings (planning/encodings/), the default first
# where a package registers an encoding of its own (planning/encodings/__init__.py)
ENCODING_ENTRY_POINTS = "pytest_roadlogic.encodings"
# what a sample at which no plan exists does to its item (refined strategy): fail it (a logical
# scenario whose ranges hold values no concrete scenario meets is a defect of the test), or be
# discarded as hypothesis.assume(False) discards it (the item then tests what can be instantiated)
FAIL, DISCARD = "fail", "discard"
NO_PLAN_POLICIES = (FAIL, DISCARD)
# how the refined strategy's property search draws its samples: Hypothesis's own generation (biased
# toward each range's ends; its target phase steers toward the closest-to-failing samples once half
# the examples are spent), uniformly at random, or by a cross-entropy sampler that steers from the
# first sample (falsification.py)
HYPOTHESIS_SEARCH, RANDOM_SEARCH, CROSS_ENTROPY = "hypothesis", "random", "cross-entropy"
SEARCHES = (HYPOTHESIS_SEARCH, RANDOM_SEARCH, CROSS_ENTROPY)
STANDARD_DIALECT, CARLA_DIALECT = "standard", "carla"
DIALECTS = (STANDARD_DIALECT, CARLA_DIALECT)  # constructs.DIALECTS holds their registries
DEFAULT_HORIZON = 25  # planning steps (of 1 s) of the grid encoding
CONTINUOUS_HORIZON = 120  # of the continuous one: two minutes of scenario time
DEFAULT_PLAN_TIMEOUT = 60.0  # seconds per planning
DEFAULT_SIM_TIMEOUT = 120.0  # seconds (wall clock) per simulation
DEFAULT_SIMULATOR = "frenetix"
# how many artifacts a run writes (``roadlogic run --artifacts``): none; what a replay and a reader
# of the verdict need (plan, trace, verdict, case); or all of them (with the CommonRoad and
# OpenSCENARIO files, the plot and the GIF: most of the artifacts' time)
ARTIFACT_LEVELS = ("none", "essential", "all")


class OptionError(ValueError):
    """An option's value that cannot be used; the message says what to give instead."""


def whole_number(least: int, what: str, most: int | None = None) -> Callable[[str], int]:
    def parse(text: str) -> int:
        try:
            number = int(str(text).strip()) if len(str(text)) <= 30 else least - 1  # no 5,000-digit number
        except ValueError:
            number = least - 1
        if number < least or (most is not None and number > most):
            span = f"from {least} up" if most is None else f"from {least} to {most}"
            raise OptionError(f"{text!r} is not {what}; give a whole number {span}")
        return number

    return parse


def real(text: str) -> float:
    """A number read from an option's text; NaN when it is none (the parser then says what to give)."""
    try:
        return float(str(text).strip())
    except ValueError:
        return math.nan


def positive(what: str, example: str, unit: str = "a number") -> Callable[[str], float]:
    """A parser of a number above 0 (``what``, ``example`` and ``unit`` for the message)."""

    def parse(text: str) -> float:
        value = real(text)
        if not (value > 0 and math.isfinite(value)):
            raise OptionError(f"{text!r} is not {what}; give {unit} above 0, e.g. {example}")
        return value

    return parse


# a day: far past any planning or simulation of one case, and far inside what a timer takes
# (``--plan-timeout 1e308`` would overflow the deadline)
MAX_SECONDS = 86_400.0


_positive_seconds = positive("a time limit", "60", "a number of seconds")


def seconds(text: str) -> float:
    """A time limit in seconds, above 0 and at most ``MAX_SECONDS``."""
    value = _positive_seconds(text)
    if value > MAX_SECONDS:
        raise OptionError(f"{text!r} is past the longest time limit; give seconds from above 0 to {MAX_SECONDS:g}")
    return value


MAX_SEED = 2**32 - 1  # clingo's --seed takes 0..2^32-1; past it a RuntimeError traceback came from the solver


def seed(text: str) -> int:
    try:
        number = int(str(text).strip())
    except ValueError:
        number = -1
    if not 0 <= number <= MAX_SEED:
        raise OptionError(f"{text!r} is not a seed; give a whole number from 0 to {MAX_SEED}, e.g. 1")
    return number


def or_none(parse: Callable[[str], Any]) -> Callable[[str | None], Any]:
    """``parse``, or None for an empty text (the option's own default then decides)."""

    def parse_or_none(text: str | None) -> Any:
        if text is None or not str(text).strip():
            return None
        return parse(str(text))

    return parse_or_none


lane_count = whole_number(1, "a lane count")


def map_file(text: str) -> str:
    """An OpenDRIVE file's path (read when a scenario is checked, inside the folders the tool reads)."""
    if not str(text).strip().lower().endswith(".xodr"):
        raise OptionError(f"{text!r} is not an OpenDRIVE file; give a path ending in .xodr, e.g. maps/highway.xodr")
    return str(text).strip()


map_file_or_none = or_none(map_file)  # a map, or each scenario's own road
lanes_or_none = or_none(lane_count)  # a lane count, or each scenario's own road
# an hour of scenario time in steps of 1 s: far past a driving scenario (the realistic suite's
# longest is a minute), and a bound on what planning grounds
MAX_HORIZON = 3600


def horizon(text: str) -> int:
    number = whole_number(1, "a planning horizon")(text)
    if number > MAX_HORIZON:
        raise OptionError(
            f"{text!r} is past the longest planning horizon; give a whole number of steps from 1 to {MAX_HORIZON}"
        )
    return number


horizon_or_none = or_none(horizon)  # a horizon limit, or the encoding's own
count = whole_number(0, "an instance count")
processes = whole_number(1, "a number of processes")


def one_of(choices: tuple[str, ...], what: str) -> Callable[[str], str]:
    """A parser that accepts one of ``choices`` and names them all otherwise."""

    def parse(text: str) -> str:
        if text not in choices:
            raise OptionError(f"{text!r} is not {what}; give {' or '.join(choices)}")
        return text

    return parse


def encoding_names() -> tuple[str, ...]:
    """Every planner encoding's name: the built-in ones, then those packages register (names
    only: nothing is imported)."""
    return registered_names(ENCODINGS, ENCODING_ENTRY_POINTS)


def encoding(text: str) -> str:
    """A planner encoding's name, one of ``encoding_names()``."""
    return one_of(encoding_names(), "a planning encoding")(text)


DIALECT_ENTRY_POINTS = "pytest_roadlogic.dialects"


def dialect(text: str) -> str:
    """A dialect's name: a built-in one, or one a package registers (the installed packages' entry
    points are read only for a name that is not built in)."""
    if text in DIALECTS:
        return text
    return one_of(registered_names(DIALECTS, DIALECT_ENTRY_POINTS), "a dialect")(text)


strategy = one_of(STRATEGIES, "a strategy")
no_plan_policy = one_of(NO_PLAN_POLICIES, "what to do with a sample without a plan")
search = one_of(SEARCHES, "a search")


SPEED_UNITS = {"kph": 1 / 3.6, "kmph": 1 / 3.6, "mps": 1.0, "mph": 0.44704}
ROAD_SPEED_TEXT = "80..130kph"  # a highway's typical speeds


def speed_band(text: str) -> tuple[float, float]:
    """``LOW..HIGH`` with a unit after either or both (kph, mps, mph; kph when none), as m/s."""
    match = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([a-z]*)\s*\.\.\s*(\d+(?:\.\d+)?)\s*([a-z]*)\s*", str(text))
    units = [match.group(2) or match.group(4) or "kph", match.group(4) or "kph"] if match else []
    if not match or any(unit not in SPEED_UNITS for unit in units):
        raise OptionError(f"{text!r} is not a speed band; give LOW..HIGH with a unit, e.g. 80..130kph or 20..35mps")
    low, high = float(match.group(1)) * SPEED_UNITS[units[0]], float(match.group(3)) * SPEED_UNITS[units[1]]
    if not 0 < low <= high <= 70:
        raise OptionError(f"{text!r} is not a speed band a car drives at; give 0 < LOW <= HIGH <= 250kph")
    return low, high


ROAD_SPEED = speed_band(ROAD_SPEED_TEXT)  # m/s


# the vehicle under test (dut.roles): the scenario's own dut, none (every vehicle follows its plan), or a name
DUT_AUTO, DUT_NONE = "auto", "none"
# how scenario files spell the vehicle under test: the standard's dut.car and dut.vehicle, CARLA's
# dut; the front end reads them without a declaration, and auto takes the first a scenario has
DUT_NAMES = ("dut.car", "dut.vehicle", "dut")


def dut_driver(text: str) -> str:
    """A reference driver's name, one of ``registries.drivers.driver_names()``."""
    return one_of(driver_names(), "a reference driver of the vehicle under test")(text)


def replan_period(text: str) -> float:
    """Seconds between replans: 0 (never), else at least the simulation's step of 0.1 s, at which
    alone the simulation can stop for one."""
    value = real(text)
    if not (math.isfinite(value) and (value == 0 or value >= 0.1 - 1e-9)):
        raise OptionError(
            f"{text!r} is not a replanning period; give seconds, at least the simulation step of 0.1 s "
            "(0: the other vehicles follow their first plan), e.g. 0.25"
        )
    return value


def name(text: str) -> str:
    if not str(text).strip():
        raise OptionError("give a name")
    return str(text).strip()


_DEFAULT = object()  # an Option's ``before``: a case file without the field meant the default


@dataclass(frozen=True)
class Option:
    """One setting a user can give: ``--roadlogic-<name>`` / ini ``roadlogic_<name>`` under pytest,
    ``--<name>`` on the command line, ``RunSettings.<field>`` in Python, and (unless it says how
    cases are drawn rather than what one is) a field of a case file and a flag of its replay."""

    name: str
    field: str  # the RunSettings field it sets
    parse: Callable[[str], Any]
    default: Any  # the value (as ``parse`` returns it) where the user gives none
    help: str
    shown: str = ""  # how help texts name the default, when it is not a value (None: decided elsewhere)
    kind: type = str  # what a case file holds for it: a whole number, a number, or its text (``text``)
    in_case: bool = True  # a case file records it and its replay takes it (not: how many cases, how drawn)
    case_key: str = ""  # its key in a case file, when not the field's name (older files' spelling)
    before: Any = _DEFAULT  # what a case file without it meant (written before the option existed)
    text: Callable[[Any], str] = str  # a value as text that ``parse`` reads back

    @property
    def default_text(self) -> str:
        return self.shown or str(self.default)

    @property
    def ini(self) -> str:
        return f"roadlogic_{self.name.replace('-', '_')}"

    @property
    def key(self) -> str:
        """Its key in a case file."""
        return self.case_key or self.field

    @property
    def absent(self) -> Any:
        """Its value in a case file without it."""
        return self.default if self.before is _DEFAULT else self.before


def speed_band_text(band: tuple[float, float]) -> str:
    """A speed band (m/s) as the text ``speed_band`` reads back exactly."""
    return f"{band[0]!r}..{band[1]!r}mps"


def threshold_option(oracle) -> Option:
    """The option that sets ``oracle``'s threshold (an ``registries.oracles.Oracle``). A case file
    without it was written before the oracle existed: it replays with the oracle off (None), so that
    its verdict is the one it was written with."""
    parse = positive(f"a {oracle.quantity}", f"{oracle.default:g}")
    return Option(oracle.option, oracle.setting, parse, oracle.default, oracle.help, kind=float, before=None)


OPTIONS = (
    Option(
        "strategy",
        "strategy",
        strategy,
        REFINED,
        "refined: sample the logical parameters with Hypothesis; base: the planner's first N plans",
    ),
    Option(
        "examples",
        "examples",
        whole_number(1, "a number of examples"),
        10,
        "samples (refined) or plans (base) per scenario",
        in_case=False,
    ),
    Option(
        "search",
        "search",
        search,
        HYPOTHESIS_SEARCH,
        "how samples look for a failure (refined, under pytest): hypothesis (favouring each range's ends, then toward "
        "the case nearest to failing after half the examples), random (uniformly), or cross-entropy (toward the case "
        "nearest to failing from the first sample: fewer simulations to a rare failure); a failure is shrunk and "
        "replays either way",
        in_case=False,
    ),
    Option("seed", "seed", seed, 1, "fixes sampling, planning and simulation", kind=int),
    Option(
        "shards",
        "shards",
        whole_number(1, "a number of shards"),
        1,
        "items per scenario, each drawing a disjoint share of its samples (refined): spread one scenario over pytest-xdist workers",
        in_case=False,
    ),
    Option(
        "no-plan",
        "no_plan",
        no_plan_policy,
        FAIL,
        "a sample at which no plan exists: fail the item (the scenario's ranges hold values no concrete scenario meets), or discard it like assume() (refined)",
        in_case=False,
    ),
    Option(
        "tries",
        "tries",
        whole_number(1, "a number of tries", 100),
        5,
        "plans to try per case when the monitor rejects the simulation",
        kind=int,
        case_key="max_tries",
    ),
    Option(
        "lanes",
        "lanes",
        lanes_or_none,
        None,
        "lanes of the road (from the scenario when not given: its path_min_driving_lanes/path_max_lanes and the "
        "lanes it names, at least 3)",
        "each scenario's own",
        kind=int,
    ),
    Option(
        "map",
        "road_map",
        map_file_or_none,
        None,
        "an OpenDRIVE file every scenario runs on, on the route of it that fits the scenario (inside the folders the "
        "tool reads)",
        "each scenario's set_map, else one straight road",
    ),
    Option(
        "road-speed",
        "road_speed",
        speed_band,
        ROAD_SPEED,
        "the speeds a vehicle starts at where the scenario names none (its first phase's speed otherwise)",
        ROAD_SPEED_TEXT,
        text=speed_band_text,
    ),
    Option(
        "dialect",
        "dialect",
        dialect,
        STANDARD_DIALECT,
        "how files are read: standard (ASAM), or carla (CARLA's scenario runner: lanes numbered from the left, speed(v) a target)",
    ),
    Option(
        "encoding",
        "encoding",
        encoding,
        CONTINUOUS,
        "continuous: real-valued speeds and positions (asp/continuous/); grid: the paper's integer grid with a run-up from standstill (asp/grid/); or one a package registers",
        before=GRID,  # case files from before the continuous encoding
    ),
    Option(
        "horizon",
        "max_horizon",
        horizon_or_none,
        None,
        f"planning horizon limit in steps of 1 s, at most {MAX_HORIZON}",
        f"the encoding's: {CONTINUOUS_HORIZON} continuous, {DEFAULT_HORIZON} grid",
        kind=int,
    ),
    Option(
        "plan-timeout",
        "planning_time_limit",
        seconds,
        DEFAULT_PLAN_TIMEOUT,
        "seconds one planning may take",
        kind=float,
    ),
    Option(
        "sim-timeout",
        "simulation_time_limit",
        seconds,
        DEFAULT_SIM_TIMEOUT,
        "seconds (wall clock) one simulation may take",
        kind=float,
    ),
    Option(
        "simulator",
        "simulator",
        name,
        DEFAULT_SIMULATOR,
        "the simulation backend: frenetix (a motion planner per vehicle), kinematic (a bicycle model tracking the plan: fast screening), or one a package registers",
    ),
    Option(
        "dut",
        "dut",
        name,
        DUT_AUTO,
        "the vehicle under test, which drives itself and is judged by the oracles: auto (the scenario's dut.car, dut.vehicle or dut), "
        "none (every vehicle follows its plan: conformance only), or a vehicle's name",
        before=DUT_NONE,  # case files from before vehicles under test: every vehicle followed its plan
    ),
    Option(
        "dut-driver",
        "dut_driver",
        dut_driver,
        DEFAULT_DUT_DRIVER,
        f"the reference driver of a vehicle under test no pytest_roadlogic_driver hook drives: {', '.join(BUILT_IN_DRIVERS)}, "
        "or one a package registers",
    ),
    Option(
        "replan-period",
        "replan_period",
        replan_period,
        0.25,
        "seconds between replans of the other vehicles from what the vehicle under test really does (at least the "
        "simulation step, 0.1); 0: they follow their first plan",
        kind=float,
    ),
    *(threshold_option(oracle) for oracle in ORACLES),
)
OPTIONS_BY_NAME = {option.name: option for option in OPTIONS}


def _from_texts(
    cls, texts: Mapping[str, str | None], origin: Callable[[Option], str] = lambda o: o.name
) -> RunSettings:
    """Settings from option texts by option name (a missing or None text keeps the default);
    an unusable text raises ``OptionError`` naming the option as ``origin`` spells it."""
    values = {}
    for option in OPTIONS:
        text = texts.get(option.name)
        if text is None:
            continue
        try:
            values[option.field] = option.parse(text)
        except OptionError as error:
            raise OptionError(f"{origin(option)}: {error}") from None
    return cls(**values)


# Everything that decides what a run does, besides the scenario, the sample and the drivers: one
# field per option (``Option.field``), with the option's default, so that an option is written once.
RunSettings = make_dataclass(
    "RunSettings",
    [(option.field, Any, dataclass_field(default=option.default)) for option in OPTIONS],
    frozen=True,
    namespace={
        "__doc__": "Everything that decides what a run does, besides the scenario, the sample and the drivers: "
        "a field per option of ``settings.OPTIONS`` (``Option.field``), its default the option's.",
        "__module__": __name__,
        "from_texts": classmethod(_from_texts),
    },
)
