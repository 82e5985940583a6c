"""oscsim.batch from Python (issue 15): the variants of a distribution run in this process or as
Ray tasks on a local Ray cluster give the table `oscsim batch` writes — results.csv,
results.parquet and report.html byte for byte, and the returned data frame row for row.

Ray comes from PyPI (scripts/python_check.sh installs it). The Ray test is skipped only when
OSCSIM_SKIP_RAY says why ray cannot be installed on this platform (python_check.sh sets it when
`pip install ray` fails); without ray and without that variable it fails."""

from __future__ import annotations

import csv
import math
import os
import re
import subprocess
from pathlib import Path

import pytest

import oscsim
import oscsim.batch
from conftest import CORPUS, REPO

# 3 x 2 x 4 = 24 variants of two cars following each other, 10 s each (crates/batch/tests).
GRID = REPO / "crates" / "batch" / "tests" / "files" / "grid.xosc"
# 2 x 2 x 3 = 12 variants of esmini's cut-in, with text parameters (vehicle catalog entries) and
# a ValueSetDistribution whose second set leaves HostVehicle unset (an empty cell).
CUT_IN_SET = CORPUS / "esmini" / "xosc" / "cut-in_parameter_set.xosc"
OUTPUTS = ("results.csv", "results.parquet", "report.html")


def cli_batch(oscsim_bin: Path, dist: Path, out: Path, *extra: str) -> None:
    """`oscsim batch DIST --out OUT EXTRA…` with the OSI recording time pinned to 0 (exit status 0
    or 1: 1 means some variant failed)."""
    done = subprocess.run(
        [str(oscsim_bin), "batch", str(dist), "--out", str(out), "--jobs", "2", "--quiet", *extra],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        env=dict(os.environ, SOURCE_DATE_EPOCH="0"),
    )
    assert done.returncode in (0, 1), done.stderr


def saved_files(out: Path) -> list:
    """The files under OUT/variants, relative to OUT, sorted."""
    return sorted(p.relative_to(out) for p in (out / "variants").rglob("*") if p.is_file())


def assert_same_saved(a: Path, b: Path) -> None:
    files = saved_files(a)
    assert files == saved_files(b)
    for name in files:
        assert (a / name).read_bytes() == (b / name).read_bytes(), name


def assert_same_outputs(a: Path, b: Path) -> None:
    for name in OUTPUTS:
        assert (a / name).read_bytes() == (b / name).read_bytes(), name


def assert_frame_is_csv(frame, results_csv: Path) -> None:
    """Every cell of the frame equals the CLI's cell: numbers by value, empties as missing."""
    with results_csv.open(newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    assert list(frame.columns) == header
    assert len(frame) == len(body)
    records = frame.to_dict("records")
    for row, record in zip(body, records):
        for name, cell in zip(header, row):
            value = record[name]
            missing = value is None or value is getattr(__import__("pandas"), "NA", None) or (
                isinstance(value, float) and math.isnan(value)
            )
            if cell == "":
                assert missing or value == "", (name, row)
            elif cell in ("true", "false"):
                assert bool(value) == (cell == "true"), (name, row)
            else:
                try:
                    assert float(value) == float(cell), (name, row)
                except (TypeError, ValueError):
                    assert value == cell, (name, row)


def test_local_backend_equals_cli(tmp_path: Path, oscsim_bin: Path):
    cli_batch(oscsim_bin, GRID, tmp_path / "cli")
    frame = oscsim.batch.run(GRID, tmp_path / "py", backend="local", jobs=2)
    assert_same_outputs(tmp_path / "cli", tmp_path / "py")
    assert_frame_is_csv(frame, tmp_path / "cli" / "results.csv")
    # The grid's parameters are numbers; variant 9 is EgoSpeed 25, TargetSpeed 10, Gap 20: the
    # gap closes at 25 − 10 = 15 m/s, contact at 20 / 15 = 1.333 s.
    assert frame["EgoSpeed"].dtype.kind == "f"
    row = frame[frame["variant"] == 9].iloc[0]
    assert (row["EgoSpeed"], row["TargetSpeed"], row["Gap"]) == (25.0, 10.0, 20.0)
    # (The first frame at or after the instant, so within one step of dt = 0.05 s after it.)
    assert bool(row["collision"]) and 20 / 15 <= row["first_collision_time"] <= 20 / 15 + 0.05


def test_saved_outputs_equal_the_cli(tmp_path: Path, oscsim_bin: Path, monkeypatch):
    # `save` is `oscsim batch --save`: 24 variants × (trajectories.csv, events.jsonl, one OSI
    # trace) = 72 files, byte for byte the CLI's (recording time pinned by SOURCE_DATE_EPOCH).
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "0")
    cli_batch(oscsim_bin, GRID, tmp_path / "cli", "--save", "csv,events,osi", "--duration", "1")
    oscsim.batch.run(GRID, tmp_path / "py", jobs=2, duration=1.0, save=("csv", "events", "osi"))
    assert len(saved_files(tmp_path / "py")) == 24 * 3
    assert_same_saved(tmp_path / "cli", tmp_path / "py")
    assert_same_outputs(tmp_path / "cli", tmp_path / "py")
    with pytest.raises(ValueError, match="out_dir"):
        oscsim.batch.run(GRID, save=("csv",))
    with pytest.raises(ValueError, match="found 'mcap'"):
        oscsim.batch.run(GRID, tmp_path / "bad", save=("mcap",))


