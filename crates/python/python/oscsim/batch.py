"""Every variant of a ParameterValueDistribution (OpenSCENARIO 1.3 §9.5), from Python: in this
process on a pool of threads, or fanned out as Ray tasks over a Ray cluster.

    import oscsim.batch

    frame = oscsim.batch.run("sweep/dist.xosc", "results/", backend="ray")

Either backend gives the table ``oscsim batch`` gives (docs/batch.md): the same variant numbers
and seeds, the same rows, and in ``out_dir`` the same ``results.csv``, ``results.parquet`` and
``report.html``, byte for byte. The variants run in the native engine (``BatchPlan.run``); a
Ray task runs a share of them and hands back its rows as the text of a ``results.csv``, and the
driver joins the shares as ``oscsim batch merge`` joins shard folders (``merge_results``).
"""

from __future__ import annotations

import csv
import io
import os
from typing import Any, Dict, List, Optional, Sequence, Tuple

from ._oscsim import BatchPlan, merge_results, summary

__all__ = ["BatchPlan", "frame", "merge_results", "run", "run_csv", "summary"]

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
    seed: int = 1,
    dt: float = 0.05,
    duration: Optional[float] = None,
    max_time: float = 3600.0,
    host: str = "Ego",
    jobs: Optional[int] = None,
    tasks: Optional[int] = None,
    timeout: Optional[float] = None,
    save: Sequence[str] = (),
) -> str:
    """Runs every variant of ``distribution`` and returns the text of its ``results.csv``.

    ``seed``, ``dt``, ``duration``, ``max_time`` and ``host`` are ``oscsim batch``'s
    ``--seed``, ``--dt``, ``--duration``, ``--max-time`` and ``--host``; ``save`` (any of
    ``"csv"``, ``"events"``, ``"osi"``) is its ``--save``: each variant's trajectories, event
    log or OSI trace in ``out_dir/variants/NNNNN/`` (``out_dir`` required), the OSI traces'
    recording time from ``SOURCE_DATE_EPOCH`` when it is set, as on the command line. With
    Ray, each task writes its variants' files at that path on its own node.

    ``backend="local"``: the variants run in this process on ``jobs`` threads (default: every
    core), the interpreter's lock released.

    ``backend="ray"``: the variants run as ``tasks`` Ray tasks of one CPU each (default: four per
    CPU of the cluster, at most one per variant); task ``k`` of ``K`` runs the variants
    ``k, k + K, …`` (round robin, as ``--shard k/K``). Ray must be installed; the cluster is the
    one this process is connected to, or, when none is, a local one ``ray.init()`` starts
    (call ``ray.init`` yourself to choose). The distribution file and the files it names must be
    readable by every worker at the same path. Each worker loads the plan once and keeps it
    for its later tasks. ``timeout`` (s) bounds the wait for the tasks' results
    (``ray.exceptions.GetTimeoutError`` after it; the tasks are cancelled).
    """
    path = os.fspath(distribution)
    out = None if out_dir is None else os.path.abspath(os.fspath(out_dir))
    options = dict(seed=seed, dt=dt, duration=duration, max_time=max_time, host=host)
    if save:
        if out is None:
            raise ValueError("expected an out_dir for the saved outputs, found none")
        options.update(save=list(save), out_dir=out, recording_time=_source_date_epoch())
    if backend == "local":
        plan = BatchPlan(path)
        text = plan.run(jobs=jobs or os.cpu_count() or 1, **options)
        return merge_results([text], out)
    if backend == "ray":
        return merge_results(_ray_shares(path, options, tasks, timeout), out)
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


def _ray_shares(path: str, options: Dict[str, Any], tasks: Optional[int], timeout: Optional[float]) -> List[str]:
    import ray

    # The plan is loaded here first, so that a distribution that cannot run fails before any
    # task starts, with the loader's error.
    count = BatchPlan(path).variant_count
    if not ray.is_initialized():
        ray.init()
    if tasks is None:
        cpus = int(ray.cluster_resources().get("CPU", 1))
        tasks = 4 * max(cpus, 1)
    tasks = max(1, min(tasks, count))
    remote = ray.remote(num_cpus=1)(_run_share)
    refs = [remote.remote(os.path.abspath(path), list(range(k, count, tasks)), options) for k in range(tasks)]
    try:
        return ray.get(refs, timeout=timeout)
    except ray.exceptions.GetTimeoutError:
        for ref in refs:
            ray.cancel(ref, force=True)
        raise


#: Plans a worker process has loaded, by (absolute path, modification time).
_PLANS: Dict[Tuple[str, int], BatchPlan] = {}


def _run_share(path: str, variants: Sequence[int], options: Dict[str, Any]) -> str:
    """One Ray task: the rows of ``variants`` as results.csv text, on one thread."""
    key = (path, os.stat(path).st_mtime_ns)
    plan = _PLANS.get(key)
    if plan is None:
        plan = _PLANS[key] = BatchPlan(path)
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
