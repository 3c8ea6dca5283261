"""Coverage as the standard writes it: a cover item's buckets are the slices its arguments name, a
run counts each case whose scenario happened in the bucket its value falls in, and a bucket no
case hit is called unreachable only with a proof: outside the parameter's range, or no plan."""

from __future__ import annotations

import json
import subprocess
import sys
from xml.etree import ElementTree

import numpy as np
import pytest

from pytest_roadlogic.evaluation.coverage import ScenarioCoverage, merged, read_json, text_lines, write_json
from pytest_roadlogic.evaluation.reach import unreachable
from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.outcomes import CONFORMANT, NO_PLAN
from pytest_roadlogic.runner import Runner
from pytest_roadlogic.settings import RunSettings
from tests.conftest import ROOT

pytest_plugins = ["pytester"]

HEAD = "scenario s:\n    ego: car\n    npc: car\n"
BODY = (
    "    do parallel(duration: 5s):\n        ego.drive() with:\n            speed(20mps)\n"
    "        npc.drive() with:\n            position(gap, behind: ego, at: start)\n"
    "            position(10m, ahead_of: ego, at: end)\n            speed([10mps..30mps])\n"
)
GAP = "    gap: length with:\n        keep(it in [10m..100m])\n"


def items_of(text: str):
    checked = check_text(text, "s.osc")
    assert not checked.errors, checked.report()
    return checked.scenarios[0]


@pytest.mark.parametrize(
    "cover, labels",
    [
        ("cover(gap, unit: m, range: [0..120], every: 40)", ["[0..40) m", "[40..80) m", "[80..120] m"]),
        ("cover(gap, unit: cm, range: [0..6000], every: 2500)", ["[0..2500) cm", "[2500..5000) cm", "[5000..6000] cm"]),
        ("cover(gap, unit: m, buckets: [10, 20, 65.5, 100])", ["[10..20) m", "[20..65.5) m", "[65.5..100] m"]),
        ("cover(gap)", ["[10..28) m", "[28..46) m", "[46..64) m", "[64..82) m", "[82..100] m"]),
    ],
    ids=["range and every", "another unit", "boundaries", "the parameter's range in five"],
)
def test_a_cover_items_buckets_are_the_slices_its_arguments_name(cover, labels):
    scenario = items_of(HEAD + GAP + f"    {cover}\n" + BODY)
    (item,) = scenario.coverage
    assert [b.label for b in item.buckets] == labels
    # every value of the range falls in exactly one bucket, the range's end in the last
    for value in (10.0, 39.999, 40.0, 64.0, 99.9, 100.0):
        assert sum(b.holds(value) for b in item.buckets) <= 1


def test_a_bool_and_a_small_whole_number_have_a_bucket_per_value():
    text = (
        HEAD
        + GAP
        + "    left: bool\n    lane_k: uint with:\n        keep(it in [1..3])\n"
        + "    cover(left)\n    cover(lane_k)\n"
        + BODY.replace("speed(20mps)", "speed(20mps)\n            lane(lane_k)")
    )
    buckets = {item.name: [b.label for b in item.buckets] for item in items_of(text).coverage}
    assert buckets == {"left": ["false", "true"], "lane_k": ["1", "2", "3"]}


@pytest.mark.parametrize(
    "cover, message",
    [
        ("cover(gap, unit: kph)", "unit kph is a unit of speed, but gap is a length"),
        ("cover(gap, unit: m, range: [0..10], buckets: [1, 2])", "buckets: is given with range: or every:"),
        (
            "cover(speed_of_ego, expression: ego.speed)",
            "cover(speed_of_ego) of a value the run takes needs its buckets",
        ),
        ("cover(ttc, expression: ego.time_to_collision(npc))", "not supported yet: cover() of this value of the run"),
        ("cover(gap_by_a, items: [gap, a])", "gap is no cover item declared before this cross"),
        ("cover(nothing)", "nothing is no logical parameter of the scenario"),
    ],
    ids=[
        "a unit of another kind",
        "buckets and a range",
        "a run value without buckets",
        "a method of the run",
        "a cross",
        "an unknown name",
    ],
)
def test_an_item_the_tool_cannot_collect_is_a_located_warning_and_the_scenario_still_runs(cover, message):
    checked = check_text(HEAD + GAP + f"    {cover}\n" + BODY, "s.osc")
    assert not checked.errors
    (warning,) = [d for d in checked.diagnostics if "not collected" in d.message]
    assert message in warning.message and warning.location.line == 6
    assert checked.scenarios[0].coverage == ()


