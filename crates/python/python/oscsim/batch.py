"""Every variant of a ParameterValueDistribution (OpenSCENARIO 1.3 §9.5), from Python: in this
process on a pool of threads, or fanned out as Ray tasks over a Ray cluster.

    import oscsim.batch

    frame = oscsim.batch.run("sweep/dist.xosc", "results/", backend="ray")

Either backend gives the table ``oscsim batch`` gives (docs/batch.md): the same variant numbers
and seeds, the same rows, and in ``out_dir`` the same ``results.csv``, ``results.parquet`` and
``report.html``, byte for byte. The variants run in the native engine (``BatchPlan.run``); a
Ray task runs a share of them and hands back its rows as the text of a ``results.csv``, and the
driver joins the shares as ``oscsim batch merge`` joins shard folders (``merge_results``).

With ``out_dir`` a batch is durable as on the command line: finished variants are recorded in
``out_dir/batch.journal`` (by the native runner, or by the Ray driver as each task's rows come
back, ``BatchJournal``), and running the same batch into the same folder again runs only what
is missing. A Ray task whose worker dies, or that raises, is retried (``TASK_RETRIES``); its
rows are recorded once.
"""

from __future__ import annotations

import csv
import io
import os
import time
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

from ._oscsim import BatchJournal, BatchPlan, merge_results, summary

__all__ = ["BatchJournal", "BatchPlan", "frame", "merge_results", "run", "run_csv", "summary"]

#: How often Ray runs a task again after its worker died or it raised (Ray's ``max_retries``
#: with ``retry_exceptions``): a variant's failure is a row, not an exception, so what fails a
#: task is the machine (a lost node, an out-of-memory kill) or its files.
TASK_RETRIES = 3

#: Columns of results.csv by kind (docs/batch.md); the parameters stand between `variant` and
#: `stop_reason`, the `monitor:<name>` columns (booleans) after `error`.
_FLOATS = {"end_time", "first_collision_time", "min_ttc", "min_headway", "min_gap"}
_INTS = {"variant", "events_started"}


def run(distribution: "os.PathLike[str] | str", out_dir: "os.PathLike[str] | str | None" = None, **options: Any) -> Any:
    """Runs every variant of ``distribution`` and returns the results table as a data frame
    (:func:`frame`); with ``out_dir``, also writes ``results.csv``, ``results.parquet`` and
    ``report.html`` there. The keyword options are :func:`run_csv`'s."""
    return frame(run_csv(distribution, out_dir, **options))