def test_plan_and_errors(tmp_path: Path):
    plan = oscsim.batch.BatchPlan(GRID)
    assert plan.variant_count == 24
    assert plan.parameters == ["EgoSpeed", "TargetSpeed", "Gap"]
    # The first distribution varies slowest: variant 23 is the last of each.
    assert plan.variant(23) == {"EgoSpeed": "30", "TargetSpeed": "20", "Gap": "80"}
    with pytest.raises(IndexError):
        plan.run([24])
    bad = tmp_path / "bad.xosc"
    bad.write_text(GRID.read_text().replace('parameterName="Gap"', 'parameterName="Gapp"').replace(
        'filepath="following.xosc"', f'filepath="{GRID.parent / "following.xosc"}"'
    ))
    # A varied parameter the scenario does not declare is a warning at its distribution element
    # (docs/batch.md, OpenSCENARIO XML 1.3 §9.3): its values vary nothing.
    warned = oscsim.batch.BatchPlan(bad)
    assert warned.parameters == ["EgoSpeed", "TargetSpeed", "Gapp"]
    assert len(warned.warnings) == 1
    assert re.fullmatch(
        r"the scenario declares no global parameter 'Gapp' \(EgoSpeed, TargetSpeed, Gap\): "
        r"its values vary nothing at .*bad.xosc:\d+:\d+",
        warned.warnings[0],
    ), warned.warnings[0]
    assert plan.warnings == []
    missing = tmp_path / "missing.xosc"
    missing.write_text(GRID.read_text().replace('filepath="following.xosc"', 'filepath="nowhere.xosc"'))
    with pytest.raises(
        oscsim.ScenarioError,
        match=r"expected an existing ScenarioFile, found none at .*nowhere.xosc \(ScenarioFile at .*missing.xosc:\d+:\d+\)",
    ):
        oscsim.batch.run(missing, backend="ray")  # refused before Ray is asked for anything
    with pytest.raises(ValueError, match="expected backend"):
        oscsim.batch.run(GRID, backend="dask")
    # Shares of different batches are refused when joined.
    a = plan.run([0])
    b = plan.run([1]).replace("Gap", "Other", 1)
    with pytest.raises(oscsim.OscsimError, match="expected shards of one batch"):
        oscsim.batch.merge_results([a, b])


def ray_or_skip():
    try:
        import ray
    except ImportError:
        reason = os.environ.get("OSCSIM_SKIP_RAY")
        if reason:
            pytest.skip(reason)
        pytest.fail("ray is not installed (pip install ray; scripts/python_check.sh does)")
    return ray


@pytest.mark.parametrize("dist", [GRID, CUT_IN_SET], ids=["grid", "cut-in_parameter_set"])
def test_ray_backend_equals_cli(tmp_path: Path, oscsim_bin: Path, dist: Path):
    ray = ray_or_skip()
    if not dist.is_file():
        pytest.fail(f"missing {dist} (CORPUS names the shared corpus)")
    cli_batch(oscsim_bin, dist, tmp_path / "cli", "--save", "csv")
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        # 5 tasks for 24 (or 12) variants: uneven round-robin shares, joined by variant number;
        # each task writes its variants' trajectories.
        frame = oscsim.batch.run(dist, tmp_path / "ray", backend="ray", tasks=5, timeout=300, save=("csv",))
    finally:
        ray.shutdown()
    assert_same_outputs(tmp_path / "cli", tmp_path / "ray")
    assert len(saved_files(tmp_path / "ray")) == len(frame)  # one trajectories.csv per variant
    assert_same_saved(tmp_path / "cli", tmp_path / "ray")
    assert_frame_is_csv(frame, tmp_path / "cli" / "results.csv")
    assert list(frame["variant"]) == list(range(len(frame)))