CATCH_UP = HEAD + GAP + "    cover(gap, unit: m, range: [0..120], every: 20)\n" + BODY


def test_a_run_counts_each_case_whose_scenario_happened_in_the_bucket_of_its_value():
    scenario = items_of(CATCH_UP)
    results = []
    Runner(scenario, RunSettings(seed=3)).refined(results.append, count=12, search=False)
    coverage = ScenarioCoverage.of("s.osc::s", scenario.coverage)
    for result in results:
        coverage.add(scenario.coverage, result.case.values, result.outcome)
    (item,) = scenario.coverage
    happened = [r.case.values["gap"] for r in results if r.outcome == CONFORMANT]
    assert any(r.outcome == NO_PLAN for r in results), "some gaps cannot be caught up: not counted"
    expected = {b.label: sum(b.holds(v) for v in happened) for b in item.buckets}
    assert coverage.items["gap"].buckets == expected and coverage.cases == len(happened)


def test_a_bucket_is_unreachable_only_outside_the_range_or_where_the_planner_proves_no_plan():
    scenario = items_of(CATCH_UP)
    (item,) = scenario.coverage
    labels = [b.label for b in item.buckets]
    found = unreachable(scenario, item, labels, RunSettings(), 1)
    # the npc gains at most 10 m/s on the ego for 5 s and must end 10 m ahead: 40 m of gap at most
    assert set(found) == {"[60..80) m", "[80..100) m", "[100..120] m"}
    assert all("cannot hold at the same time" in why and "parameter gap" in why for why in found.values())
    # brute force from the definition: some value of a bucket (every 4 m of it within the range)
    # has a plan exactly where the bucket is not claimed unreachable
    runner = Runner(scenario, RunSettings(seed=1))
    for bucket in item.buckets:
        values = [v for v in range(int(bucket.low), int(bucket.high) + 1, 4) if 10 <= v <= 100 and bucket.holds(v)]
        planned = any(
            runner.run_case(runner.case(strategy="refined", values={"gap": float(v)})).outcome != NO_PLAN
            for v in values
        )
        assert planned == (bucket.label not in found), (bucket.label, values)
    # below the parameter's range: said so, without planning
    low = check_text(CATCH_UP.replace("[10m..100m]", "[25m..35m]"), "s.osc").scenarios[0]
    outside = unreachable(low, low.coverage[0], ["[0..20) m"], RunSettings(), 1)
    assert outside == {"[0..20) m": "outside the range of gap, 25 m to 35 m (s.osc:4)"}


def test_tallies_travel_as_json_and_merge_per_scenario(tmp_path):
    scenario = items_of(CATCH_UP)
    first, second = (ScenarioCoverage.of("s.osc::s", scenario.coverage) for _ in range(2))
    first.add(scenario.coverage, {"gap": 15.0}, CONFORMANT)
    second.add(scenario.coverage, {"gap": 15.0}, CONFORMANT)
    second.add(scenario.coverage, {"gap": 35.0}, CONFORMANT)
    second.items["gap"].unreachable["[60..80) m"] = "no plan"
    (both,) = merged([ScenarioCoverage.from_json(json.loads(json.dumps(c.to_json()))) for c in (first, second)])
    assert (
        both.cases == 3 and both.items["gap"].buckets["[0..20) m"] == 2 and both.items["gap"].buckets["[20..40) m"] == 1
    )
    write_json([both], tmp_path / "c.json")
    assert read_json(tmp_path / "c.json") == [both]
    assert "    [60..80) m                unreachable: no plan" in text_lines([both])
    (tmp_path / "bad.json").write_text("{}")
    with pytest.raises(ValueError, match="not a coverage file"):
        read_json(tmp_path / "bad.json")


