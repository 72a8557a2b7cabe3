"""solve against `relgeo linsolve --format json` on the same matrix file."""

import numpy as np
import pytest

import relgeo

FIELDS = ["status", "n", "method", "scalar", "unit_roundoff", "normwise_backward_error", "componentwise_backward_error",
          "forward_error", "condition_number", "condition_number_exact", "forward_error_bound",
          "growth_factor", "residual_norm"]


def write_system(path, A, b):
    path.write_text("".join(" ".join(repr(float(v)) for v in [*row, bi]) + "\n" for row, bi in zip(A, b)))
    return path


def hilbert(n):
    """The Hilbert matrix rounded to double, and b = H * ones rounded."""
    i, j = np.indices((n, n))
    H = 1.0 / (i + j + 1)
    return H, H @ np.ones(n)


SYSTEMS = {
    "hilbert6": lambda: hilbert(6),
    "random": lambda: (np.random.default_rng(5).uniform(-1, 1, (7, 7)), np.random.default_rng(6).uniform(-1, 1, 7)),
    "needs_pivoting": lambda: (np.array([[1e-20, 1.0], [1.0, 1.0]]), np.array([1.0, 2.0])),
}


@pytest.mark.parametrize("method,scalar", [
    ("partial", "double"), ("none", "double"), ("complete", "float"), ("partial", "mpfr-24"),
    ("partial", "rational"), ("eigen-partial", "double"), ("none", "long-double"),
])
@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_solve_matches_the_tool(tool, tmp_path, name, method, scalar):
    A, b = SYSTEMS[name]()
    expected = tool.json("linsolve", write_system(tmp_path / "system.txt", A, b), "--method", method,
                         "--scalar", scalar, expect_codes=(0, 1))
    got = relgeo.solve(A, b, pivoting=method, scalar=scalar)
    for field in FIELDS:
        assert got[field] == expected[field], field
    assert got["failure"] == expected["failure"]
    if expected["x"] is None:
        assert got["x"] is None
    else:
        np.testing.assert_array_equal(got["x"], expected["x"])
    np.testing.assert_array_equal(got["exact_solution"], expected["exact_solution"])


def test_backward_errors_tell_pivoting_apart():
    """Without pivoting the tiny pivot ruins the solve, with it the result is
    backward stable: the measures distinguish them (the comparisons above
    compare different values)."""
    A, b = SYSTEMS["needs_pivoting"]()
    none, partial = relgeo.solve(A, b, pivoting="none"), relgeo.solve(A, b, pivoting="partial")
    assert none["normwise_backward_error"] > 1e-6 > 1e-15 > partial["normwise_backward_error"]
    assert relgeo.solve(A, b, scalar="rational")["forward_error"] == 0


def test_zero_pivot_without_pivoting_is_a_failed_status(tool, tmp_path):
    A, b = np.array([[0.0, 1.0], [1.0, 0.0]]), np.array([1.0, 2.0])
    got = relgeo.solve(A, b, pivoting="none")
    expected = tool.json("linsolve", write_system(tmp_path / "s.txt", A, b), "--method", "none", expect_codes=(1,))
    assert got["status"] == expected["status"] == "failed"
    assert got["failure"] == expected["failure"] and got["x"] is None


def test_bad_input(tool, tmp_path):
    singular = np.array([[1.0, 2.0], [2.0, 4.0]]), np.array([1.0, 1.0])
    with pytest.raises(relgeo.SingularMatrix) as e:
        relgeo.solve(*singular)
    assert isinstance(e.value, ValueError) and isinstance(e.value, np.linalg.LinAlgError)
    assert e.value.code == "invalid_input"
    assert str(e.value) == tool.error("linsolve", write_system(tmp_path / "s.txt", *singular))
    with pytest.raises(relgeo.NonFiniteInput):
        relgeo.solve([[1.0, 0.0], [0.0, float("nan")]], [1.0, 1.0])
    with pytest.raises(relgeo.InvalidInput, match="square"):
        relgeo.solve(np.ones((2, 3)), np.ones(2))
    with pytest.raises(relgeo.InvalidInput):
        relgeo.solve(np.eye(3), np.ones(2))
    with pytest.raises(ValueError, match="1-d"):
        relgeo.solve(np.eye(2), np.ones((2, 1)))
    with pytest.raises(ValueError, match="unknown"):
        relgeo.solve(np.eye(2), np.ones(2), pivoting="rook")
    with pytest.raises(ValueError, match="unknown"):
        relgeo.solve(np.eye(2), np.ones(2), scalar="decimal")
