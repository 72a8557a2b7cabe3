"""orient2d / orient3d over arrays and Kettner's orientation grids, against
the tool's `orient-grid` counts and against signs computed exactly here
(fractions.Fraction holds every double exactly)."""

from fractions import Fraction

import numpy as np
import pytest

import relgeo

GRID_KERNELS = ["float", "double", "long-double", "failsafe", "interval", "filtered", "exact", "mpfr-53",
                "cgal-sc", "cgal-epick"]
COUNTS = ["cells", "correct", "uncertain", "wrong", "plus_to_zero", "minus_to_zero", "zero_to_sign", "inversions"]


def grid_points(triple, size):
    """The cells of `relgeo orient-grid`: p + (X, Y) * 2**-53, row-major by Y."""
    (px, py), q, r = relgeo.kettner_triples()[triple]
    ys, xs = np.mgrid[0:size, 0:size]
    p = np.stack([px + xs.ravel() * 2.0**-53, py + ys.ravel() * 2.0**-53], axis=1)
    return p, np.array(q), np.array(r)


def tally(answers, exact):
    """The tool's counts (relgeo::analysis::Sign_tally) of answers against exact signs."""
    definite = answers != relgeo.UNCERTAIN
    wrong = definite & (answers != exact)
    return {
        "cells": answers.size,
        "correct": int(np.sum(answers == exact)),
        "uncertain": int(np.sum(~definite)),
        "wrong": int(np.sum(wrong)),
        "plus_to_zero": int(np.sum(wrong & (exact == 1) & (answers == 0))),
        "minus_to_zero": int(np.sum(wrong & (exact == -1) & (answers == 0))),
        "zero_to_sign": int(np.sum(wrong & (exact == 0))),
        "inversions": int(np.sum(wrong & (exact != 0) & (answers == -exact))),
    }


@pytest.mark.parametrize("triple", ["a", "b", "c"])
@pytest.mark.parametrize("kernel", GRID_KERNELS)
def test_vectorised_orient2d_reproduces_the_tools_grid(tool, triple, kernel):
    size = 24
    p, q, r = grid_points(triple, size)
    answers = relgeo.orient2d(p, q, r, kernel=kernel)
    exact = relgeo.orient2d(p, q, r, kernel="exact")
    assert answers.dtype == np.int8 and answers.shape == (size * size,)
    expected = tool.json("orient-grid", "--triple", triple, "--kernel", kernel, "--size", size)
    assert tally(answers, exact) == {k: expected[k] for k in COUNTS}

    grid = relgeo.orientation_grid(triple, size=size, kernel=kernel)
    assert {k: grid[k] for k in COUNTS} == {k: expected[k] for k in COUNTS}
    np.testing.assert_array_equal(grid["answers"].ravel(), answers)
    np.testing.assert_array_equal(grid["exact"].ravel(), exact)


def test_the_grids_are_hard():
    """Triple a under double gives wrong answers and failsafe uncertain ones:
    the comparisons above compare something."""
    p, q, r = grid_points("a", 24)
    exact = relgeo.orient2d(p, q, r, kernel="exact")
    assert tally(relgeo.orient2d(p, q, r, kernel="double"), exact)["wrong"] > 0
    assert np.any(relgeo.orient2d(p, q, r, kernel="failsafe") == relgeo.UNCERTAIN)


def exact_orient2d(p, q, r):
    (px, py), (qx, qy), (rx, ry) = ([Fraction(float(c)) for c in v] for v in (p, q, r))
    d = (qx - px) * (ry - py) - (qy - py) * (rx - px)
    return (d > 0) - (d < 0)


def exact_orient3d(p, q, r, s):
    """relgeo's orientation_3 is CGAL's: the sign of det[q-p, r-p, s-p]."""
    a, b, c = ([Fraction(float(x)) - Fraction(float(y)) for x, y in zip(v, p)] for v in (q, r, s))
    d = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
         + a[2] * (b[0] * c[1] - b[1] * c[0]))
    return (d > 0) - (d < 0)


def near_degenerate(rng, n, dimension):
    """n tuples of dimension + 1 points, exactly on a line (plane): dyadic
    coordinates, small integer combinations, so every value is a double; then
    the last point of half of the tuples moved by one to three ulps, and all
    of it scaled by an odd factor that rounds. Exact zeros, and signs that
    only exact arithmetic gets right."""
    a = rng.integers(-64, 64, size=(n, dimension)) / 8
    directions = [rng.integers(-64, 64, size=(n, dimension)) / 8 for _ in range(dimension - 1)]
    points = [a] + [a + d for d in directions]
    weights = rng.integers(-4, 5, size=(n, dimension - 1))
    points.append(a + sum(w[:, None] * d for w, d in zip(weights.T, directions)))
    moved = rng.random(n) < 0.5
    ulps = rng.integers(1, 4, size=(n, dimension)) * rng.choice([-1, 1], size=(n, dimension))
    points[-1] = np.where(moved[:, None], points[-1] + ulps * np.spacing(np.abs(points[-1]) + 1), points[-1])
    return [x * 0.1 for x in points]