def test_pytest_reports_coverage_merged_over_workers_and_writes_it_for_a_ci(pytester):
    pytester.makefile(".osc", catch_up=CATCH_UP.replace("scenario s:", "scenario catch_up:"))
    pytester.makefile(".osc", second=CATCH_UP.replace("scenario s:", "scenario second:").replace("seed", "seed"))
    result = pytester.runpytest_subprocess(
        "-p", "no:cacheprovider", "-n", "2", "--roadlogic-examples", "4", "--roadlogic-coverage", "out/cov.json"
    )
    text = result.stdout.str()
    assert "roadlogic coverage" in text and "catch_up.osc::catch_up" in text and "second.osc::second" in text
    assert "unreachable: no plan exists" in text
    written = read_json(pytester.path / "out" / "cov.json")
    assert [c.scenario for c in written] == ["catch_up.osc::catch_up", "second.osc::second"]
    # a file that cannot be written is said, never raised
    (pytester.path / "blocked").write_text("a file, not a folder")
    result = pytester.runpytest_subprocess(
        "-p",
        "no:cacheprovider",
        "--roadlogic-examples",
        "2",
        "--roadlogic-coverage",
        "blocked/cov.json",
        "catch_up.osc",
    )
    assert "--roadlogic-coverage blocked/cov.json: cannot write it" in result.stdout.str()
    assert "Traceback" not in result.stdout.str() + result.stderr.str()


def test_a_cross_counts_each_combination_and_proves_a_combination_unreachable_by_planning_both_held():
    from pathlib import Path

    from pytest_roadlogic.frontend import load_file

    path = Path(__file__).resolve().parents[2] / "scenarios" / "coverage" / "catch_up_from_behind.osc"
    scenario = load_file(path).scenario_to_run(None)
    cross = next(item for item in scenario.coverage if item.crossed)
    assert cross.crossed == ("gap", "top") and len(cross.buckets) == 6
    results = []
    Runner(scenario, RunSettings(seed=2)).refined(results.append, count=10, search=False)
    coverage = ScenarioCoverage.of("catch_up", scenario.coverage)
    for result in results:
        coverage.add(scenario.coverage, result.case.values, result.outcome)
    items = {i.name: i for i in scenario.coverage}
    expected = {b.label: 0 for b in cross.buckets}
    for result in results:
        if result.outcome == CONFORMANT:
            gap = next(b for b in items["gap"].buckets if b.holds(result.case.values["gap"]))
            top = next(b for b in items["top"].buckets if b.holds(result.case.values["top_speed"]))
            expected[f"{gap.label} x {top.label}"] += 1
    assert coverage.items["gap_by_top"].buckets == expected
    found = unreachable(scenario, cross, [b.label for b in cross.buckets], RunSettings(), 1)
    assert set(found) == {"[80..120] m x [25..35) mps"}
    # brute force: every pair of values on a grid of the combination has no plan there, and one of
    # the combination next to it (the same gaps, the faster top speeds) has one
    runner = Runner(scenario, RunSettings(seed=1))

    def outcome(gap: float, top: float) -> str:
        return runner.run_case(runner.case(strategy="refined", values={"gap": gap, "top_speed": top})).outcome

    assert all(outcome(gap, top) == NO_PLAN for gap in (80.0, 90.0, 100.0) for top in (25.0, 30.0, 34.9))
    assert any(outcome(gap, top) != NO_PLAN for gap in (80.0, 85.0) for top in (38.0, 40.0))


