"""Time per call of relgeo.orient2d over arrays of uniform triples, to set
against relgeo_predicate_benchmark's orientation_2/uniform rows (doc/python.md,
"Binding overhead").

    PYTHONPATH=build/python /usr/bin/python3 python/benchmark/orient2d_overhead.py 32768 double failsafe filtered
"""

import sys
import time

import relgeo


def best_time(call, repetitions):
    best = float("inf")
    for _ in range(repetitions):
        start = time.perf_counter()
        call()
        best = min(best, time.perf_counter() - start)
    return best


def main(n, kernels):
    # relgeo::analysis::uniform_2: the benchmark's family (its cases, not its batch order)
    p, q, r = relgeo._relgeo.orientation_workloads(2, n, 1)["uniform"]
    repetitions = 7 if n >= 10**6 else 201
    for kernel in kernels:
        relgeo.orient2d(p, q, r, kernel=kernel)  # warm up
        seconds = best_time(lambda: relgeo.orient2d(p, q, r, kernel=kernel), repetitions)
        print(f"{kernel:10s} {1e9 * seconds / n:6.2f} ns per call ({n} triples, best of {repetitions})")


if __name__ == "__main__":
    main(int(sys.argv[1]), sys.argv[2:] or ["double", "failsafe", "filtered"])
