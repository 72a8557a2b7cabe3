"""Kernel-comparison sweeps as Dask tasks (doc/python.md, "Sweeps").

A sweep is a grid of tasks, workload x size x shard x kernel; each task
generates its inputs itself from (workload, size, seed of its shard), so a
task is the same wherever it runs and the table does not depend on how
many workers there are. ``sweep`` runs the tasks on Dask and gathers one
table: a list of dicts, one row a task, in the grid's order.

    rows = relgeo.sweep.orientation_sweep(["double", "failsafe", "interval", "filtered"], sizes=[10000])
    rows = relgeo.sweep.orientation_sweep(kernels, sizes, scheduler="tcp://host:8786")  # an existing cluster
    rows = relgeo.sweep.orientation_sweep(kernels, sizes, scheduler="serial")           # no Dask
    rows = relgeo.sweep.boolean_sweep("meshes/", ["union", "difference"], ["filtered", "exact"])

A task that raises, or whose worker dies, gives a row with ``error`` set
(the exception's type and message) and no counts; the others still run.

A script that starts the embedded LocalCluster must do so under
``if __name__ == "__main__":`` (Dask's worker processes re-import the main
module).
"""

import contextlib
import os
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
    return run_orientation_shard([task])[0]


def run_orientation_shard(tasks):
    """The tasks of one shard (one workload, size and seed; a kernel each):
    its cases generated once, the exact signs computed once, then each
    kernel's signs against them; the rows in the tasks' order. An exception
    is the ``error`` of the rows it concerns (every row when the shard itself
    fails, that kernel's row when a kernel does)."""
    first = tasks[0]
    try:
        points = _relgeo.orientation_workloads(first["dimension"], first["cases"], first["seed"],
                                               first["workload"])[first["workload"]]
        signs = _relgeo.orient2d if first["dimension"] == 2 else _relgeo.orient3d
        exact = signs(*points, "exact")
    except Exception as e:  # reported in the table, not fatal to the sweep
        return [_error_row(task, e) for task in tasks]
    rows = []
    for task in tasks:
        row = dict(task, error=None)
        try:
            start = time.perf_counter()
            answers = signs(*points, task["kernel"])
            elapsed = time.perf_counter() - start
            row.update(_relgeo.sign_tally(answers, exact))
            row["time_s"] = elapsed
            row["ns_per_call"] = 1e9 * elapsed / max(task["cases"], 1)
        except Exception as e:
            row = _error_row(task, e)
        rows.append(row)
    return rows


def _shards(tasks):
    """The tasks grouped by shard (consecutive tasks of one workload,
    dimension, size and seed: orientation_tasks puts the kernels innermost)."""
    groups = []
    for task in tasks:
        key = (task["workload"], task["dimension"], task["size"], task["cases"], task["seed"])
        if groups and groups[-1][0] == key:
            groups[-1][1].append(task)
        else:
            groups.append((key, [task]))
    return [group for _, group in groups]


_PRE_SPAWN = "distributed.nanny.pre-spawn-environ"


def _embedded_cluster_config(threads_per_worker):
    """Dask settings for the embedded LocalCluster, which has no dashboard and
    shares the machine's cores with its tasks (doc/python.md, "Sweeps on
    Dask", has the measurements behind each):
    - no statistical profiler in the workers (it samples every thread's
      stack every 10 ms for the dashboard);
    - the event-loop tick of its five servers (scheduler, two nannies, two
      workers) every 200 ms instead of 20, and their system monitor every 2 s
      instead of 0.5: both only feed diagnostics and the dashboard. With the
      profiler off, the idle cluster took 5-8% of a core, with these 2-2.5%;
    - one malloc arena in a worker that runs one task thread: Dask runs tasks
      in a thread of its own, and glibc gives such a thread an arena of its
      own, on which the exact kernel's many small GMP allocations ran 2-8%
      slower than on the main thread's.
    The memory monitor (and so the memory limit) keeps Dask's defaults."""
    import dask

    environ = dict(dask.config.get(_PRE_SPAWN, default={}) or {})  # Dask's own, kept
    if threads_per_worker == 1:
        environ.setdefault("MALLOC_ARENA_MAX", 1)
    return {"distributed.worker.profile.enabled": False, "distributed.admin.tick.interval": "200ms",
            "distributed.admin.system-monitor.interval": "2s", _PRE_SPAWN: environ}