def test_a_value_of_the_run_is_read_at_its_event_and_a_bucket_the_scenario_rules_out_there_is_unreachable():
    from pathlib import Path

    import numpy as np

    from pytest_roadlogic.frontend import load_file

    path = Path(__file__).resolve().parents[2] / "scenarios" / "coverage" / "cut_in_gap_at_the_cut_in.osc"
    scenario = load_file(path).scenario_to_run(None)
    items = {item.name: item for item in scenario.coverage}
    gap = items["gap_at_cut_in"]
    assert gap.observed is not None and gap.event == ("cut_in", "end")
    results = []
    Runner(scenario, RunSettings(seed=1)).refined(results.append, count=4, search=False)
    coverage = ScenarioCoverage.of("cut_in", scenario.coverage)
    for result in results:
        coverage.add(scenario.coverage, result.case.values, result.outcome, result.run)
    # from the definition: the gap between the cars' centres at the first sample at or after the
    # time the monitor's run ended the cut_in phase (the transition that ends it, by its events)
    expected = {b.label: 0 for b in gap.buckets}
    for result in results:
        assert result.outcome == CONFORMANT
        automaton, trace = result.run.automaton, result.run.simulation.trace
        ends = {t.label for t in automaton.transitions for k in t.ends if automaton.timings[k].name == "cut_in"}
        time = next(t for t, events in result.run.verdict.run if events in ends)
        k = int(np.searchsorted(trace.times, time - 1e-9))
        value = trace.actors["npc"]["x"][k] - trace.actors["ego"]["x"][k]
        expected[next(b.label for b in gap.buckets if b.holds(value))] += 1
    assert coverage.items["gap_at_cut_in"].buckets == expected
    assert len(coverage.items["npc_speed_at_cut_in"].recorded) == 4
    # the scenario asks for a gap of 10-25 m when the cut-in ends: every bucket wholly outside
    # that is unreachable, and none that holds a gap it allows ([25..30) holds 25 m itself)
    found = unreachable(scenario, gap, [b.label for b in gap.buckets], RunSettings(), 1)
    outside = {b.label for b in gap.buckets if b.high <= 10.0 or b.low > 25.0}
    assert set(found) == outside
    assert all("cannot hold at the same time" in why for why in found.values())


def test_closure_asks_one_case_inside_each_bucket_not_hit_nor_ruled_out():
    from pytest_roadlogic.evaluation.closure import closing_values

    scenario = items_of(CATCH_UP)
    coverage = ScenarioCoverage.of("s", scenario.coverage)
    coverage.add(scenario.coverage, {"gap": 15.0}, CONFORMANT)
    coverage.items["gap"].unreachable["[60..80) m"] = "no plan"
    asked = {label: tries for _, label, tries in closing_values(scenario, coverage)}
    # [0..20) is hit; [60..80) is ruled out; the others are tried from their middle (within 10-100 m)
    assert set(asked) == {"[20..40) m", "[40..60) m", "[80..100) m", "[100..120] m"}
    assert [t["gap"] for t in asked["[20..40) m"]] == [30.0, 24.0, 36.0, 20.4, 39.6]
    assert [t["gap"] for t in asked["[100..120] m"]] == [100.0]  # the range ends at its low edge
    buckets = {b.label: b for b in scenario.coverage[0].buckets}
    assert all(buckets[label].holds(t["gap"]) for label, tries in asked.items() for t in tries)


def test_pytest_with_closure_covers_every_reachable_bucket_in_few_cases(pytester):
    from pathlib import Path

    source = Path(__file__).resolve().parents[2] / "scenarios" / "coverage" / "catch_up_from_behind.osc"
    pytester.makefile(".osc", catch_up=source.read_text())
    result = pytester.runpytest_subprocess(
        "-p",
        "no:cacheprovider",
        "--roadlogic-examples",
        "3",
        "--roadlogic-coverage-closure",
        "yes",
        "--roadlogic-coverage",
        "cov.json",
    )
    (coverage,) = read_json(pytester.path / "cov.json")
    for item in coverage.items.values():
        assert all(hits >= 1 or label in item.unreachable for label, hits in item.buckets.items()), item
    assert "closure:" in result.stdout.str()
    bad = pytester.runpytest_subprocess("-p", "no:cacheprovider", "--roadlogic-coverage-closure", "maybe")
    assert "--roadlogic-coverage-closure 'maybe': give yes or no" in bad.stderr.str() + bad.stdout.str()
    assert "Traceback" not in bad.stderr.str()


RECORDED = ROOT / "scenarios" / "coverage" / "cut_in_gap_at_the_cut_in.osc"


