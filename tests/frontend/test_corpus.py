"""A corpus of realistic .osc files: every file checks, and together they cover tier 1.

The files in tests/corpus are written from the examples in the standard's text and from
docs/language.md. Coverage is asserted, not hoped for: each tier-1 construct is matched by a
pattern over the corpus text, so deleting the only file that uses a construct fails here.
"""

import re
from pathlib import Path

import pytest

from pytest_roadlogic.frontend import check_file

CORPUS = Path(__file__).resolve().parents[1] / "corpus"
FILES = sorted(p for p in CORPUS.glob("*.osc"))

# tier-1 construct -> a pattern that finds it in source text
TIER_1 = {
    "import of the standard library": r"^import osc\.",
    "import of a file": r'^import "',
    "scenario tied to an actor type": r"^scenario \w+\.\w+:",
    "actor type car": r": car\b",
    "actor type truck": r": truck\b",
    "actor type vehicle": r": vehicle\b",
    "actor type stationary_object": r": stationary_object\b",
    "two fields declared together": r"^\s+\w+, \w+: \w+",
    "parameter of each physical type": r": length\b(?s:.*): speed\b(?s:.*): time\b|: speed\b(?s:.*): length\b",
    "parameter of int/uint/float/bool/string": r": uint\b(?s:.*): float\b(?s:.*): bool\b|: string\b",
    "parameter default": r"^\s+\w+: \w+ = ",
    "field with: block": r"^\s+\w+: \w+( = \S+)? with:$",
    "field with: on one line": r"^\s+\w+: \w+ with: keep\(",
    "keep hard": r"keep\(hard ",
    "keep default": r"keep\(default ",
    "keep with in": r"keep\(\w+ in \[",
    "keep with comparisons": r"keep\(it [<>]=? ",
    "remove_default": r"remove_default\(",
    "global parameter": r"^global ",
    "enum declaration": r"^enum \w+: \[",
    "do with serial": r"do serial",
    "parallel": r"parallel",
    "one_of": r"one_of",
    "labelled phases": r"^\s+\w+: \w+\.\w+\(",
    "labelled composition": r"^\s+\w+: (serial|parallel|one_of)",
    "composition with duration": r"(serial|parallel)\(duration: ",
    "action with duration": r"\.\w+\(duration: ",
    "drive": r"\.drive\(\)",
    "change_lane action": r"\.change_lane\(",
    "change_speed action": r"\.change_speed\(",
    "keep_speed action": r"\.keep_speed\(",
    "follow_lane action": r"\.follow_lane\(",
    "remain_stationary action": r"\.remain_stationary\(",
    "speed modifier": r"^\s+speed\(\[",
    "speed relative": r"speed\(.*faster_than:",
    "speed same_as": r"speed\(same_as:",
    "position behind": r"position\(.*behind:",
    "position ahead_of": r"position\(.*ahead_of:",
    "position time headway": r"position\(time:",
    "lane absolute": r"lane\(\d, at:",
    "lane from left": r"lane\(\d, from: left",
    "lane same_as": r"lane\(same_as:",
    "lane left_of": r"lane\(left_of:",
    "lane right_of": r"lane\(right_of:",
    "lane side_of with side": r"lane\(side_of: \w+, side: ",
    "keep_lane modifier": r"keep_lane\(\)",
    "keep_speed modifier": r"^\s+keep_speed\(\)",
    "at: start": r"at: start",
    "at: end": r"at: end",
    "at: all written out": r"at: all",
    "modifier without at (all)": r"^\s+lane\(\d\)$",
    "wait elapsed": r"wait elapsed\(\d",
    "wait elapsed range": r"wait elapsed\(\[",
    "wait condition": r"wait \w+\.speed",
    "range with unit after": r"\[[\d.]+\.\.[\d.]+\][a-z]",
    "range with units on bounds": r"\[[\d.]+[a-z]+\s*\.\.\s*[\d.]+[a-z]+\]",
    "length units m, cm, km, meter": r"\dcm\b(?s:.*)\dkm\b(?s:.*)\dmeter\b",
    "speed units mps, kph, kmph, mph": r"\dmps\b(?s:.*)\dkph\b(?s:.*)\dkmph\b(?s:.*)\dmph\b",
    "time units s, ms, sec, second, min": r"\dms\b(?s:.*)\dsec\b(?s:.*)\dsecond\b(?s:.*)\dmin\b",
    "hex literal": r"0x[0-9A-Fa-f]+",
    "float with exponent": r"\de\d",
    "negative literal": r"-\d",
    "strings in three spellings": r'"[^"]+"(?s:.*)\'[^\']+\'(?s:.*)"""',
    "true/false": r"\b(true|false)\b",
    "inf": r"\binf\b",
    "qualified enum value": r"\w+!\w+",
    "arithmetic in an argument": r"position\(\w+ \+ \w+",
    "relation between parameters": r"keep\(\w+ \+ \w+ <=",
    "quoted identifier": r"\|[^|\n]+\|",
    "line joined inside brackets": r"\.\.\n",
    "line joined by backslash": r"\\\n",
    "comment": r"#",
    "several scenarios in a file": r"^scenario(?s:.*)^scenario",
    # events and conditions
    "emit": r"^\s+emit \w+$",
    "wait for an event": r"wait @\w+$",
    "wait for an event with a condition": r"wait @\w+ if ",
    "until an event": r"until @\w+$",
    "until a condition on a method": r"until \(?\w+\.\w+\(reference: ",
    "event defined by elapsed time": r"event \w+ is elapsed\(",
    "condition with or / not": r" or not ",
    # CARLA-style libraries
    "physical type declaration": r"^type \w+ is SI\(",
    "unit declaration with a factor": r"^unit \w+ of \w+ is SI\(.*factor: ",
    "unquoted import of a file": r"^import \w+\.osc$",
    "bare actor type": r"^actor \w+$",
    "modifier declaration": r"^modifier \w+\.\w+$",
    "set_map": r"\.set_map\(",
    "drive(path)": r"\.drive\(path\)",
    # issue 18: the rest of the standard's constructs that run
    "acceleration modifier": r"^\s+acceleration\(\[",
    "braking to a stop": r"change_speed\(target: 0kph",
    "scenario call with arguments": r"do dut\.\w+\(\w+: ",
    "labelled scenario calls": r"^\s+first: dut\.\w+\(",
    "emit and wait across threads": r"until @\w+",
    "distance modifier": r"^\s+distance\(\[",
    "keep_position action": r"\.keep_position\(\)",
    "assign_speed action": r"\.assign_speed\(",
    "change_speed with rate_peak": r"change_speed\(.*rate_peak: ",
    "change_lane with a range of lanes": r"change_lane\(\[\d\.\.\d\]",
    "along the road": r"^\s+along\(path\)",
    "avoid_collisions": r"avoid_collisions\(true\)",
    "import of one part of the standard library": r"^import osc\.physical$",
    "actor derived from an abstract library actor": r"^actor \w+ inherits movable_object$",
    "event with a parameter": r"^\s+event \w+\(\w+: ",
    "event defined by a condition": r"^\s+event \w+ is \(",
    "wait for an event with a condition on another actor": r"wait @\w+ if \w+\.speed",
    "gap actions (tier 2)": r"\.keep_space_gap\((?s:.*)\.change_time_gap\(",
    "lateral distance": r"^\s+lateral\(",
    "the environment's weather, read and set aside": r"^\s+environment\.air\((?s:.*)^\s+\w+\.rain\(",
    "scenario call with positional arguments": r"\.hold_lane_at\(\d",
}