# Five variants of a slow-and-failing distribution (crates/batch/tests/files/guarded_dist.xosc):
# 1 stands still until t = 1 000 000 s, 2 fails at t = 1 s; 0, 3, 4 stop at 5, 4, 3 s.
GUARDED = REPO / "crates" / "batch" / "tests" / "files" / "guarded_dist.xosc"


def journal_rows(out: Path) -> list:
    """The variant numbers of the rows in OUT/batch.journal, one per record, in the order
    written (crates/batch/src/journal.rs: 8 magic bytes, then length, CRC-32, payload)."""
    data = (out / "batch.journal").read_bytes()
    assert data[:8] == b"OSCSIMJ1"
    at, records = 8, []
    while at + 8 <= len(data):
        n = int.from_bytes(data[at : at + 4], "little")
        records.append(data[at + 8 : at + 8 + n].decode())
        at += 8 + n
    assert at == len(data), "a torn record"
    return [int(r.split(",", 1)[0]) for r in records[1:]]


def test_local_backend_resumes_from_a_journal(tmp_path: Path, oscsim_bin: Path):
    # Ten variants recorded as an interrupted run leaves them (BatchJournal, as the Ray driver
    # records shares), then the batch run again into the folder runs the other 14 only and
    # writes the CLI's files.
    cli_batch(oscsim_bin, GRID, tmp_path / "cli")
    plan = oscsim.batch.BatchPlan(GRID)
    out = tmp_path / "py"
    journal = oscsim.batch.BatchJournal(plan, out)
    assert journal.record(plan.run(list(range(10)))) == 10
    assert journal.record(plan.run([3, 4])) == 0  # recorded once
    del journal
    text = oscsim.batch.run_csv(GRID, out, backend="local", jobs=2)
    assert text == (tmp_path / "cli" / "results.csv").read_text()
    assert_same_outputs(tmp_path / "cli", out)
    rows = journal_rows(out)
    assert rows[:10] == list(range(10)) and sorted(rows) == list(range(24))
    # The CLI's own folder is the same sweep: nothing runs, the same files.
    assert oscsim.batch.run_csv(GRID, tmp_path / "cli", backend="ray") == text
    assert sorted(journal_rows(tmp_path / "cli")) == list(range(24))  # nothing added
    # Another sweep into either folder is refused before anything runs.
    with pytest.raises(oscsim.OscsimError, match="expected the journal of this sweep"):
        oscsim.batch.run_csv(GRID, out, seed=2)
    with pytest.raises(oscsim.OscsimError, match="expected the journal of this sweep"):
        oscsim.batch.run_csv(CUT_IN_SET, out, backend="ray")


def test_variant_timeout_and_failures_are_rows(tmp_path: Path):
    frame = oscsim.batch.run(GUARDED, tmp_path, max_time=2e6, variant_timeout=2.0, jobs=2)
    errors = dict(zip(frame["variant"], frame["error"]))
    assert errors[1] == "timed out: ran longer than the variant timeout of 2 s (wall clock)"
    assert errors[2].startswith("expected lane -10 (lane -1 + dLane -9)") and errors[2].endswith("(at t = 1.000 s)")
    ends = dict(zip(frame["variant"], frame["end_time"]))
    # The stop triggers "time > 4.99", "> 3.99", "> 2.99" fire at the first step past them.
    assert [ends[v] for v in (0, 3, 4)] == pytest.approx([5.0, 4.0, 3.0], abs=1e-9)
    assert [errors[v] for v in (0, 3, 4)] == ["", "", ""]
    with pytest.raises(ValueError, match="variant_timeout"):
        oscsim.batch.run(GUARDED, variant_timeout=0.0)


def test_ray_retries_a_task_that_fails_once_and_counts_it_once(tmp_path: Path, oscsim_bin: Path, monkeypatch):
    ray = ray_or_skip()
    cli_batch(oscsim_bin, GRID, tmp_path / "cli", "--save", "csv")
    died, raised = tmp_path / "died", tmp_path / "raised"

    def flaky(path, source, variants, options):
        # The task holding variant 0 loses its worker the first time it runs (an out-of-memory
        # kill, a lost node); the one holding variant 1 raises the first time. A marker file
        # says it happened, and the retry runs the share. (Pickled by value: a closure.)
        import os as os_
        import oscsim.batch as batch_

        if 0 in variants and not died.exists():
            died.touch()
            os_._exit(1)
        if 1 in variants and not raised.exists():
            raised.touch()
            raise RuntimeError("a task failing once")
        return batch_._run_share(path, source, variants, options)

    monkeypatch.setattr(oscsim.batch, "_run_share", flaky)
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        frame = oscsim.batch.run(GRID, tmp_path / "ray", backend="ray", tasks=5, timeout=300, save=("csv",))
    finally:
        ray.shutdown()
    assert died.exists() and raised.exists()
    assert list(frame["variant"]) == list(range(24))
    assert sorted(journal_rows(tmp_path / "ray")) == list(range(24))  # each recorded once
    assert_same_outputs(tmp_path / "cli", tmp_path / "ray")
    assert_same_saved(tmp_path / "cli", tmp_path / "ray")