def test_a_case_keeps_what_it_records_in_the_cli_report_the_verdict_and_the_case_file_which_replays(tmp_path):
    out = tmp_path / "out"
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest_roadlogic.cli",
            "run",
            str(RECORDED),
            "--out",
            str(out),
            "--artifacts",
            "essential",
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=600,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    line = next(line for line in run.stdout.splitlines() if line.strip().startswith("recorded:"))
    verdict = json.loads((out / "verdict.json").read_text())
    case = json.loads((out / "case.json").read_text())
    (value,) = verdict["recorded"].values()
    assert verdict["recorded"] == case["recorded"] and list(verdict["recorded"]) == ["npc_speed_at_cut_in"]
    assert line.strip() == f"recorded: npc_speed_at_cut_in {value}" and value.endswith(" kph")
    # the npc is the faster car: what it records lies above the ego's sampled speed range's bottom
    assert float(value.split()[0]) > 80
    replay = subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", "replay", str(out / "case.json"), "--artifacts", "none"],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=600,
    )
    assert replay.returncode == 0, replay.stderr
    assert f"recorded: npc_speed_at_cut_in {value}" in replay.stdout


def test_junit_lists_each_record_items_values_over_the_items_cases(pytester):
    pytester.makefile(".osc", cut_in=RECORDED.read_text())
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider", "--roadlogic-examples", "3", "--junitxml", "j.xml")
    assert "Traceback" not in result.stdout.str()
    properties = {p.get("name"): p.get("value") for p in ElementTree.parse(pytester.path / "j.xml").iter("property")}
    values = properties["record_npc_speed_at_cut_in"].split(", ")
    assert 1 <= len(values) <= 3 and all(v.endswith(" kph") for v in values)


def test_a_coverage_database_adds_each_runs_tally_and_drops_one_counted_on_a_changed_file(tmp_path):
    from pytest_roadlogic.evaluation.coverage_db import database_lines, read

    scenario = items_of(CATCH_UP)
    database = tmp_path / "db.json"
    first, second = (ScenarioCoverage.of("s.osc::s", scenario.coverage, "abc") for _ in range(2))
    first.add(scenario.coverage, {"gap": 15.0}, CONFORMANT)
    second.add(scenario.coverage, {"gap": 55.0}, CONFORMANT)
    database_lines(database, [first], "--db")
    lines, _ = database_lines(database, [second], "--db")
    (both,) = read(database)
    assert (
        both.cases == 2 and both.items["gap"].buckets["[0..20) m"] == 1 and both.items["gap"].buckets["[40..60) m"] == 1
    )
    assert any("s.osc::s: 2 cases" in line for line in lines)
    edited = ScenarioCoverage.of("s.osc::s", scenario.coverage, "def")  # the file changed
    edited.add(scenario.coverage, {"gap": 95.0}, CONFORMANT)
    lines, _ = database_lines(database, [edited], "--db")
    (after,) = read(database)
    assert after.cases == 1 and after.fingerprint == "def"
    assert "s.osc::s: its file changed since the earlier runs; their counts were dropped" in lines
    # a file that is not a database is neither read nor overwritten
    (tmp_path / "notes.json").write_text("my notes")
    (line,), _ = database_lines(tmp_path / "notes.json", [edited], "--db")
    assert line.startswith("roadlogic: --db ") and "not overwritten" in line
    assert (tmp_path / "notes.json").read_text() == "my notes"


def test_pytest_with_a_coverage_database_asks_closure_only_for_buckets_no_earlier_run_hit(pytester):
    pytester.makefile(".osc", catch_up=(ROOT / "scenarios" / "coverage" / "catch_up_from_behind.osc").read_text())
    run = ("-p", "no:cacheprovider", "--roadlogic-coverage-closure", "yes", "--roadlogic-coverage-db", "db.json")
    first = pytester.runpytest_subprocess(*run, "--roadlogic-examples", "3")
    asked = [line for line in first.stdout.lines if line.startswith("closure: ")]
    assert asked, first.stdout.str()
    second = pytester.runpytest_subprocess(*run, "--roadlogic-examples", "1", "--hypothesis-seed", "9")
    text = second.stdout.str()
    assert "coverage database db.json: this run added to the earlier runs'" in text
    # every reachable bucket was closed by the first session: the second asks none
    assert not [line for line in second.stdout.lines if line.startswith("closure: ")], text
    (both,) = read_json(pytester.path / "db.json")
    assert both.cases >= 4