# The files written for issue 18 (the public suites' styles, the standard's whole vocabulary):
# 46-59 and 60-104 with carla_types.osc, carla_highway.osc and lib/maneuvers.osc.
ISSUE_18_FILES = [p for p in FILES if p.stem[:2].isdigit() and int(p.stem.split("_")[0]) >= 46] + [
    CORPUS / "carla_types.osc",
    CORPUS / "carla_highway.osc",
]


def corpus_text() -> str:
    return "\n".join(p.read_bytes().decode("utf-8") for p in [*FILES, *CORPUS.glob("lib/*.osc")])


def test_the_corpus_has_at_least_60_files_written_for_the_standards_whole_language():
    assert len(FILES) >= 100
    assert len(ISSUE_18_FILES) >= 60


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_every_corpus_file_says_in_its_first_comment_what_it_exercises(path):
    text = path.read_bytes().decode("utf-8").replace("\t", " ")
    assert re.match(r"#\s*\S.{20,}", text) or path.name in ("32_tabs.osc", "33_crlf_no_final_newline.osc"), (
        "start the file with a comment line saying what it exercises"
    )


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_every_corpus_file_checks_without_errors(path):
    result = check_file(path)
    assert not result.errors, result.report()


@pytest.mark.parametrize("construct", sorted(TIER_1))
def test_the_corpus_covers_every_tier_1_construct(construct):
    assert re.search(TIER_1[construct], corpus_text(), re.MULTILINE), f"no corpus file uses: {construct}"