@contextlib.contextmanager
def _client(scheduler, n_workers, threads_per_worker):
    import dask  # only when Dask is used
    from dask.distributed import Client, LocalCluster

    if scheduler is None:
        settings = _embedded_cluster_config(threads_per_worker)
        # Dask's nannies run in this process and set their pre-spawn variables
        # in its environment; they are put back as they were afterwards.
        saved = {key: os.environ.get(key) for key in settings[_PRE_SPAWN]}
        try:
            with dask.config.set(settings), \
                    LocalCluster(n_workers=n_workers, threads_per_worker=threads_per_worker, processes=True,
                                 dashboard_address=None) as cluster, Client(cluster) as client:
                yield client
        finally:
            for key, value in saved.items():
                if value is None:
                    os.environ.pop(key, None)
                else:
                    os.environ[key] = value
    else:
        with Client(scheduler) as client:
            yield client


def _error_row(task, error):
    """The task's fields with ``error``; a row for each task of a group (a
    list of tasks run as one)."""
    if isinstance(task, list):
        return [_error_row(t, error) for t in task]
    return dict(task, error=f"{type(error).__name__}: {error}")


def run_tasks(run, tasks, scheduler=None, n_workers=2, threads_per_worker=1, progress=True):
    """run(task) for every task: on an embedded LocalCluster of n_workers
    processes (scheduler=None), on the cluster at a scheduler address
    ("tcp://host:8786"), or here, one after another (scheduler="serial").
    Returns the rows in the tasks' order; a task whose future fails (its
    worker died, say) gives its task's fields with ``error`` (a task may be
    a list of tasks that ``run`` runs together: it gives a list of rows)."""
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
    vectorised call, and error (None when the task ran). A shard's kernels
    run in one Dask task, which generates the cases and the exact signs once
    for all of them."""
    results = run_tasks(run_orientation_shard, _shards(orientation_tasks(kernels, sizes, workloads, dimension, seed,
                                                                         shards)),
                        scheduler, n_workers, progress=progress)
    return [row for shard_rows in results for row in shard_rows]


BOOLEAN_COUNTS = ("faces", "unchanged_faces", "moved_vertices", "repair_rounds")
"""The integer columns of a Boolean sweep's rows (-1 when the task failed)."""

MESH_SUFFIXES = (".off", ".obj", ".ply", ".stl")


def _mesh_files(meshes):
    """The mesh files of a folder (sorted by name), or the given paths."""
    if isinstance(meshes, (str, os.PathLike)) and os.path.isdir(meshes):
        return sorted(os.path.join(meshes, f) for f in os.listdir(meshes) if f.lower().endswith(MESH_SUFFIXES))
    return [os.fspath(m) for m in ([meshes] if isinstance(meshes, (str, os.PathLike)) else meshes)]


def _rigid_motion(rng):
    """A rotation by 0.1-0.6 rad about a random axis and a shift of 5-15% of
    the box diagonal along a random direction (the Boolean tests' and
    benchmark's moved copies)."""
    axis = rng.normal(size=3)
    direction = rng.normal(size=3)
    return {"axis": (axis / np.linalg.norm(axis)).tolist(), "angle": float(rng.uniform(0.1, 0.6)),
            "direction": (direction / np.linalg.norm(direction)).tolist(), "shift": float(rng.uniform(0.05, 0.15))}