def test_the_html_report_draws_each_item_as_bars_a_cross_as_a_grid_and_escapes_the_scenarios_text(pytester):
    source = (ROOT / "scenarios" / "coverage" / "catch_up_from_behind.osc").read_text()
    hostile = source.replace('"how far behind the other car starts"', '"<script>alert(1)</script>"')
    assert hostile != source
    pytester.makefile(".osc", catch_up=hostile)
    pytester.runpytest_subprocess(
        "-p", "no:cacheprovider", "--roadlogic-examples", "3", "--html", "report.html", "--self-contained-html"
    )
    page = (pytester.path / "report.html").read_text()
    section = page[page.index('<div class="roadlogic-coverage">') :]
    assert "<script>alert(1)</script>" not in section and "&lt;script&gt;alert(1)&lt;/script&gt;" in section
    assert section.count('<table class="roadlogic-coverage-bars">') == 2  # gap and top
    grid = section[section.index('<table class="roadlogic-coverage-grid">') :]
    grid = grid[: grid.index("</table>")]
    # rows the gap's three buckets, columns the top speed's two; the combination no car can reach greyed
    assert grid.count("<tr><th>[") == 3 and grid.count("<th>[25..35) mps</th>") == 1
    assert 'background:#bdbdbd" title="unreachable: no plan exists' in grid


SAMPLED = """scenario s:
    ego: car
    npc: car
    var gap_at_end: length = sample(ego.space_gap(npc), @pass)
    cover(gap_at_end, expression: gap_at_end > 50cm, unit: m, range: [-20..40], every: 10)
    do serial:
        pass: parallel(duration: 5s):
            ego.drive() with:
                speed(20mps)
            npc.drive() with:
                position(20m, behind: ego, at: start)
                position([10m..15m], ahead_of: ego, at: end)
"""


def test_a_var_sampled_at_a_phase_is_the_gap_between_bumpers_at_its_end_and_the_gaps_ruled_out_are_proved():
    checked = check_text(SAMPLED, "s.osc")
    assert not checked.errors, checked.report()
    # as public files write it: expression: compares the var beside range: and every:
    (warned,) = [d for d in checked.diagnostics if "expression: compares gap_at_end" in d.message]
    assert warned.location.line == 5
    scenario = checked.scenarios[0]
    (item,) = scenario.coverage
    assert item.event == ("pass", "end")  # @pass: the phase's end
    result = Runner(scenario, RunSettings(seed=2)).run_case(
        Runner(scenario, RunSettings(seed=2)).case(strategy="base", instance=0)
    )
    assert result.outcome == CONFORMANT, result.message
    coverage = ScenarioCoverage.of("s", scenario.coverage)
    coverage.add(scenario.coverage, {}, result.outcome, result.run)
    trace = result.run.simulation.trace
    end = max(t for t, _ in result.run.verdict.run)
    k = int(np.searchsorted(trace.times, end - 1e-9))
    centres = trace.actors["npc"]["x"][k] - trace.actors["ego"]["x"][k]
    (hit,) = [label for label, hits in coverage.items["gap_at_end"].buckets.items() if hits]
    gap = centres - 4.5
    assert 5.5 - 0.5 <= gap <= 10.5 + 0.5, gap
    assert hit == ("[0..10) m" if gap < 10 else "[10..20) m")
    labels = list(coverage.items["gap_at_end"].buckets)
    proved = unreachable(scenario, item, labels, RunSettings(seed=2), 2)
    assert set(proved) == {"[-20..-10) m", "[-10..0) m", "[20..30) m", "[30..40] m"}, proved


def test_a_sampled_var_declared_of_another_kind_than_its_value_is_a_located_warning_and_not_collected():
    checked = check_text(SAMPLED.replace("var gap_at_end: length", "var gap_at_end: speed"), "s.osc")
    (said,) = [d for d in checked.diagnostics if "samples a length, not a speed" in d.message]
    assert (said.location.line, said.severity) == (4, "warning") and "the item is not collected" in said.message
    assert checked.scenarios[0].coverage == ()
