"""`roadlogic bench`: the paper's evaluation. The quick run goes end to end here; the full run is
selected with --run-bench (about 10 minutes on two cores)."""

import json
import math
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

from pytest_roadlogic.evaluation import Occupancy, jaccard, mean_pairwise
from pytest_roadlogic.outcomes import STAGES
from pytest_roadlogic.simulation.trace import Trace
from tests.conftest import ROOT

SCENARIOS = sorted(p.stem for p in (ROOT / "scenarios").glob("*.osc"))
OUTCOMES = ("conformant", "non-conformant", "timed out", "no plan")


def bench(*args, cwd=ROOT):
    return subprocess.run(
        [sys.executable, "-m", "pytest_roadlogic.cli", "bench", *args], capture_output=True, text=True, cwd=cwd
    )


# ------------------------------------------------------------------ the metric


def trace_of(**vehicles):
    """A trace of vehicles given as lists of (x, lane), one per instant."""
    length = len(next(iter(vehicles.values())))
    actors = {}
    for name, states in vehicles.items():
        x = np.array([s[0] for s in states], dtype=float)
        lane = np.array([s[1] for s in states], dtype=float)
        zeros = np.zeros(length)
        actors[name] = {"x": x, "y": zeros, "heading": zeros, "speed": zeros, "acceleration": zeros, "lane": lane}
    return Trace(np.arange(length) * 0.1, actors)


def test_a_car_occupies_the_cells_its_body_covers_in_its_lane():
    occupancy = Occupancy.of_trace(trace_of(v1=[(10.0, 1)]))
    # a 4.5 m car centred at 10 m covers 7.75..12.25 m: cells 7 to 12
    assert occupancy.cells() == {(1, k) for k in range(7, 13)}


def test_occupancy_is_the_union_over_time_and_vehicles():
    occupancy = Occupancy.of_trace(trace_of(v1=[(10.0, 0), (11.0, 0), (11.0, 1)], v2=[(50.0, 2), (50.0, 2), (50.0, 2)]))
    assert occupancy.runs == {0: ((7, 13),), 1: ((8, 13),), 2: ((47, 52),)}


def test_occupancy_survives_the_results_file():
    occupancy = Occupancy.of_trace(trace_of(v1=[(10.0, 0), (30.0, 0)], v2=[(-5.0, 1), (-4.0, 1)]))
    assert Occupancy.from_json(json.loads(json.dumps(occupancy.to_json()))) == occupancy


def test_jaccard_index_of_occupied_cells():
    a, b = {(0, 1), (0, 2), (0, 3)}, {(0, 2), (0, 3), (0, 4), (0, 5)}
    assert jaccard(a, a) == 1.0
    assert jaccard(a, {(1, 1)}) == 0.0
    assert jaccard(a, b) == pytest.approx(2 / 5)


def test_mean_pairwise_similarity_ignores_the_diagonal():
    assert mean_pairwise([[1.0, 0.2, 0.4], [0.2, 1.0, 0.6], [0.4, 0.6, 1.0]]) == pytest.approx(0.4)
    assert math.isnan(mean_pairwise([[1.0]]))


# ------------------------------------------------------------------ the quick run, end to end


@pytest.fixture(scope="module")
def quick(tmp_path_factory):
    out = tmp_path_factory.mktemp("bench")
    result = bench("scenarios", "--quick", "--seed", "3", "--out", str(out))
    assert result.returncode in (0, 1), result.stderr  # 1: a target missed, which small samples may do
    return out, result


def table_after(report: str, heading: str) -> list[dict[str, str]]:
    """The first Markdown table after ``heading``, as rows of column -> cell."""
    lines = report[report.index(heading) :].splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("|"))
    rows = []
    for line in lines[start:]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip("|").split("|")])
    header, body = rows[0], rows[2:]
    return [dict(zip(header, row)) for row in body]


def cells_of(raw_occupancy) -> set:
    """Expand a results file's runs of cells, independently of the package's own code."""
    return {(int(lane), k) for lane, runs in raw_occupancy.items() for low, high in runs for k in range(low, high + 1)}


