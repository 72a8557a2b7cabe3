"""relgeo.sweep on Dask: the table of a 2-worker LocalCluster and of a
scheduler started here equal the serial run's; a failing task is a row."""

import os
import socket
import subprocess
import sys
import time

import numpy as np
import pytest

import relgeo
from relgeo import sweep

distributed = pytest.importorskip("dask.distributed")

# Dask 2022.12 on tornado 6.2 warns from inside its event loop.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

KERNELS = ["double", "failsafe", "interval", "filtered"]


def deterministic(rows):
    return [{k: v for k, v in row.items() if k not in sweep.TIMING_COLUMNS} for row in rows]


@pytest.fixture(scope="module")
def serial_rows():
    return sweep.orientation_sweep(KERNELS, sizes=[3000], shards=2, scheduler="serial")


def test_serial_table_is_complete_and_agrees_with_the_predicates(serial_rows):
    workloads = sweep.orientation_workload_names()
    assert len(workloads) == 4 and "uniform" in workloads
    assert len(serial_rows) == len(workloads) * 2 * len(KERNELS)
    assert all(row["error"] is None for row in serial_rows)
    assert sum(row["cases"] for row in serial_rows if row["kernel"] == "double") == 4 * 3000
    for row in serial_rows:
        assert row["cells"] == row["cases"] == row["correct"] + row["uncertain"] + row["wrong"]
        if relgeo.kernel(row["kernel"])["certified"]:
            assert row["wrong"] == 0
    # the near-degenerate families are hard: double errs and failsafe admits it
    assert any(r["wrong"] > 0 for r in serial_rows if r["kernel"] == "double")
    assert any(r["uncertain"] > 0 for r in serial_rows if r["kernel"] == "failsafe")
    # a row is what the bindings compute on the same workload
    row = next(r for r in serial_rows if r["kernel"] == "double" and r["workload"] == "near-collinear")
    points = relgeo._relgeo.orientation_workloads(2, row["cases"], row["seed"])["near-collinear"]
    expected = relgeo._relgeo.sign_tally(relgeo.orient2d(*points, kernel="double"),
                                         relgeo.orient2d(*points, kernel="exact"))
    assert {k: row[k] for k in sweep.ORIENTATION_COUNTS} == expected


def test_local_cluster_table_equals_the_serial_one(serial_rows):
    rows = sweep.orientation_sweep(KERNELS, sizes=[3000], shards=2, n_workers=2, progress=False)
    assert deterministic(rows) == deterministic(serial_rows)


def worker_settings(_task):
    import dask

    return {"MALLOC_ARENA_MAX": os.environ.get("MALLOC_ARENA_MAX"),
            "tick": dask.config.get("distributed.admin.tick.interval"),
            "profile": dask.config.get("distributed.worker.profile.enabled")}


def test_the_embedded_cluster_tunes_its_workers_and_leaves_this_environment_as_found():
    import cloudpickle

    cloudpickle.register_pickle_by_value(sys.modules[__name__])  # the workers cannot import this test file
    before = dict(os.environ)
    rows = sweep.run_tasks(worker_settings, [0, 1], n_workers=2, progress=False)
    assert rows == [{"MALLOC_ARENA_MAX": "1", "tick": "200ms", "profile": False}] * 2
    assert dict(os.environ) == before
    # a worker of several task threads keeps glibc's arenas
    assert "MALLOC_ARENA_MAX" not in sweep._embedded_cluster_config(2)[sweep._PRE_SPAWN]


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_scheduler_and_two_workers_started_here(serial_rows):
    address = f"tcp://127.0.0.1:{free_port()}"
    bin_dir = os.path.dirname(sys.executable)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))  # the workers import relgeo as this test does
    scheduler = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
                                  "--port", address.rsplit(":", 1)[1], "--no-dashboard"],
                                 env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    workers = [subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", address, "--nworkers", "1",
                                 "--nthreads", "1", "--no-dashboard"],
                                env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) for _ in range(2)]
    try:
        with distributed.Client(address, timeout=60) as client:
            client.wait_for_workers(2, timeout=60)
        rows = sweep.orientation_sweep(KERNELS, sizes=[3000], shards=2, scheduler=address, progress=False)
        assert deterministic(rows) == deterministic(serial_rows)
    finally:
        for p in workers + [scheduler]:
            p.terminate()
        for p in workers + [scheduler]:
            p.wait(timeout=30)