def moved_copy(V, motion):
    """V rotated about its box centre and shifted (motion: as in boolean_tasks).
    Elementwise numpy operations, no BLAS: the same doubles on every machine."""
    V = np.asarray(V, dtype=np.float64)
    lo, hi = V.min(axis=0), V.max(axis=0)
    centre, diagonal = 0.5 * (lo + hi), float(np.sqrt(((hi - lo) ** 2).sum()))
    (x, y, z), a = motion["axis"], motion["angle"]
    c, s, t = np.cos(a), np.sin(a), 1 - np.cos(a)
    R = [[c + x * x * t, x * y * t - z * s, x * z * t + y * s],
         [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
         [z * x * t - y * s, z * y * t + x * s, c + z * z * t]]
    P = V - centre
    out = np.empty_like(V)
    for i in range(3):
        out[:, i] = R[i][0] * P[:, 0] + R[i][1] * P[:, 1] + R[i][2] * P[:, 2] + centre[i] + \
            motion["shift"] * diagonal * motion["direction"][i]
    return out


def boolean_tasks(meshes, operations=("union", "intersection", "difference"), kernels=("filtered",), seed=1):
    """The grid of a Boolean sweep: one dict per (mesh, operation, kernel), in
    that nesting order, each mesh against a rigidly moved copy of itself
    (the motion drawn per mesh from ``seed``, stored in the task: every task
    of a mesh uses the same copy, wherever it runs). ``meshes``: a folder
    (its .off, .obj, .ply and .stl files, sorted by name) or a list of paths."""
    rng = np.random.default_rng(seed)
    tasks = []
    for path in _mesh_files(meshes):
        motion = _rigid_motion(rng)
        for operation in operations:
            for kernel in kernels:
                tasks.append({"mesh": os.path.basename(path), "path": path, "operation": operation,
                              "kernel": kernel, "motion": motion})
    return tasks


def run_boolean_task(task):
    """One task: relgeo.boolean of the mesh and its moved copy under the
    task's kernel. The row: status ("ok", "failed" or "error"), failure,
    valid (the output's validation), volume, faces, unchanged_faces (kept
    whole from a certified operand), moved_vertices and repair_rounds (the
    rounding repair), rounding_error, and time_s (the Boolean, without its
    validation). Never raises: a refused operand (InvalidOperand: an open or
    self-intersecting mesh of a collection is real input) or any other
    exception is the row's ``error``."""
    from . import boolean, read_mesh  # the package's functions (it imports this module first)

    row = dict(task, error=None)
    del row["path"]
    try:
        V, F = read_mesh(task["path"], triangulate=True)
        r = boolean((V, F), (moved_copy(V, task["motion"]), F), task["operation"], task["kernel"])
        row.update(status=r["status"], failure=r["failure"], valid=bool(r["validation"].get("valid_solid", False)),
                   volume=r["validation"].get("volume", {}).get("value"), faces=int(r["output"]["faces"]),
                   unchanged_faces=int(r["counts"].get("unchanged_certified_faces", 0)),
                   moved_vertices=int(r["rounding"]["moved_vertices"]), repair_rounds=int(r["rounding"]["rounds"]),
                   rounding_error=r["rounding_error"],
                   time_s=sum(t for phase, t in r["time_s"].items() if phase != "validation"))
    except Exception as e:  # reported in the table, not fatal to the sweep
        row.update(status="error", error=f"{type(e).__name__}: {e}")
    return row


def boolean_sweep(meshes, operations=("union", "intersection", "difference"), kernels=("filtered",), seed=1,
                  scheduler=None, n_workers=2, progress=True):
    """A kernel comparison of the mesh Boolean over a collection of meshes
    (CGAL's data set, say): every mesh against a moved copy of itself, for
    each operation and kernel (boolean_tasks, run_boolean_task), on Dask as
    orientation_sweep. One row per task, in the grid's order."""
    return run_tasks(run_boolean_task, boolean_tasks(meshes, operations, kernels, seed), scheduler, n_workers,
                     progress=progress)


def as_records(rows):
    """The table as a numpy record array (columns of the first error-free row;
    missing counts of failed rows are -1, their time NaN)."""
    columns = next((list(r) for r in rows if r.get("error") is None), list(rows[0]) if rows else [])
    def column(name):
        values = [r.get(name) for r in rows]
        if name in ORIENTATION_COUNTS or name in BOOLEAN_COUNTS:
            return np.array([-1 if v is None else v for v in values], dtype=np.int64)
        if name in TIMING_COLUMNS or name in ("volume", "rounding_error"):
            return np.array([np.nan if v is None else v for v in values], dtype=np.float64)
        return np.array(["" if v is None else v for v in values]) if name == "error" else np.array(values)
    return np.rec.fromarrays([column(c) for c in columns], names=columns)