def test_the_quick_run_writes_the_report_and_every_plot(quick):
    out, result = quick
    report = (out / "report.md").read_text()
    expected = ["rq1-time-base.png", "rq1-time-refined.png", "rq2-similarity.png", "rq2-outcomes-refined.png"]
    expected += [f"rq2-similarity-{s}-{strategy}.png" for s in SCENARIOS for strategy in ("base", "refined")]
    for name in expected:
        assert (out / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", f"{name} is missing or not a PNG"
        assert name in report, f"report.md does not show {name}"
    for linked in re.findall(r"\]\(([^)]+\.png)\)", report):
        assert (out / linked).exists(), f"report.md links {linked}, which was not written"
    assert f"report: {out / 'report.md'}" in result.stdout


def test_the_report_names_machine_versions_and_seed(quick):
    out, _ = quick
    report = (out / "report.md").read_text()
    raw = json.loads((out / "results.json").read_text())
    assert "Seed 3; 2 base and 5 refined instances per scenario" in report
    assert raw["settings"]["seed"] == 3 and raw["settings"]["base"] == 2 and raw["settings"]["refined"] == 5
    for package in ("clingo", "frenetix", "commonroad-io", "hypothesis"):
        assert f"{package} {raw['environment']['versions'][package]}" in report
    assert f"{raw['environment']['cpus']} CPUs" in report
    assert "roadlogic bench scenarios --quick --seed 3" in report


def test_every_instance_is_recorded_with_its_artifacts(quick):
    out, _ = quick
    raw = json.loads((out / "results.json").read_text())
    for scenario in SCENARIOS:
        base = [r for r in raw["instances"] if r["scenario"] == scenario and r["strategy"] == "base"]
        refined = [r for r in raw["instances"] if r["scenario"] == scenario and r["strategy"] == "refined"]
        assert len(base) == 2 and len(refined) == 5, scenario
        assert all(r["values"] for r in refined), "a refined instance records its sample"
        for record in base + refined:
            assert record["outcome"] in OUTCOMES
            if record["occupancy"] is not None:
                for name in ("plan.json", "trace.csv", "scenario.xml", "trajectories.png", "verdict.json"):
                    assert (out / record["artifacts"] / name).exists(), f"{record['artifacts']}/{name}"


def test_the_base_strategy_conforms_on_every_scenario(quick):
    out, _ = quick
    raw = json.loads((out / "results.json").read_text())
    rejected = [
        (r["scenario"], r["index"], r["message"])
        for r in raw["instances"]
        if r["strategy"] == "base" and r["outcome"] != "conformant"
    ]
    assert not rejected


def test_rq1_tables_match_the_raw_results(quick):
    out, _ = quick
    report = (out / "report.md").read_text()
    raw = json.loads((out / "results.json").read_text())
    for strategy in ("base", "refined"):
        rows = {row["scenario"]: row for row in table_after(report, f"### {strategy.capitalize()} strategy")}
        assert sorted(rows) == SCENARIOS
        for scenario, row in rows.items():
            records = [r for r in raw["instances"] if r["scenario"] == scenario and r["strategy"] == strategy]
            assert int(row["instances"]) == len(records)
            conformant = sum(r["outcome"] == "conformant" for r in records)
            assert row["conformant"] == f"{100 * conformant / len(records):.1f}%"
            means = {stage: sum(r["seconds"].get(stage, 0.0) for r in records) / len(records) for stage in STAGES}
            for stage in STAGES:
                assert float(row[f"{stage} s"]) == pytest.approx(means[stage], abs=0.006), (scenario, strategy, stage)
            assert float(row["total s"]) == pytest.approx(sum(means.values()), abs=0.006)
            everything = sum(sum(r["seconds"].values()) for r in records) / 60
            assert float(row["all instances min"]) == pytest.approx(everything, abs=0.006)


def test_rq2_similarity_table_matches_the_raw_results(quick):
    out, _ = quick
    report = (out / "report.md").read_text()
    raw = json.loads((out / "results.json").read_text())
    rows = {row["scenario"]: row for row in table_after(report, "## RQ2: diversity")}
    assert sorted(rows) == SCENARIOS
    for scenario, row in rows.items():
        means = {}
        for strategy in ("base", "refined"):
            grids = [
                cells_of(r["occupancy"])
                for r in raw["instances"]
                if r["scenario"] == scenario and r["strategy"] == strategy and r["occupancy"]
            ]
            pairs = [len(a & b) / len(a | b) for i, a in enumerate(grids) for b in grids[i + 1 :]]
            means[strategy] = sum(pairs) / len(pairs)
            assert float(row[strategy]) == pytest.approx(means[strategy], abs=0.0006), (scenario, strategy)
        assert row["refined lower"] == ("yes" if means["refined"] < means["base"] else "no")


def test_refined_outcome_table_matches_the_raw_results(quick):
    out, _ = quick
    report = (out / "report.md").read_text()
    raw = json.loads((out / "results.json").read_text())
    for row in table_after(report, "### Outcomes, refined strategy"):
        records = [r for r in raw["instances"] if r["scenario"] == row["scenario"] and r["strategy"] == "refined"]
        for outcome in OUTCOMES:
            assert int(row[outcome]) == sum(r["outcome"] == outcome for r in records), (row["scenario"], outcome)


def test_the_report_can_be_rebuilt_from_the_results_alone(quick, tmp_path):
    out, _ = quick
    copy = tmp_path / "copy"
    copy.mkdir()
    (copy / "results.json").write_text((out / "results.json").read_text())
    result = bench("--report-only", "--out", str(copy))
    assert result.returncode in (0, 1), result.stderr
    assert (copy / "report.md").read_text() == (out / "report.md").read_text()


# ------------------------------------------------------------------ input errors, reproducibility


def test_a_bad_file_is_reported_and_the_others_still_run(tmp_path):
    (tmp_path / "broken.osc").write_text("scenario broken:\n  v1: car\n  do v1.drive() with:\n    speed(10 kg)\n")
    (tmp_path / "follow.osc").write_text((ROOT / "scenarios" / "follow.osc").read_text())
    result = bench(str(tmp_path), "--base", "1", "--refined", "2", "--no-artifacts", "--out", str(tmp_path / "out"))
    assert result.returncode == 1, result.stdout + result.stderr
    assert "broken.osc:4:" in result.stderr and "Traceback" not in result.stderr
    report = (tmp_path / "out" / "report.md").read_text()
    assert "## Scenarios that could not run" in report and "broken.osc:4:" in report
    assert "| follow | 1 | 100.0% |" in report


def test_a_realistic_suite_runs_beside_the_papers_in_each_files_dialect_and_is_reported_apart(tmp_path):
    """Issue 21: the bench runs a second suite (scenarios/realistic/ by default) and reports it in
    its own section; a file is read in the dialect its folder's conftest.py gives, as under pytest,
    and a suite's library file (no scenario to run) is not a scenario."""
    suite = tmp_path / "realistic"
    shutil.copytree(ROOT / "scenarios" / "realistic" / "carla_dialect", suite / "carla_dialect")
    shutil.copy(ROOT / "scenarios" / "realistic" / "lead_brake.osc", suite)
    result = bench(
        "scenarios/follow.osc",
        "--realistic",
        str(suite),
        "--quick",
        "--base",
        "1",
        "--refined",
        "1",
        "--no-artifacts",
        "--out",
        str(tmp_path / "out"),
    )
    assert result.returncode in (0, 1), result.stdout + result.stderr
    raw = json.loads((tmp_path / "out" / "results.json").read_text())
    assert raw["scenarios"] == ["follow"] and raw["realistic"] == ["slow_cut_in", "lead_brake"]
    assert raw["settings"]["realistic"]["dialects"] == {str(suite / "carla_dialect" / "slow_cut_in.osc"): "carla"}
    assert raw["settings"]["realistic"]["encoding"] == "continuous" and raw["settings"]["encoding"] == "grid"
    assert {r["scenario"] for r in raw["instances"]} == {"follow", "slow_cut_in", "lead_brake"}
    report = (tmp_path / "out" / "report.md").read_text()
    realistic = report[report.index("## Realistic scenarios") :]
    rows = {row["scenario"]: row for row in table_after(realistic, "### Base strategy")}
    assert sorted(rows) == ["lead_brake", "slow_cut_in"] and all(row["instances"] == "1" for row in rows.values())
    assert "slow_cut_in" not in report[: report.index("## Realistic scenarios")], (
        "the targets and RQ tables are the paper's suite's"
    )


def test_a_missing_path_or_results_file_is_a_usage_error(tmp_path):
    result = bench(str(tmp_path / "nowhere"))
    assert result.returncode == 2 and "no such file or folder" in result.stderr
    result = bench("--report-only", "--out", str(tmp_path))
    assert result.returncode == 2 and "run roadlogic bench first" in result.stderr and "Traceback" not in result.stderr


def test_the_same_seed_gives_the_same_instances(tmp_path):
    runs = []
    for name in ("a", "b"):
        assert bench(
            "scenarios/change_lane.osc",
            "--base",
            "1",
            "--refined",
            "2",
            "--seed",
            "5",
            "--no-artifacts",
            "--out",
            str(tmp_path / name),
        ).returncode in (0, 1)
        raw = json.loads((tmp_path / name / "results.json").read_text())
        runs.append(
            [(r["strategy"], r["values"], r["outcome"], r["horizon"], r["occupancy"]) for r in raw["instances"]]
        )
    assert runs[0] == runs[1]


# ------------------------------------------------------------------ the full run


@pytest.fixture(scope="module")
def full_run(tmp_path_factory):
    """The paper's setting: 10 base and 50 refined instances of each of the seven scenarios, seed 1."""
    out = tmp_path_factory.mktemp("full")
    result = bench("scenarios", "--out", str(out))
    assert result.returncode in (0, 1), result.stderr
    return result.stdout


@pytest.mark.bench
def test_the_full_run_conforms(full_run):
    for target in (
        "base strategy: 100% conformant",
        "refined strategy: at least 98% conformant",
        "refined strategy: no timeouts",
    ):
        assert f"met: {target}" in full_run, full_run


@pytest.mark.bench
def test_the_full_run_is_more_diverse_with_the_refined_strategy(full_run):
    assert "met: refined mean similarity below base" in full_run, full_run


@pytest.mark.parametrize("where", ["two processes", "a two-node Ray cluster"])
def test_a_bench_elsewhere_records_what_the_serial_run_records_in_its_order(where, tmp_path, request):
    from pytest_roadlogic.evaluation import BenchmarkSettings, run_benchmark
    from pytest_roadlogic.executors import executor
    from pytest_roadlogic.settings import RunSettings

    paths = (ROOT / "scenarios" / "overtake.osc", ROOT / "scenarios" / "follow.osc", ROOT / "tests" / "nothing.osc")
    settings = BenchmarkSettings(paths, base=1, refined=2, run=RunSettings(seed=3), artifacts=False)

    def recorded(chosen):
        with chosen:
            results = run_benchmark(settings, tmp_path / chosen.name, executor=chosen)
        return [
            {k: v for k, v in record.to_json().items() if k not in ("seconds", "artifacts")}
            for record in results.instances
        ], results.errors

    if where == "two processes":
        elsewhere = executor(jobs=2)
    else:
        elsewhere = executor(ray=request.getfixturevalue("two_node_ray_cluster"))
    serial = recorded(executor())
    assert recorded(elsewhere) == serial
    assert [r["scenario"] for r in serial[0]] == ["overtake"] * 3 + ["follow"] * 3
    assert list(serial[1]) == ["nothing"]  # a file that cannot be read is reported, the others run


def test_a_ray_cluster_runs_jobs_on_each_of_its_nodes(two_node_ray_cluster):
    from pytest_roadlogic.executors import executor

    with executor(ray=two_node_ray_cluster) as cluster:
        assert cluster.workers() == 2
        assert "2 nodes" in cluster.describe()
        nodes = list(cluster.results([(_node_of_a_slow_job, (k,)) for k in range(4)]))
    assert [k for k, _ in nodes] == [0, 1, 2, 3]  # in the order of the jobs
    assert len({node for _, node in nodes}) == 2


def _node_of_a_slow_job(k: int) -> tuple[int, str]:
    import time

    import ray

    time.sleep(0.5)  # long enough that the second node takes a job while the first holds one
    return k, ray.get_runtime_context().get_node_id()


def test_a_ray_address_nothing_answers_at_is_refused_with_what_to_give(tmp_path):
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest_roadlogic.cli",
            "bench",
            str(ROOT / "scenarios" / "follow.osc"),
            "--quick",
            "--out",
            str(tmp_path / "out"),
            "--ray",
            "127.0.0.1:1",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 2, result.stderr
    assert "roadlogic bench: --ray: no Ray cluster answers at '127.0.0.1:1'" in result.stderr
    assert "ray start --head" in result.stderr
    assert "Traceback" not in result.stderr


SET_ASIDE_FIRST = """scenario widen:
    ego: car
    npc: car
    start_gap: length with:
        keep(it in [5m..60m])
    npc_speed: speed with:
        keep(it in [10mps..30mps])
    do parallel(duration: 3s):
        ego.drive() with:
            speed(20mps)
        npc.drive() with:
            position(start_gap, ahead_of: ego, at: start)
            position([25m..40m], ahead_of: ego, at: end)
            speed(npc_speed, at: start)
"""


def test_a_bench_replaces_a_sample_set_aside_with_a_new_draw_the_same_on_any_executor(tmp_path):
    from pytest_roadlogic.evaluation import BenchmarkSettings, run_benchmark
    from pytest_roadlogic.executors import executor
    from pytest_roadlogic.settings import RunSettings

    path = tmp_path / "widen.osc"
    path.write_text(SET_ASIDE_FIRST)
    settings = BenchmarkSettings((path,), base=0, refined=3, run=RunSettings(seed=1), artifacts=False)

    def recorded(chosen):
        with chosen:
            results = run_benchmark(settings, tmp_path / chosen.name, executor=chosen)
        return [(r.index, r.outcome, r.values) for r in results.instances]

    serial = recorded(executor())
    # the first draw starts at the simplest sample, 5 m ahead at 10 m/s against the ego's 20,
    # 25 m ahead or more 3 s later: each value alone has plans, not the two together, so it is
    # set aside and a new draw takes its place
    assert [index for index, _, _ in serial] == [0, 1, 2]
    assert {"start_gap": 5.0, "npc_speed": 10.0} not in [values for _, _, values in serial]
    assert len({json.dumps(values, sort_keys=True) for _, _, values in serial}) == 3
    assert recorded(executor(jobs=2)) == serial