def test_a_failing_task_is_a_row_not_a_failure():
    rows = sweep.orientation_sweep(["double", "no-such-kernel"], sizes=[500], workloads=["uniform"],
                                   n_workers=2, progress=False)
    assert [r["kernel"] for r in rows] == ["double", "no-such-kernel"]
    assert rows[0]["error"] is None and rows[0]["cells"] == 500
    assert rows[1]["error"].startswith("ValueError: unknown kernel 'no-such-kernel'")
    assert "cells" not in rows[1]


def die_on_second_task(task):
    if task["kernel"] == "filtered":
        os._exit(3)  # the worker process dies, not just the task
    return sweep.run_orientation_task(task)


def test_a_dying_worker_is_a_row_not_a_failure():
    import cloudpickle
    import dask

    cloudpickle.register_pickle_by_value(sys.modules[__name__])  # the workers cannot import this test file

    tasks = sweep.orientation_tasks(["double", "filtered"], sizes=[200], workloads=["uniform"])
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        rows = sweep.run_tasks(die_on_second_task, tasks, n_workers=2, progress=False)
    assert rows[0]["error"] is None and rows[0]["cells"] == 200
    assert rows[1]["kernel"] == "filtered" and "KilledWorker" in rows[1]["error"]


def test_a_shard_generates_its_family_alone_and_shares_the_exact_signs(serial_rows):
    # one family alone has the cases it has among all four, in 2D and 3D
    for dimension in (2, 3):
        every = relgeo._relgeo.orientation_workloads(dimension, 500, 5)
        for name, arrays in every.items():
            alone = relgeo._relgeo.orientation_workloads(dimension, 500, 5, name)
            assert list(alone) == [name]
            assert all(np.array_equal(a, b) for a, b in zip(alone[name], arrays))
    with pytest.raises(ValueError, match="unknown family 'uniformly' .valid: uniform, near-collinear"):
        relgeo._relgeo.orientation_workloads(2, 10, 1, "uniformly")
    # a shard's rows are those of its kernels run one task each
    shard = [t for t in sweep.orientation_tasks(KERNELS, sizes=[3000], shards=2) if t["shard"] == 1][:len(KERNELS)]
    assert deterministic(sweep.run_orientation_shard(shard)) == deterministic(
        [sweep.run_orientation_task(t) for t in shard])
    assert deterministic(sweep.run_orientation_shard(shard)) == deterministic(
        [r for r in serial_rows if r["shard"] == 1][:len(KERNELS)])


def die_on_the_second_shard(tasks):
    if tasks[0]["shard"] == 1:
        os._exit(3)
    return sweep.run_orientation_shard(tasks)


def test_a_dying_shard_is_a_row_for_each_of_its_kernels():
    import cloudpickle
    import dask

    cloudpickle.register_pickle_by_value(sys.modules[__name__])

    groups = sweep._shards(sweep.orientation_tasks(["double", "filtered"], sizes=[400], workloads=["uniform"],
                                                   shards=2))
    assert [len(g) for g in groups] == [2, 2]
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        results = sweep.run_tasks(die_on_the_second_shard, groups, n_workers=2, progress=False)
    assert [r["error"] for r in results[0]] == [None, None]
    assert [r["kernel"] for r in results[1]] == ["double", "filtered"]
    assert all("KilledWorker" in r["error"] for r in results[1])


