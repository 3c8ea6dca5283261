"""Every oracle as one record: what it measures, in what unit, where it fails, how a failure reads.

``ORACLES`` is the one list the rest iterates: the run settings make a threshold option of each
(``--roadlogic-<option>``, ini ``roadlogic_<option>``, ``--<option>``, a case file's field),
``judge`` measures each, ``DutReport`` words its failures and margins, and the JUnit properties,
``verdict.json``, the CLI's summary line and the HTML report list each. Adding an oracle is a
record here and its measure in ``oracles/measures.py``. Plain data: the settings read this
module in every pytest session, so it imports nothing.

Collisions and leaving the road are not records: they fail at any value, have no threshold, and
say who caused them (``oracles.verdict``).
"""

from __future__ import annotations

from dataclasses import dataclass

LOWER, UPPER = "lower", "upper"  # a value below the threshold fails it; a value above it does
# how keys spell a unit (verdict.json, JUnit properties)
_UNIT_KEYS = {"s": "s", "m": "m", "m/s^2": "mps2"}


@dataclass(frozen=True)
class Oracle:
    """One oracle of the vehicle under test: a value read off a trace, judged against one threshold."""

    name: str  # its identity, in thresholds and reports: "time_to_collision"
    quantity: str  # what it measures, as messages name it: "time to collision"
    title: str  # how a table names its value: "least time to collision"
    unit: str  # "s", "m" or "m/s^2"
    bound: str  # LOWER: a value below ``threshold`` fails; UPPER: a value above it
    option: str  # the option that sets its threshold: "min-ttc"
    setting: str  # the RunSettings field the option sets: "min_ttc"
    default: float  # the threshold when no option sets one
    help: str  # the option's help text
    measure: str  # the function of ``oracles.measures`` that measures it (a ``Seen`` in, a ``Closest`` out)
    # a failure, as a sentence: {value}, {threshold}, {other} (whom it was measured to) and {time}
    failure: str

    @property
    def key(self) -> str:
        """Its threshold's key in ``verdict.json``: "min_time_to_collision"."""
        return f"{'min' if self.bound == LOWER else 'max'}_{self.name}"

    @property
    def value_key(self) -> str:
        """Its value's key in ``verdict.json`` and (after ``dut_``) in JUnit properties."""
        return f"{self.key}_{_UNIT_KEYS[self.unit]}"

    @property
    def never(self) -> float:
        """Its value where it never applied (no vehicle ahead in the path, no braking): never failing."""
        return float("inf") if self.bound == LOWER else 0.0

    def fails(self, value: float, threshold: float | None) -> bool:
        """Whether ``value`` is past ``threshold`` (None: the oracle is off, and nothing fails it)."""
        if threshold is None:
            return False
        return value < threshold if self.bound == LOWER else value > threshold

    def margin(self, value: float, threshold: float | None) -> float:
        """How far ``value`` is from failing, as a fraction of ``threshold``: negative once it fails,
        at most 1 (a value that never applied, or an oracle that is off, is as far as can be)."""
        if threshold is None or value == self.never or threshold <= 0:
            return 1.0
        distance = value - threshold if self.bound == LOWER else threshold - value
        return min(1.0, distance / threshold)

    def worst(self, values: list[float]) -> float:
        """The value nearest to failing among ``values`` (the least of a lower bound's)."""
        return min(values) if self.bound == LOWER else max(values)


ORACLES = (
    Oracle(
        "time_to_collision",
        "time to collision",
        "least time to collision",
        "s",
        LOWER,
        "min-ttc",
        "min_ttc",
        1.5,
        "seconds: a smaller time to collision of the vehicle under test with one ahead in its path fails it",
        "least_time_to_collision",
        "time to collision {value:.2f} s (threshold {threshold:g} s) behind {other} at t={time:.1f} s",
    ),
    Oracle(
        "gap",
        "gap",
        "least gap",
        "m",
        LOWER,
        "min-gap",
        "min_gap",
        2.0,
        "metres bumper to bumper: a smaller gap of the vehicle under test to one ahead in its path fails it",
        "least_gap",
        "gap {value:.2f} m (threshold {threshold:g} m) behind {other} at t={time:.1f} s",
    ),
    Oracle(
        "time_headway",
        "time headway",
        "least time headway",
        "s",
        LOWER,
        "min-headway",
        "min_headway",
        0.5,
        "seconds: a smaller time headway (the gap over its own speed) of the vehicle under test while it closes in on "
        "one ahead in its path fails it",
        "least_time_headway",
        "time headway {value:.2f} s (threshold {threshold:g} s) behind {other} at t={time:.1f} s",
    ),
    Oracle(
        "deceleration",
        "deceleration",
        "hardest braking",
        "m/s^2",
        UPPER,
        "max-decel",
        "max_decel",
        8.0,
        "m/s^2: harder braking of the vehicle under test fails it (8: beyond a car's hard braking)",
        "greatest_deceleration",
        "braked at {value:.2f} m/s^2 (threshold {threshold:g} m/s^2) at t={time:.1f} s",
    ),
)
ORACLES += (
    Oracle(
        "post_encroachment_time",
        "post-encroachment time",
        "least post-encroachment time",
        "s",
        LOWER,
        "min-pet",
        "min_pet",
        1.0,
        "seconds: a vehicle under test that drives where a car of another way through a junction drove, or will "
        "drive, less than this apart in time (its post-encroachment time) fails (1: a serious conflict)",
        "least_post_encroachment_time",
        "post-encroachment time {value:.2f} s (threshold {threshold:g} s) with {other} at t={time:.1f} s",
    ),
)
ORACLES_BY_NAME = {oracle.name: oracle for oracle in ORACLES}
