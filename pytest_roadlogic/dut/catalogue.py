"""A vehicle-under-test catalogue's summary: one row per test point, and a grade to track.

A test point is one scenario item run with a vehicle under test (``pytest scenarios/dut/``): it
failed when a case failed an oracle; passed when its item passed and a case tested something; and
was not exercised otherwise: no case tested anything, or its item failed without an oracle failing
(most cases tested nothing, a case timed out or had no plan: the row says which). The grade is the share of test points passed. The
rows are read from the items' JUnit properties (the plugin's), so that a session's workers and a
JUnit file give the same summary; the plugin prints it, the HTML report shows it.
"""

from __future__ import annotations

import html
from dataclasses import dataclass

from ..outcomes import DUT_FAILED, NOT_EXERCISED, PASSED, key
from ..registries.oracles import ORACLES

MOST_SAID = 160  # characters of an item's failure in a row


@dataclass(frozen=True)
class TestPoint:
    """One item's outcome with a vehicle under test: its cases by outcome, each oracle's value
    nearest to failing over them (``oracle.value_key`` -> a number, or "inf" where it never
    applied), and what failed (the first failure's sentence)."""

    __test__ = False  # not a pytest test class

    name: str
    passed: int
    failed: int
    not_exercised: int
    worst: dict[str, object]
    failure: str = ""
    item_passed: bool = True
    why_not: str = ""  # why the item failed without an oracle failing (its report's first line)

    @property
    def verdict(self) -> str:
        if self.failed:
            return DUT_FAILED
        return PASSED if self.passed and self.item_passed else NOT_EXERCISED


def point_from(
    name: str, properties: dict[str, object], item_passed: bool = True, report: str = ""
) -> TestPoint | None:
    """The test point of an item with these JUnit ``properties``, whether the item passed and its
    failure's report; None without a vehicle under test."""
    if "vehicle_under_test" not in properties:
        return None
    return TestPoint(
        name=name,
        passed=int(properties.get(key(PASSED), 0)),
        failed=int(properties.get(key(DUT_FAILED), 0)),
        not_exercised=int(properties.get(key(NOT_EXERCISED), 0)),
        worst={o.value_key: properties.get(f"dut_{o.value_key}", "inf") for o in ORACLES},
        failure=str(properties.get("explanation", "")),
        item_passed=item_passed,
        why_not=next((line.strip() for line in report.splitlines() if line.strip()), "")[:MOST_SAID],
    )


def grade(points: list[TestPoint]) -> str:
    """The share of test points passed, in a line: ``grade 83% (5 of 6 test points passed, ...)``."""
    passed = sum(p.verdict == PASSED for p in points)
    failed = sum(p.verdict == DUT_FAILED for p in points)
    unexercised = len(points) - passed - failed
    share = round(100 * passed / len(points)) if points else 0
    return (
        f"grade {share}% ({passed} of {len(points)} test points passed, {failed} failed, {unexercised} not exercised)"
    )


def _value(value: object) -> str:
    return "-" if value in ("inf", None) else f"{float(value):.2f}"


def rows(points: list[TestPoint]) -> list[list[str]]:
    """The table: a header, then per test point its name, verdict, cases (passed/failed/not
    exercised), each oracle's value nearest to failing, and what failed."""
    header = ["test point", "verdict", "cases p/f/n", *(f"{o.title} ({o.unit})" for o in ORACLES), "what failed"]
    body = [
        [
            p.name,
            p.verdict,
            f"{p.passed}/{p.failed}/{p.not_exercised}",
            *(_value(p.worst[o.value_key]) for o in ORACLES),
            p.failure if p.verdict == DUT_FAILED else p.why_not if not p.item_passed else "",
        ]
        for p in sorted(points, key=lambda p: p.name)
    ]
    return [header, *body]


def text_table(points: list[TestPoint]) -> list[str]:
    """The table as aligned text lines (the last column left as it is)."""
    table = rows(points)
    widths = [max(len(row[i]) for row in table) for i in range(len(table[0]) - 1)]
    return ["  ".join([*(cell.ljust(w) for cell, w in zip(row, widths)), row[-1]]).rstrip() for row in table]


def html_table(points: list[TestPoint]) -> str:
    """The grade and the table as HTML, for the HTML report's summary."""
    table = rows(points)
    head = "".join(f"<th>{html.escape(cell)}</th>" for cell in table[0])
    body = "".join("<tr>" + "".join(f"<td>{html.escape(cell)}</td>" for cell in row) + "</tr>" for row in table[1:])
    return (
        f"<h2>Vehicle under test</h2><p>{html.escape(grade(points))}</p>"
        f'<table class="roadlogic-catalogue"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>'
    )