@pytest.mark.parametrize("kernel", ["filtered", "exact", "interval", "failsafe", "double", "cgal-epick"])
def test_orient2d_against_exact_signs(kernel):
    p, q, r = near_degenerate(np.random.default_rng(2), 400, 2)
    exact = np.array([exact_orient2d(*t) for t in zip(p, q, r)], dtype=np.int8)
    assert np.count_nonzero(exact == 0) > 0 and np.count_nonzero(exact) > 0
    answers = relgeo.orient2d(p, q, r, kernel=kernel)
    definite = answers != relgeo.UNCERTAIN
    if relgeo.kernel(kernel)["certified"]:
        np.testing.assert_array_equal(answers[definite], exact[definite])
    if relgeo.kernel(kernel)["exact_predicates"]:
        np.testing.assert_array_equal(answers, exact)


@pytest.mark.parametrize("kernel", ["filtered", "exact", "interval", "failsafe", "double", "cgal-epeck"])
def test_orient3d_against_exact_signs(kernel):
    p, q, r, s = near_degenerate(np.random.default_rng(3), 300, 3)
    exact = np.array([exact_orient3d(*t) for t in zip(p, q, r, s)], dtype=np.int8)
    assert np.count_nonzero(exact == 0) > 0 and np.count_nonzero(exact) > 0
    answers = relgeo.orient3d(p, q, r, s, kernel=kernel)
    definite = answers != relgeo.UNCERTAIN
    if relgeo.kernel(kernel)["certified"]:
        np.testing.assert_array_equal(answers[definite], exact[definite])
    if relgeo.kernel(kernel)["exact_predicates"]:
        np.testing.assert_array_equal(answers, exact)


def test_single_points_give_a_scalar_and_broadcast():
    assert relgeo.orient2d([0, 0], [1, 0], [0, 1]) == relgeo.POSITIVE
    assert isinstance(relgeo.orient2d([0, 0], [1, 0], [0, 1]), np.int8)
    assert relgeo.orient2d((0, 0), (1, 1), (2, 2)) == relgeo.ZERO
    r = np.array([[0, 1], [0, -1], [2, 0], [0.5, 0]])
    np.testing.assert_array_equal(relgeo.orient2d([0, 0], [1, 0], r), [1, -1, 0, 0])
    assert relgeo.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]) == relgeo.POSITIVE
    assert relgeo.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, -1]) == relgeo.NEGATIVE
    # any array-like converts: integers, Fortran order, non-contiguous slices
    wide = np.asfortranarray(np.tile(np.arange(8.0).reshape(4, 2), (1, 2)))[:, ::2]
    assert relgeo.orient2d(wide, wide, wide).tolist() == [0, 0, 0, 0]


def test_failsafe_admits_uncertainty_with_the_documented_value():
    # Kettner's triple a, first cell: exactly collinear, failsafe cannot tell
    p, q, r = relgeo.kettner_triples()["a"]
    assert relgeo.orient2d(p, q, r, kernel="failsafe") == relgeo.UNCERTAIN == 2
    assert relgeo.orient2d(p, q, r, kernel="exact") == relgeo.ZERO


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_non_finite_coordinates_raise(bad):
    p = np.zeros((5, 2))
    p[3, 1] = bad
    for kernel in relgeo.kernel_names():
        with pytest.raises(relgeo.NonFiniteInput, match="orient2d: tuple 3 has a NaN or infinite coordinate") as e:
            relgeo.orient2d(p, [1, 0], [0, 1], kernel=kernel)
        assert isinstance(e.value, ValueError) and e.value.code == "non_finite_coordinate"
    # Under the certified kernels that hold NaN and infinity, a block is checked
    # only when an answer is uncertain: a bad tuple among certain ones in a
    # later block, in every kernel, 2D and 3D
    rng = np.random.default_rng(7)
    for kernel in relgeo.kernel_names():
        q = rng.uniform(-1, 1, (700, 3))
        q[611, 2] = bad
        with pytest.raises(relgeo.NonFiniteInput, match="orient2d: tuple 611 "):
            relgeo.orient2d(q[:, 1:], rng.uniform(-1, 1, (700, 2)), rng.uniform(-1, 1, (700, 2)), kernel=kernel)
        with pytest.raises(relgeo.NonFiniteInput, match="orient3d: tuple 611 "):
            relgeo.orient3d(*(rng.uniform(-1, 1, (700, 3)) for _ in range(3)), q, kernel=kernel)
    with pytest.raises(relgeo.NonFiniteInput, match="orient3d: tuple 0"):
        relgeo.orient3d([bad, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1])
    # every layout the check reads: a later block, a broadcast point, strided rows
    many = np.zeros((1000, 2))
    many[700, 0] = bad
    with pytest.raises(relgeo.NonFiniteInput, match="tuple 700 "):
        relgeo.orient2d([1, 0], many, [0, 1])
    with pytest.raises(relgeo.NonFiniteInput, match="tuple 0 "):
        relgeo.orient2d([bad, 0], np.zeros((10, 2)), np.ones((10, 2)))
    strided = np.zeros((600, 6))
    strided[599, 4] = bad
    with pytest.raises(relgeo.NonFiniteInput, match="tuple 599 "):
        relgeo.orient2d(strided[:, ::2][:, 1:], np.zeros((600, 2)), np.ones((600, 2)), kernel="exact")
    with pytest.raises(relgeo.NonFiniteInput, match="orient3d: tuple 599 "):
        relgeo.orient3d(np.zeros((600, 3)), np.ones((600, 3)), strided[:, 2:5], np.eye(3)[[0] * 600])