def test_records(serial_rows):
    table = sweep.as_records(serial_rows)
    assert len(table) == len(serial_rows)
    assert table.wrong.dtype == np.int64 and table.ns_per_call.dtype == np.float64
    assert list(table.kernel[:4]) == KERNELS


# ---- Booleans over a folder of meshes ---------------------------------------------------

from conftest import TESTDATA  # noqa: E402


@pytest.fixture(scope="module")
def mesh_folder(tmp_path_factory):
    """Two solids, an open mesh (refused: a row with InvalidOperand) and a
    file that is not a mesh (a row with UnreadableFile)."""
    folder = tmp_path_factory.mktemp("meshes")
    for name in ("icosahedron.off", "cube_open.off"):
        (folder / name).write_bytes((TESTDATA / name).read_bytes())
    (folder / "sphere.off").write_bytes((TESTDATA / "csg" / "fused_spheres_01.off").read_bytes())
    (folder / "zz_garbage.off").write_text("OFF\n3 1 0\n0 0\n")
    (folder / "notes.txt").write_text("not a mesh: not in the sweep")
    return folder


BOOLEAN_KERNELS = ["filtered", "exact", "double"]


@pytest.fixture(scope="module")
def boolean_rows(mesh_folder):
    return sweep.boolean_sweep(mesh_folder, ["union", "difference"], BOOLEAN_KERNELS, scheduler="serial")


def test_boolean_sweep_covers_the_folder_and_reports_bad_meshes(mesh_folder, boolean_rows):
    assert len(boolean_rows) == 4 * 2 * len(BOOLEAN_KERNELS)
    assert [r["mesh"] for r in boolean_rows[::6]] == ["cube_open.off", "icosahedron.off", "sphere.off",
                                                      "zz_garbage.off"]
    by_mesh = {}
    for r in boolean_rows:
        by_mesh.setdefault(r["mesh"], []).append(r)
    assert all(r["error"].startswith("InvalidOperand") for r in by_mesh["cube_open.off"])
    assert all(r["error"].startswith("UnreadableFile") for r in by_mesh["zz_garbage.off"])
    for mesh in ("icosahedron.off", "sphere.off"):
        for r in by_mesh[mesh]:
            assert r["error"] is None, r
            if r["kernel"] != "double":  # the naive kernel may fail a Boolean, and says so
                assert r["status"] == "ok" and r["valid"], r
        # the certified kernels agree on every doubles of the output
        filtered, exact = ({r["operation"]: r for r in by_mesh[mesh] if r["kernel"] == k} for k in ("filtered", "exact"))
        for op in ("union", "difference"):
            assert filtered[op]["volume"] == exact[op]["volume"] and filtered[op]["faces"] == exact[op]["faces"]
    # a row is what relgeo.boolean gives on the same operands
    task = next(t for t in sweep.boolean_tasks(mesh_folder, ["union"], ["filtered"]) if t["mesh"] == "sphere.off")
    V, F = relgeo.read_mesh(task["path"])
    r = relgeo.boolean((V, F), (sweep.moved_copy(V, task["motion"]), F), "union", "filtered")
    row = next(r for r in boolean_rows if r["mesh"] == "sphere.off" and r["operation"] == "union"
               and r["kernel"] == "filtered")
    assert row["volume"] == r["validation"]["volume"]["value"] and row["faces"] == len(r["F"])
    assert 0 < row["unchanged_faces"] < row["faces"]  # the sphere's copy cuts it: some faces kept whole, not all


def test_boolean_sweep_on_a_local_cluster_equals_the_serial_one(mesh_folder, boolean_rows):
    rows = sweep.boolean_sweep(mesh_folder, ["union", "difference"], BOOLEAN_KERNELS, n_workers=2, progress=False)
    assert deterministic(rows) == deterministic(boolean_rows)
    table = sweep.as_records(rows)
    assert table.faces.dtype == np.int64 and list(table.faces[:6]) == [-1] * 6  # the open mesh's rows
