"""The catalogue's summary is read from the items' JUnit properties: a test point failed when a case
failed an oracle, passed when one passed and none failed, not exercised otherwise; the grade is the
share passed."""

from pytest_roadlogic.dut.catalogue import grade, html_table, point_from, text_table


def properties(passed=0, failed=0, not_exercised=0, **extra):
    return {
        "vehicle_under_test": "dut.car",
        "passed": passed,
        "failed": failed,
        "not_exercised": not_exercised,
        "dut_least_time_to_collision_s": 1.2 if failed else "inf",
        **extra,
    }


def test_an_item_without_a_vehicle_under_test_is_no_test_point():
    assert point_from("x.osc::x", {"conformant": 3}) is None


def test_verdicts_grade_and_table_say_what_each_test_point_did():
    points = [
        point_from("a.osc::a", properties(passed=3)),
        point_from("b.osc::b", properties(passed=2, failed=1, explanation="dut.car: time to collision 1.20 s")),
        point_from("c.osc::c", properties(not_exercised=2)),
    ]
    assert [p.verdict for p in points] == ["passed", "failed", "not exercised"]
    assert grade(points) == "grade 33% (1 of 3 test points passed, 1 failed, 1 not exercised)"
    lines = text_table(points)
    assert lines[0].startswith("test point") and "least time to collision (s)" in lines[0]
    failed_row = next(line for line in lines if line.startswith("b.osc::b"))
    assert "failed" in failed_row and "2/1/0" in failed_row and "1.20" in failed_row
    assert failed_row.endswith("dut.car: time to collision 1.20 s")
    assert "<table" in html_table(points) and "grade 33%" in html_table(points)


def test_an_item_that_failed_without_an_oracle_failing_is_not_exercised_and_its_row_says_why():
    # a case ran over its time limit, or most cases tested nothing: the item failed, so the test
    # point did not pass, whatever its other cases did
    timed_out = point_from(
        "d.osc::d", properties(passed=1), item_passed=False, report="simulation timed out: over 120 s\nmore lines"
    )
    mostly = point_from("e.osc::e", properties(passed=4, not_exercised=6), item_passed=False, report="6 of 10 ...")
    assert [timed_out.verdict, mostly.verdict] == ["not exercised", "not exercised"]
    assert grade([timed_out, mostly]) == "grade 0% (0 of 2 test points passed, 0 failed, 2 not exercised)"
    row = next(line for line in text_table([timed_out]) if line.startswith("d.osc::d"))
    assert row.endswith("simulation timed out: over 120 s")