def run_csv(
    distribution: "os.PathLike[str] | str",
    out_dir: "os.PathLike[str] | str | None" = None,
    *,
    backend: str = "local",
    seeds: "str | Sequence[int] | None" = None,
    road: "os.PathLike[str] | str | None" = None,
    seed: int = 1,
    dt: float = 0.05,
    duration: Optional[float] = None,
    max_time: float = 3600.0,
    host: str = "Ego",
    jobs: Optional[int] = None,
    tasks: Optional[int] = None,
    timeout: Optional[float] = None,
    save: Sequence[str] = (),
    variant_timeout: Optional[float] = None,
) -> str:
    """Runs every variant of ``distribution`` and returns the text of its ``results.csv``.

    With ``seeds`` (``"A..B"``, a count ``"N"``, or a list of seeds: ``oscsim batch --seeds``),
    ``distribution`` is an OpenSCENARIO DSL scenario (.osc) on the road network ``road``, run
    once per seed with its constraints re-solved (docs/batch.md); its coverage items give
    ``coverage.csv`` in ``out_dir``.

    ``seed``, ``dt``, ``duration``, ``max_time`` and ``host`` are ``oscsim batch``'s
    ``--seed``, ``--dt``, ``--duration``, ``--max-time`` and ``--host``; ``variant_timeout``
    (s) is ``--variant-timeout``: a variant still running after it is a failed row; ``save`` (any of
    ``"csv"``, ``"events"``, ``"osi"``) is its ``--save``: each variant's trajectories, event
    log or OSI trace in ``out_dir/variants/NNNNN/`` (``out_dir`` required), the OSI traces'
    recording time from ``SOURCE_DATE_EPOCH`` when it is set, as on the command line. With
    Ray, each task writes its variants' files at that path on its own node.

    With ``out_dir`` the batch is durable, as ``oscsim batch --out`` is: each finished variant
    is recorded in ``out_dir/batch.journal``, and the same call on the same ``out_dir`` after an
    interruption runs only the variants not recorded yet (a folder holding another batch's
    results raises ``OscsimError``).

    ``backend="local"``: the variants run in this process on ``jobs`` threads (default: every
    core), the interpreter's lock released.

    ``backend="ray"``: the variants run as ``tasks`` Ray tasks of one CPU each (default: four per
    CPU of the cluster, at most one per variant); task ``k`` of ``K`` runs the variants
    ``k, k + K, …`` of the variants still to run (round robin, as ``--shard k/K``); the driver
    records each task's rows as the task ends. A task whose worker dies or that raises is run
    again, up to ``TASK_RETRIES`` times; one that still fails is raised (``ray.exceptions.RayError``)
    after the other tasks have finished and their rows are recorded, so that the same call again
    runs only its variants. Ray must be installed; the cluster is the
    one this process is connected to, or, when none is, a local one ``ray.init()`` starts
    (call ``ray.init`` yourself to choose). The distribution file and the files it names must be
    readable by every worker at the same path. Each worker loads the plan once and keeps it
    for its later tasks. ``timeout`` (s) bounds the wait for the tasks' results
    (``ray.exceptions.GetTimeoutError`` after it; the tasks are cancelled).
    """
    path = os.fspath(distribution)
    out = None if out_dir is None else os.path.abspath(os.fspath(out_dir))
    options: Dict[str, Any] = dict(
        seed=seed, dt=dt, duration=duration, max_time=max_time, host=host, variant_timeout=variant_timeout
    )
    if save:
        if out is None:
            raise ValueError("expected an out_dir for the saved outputs, found none")
        options.update(save=list(save), recording_time=_source_date_epoch())
    source = dict(seeds=seeds, road=None if road is None else os.path.abspath(os.fspath(road)))
    if backend == "local":
        plan = BatchPlan(path, **source)
        threads = jobs or os.cpu_count() or 1
        if out is None:
            return merge_results([plan.run(jobs=threads, **options)])
        journal = BatchJournal(plan, out, **options)
        done = set(journal.done)
        todo = [v for v in range(plan.variant_count) if v not in done]
        plan.run(todo, jobs=threads, out_dir=out, journal=journal, **options)
        return journal.finish()
    if backend == "ray":
        return _ray_batch(path, source, out, options, tasks, timeout)
    raise ValueError(f"expected backend 'local' or 'ray', found {backend!r}")


def _source_date_epoch() -> Optional[int]:
    """``SOURCE_DATE_EPOCH`` as Unix seconds, if set (the recording time of saved OSI traces)."""
    text = os.environ.get("SOURCE_DATE_EPOCH")
    if text is None:
        return None
    try:
        return int(text.strip())
    except ValueError:
        raise ValueError(f"expected Unix seconds in SOURCE_DATE_EPOCH, found {text!r}") from None


def _ray_batch(
    path: str,
    source: Dict[str, Any],
    out: Optional[str],
    options: Dict[str, Any],
    tasks: Optional[int],
    timeout: Optional[float],
    task: Optional[Callable[[str, Dict[str, Any], Sequence[int], Dict[str, Any]], str]] = None,
) -> str:
    """The Ray backend: the variants not yet recorded in ``out``'s journal as ``tasks`` tasks,
    each task's rows recorded as it ends; ``source`` the plan's ``seeds`` and ``road``;
    ``task`` stands in for :func:`_run_share` (tests)."""
    import ray

    # The plan is loaded here first, so that a distribution that cannot run fails before any
    # task starts, with the loader's error.
    plan = BatchPlan(path, **source)
    journal = None if out is None else BatchJournal(plan, out, **options)
    done = set(journal.done) if journal is not None else set()
    todo = [v for v in range(plan.variant_count) if v not in done]
    texts: List[str] = []
    if todo:
        if not ray.is_initialized():
            ray.init()
        if tasks is None:
            cpus = int(ray.cluster_resources().get("CPU", 1))
            tasks = 4 * max(cpus, 1)
        tasks = max(1, min(tasks, len(todo)))
        remote = ray.remote(num_cpus=1, max_retries=TASK_RETRIES, retry_exceptions=True)(task or _run_share)
        share_options = dict(options, out_dir=out) if "save" in options else options
        pending = [
            remote.remote(os.path.abspath(path), source, todo[k::tasks], share_options) for k in range(tasks)
        ]
        deadline = None if timeout is None else time.monotonic() + timeout
        # A task that failed for good (its retries spent) is raised once the others have
        # finished and their rows are recorded: a rerun then has only its variants to run.
        failure: Optional[BaseException] = None
        try:
            while pending:
                left = None if deadline is None else max(0.0, deadline - time.monotonic())
                ready, pending = ray.wait(pending, num_returns=1, timeout=left)
                if not ready:
                    raise ray.exceptions.GetTimeoutError(f"the batch's tasks did not finish within {timeout} s")
                try:
                    text = ray.get(ready[0])
                except ray.exceptions.RayError as e:
                    failure = failure or e
                    continue
                if journal is not None:
                    journal.record(text)
                else:
                    texts.append(text)
        except BaseException:
            for ref in pending:
                ray.cancel(ref, force=True)
            raise
        if failure is not None:
            raise failure
    if journal is not None:
        return journal.finish()
    return merge_results(texts)