def test_the_largest_and_smallest_doubles_are_finite():
    # the check reads exponent bits: the largest finite double, the smallest
    # subnormal and -0.0 pass; an infinity or a NaN with any payload or sign is
    # refused, whatever the block it falls in
    edge = np.array([[np.finfo(float).max, -np.finfo(float).max], [5e-324, -0.0]] * 300)
    signs = relgeo.orient2d(edge, np.ones((600, 2)), np.zeros((600, 2)), kernel="exact")
    assert np.array_equal(signs, relgeo.orient2d(edge, np.ones((600, 2)), np.zeros((600, 2)), kernel="filtered"))
    for bits in (0x7FF0000000000000, 0xFFF0000000000000, 0x7FF0000000000001, 0xFFFFFFFFFFFFFFFF, 0x7FF8000000000000):
        bad = edge.copy()
        bad.view(np.uint64)[513, 1] = bits
        with pytest.raises(relgeo.NonFiniteInput, match="tuple 513 "):
            relgeo.orient2d(bad, np.ones((600, 2)), np.zeros((600, 2)), kernel="double")


def test_wrong_shapes_raise_value_error():
    with pytest.raises(ValueError, match=r"shape \(2,\) or \(n, 2\)"):
        relgeo.orient2d(np.zeros((4, 3)), np.zeros((4, 2)), np.zeros((4, 2)))
    with pytest.raises(ValueError, match=r"shape \(3,\) or \(n, 3\)"):
        relgeo.orient3d(np.zeros(3), np.zeros(3), np.zeros(3), np.zeros((2, 2, 3)))
    with pytest.raises(ValueError):  # 3 and 4 rows do not broadcast
        relgeo.orient2d(np.zeros((3, 2)), np.zeros((4, 2)), np.zeros(2))
    with pytest.raises(ValueError):
        relgeo.orient2d(["a", "b"], [0, 0], [0, 1])
    with pytest.raises(ValueError, match="shape"):  # the module itself checks too
        relgeo._relgeo.orient2d(np.zeros((3, 2)), np.zeros((3, 3)), np.zeros((3, 2)), "double")


def test_orientation_grid_bad_input(tool):
    with pytest.raises(ValueError, match="unknown triple 'd'"):
        relgeo.orientation_grid("d")
    with pytest.raises(relgeo.InvalidInput, match=r"size must be in \[1, 4096\]"):
        relgeo.orientation_grid(size=0)
    with pytest.raises(relgeo.NonFiniteInput):
        relgeo.orientation_grid(p=(float("nan"), 0), q=(1, 1), r=(2, 2), size=2)
    custom = relgeo.orientation_grid(p=(0.5, 0.5), q=(12, 12), r=(24, 24), size=8, kernel="double")
    expected = tool.json("orient-grid", "--p", "0.5,0.5", "--q", "12,12", "--r", "24,24", "--kernel", "double",
                         "--size", 8)
    assert {k: custom[k] for k in COUNTS} == {k: expected[k] for k in COUNTS}


def test_sign_tally_checks_its_input():
    assert relgeo._relgeo.sign_tally([1, 0, 2, -1], [1, 1, 0, 1]) == {
        "cells": 4, "correct": 1, "uncertain": 1, "wrong": 2, "plus_to_zero": 1, "minus_to_zero": 0,
        "zero_to_sign": 0, "inversions": 1}
    with pytest.raises(relgeo.PreconditionViolation, match="exact sign is uncertain") as e:
        relgeo._relgeo.sign_tally([1], [2])  # an exact sign must be definite
    assert isinstance(e.value, ValueError) and e.value.code == "precondition_violation"
    with pytest.raises(ValueError, match="signs are -1, 0, 1 or 2"):
        relgeo._relgeo.sign_tally([5], [1])
    with pytest.raises(ValueError, match="one length"):
        relgeo._relgeo.sign_tally([1, 1], [1])
