"""Wall time of an orientation sweep run serially and on a 2-worker
LocalCluster (its start included), and whether the two tables agree
(doc/python.md, "Sweeps on Dask"). Run it on an otherwise idle machine:

    PYTHONPATH=build/python /usr/bin/python3 python/benchmark/sweep_speedup.py [CASES] [SHARDS]
"""

import sys
import time

from relgeo import sweep

KERNELS = ["double", "failsafe", "interval", "filtered"]


def deterministic(rows):
    return [{k: v for k, v in row.items() if k not in sweep.TIMING_COLUMNS} for row in rows]


def main(cases, shards):
    start = time.perf_counter()
    serial = sweep.orientation_sweep(KERNELS, sizes=[cases], shards=shards, scheduler="serial")
    serial_s = time.perf_counter() - start
    start = time.perf_counter()
    parallel = sweep.orientation_sweep(KERNELS, sizes=[cases], shards=shards, n_workers=2, progress=False)
    parallel_s = time.perf_counter() - start
    tasks = len(serial)
    same = deterministic(serial) == deterministic(parallel)
    print(f"{tasks} tasks ({cases} cases per workload in {shards} shards x {len(KERNELS)} kernels): "
          f"serial {serial_s:.1f} s, 2-worker LocalCluster {parallel_s:.1f} s (start included), "
          f"speed-up {serial_s / parallel_s:.2f}x, same table: {same}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 800000, int(sys.argv[2]) if len(sys.argv) > 2 else 4)
