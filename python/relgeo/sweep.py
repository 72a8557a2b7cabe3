"""Kernel-comparison sweeps as Dask tasks (doc/python.md, "Sweeps").

A sweep is a grid of tasks, workload x size x shard x kernel; each task
generates its inputs itself from (workload, size, seed of its shard), so a
task is the same wherever it runs and the table does not depend on how
many workers there are. ``sweep`` runs the tasks on Dask and gathers one
table: a list of dicts, one row a task, in the grid's order.

    rows = relgeo.sweep.orientation_sweep(["double", "failsafe", "interval", "filtered"], sizes=[10000])
    rows = relgeo.sweep.orientation_sweep(kernels, sizes, scheduler="tcp://host:8786")  # an existing cluster
    rows = relgeo.sweep.orientation_sweep(kernels, sizes, scheduler="serial")           # no Dask

A task that raises, or whose worker dies, gives a row with ``error`` set
(the exception's type and message) and no counts; the others still run.

A script that starts the embedded LocalCluster must do so under
``if __name__ == "__main__":`` (Dask's worker processes re-import the main
module).
"""

import contextlib
import sys
import time

import numpy as np

from . import _relgeo

ORIENTATION_COUNTS = ("cells", "correct", "uncertain", "wrong", "plus_to_zero", "minus_to_zero", "zero_to_sign",
                      "inversions")
"""The columns of relgeo::analysis::Sign_tally (relgeo.orientation_grid's counts)."""

TIMING_COLUMNS = ("time_s", "ns_per_call")
"""The columns that depend on the machine and its load (the rest is deterministic)."""


def orientation_workload_names(dimension=2):
    """The workload families of relgeo::analysis::standard_workloads_2/3."""
    return list(_relgeo.orientation_workloads(dimension, 1, 1))


def orientation_tasks(kernels, sizes, workloads=None, dimension=2, seed=1, shards=1):
    """The grid of a sweep: one dict per (workload, size, shard, kernel), in
    that nesting order. Shard k of a size holds size // shards cases (the
    first size % shards shards one more) generated from seed + 100 * k."""
    workloads = orientation_workload_names(dimension) if workloads is None else list(workloads)
    tasks = []
    for workload in workloads:
        for size in sizes:
            for shard in range(shards):
                cases = size // shards + (shard < size % shards)
                for kernel in kernels:
                    tasks.append({"workload": workload, "dimension": dimension, "size": size, "shard": shard,
                                  "cases": cases, "seed": seed + 100 * shard, "kernel": kernel})
    return tasks


def run_orientation_task(task):
    """One task: the kernel's signs on the shard's cases against the exact
    ones (relgeo's exact kernel), counted as relgeo::analysis::Sign_tally
    counts, and the time of the kernel's call. Never raises: an exception is
    the row's ``error``."""
    row = dict(task, error=None)
    try:
        points = _relgeo.orientation_workloads(task["dimension"], task["cases"], task["seed"])[task["workload"]]
        signs = _relgeo.orient2d if task["dimension"] == 2 else _relgeo.orient3d
        start = time.perf_counter()
        answers = signs(*points, task["kernel"])
        elapsed = time.perf_counter() - start
        row.update(_relgeo.sign_tally(answers, signs(*points, "exact")))
        row["time_s"] = elapsed
        row["ns_per_call"] = 1e9 * elapsed / max(task["cases"], 1)
    except Exception as e:  # reported in the table, not fatal to the sweep
        row["error"] = f"{type(e).__name__}: {e}"
    return row


@contextlib.contextmanager
def _client(scheduler, n_workers, threads_per_worker):
    from dask.distributed import Client, LocalCluster  # only when Dask is used

    if scheduler is None:
        with LocalCluster(n_workers=n_workers, threads_per_worker=threads_per_worker, processes=True,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            yield client
    else:
        with Client(scheduler) as client:
            yield client


def _error_row(task, error):
    return dict(task, error=f"{type(error).__name__}: {error}")


def run_tasks(run, tasks, scheduler=None, n_workers=2, threads_per_worker=1, progress=True):
    """run(task) for every task: on an embedded LocalCluster of n_workers
    processes (scheduler=None), on the cluster at a scheduler address
    ("tcp://host:8786"), or here, one after another (scheduler="serial").
    Returns the rows in the tasks' order; a task whose future fails (its
    worker died, say) gives its task's fields with ``error``."""
    if scheduler == "serial":
        return [run(task) for task in tasks]
    with _client(scheduler, n_workers, threads_per_worker) as client:
        # pure=False: equal tasks of a repeated sweep are run again, not taken from a cache
        futures = client.map(run, tasks, pure=False)
        if progress:
            from dask.distributed import progress as progress_bar

            progress_bar(futures, notebook=False)
            print(file=sys.stderr)
        rows = []
        for task, future in zip(tasks, futures):
            try:
                rows.append(future.result())
            except Exception as e:
                rows.append(_error_row(task, e))
        return rows


def orientation_sweep(kernels, sizes, workloads=None, dimension=2, seed=1, shards=1, scheduler=None, n_workers=2,
                      progress=True):
    """A kernel comparison of the orientation predicate over the standard
    workloads (the families of ``relgeo experiment`` and the predicate
    benchmark): one row per (workload, size, shard, kernel) with the task's
    fields, the Sign_tally counts, time_s and ns_per_call of the kernel's
    vectorised call, and error (None when the task ran)."""
    tasks = orientation_tasks(kernels, sizes, workloads, dimension, seed, shards)
    return run_tasks(run_orientation_task, tasks, scheduler, n_workers, progress=progress)


def as_records(rows):
    """The table as a numpy record array (columns of the first error-free row;
    missing counts of failed rows are -1, their time NaN)."""
    columns = next((list(r) for r in rows if r.get("error") is None), list(rows[0]) if rows else [])
    def column(name):
        values = [r.get(name) for r in rows]
        if name in ORIENTATION_COUNTS:
            return np.array([-1 if v is None else v for v in values], dtype=np.int64)
        if name in TIMING_COLUMNS:
            return np.array([np.nan if v is None else v for v in values], dtype=np.float64)
        return np.array(["" if v is None else v for v in values]) if name == "error" else np.array(values)
    return np.rec.fromarrays([column(c) for c in columns], names=columns)