# Driving scenarios of the corpus that run end to end at seed 1 (plan, simulate, monitor: accepted
# within the tries a rejection allows), in the styles of the public suites; (file, dialect).
# benchmarks/corpus.py prints the whole corpus's table.
RUNNABLE = [
    ("03_cut_in.osc", None),
    ("04_cut_in_dut.osc", None),
    ("15_serial_labels.osc", None),
    ("16_one_of.osc", None),
    ("19_lane_relative.osc", None),
    ("23_change_speed.osc", None),
    ("27_wait.osc", None),
    ("37_import_library.osc", None),
    ("39_events.osc", None),
    ("46_time_headway.osc", None),
    ("47_conditions.osc", None),
    ("48_emit_wait.osc", None),
    ("49_carla_style.osc", "carla"),
    ("50_acceleration.osc", None),
    ("51_scenario_call.osc", None),
    ("52_carla_cut_in_call.osc", "carla"),
    ("53_stop_and_go.osc", None),
    ("54_headway_then_brake.osc", None),
    ("55_event_after_cut_in.osc", None),
    ("56_three_lane_weave.osc", None),
    ("57_paper_listing_overtake.osc", None),
    ("58_obstacle_keep_speed.osc", None),
    ("59_library_call_twice.osc", None),
    ("60_distance_cruise.osc", None),
    ("61_parked_keep_position.osc", None),
    ("62_assign_then_slow.osc", None),
    ("63_change_lane_range.osc", None),
    ("64_along_no_collision_follow.osc", None),
    ("65_carla_lead_slowdown.osc", "carla"),
    ("66_carla_overtake_van.osc", "carla"),
    ("67_physical_part_import.osc", None),
    ("68_wait_until_slow.osc", None),
    ("69_headway_kph.osc", None),
    ("70_one_of_pass_side.osc", None),
    ("71_truck_overtake.osc", None),
    ("72_overlap_equal.osc", None),
    ("78_event_with_parameter.osc", None),
    ("79_robot_style_params.osc", None),
    ("81_dut_owned_cut_out.osc", None),
    ("85_wait_event_if.osc", None),
    ("86_event_is_condition.osc", None),
    ("95_scenario_calls_positional.osc", None),
    ("99_same_lane_relative.osc", None),
    ("100_until_condition_or.osc", None),
    ("101_stationary_obstacle_dodge.osc", None),
    ("103_time_headway_ahead.osc", None),
    ("104_acceleration_then_distance.osc", None),
    ("105_scenario_inheritance.osc", None),
    ("106_traveled_distance_condition.osc", None),
    ("107_relative_lane_condition.osc", None),
    ("108_builtin_end_event.osc", None),
    ("42_gap_actions.osc", None),
    ("75_keep_space_gap.osc", None),
    ("76_change_time_gap.osc", None),
    ("109_runner_mph_library.osc", None),
    ("110_unplanned_dimensions.osc", None),
    ("111_global_map_and_anchor.osc", None),
    ("112_overtake_ego_returns.osc", None),
    ("113_carla_targets_in_sequence.osc", "carla"),
    ("114_gap_methods_and_casts.osc", None),
    ("116_delayed_cut_in_start_to_start.osc", None),
]


@pytest.mark.slow
@pytest.mark.parametrize("name, dialect", RUNNABLE, ids=[n for n, _ in RUNNABLE])
def test_corpus_driving_scenarios_run_end_to_end_and_are_accepted(name, dialect):
    from pytest_roadlogic.pipeline import load_scenario, run_scenario

    outcome = run_scenario(load_scenario(CORPUS / name, dialect=dialect), seed=1)
    assert outcome.verdict.accepted, outcome.verdict.explain()


def test_tabs_crlf_and_a_missing_final_newline_are_in_the_corpus():
    raw = {p.name: p.read_bytes() for p in FILES}
    assert any(b"\n\t" in data for data in raw.values())
    assert any(b"\r\n" in data for data in raw.values())
    assert any(not data.endswith(b"\n") for data in raw.values())
