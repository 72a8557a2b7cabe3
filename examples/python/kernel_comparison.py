# examples/python/kernel_comparison.py — notebook-style (cells marked "# %%",
# run them in Jupyter/VS Code or the whole file with python3): the orientation
# grids of Kettner et al. under every kernel, as the "kernels" section of
# `relgeo experiment` shows them:
#   * the table: for each grid (triple a, b, c) and kernel, the tally of the
#     kernel's answers against the exact signs (wrong, plus_to_zero,
#     minus_to_zero, zero_to_sign, inversions, uncertain, correct);
#   * the plot: grid a under each kernel, coloured as the experiment's
#     pictures (red/yellow/blue = negative/zero/positive, dark = wrong,
#     grey = uncertain), one PNG.
#
#   PYTHONPATH=build/python /usr/bin/python3 examples/python/kernel_comparison.py [--size 256] [--output DIR]
#
# Needs the relgeo package (doc/python.md) and matplotlib (Debian:
# python3-matplotlib). python/tests/test_examples.py runs it on a small grid
# and checks its table against `relgeo orient-grid`.

# %% Parameters
import argparse
import json
import pathlib

import matplotlib
import numpy as np

import relgeo

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--size", type=int, default=256, help="cells per side (the experiment's grids: 256)")
parser.add_argument("--kernels", nargs="+", default=relgeo.kernel_names(), help="kernel names (default: all)")
parser.add_argument("--output", type=pathlib.Path, default=pathlib.Path("kernel_comparison"),
                    help="folder for grids.json and grid_a.png")
args, _ = parser.parse_known_args()  # known only: Jupyter passes its own arguments
args.output.mkdir(parents=True, exist_ok=True)
certified = {k["name"]: k["certified"] for k in relgeo.kernels()}

# %% The grids under every kernel
# One record per (triple, kernel), the fields of the experiment's kernels.json
# "grids" records; the answers are kept for the plot.
COUNTS = ["wrong", "plus_to_zero", "minus_to_zero", "zero_to_sign", "inversions", "uncertain", "correct"]
records, answers = [], {}
for triple in ("a", "b", "c"):
    for kernel in args.kernels:
        g = relgeo.orientation_grid(triple, size=args.size, kernel=kernel)
        records.append({"triple": triple, "kernel": kernel, "certified": certified[kernel], "size": g["size"],
                        "cells": g["cells"], **{c: g[c] for c in COUNTS}})
        answers[triple, kernel] = (g["answers"], g["exact"])
(args.output / "grids.json").write_text(json.dumps(records, indent=1) + "\n")

# %% The table (the experiment's "Orientation grid" tables, one per triple)
width = max(len(k) for k in args.kernels)
for triple in ("a", "b", "c"):
    print(f"Orientation grid {triple}: {args.size} x {args.size} cells p + (X, Y) * 2^-53")
    print(f"{'kernel':<{width}}  certified " + " ".join(f"{c:>13}" for c in COUNTS))
    for r in records:
        if r["triple"] == triple:
            flag = " !" if r["certified"] and r["wrong"] else ""  # a certified kernel answering wrong
            print(f"{r['kernel']:<{width}}  {'yes' if r['certified'] else 'no':<9} " +
                  " ".join(f"{r[c]:>13}" for c in COUNTS) + flag)
    print()

# %% The plot: grid a under each kernel
# The experiment's colours (tools/relgeo/commands/orient_grid/picture.cpp).
RIGHT = {-1: (230, 40, 40), 0: (250, 220, 40), 1: (50, 90, 230)}
WRONG = {-1: (110, 0, 0), 0: (120, 110, 0), 1: (0, 0, 110)}
GREY = (160, 160, 160)


def grid_image(answer, exact):
    """RGB image of a grid: row Y=0 at the bottom (origin="lower" below)."""
    image = np.empty(answer.shape + (3,), dtype=np.uint8)
    image[...] = GREY
    for sign in (-1, 0, 1):
        image[(answer == sign) & (exact == sign)] = RIGHT[sign]
        image[(answer == sign) & (exact != sign)] = WRONG[sign]
    return image


columns = min(5, len(args.kernels))
rows = -(-len(args.kernels) // columns)
figure, axes = plt.subplots(rows, columns, figsize=(2.4 * columns, 2.6 * rows), squeeze=False)
for ax in axes.flat:
    ax.axis("off")
for ax, kernel in zip(axes.flat, args.kernels):
    ax.imshow(grid_image(*answers["a", kernel]), origin="lower", interpolation="nearest")
    r = next(r for r in records if r["triple"] == "a" and r["kernel"] == kernel)
    ax.set_title(f"{kernel}\n{r['wrong']} wrong" + (f", {r['uncertain']} uncertain" if r["uncertain"] else ""),
                 fontsize=8)
figure.suptitle(f"Orientation grid a ({args.size} x {args.size}) under each kernel", fontsize=10)
figure.tight_layout()
figure.savefig(args.output / "grid_a.png", dpi=100)
print("wrote", args.output / "grids.json", "and", args.output / "grid_a.png")