#: Plans a worker process has loaded, by (absolute path, modification time, seeds, road).
_PLANS: Dict[Tuple[str, int, str, Optional[str]], BatchPlan] = {}


def _run_share(path: str, source: Dict[str, Any], variants: Sequence[int], options: Dict[str, Any]) -> str:
    """One Ray task: the rows of ``variants`` as results.csv text, on one thread."""
    key = (path, os.stat(path).st_mtime_ns, repr(source["seeds"]), source["road"])
    plan = _PLANS.get(key)
    if plan is None:
        plan = _PLANS[key] = BatchPlan(path, **source)
    return plan.run(list(variants), jobs=1, **options)


def frame(results_csv: str) -> Any:
    """The table in ``results_csv`` (the text of a ``results.csv``) as a pandas DataFrame, or a
    polars DataFrame when pandas is not installed (``ImportError`` when neither is).

    One row per variant, the file's columns in its order: ``variant`` and ``events_started``
    integers, ``collision`` booleans, the times and distances floats, a parameter float when
    every value of it is a number (as in ``results.parquet``) and text otherwise, monitors
    booleans; an empty cell (never defined, or a failed variant's) is missing: NaN or None in
    pandas, null in polars.
    """
    columns = _columns(results_csv)
    try:
        import pandas

        data = {}
        for name, (kind, values) in columns.items():
            if kind == "int" and any(v is None for v in values):
                data[name] = pandas.array(values, dtype="Int64")
            elif kind == "float":
                data[name] = pandas.array([float("nan") if v is None else v for v in values], dtype="float64")
            elif kind == "bool" and any(v is None for v in values):
                data[name] = pandas.array(values, dtype="boolean")
            else:
                data[name] = values
        return pandas.DataFrame(data, columns=list(columns))
    except ImportError:
        pass
    try:
        import polars

        return polars.DataFrame({name: values for name, (_, values) in columns.items()})
    except ImportError:
        raise ImportError("oscsim.batch.frame needs pandas or polars; run_csv gives the CSV text") from None


def _columns(results_csv: str) -> Dict[str, Tuple[str, list]]:
    """The columns of a results.csv text, each (kind, values) with None for an empty cell."""
    reader = csv.reader(io.StringIO(results_csv))
    header = next(reader)
    rows = [r for r in reader if r]
    params = range(1, header.index("stop_reason"))
    out: Dict[str, Tuple[str, list]] = {}
    for i, name in enumerate(header):
        cells = [r[i] for r in rows]
        if i in params:
            kind = "float" if _all_numbers(cells) else "str"
        elif name in _INTS:
            kind = "int"
        elif name in _FLOATS:
            kind = "float"
        elif name == "collision" or name.startswith("monitor:"):
            kind = "bool"
        else:
            kind = "str"
        out[name] = (kind, [_cell(kind, c) for c in cells] if kind != "str" else cells)
    return out


def _cell(kind: str, text: str) -> Any:
    if not text:
        return None
    if kind == "int":
        return int(text)
    if kind == "float":
        return float(text)
    return text == "true"


def _all_numbers(cells: List[str]) -> bool:
    try:
        for c in cells:
            if c:
                float(c)
    except ValueError:
        return False
    return True
