"""examples/python/kernel_comparison.py, run on small grids so that it cannot rot:
its table against `relgeo orient-grid` on the same grids, its plot a PNG."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "kernel_comparison.py"
KERNELS = ["double", "failsafe", "interval", "filtered", "cgal-epick"]


def test_kernel_comparison_example(tool, tmp_path):
    pytest.importorskip("matplotlib")
    done = subprocess.run([sys.executable, EXAMPLE, "--size", "24", "--kernels", *KERNELS, "--output", tmp_path],
                          capture_output=True, text=True, timeout=300, env=os.environ)
    assert done.returncode == 0, done.stderr
    records = json.loads((tmp_path / "grids.json").read_text())
    assert [(r["triple"], r["kernel"]) for r in records] == [(t, k) for t in "abc" for k in KERNELS]
    for r in records:
        expected = tool.json("orient-grid", "--triple", r["triple"], "--kernel", r["kernel"], "--size", 24)
        for field in ("cells", "correct", "uncertain", "wrong", "plus_to_zero", "minus_to_zero", "zero_to_sign",
                      "inversions"):
            assert r[field] == expected[field], (r["triple"], r["kernel"], field)
        # the printed table holds the row
        row = [r["kernel"], "yes" if r["certified"] else "no"] + [str(r[c]) for c in (
            "wrong", "plus_to_zero", "minus_to_zero", "zero_to_sign", "inversions", "uncertain", "correct")]
        assert any(line.split()[:len(row)] == row for line in done.stdout.splitlines() if line.strip()), row
    assert any(r["wrong"] > 0 for r in records if r["kernel"] == "double")  # the grids do catch double out
    png = (tmp_path / "grid_a.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 1000
