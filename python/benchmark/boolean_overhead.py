"""Wall time of relgeo.boolean against the C++ call it wraps, on one mesh pair
(doc/python.md, "Binding overhead"): the best of N runs of

  * the tool, `relgeo boolean A B --format json`: the record's time_s.total
    + time_s.validation (total is the Boolean's phases, operand checks
    included; the validation of the result is timed apart), the time of the
    C++ call evaluate_boolean (files read before, not timed);
  * relgeo.boolean((VA, FA), (VB, FB)) from arrays already in memory: its
    wall time (the arrays' conversion and index checks, the call, the dict
    and the result arrays) and its record's total + validation (the same
    C++ call).

The exact kernel's call also counts the result's exact self-intersecting
pairs (exact_self_intersecting_pairs), which time_s does not hold: compare
it by the tool's process time.

    RELGEO_TOOL=build/tools/relgeo/relgeo PYTHONPATH=build/python \\
        /usr/bin/python3 python/benchmark/boolean_overhead.py [A.off B.off] [--op union] [--kernel filtered] [-n 5]

Without meshes: two Loop spheres of 20480 faces each, the icosahedron and
its moved copy (tools/relgeo/testdata) refined 5 times (written to a
temporary folder).
"""

import argparse
import json
import os
import pathlib
import subprocess
import tempfile
import time

import relgeo

TESTDATA = pathlib.Path(__file__).resolve().parents[2] / "tools" / "relgeo" / "testdata"


def call_seconds(record):
    """The C++ call's time in a Boolean record: its phases and the validation."""
    return record["time_s"]["total"] + record["time_s"]["validation"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("meshes", nargs="*", type=pathlib.Path)
    parser.add_argument("--op", default="union")
    parser.add_argument("--kernel", default="filtered")
    parser.add_argument("-n", type=int, default=5)
    args = parser.parse_args()
    tool = os.environ.get("RELGEO_TOOL", "build/tools/relgeo/relgeo")
    with tempfile.TemporaryDirectory() as tmp:
        if args.meshes:
            a, b = args.meshes
        else:
            a, b = pathlib.Path(tmp) / "sphere_a.off", pathlib.Path(tmp) / "sphere_b.off"
            for source, target in ((TESTDATA / "icosahedron.off", a), (TESTDATA / "icosahedron_moved.off", b)):
                relgeo.write_mesh(target, *relgeo.loop_subdivide(*relgeo.read_mesh(source), 5))
        A, B = relgeo.read_mesh(a), relgeo.read_mesh(b)
        print(f"A: {len(A[1])} faces, B: {len(B[1])} faces, {args.op} under {args.kernel}, best of {args.n}")
        tool_call, tool_wall, python_wall, python_call = [], [], [], []
        for _ in range(args.n):
            start = time.perf_counter()
            done = subprocess.run([tool, "boolean", a, b, "--op", args.op, "--kernel", args.kernel, "--format", "json"],
                                  capture_output=True, text=True, check=True)
            tool_wall.append(time.perf_counter() - start)
            tool_call.append(call_seconds(json.loads(done.stdout)))
            start = time.perf_counter()
            r = relgeo.boolean(A, B, op=args.op, kernel=args.kernel)
            python_wall.append(time.perf_counter() - start)
            python_call.append(call_seconds(r))
        t, w, c = min(tool_call), min(python_wall), min(python_call)
        print(f"tool, the process (reading the files)   {min(tool_wall):8.4f} s")
        print(f"tool, the C++ call (total + validation) {t:8.4f} s")
        print(f"relgeo.boolean, wall                    {w:8.4f} s   {w / t:5.3f}x the tool's call")
        print(f"relgeo.boolean, the C++ call inside     {c:8.4f} s   binding adds {w - c:.4f} s ({w / c:5.3f}x)")


if __name__ == "__main__":
    main()