def test_ray_driver_records_what_finished_and_a_rerun_completes(tmp_path: Path, oscsim_bin: Path, monkeypatch):
    # The task holding variant 3 fails every time: after its retries the driver raises, once
    # the other tasks' rows are recorded. The same call again (the task healthy) runs only the
    # failed task's variants and ends with the CLI's files.
    ray = ray_or_skip()
    cli_batch(oscsim_bin, GRID, tmp_path / "cli")
    attempts = tmp_path / "attempts"
    attempts.mkdir()

    def broken(path, source, variants, options):
        import oscsim.batch as batch_
        import uuid

        if 3 in variants:
            (attempts / uuid.uuid4().hex).touch()
            raise RuntimeError("a task that always fails")
        return batch_._run_share(path, source, variants, options)

    out = tmp_path / "ray"
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        monkeypatch.setattr(oscsim.batch, "_run_share", broken)
        with pytest.raises(ray.exceptions.RayError, match="a task that always fails"):
            oscsim.batch.run(GRID, out, backend="ray", tasks=5, timeout=300)
        # 1 + TASK_RETRIES attempts; task 3 of 5 held 3, 8, 13, 18, 23.
        assert len(list(attempts.iterdir())) == 1 + oscsim.batch.TASK_RETRIES
        assert sorted(journal_rows(out)) == [v for v in range(24) if v % 5 != 3]
        assert not (out / "results.csv").exists()
        monkeypatch.undo()
        frame = oscsim.batch.run(GRID, out, backend="ray", tasks=5, timeout=300)
    finally:
        ray.shutdown()
    assert list(frame["variant"]) == list(range(24))
    assert sorted(journal_rows(out)) == list(range(24))
    assert len(journal_rows(out)) == 24 and sorted(journal_rows(out)[-5:]) == [3, 8, 13, 18, 23]
    assert_same_outputs(tmp_path / "cli", out)


# A cut-in varied by seed with two cover items and a record (crates/cli/tests/files): its
# `keep` ranges re-solved per seed, its coverage counted into coverage.csv.
COVERED = REPO / "crates" / "cli" / "tests" / "files" / "covered_cut_in.osc"
HIGHWAY_ROAD = REPO / "examples" / "roads" / "highway.xodr"


@pytest.mark.parametrize("backend", ["local", "ray"])
def test_seeds_of_a_dsl_scenario_equal_the_cli(tmp_path: Path, oscsim_bin: Path, backend: str):
    # `oscsim batch X.osc --road R --seeds 3..42` (40 seeds) and the same from Python give the
    # same results, parquet, report and coverage.csv byte for byte, on either backend.
    cli_batch(oscsim_bin, COVERED, tmp_path / "cli", "--road", str(HIGHWAY_ROAD), "--seeds", "3..42")
    options = dict(seeds="3..42", road=HIGHWAY_ROAD)
    if backend == "ray":
        ray = ray_or_skip()
        ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
        try:
            # 3 tasks for 40 seeds: uneven round-robin shares.
            frame = oscsim.batch.run(COVERED, tmp_path / "py", backend="ray", tasks=3, timeout=300, **options)
        finally:
            ray.shutdown()
    else:
        frame = oscsim.batch.run(COVERED, tmp_path / "py", jobs=2, **options)
    for name in (*OUTPUTS, "coverage.csv"):
        assert (tmp_path / "cli" / name).read_bytes() == (tmp_path / "py" / name).read_bytes(), name
    assert_frame_is_csv(frame, tmp_path / "cli" / "results.csv")
    # Variant i is seed 3 + i; every resolved value inside its `keep` range (20..30 m/s,
    # 15..40 m), the side a member of side_left_right.
    assert list(frame["seed"]) == list(range(3, 43))
    assert frame["ego_speed"].between(20.0, 30.0).all() and frame["gap"].between(15.0, 40.0).all()
    assert set(frame["side"]) <= {"left", "right"}
    # A list of seeds is the same sweep as its range; a seeds text that is no list is refused.
    plan = oscsim.batch.BatchPlan(COVERED, seeds=list(range(3, 43)), road=HIGHWAY_ROAD)
    assert plan.variant_count == 40
    with pytest.raises(ValueError, match="seeds"):
        oscsim.batch.BatchPlan(COVERED, seeds="9..3", road=HIGHWAY_ROAD)
