"""convex_hull against `relgeo hull --format json` on the same points."""

import numpy as np
import pytest

import relgeo
from conftest import TESTDATA

FIELDS = ["status", "failure", "hull_size", "convex", "error", "backward_error", "backward_error_bound",
          "coordinate_bound", "moved_points", "worst_point", "uncertain_answers", "predicate_calls",
          "kernel", "kernel_model", "certified", "n"]


def write_points(path, points):
    path.write_text("".join(f"{x!r} {y!r}\n" for x, y in points))  # repr round-trips doubles
    return path


def near_collinear_points(n, seed):
    """Points close to a line, a few far off it: wrong turns for naive kernels."""
    rng = np.random.default_rng(seed)
    t = rng.uniform(0, 1, n)
    points = np.stack([0.5 + 23.5 * t, 0.5 + 23.5 * t], axis=1)
    points += rng.integers(-3, 4, size=(n, 2)) * np.spacing(points)
    return np.vstack([points, rng.uniform(0, 24, size=(8, 2))])


INPUTS = {
    "classroom": lambda: np.loadtxt(TESTDATA / "classroom_a1.txt"),
    "uniform": lambda: np.random.default_rng(1).uniform(-1, 1, size=(200, 2)),
    "near_collinear": lambda: near_collinear_points(300, 4),
}


@pytest.mark.parametrize("algorithm,kernel", [
    ("graham-fortune", "filtered"), ("graham-fortune", "double"), ("graham-fortune", "failsafe"),
    ("graham-incremental", "exact"), ("graham-incremental", "double"), ("graham-incremental", "failsafe"),
    ("monotone-chain", "interval"), ("monotone-chain", "float"), ("cgal", "cgal-epick"),
])
@pytest.mark.parametrize("name", sorted(INPUTS))
def test_convex_hull_matches_the_tool(tool, tmp_path, name, algorithm, kernel):
    points = INPUTS[name]()
    expected = tool.json("hull", write_points(tmp_path / "points.txt", points), "--algorithm", algorithm,
                         "--kernel", kernel, expect_codes=(0, 1))
    got = relgeo.convex_hull(points, algorithm=algorithm, kernel=kernel)
    assert got["algorithm"] == algorithm
    for field in FIELDS:
        assert got[field] == expected[field], field
    assert got["hull_indices"].dtype == np.int64
    assert got["hull_indices"].tolist() == expected["hull_indices"]
    np.testing.assert_array_equal(got["hull"], np.array(expected["hull"]).reshape(-1, 2))
    np.testing.assert_array_equal(got["hull"], points[got["hull_indices"]])


def test_exact_hull_of_a_square_with_interior_points():
    square = [[0, 0], [2, 0], [2, 2], [0, 2]]
    points = np.array(square + [[1, 1], [0.5, 1.5], [1, 0]])  # (1, 0) lies on an edge: not a vertex
    h = relgeo.convex_hull(points)
    assert h["status"] == "ok" and h["convex"] and h["error"] == 0 and h["backward_error"] == 0
    assert sorted(h["hull_indices"].tolist()) == [0, 1, 2, 3]


def test_the_inputs_are_hard():
    """Kettner's classroom example and the near-collinear points defeat the
    incremental scan under double, and make failsafe undecided: the
    comparisons above compare nonzero measures and counts too."""
    for name in ("classroom", "near_collinear"):
        assert relgeo.convex_hull(INPUTS[name](), "graham-incremental", "double")["error"] > 0
    fortune = relgeo.convex_hull(INPUTS["near_collinear"](), "graham-fortune", "failsafe")
    assert fortune["uncertain_answers"] > 0 and fortune["backward_error_bound"] > 0


def test_bad_input():
    with pytest.raises(relgeo.NonFiniteInput) as e:
        relgeo.convex_hull([[0, 0], [1, float("nan")], [0, 1]])
    assert isinstance(e.value, ValueError)
    with pytest.raises(ValueError, match=r"must have shape \(n, 2\)"):
        relgeo.convex_hull(np.zeros((4, 3)))
    with pytest.raises(ValueError, match="unknown algorithm 'quickhull'; algorithms: graham-incremental"):
        relgeo.convex_hull([[0, 0], [1, 0], [0, 1]], algorithm="quickhull")
    with pytest.raises(ValueError, match="needs a CGAL kernel"):
        relgeo.convex_hull([[0, 0], [1, 0], [0, 1]], algorithm="cgal", kernel="filtered")
