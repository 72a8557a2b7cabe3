"""loop_subdivide and limit_mesh against `relgeo subdivide --output` on the same meshes."""

import numpy as np
import pytest

import relgeo
from conftest import TESTDATA


@pytest.mark.parametrize("kernel", ["double", "float", "interval", "exact"])
@pytest.mark.parametrize("levels", [0, 1, 2])
@pytest.mark.parametrize("name", ["icosahedron.off", "cube.off", "cube_open.off"])
def test_meshes_match_the_tool(tool, tmp_path, name, levels, kernel):
    V, F = relgeo.read_mesh(TESTDATA / name)
    for limit, ours in ((False, relgeo.loop_subdivide(V, F, levels, kernel=kernel)),
                        (True, relgeo.limit_mesh(V, F, levels, kernel=kernel))):
        out = tmp_path / f"out_{limit}.off"
        tool.run("subdivide", TESTDATA / name, "--levels", levels, "--kernel", kernel, "--samples", 0,
                 "--output", out, *(["--limit"] if limit else []))
        expected_V, expected_F = relgeo.read_mesh(out)
        np.testing.assert_array_equal(ours[0], expected_V)
        np.testing.assert_array_equal(ours[1], expected_F)


def test_known_counts_and_the_limit_differs():
    V, F = relgeo.read_mesh(TESTDATA / "icosahedron.off")
    V2, F2 = relgeo.loop_subdivide(V, F, 2)
    assert (len(V2), len(F2)) == (162, 320)  # V' = V + E per level, F' = 4 F
    L2, G2 = relgeo.limit_mesh(V, F, 2)
    np.testing.assert_array_equal(G2, F2)
    assert np.max(np.abs(L2 - V2)) > 1e-3  # the limit points are not the control points
    np.testing.assert_array_equal(relgeo.loop_subdivide(V, F, 0)[0], V)


def test_bad_input():
    V, F = relgeo.read_mesh(TESTDATA / "icosahedron.off")
    with pytest.raises(ValueError, match="--levels must be in 0..12"):
        relgeo.loop_subdivide(V, F, 13)
    with pytest.raises(ValueError, match="not supported by subdivide"):
        relgeo.loop_subdivide(V, F, 1, kernel="cgal-epick")
    with pytest.raises(ValueError, match="hoppe or blz"):
        relgeo.loop_subdivide(V, F, 1, rules="catmull-clark")
    with pytest.raises(relgeo.InvalidMesh, match="index_out_of_range"):
        relgeo.loop_subdivide(V, np.vstack([F, [[0, 1, 99]]]), 1)
    Vnan = V.copy()
    Vnan[3, 1] = np.nan
    with pytest.raises(relgeo.NonFiniteInput):
        relgeo.limit_mesh(Vnan, F, 1)


# ---- limit_evaluate ------------------------------------------------------------------

def edge_children(F1, n):
    """The vertex of the level-1 refinement F1 on each edge {a, b} of the control
    mesh (its n vertices keep their indices): the one neighbour of both a and b."""
    neighbours = {}
    for a, b, c in F1:
        for x, y in ((a, b), (b, c), (c, a)):
            neighbours.setdefault(x, set()).add(y)
            neighbours.setdefault(y, set()).add(x)
    def child(a, b):
        (e,) = [e for e in neighbours[a] & neighbours[b] if e >= n]
        return e
    return child


# The parameters of face (a, b, c) that are vertices of its level-1 refinement:
# w a + u b + v c.
CORNERS = [((0, 0), "a"), ((1, 0), "b"), ((0, 1), "c"), ((0.5, 0), "ab"), ((0.5, 0.5), "bc"), ((0, 0.5), "ca")]


def tool_level_1(tool, tmp_path, path, kernel, limit):
    out = tmp_path / f"level1_{limit}.off"
    tool.run("subdivide", path, "--levels", 1, "--kernel", kernel, "--samples", 0, "--output", out,
             *(["--limit"] if limit else []))
    return relgeo.read_mesh(out)


@pytest.mark.parametrize("kernel", ["exact", "double", "filtered", "interval"])
@pytest.mark.parametrize("name", ["icosahedron.off", "cube.off", "cube_open.off", "icosahedron_L1"])
def test_limit_evaluate_matches_the_tools_limit_mesh(tool, tmp_path, name, kernel):
    """The limit surface at the parameters of the level-1 vertices is the
    tool's level-1 limit mesh (`relgeo subdivide --levels 1 --limit`): equal
    under the exact kernel (both the exact point, rounded), within rounding
    otherwise. icosahedron_L1: the refined icosahedron, with regular patches."""
    path = TESTDATA / name
    if name == "icosahedron_L1":
        path = tmp_path / "icosahedron_L1.off"
        relgeo.write_mesh(path, *relgeo.loop_subdivide(*relgeo.read_mesh(TESTDATA / "icosahedron.off"), 1))
    V, F = relgeo.read_mesh(path)
    _, F1 = tool_level_1(tool, tmp_path, path, kernel, limit=False)
    L1, _ = tool_level_1(tool, tmp_path, path, kernel, limit=True)
    child = edge_children(F1, len(V))
    faces, us, vs, expected = [], [], [], []
    for f, (a, b, c) in enumerate(F):
        where = {"a": a, "b": b, "c": c, "ab": child(a, b), "bc": child(b, c), "ca": child(c, a)}
        for (u, v), vertex in CORNERS:
            faces.append(f), us.append(u), vs.append(v), expected.append(L1[where[vertex]])
    got = relgeo.limit_evaluate(V, F, faces, us, vs, kernel=kernel)
    assert got.shape == (len(faces), 3)
    if kernel == "exact":
        np.testing.assert_array_equal(got, expected)
    else:
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13)
        assert not np.array_equal(got[:, 0], np.asarray(V)[np.asarray(F)[np.asarray(faces), 0], 0])


def test_limit_evaluate_broadcasts_and_agrees_across_kernels():
    V, F = relgeo.read_mesh(TESTDATA / "icosahedron.off")
    p = relgeo.limit_evaluate(V, F, 3, 0.25, 0.125, kernel="exact")
    assert p.shape == (3,)
    u = np.linspace(0, 0.5, 7)
    exact = relgeo.limit_evaluate(V, F, 3, u, 0.125, kernel="exact")
    assert exact.shape == (7, 3)
    np.testing.assert_array_equal(exact[3], relgeo.limit_evaluate(V, F, [3], [0.25], [0.125], kernel="exact")[0])
    np.testing.assert_allclose(relgeo.limit_evaluate(V, F, 3, u, 0.125), exact, rtol=0, atol=1e-14)
    # the limit surface of a convex polyhedron's subdivision lies inside it: nearer the centre than the vertices
    radius = np.linalg.norm(V, axis=1).max()
    assert np.all(np.linalg.norm(exact, axis=1) < radius)


def test_limit_evaluate_bad_input():
    V, F = relgeo.read_mesh(TESTDATA / "icosahedron.off")
    with pytest.raises(relgeo.InvalidInput, match=r"face 20 out of range \(20 faces\)"):
        relgeo.limit_evaluate(V, F, 20, 0.1, 0.1)
    with pytest.raises(relgeo.InvalidInput, match="face -1 out of range"):
        relgeo.limit_evaluate(V, F, -1, 0.1, 0.1)
    with pytest.raises(relgeo.InvalidInput, match="outside the triangle"):
        relgeo.limit_evaluate(V, F, 0, 0.75, 0.5)
    with pytest.raises(relgeo.NonFiniteInput):
        relgeo.limit_evaluate(V, F, 0, np.nan, 0.5, kernel="exact")
    with pytest.raises(ValueError, match="not supported by subdivide"):
        relgeo.limit_evaluate(V, F, 0, 0.1, 0.1, kernel="cgal-epick")
    with pytest.raises(ValueError, match="hoppe or blz"):
        relgeo.limit_evaluate(V, F, 0, 0.1, 0.1, rules="stam")
    with pytest.raises(ValueError):
        relgeo.limit_evaluate(V, F, [0, 1], [0.1, 0.2, 0.3], 0.1)  # shapes do not broadcast
    with pytest.raises(ValueError, match="1-d"):
        relgeo.limit_evaluate(V, F, [[0, 1]], 0.1, 0.1)
    with pytest.raises(relgeo.InvalidMesh, match="index_out_of_range"):
        relgeo.limit_evaluate(V, np.vstack([F, [[0, 1, 99]]]), 0, 0.1, 0.1)
    with pytest.raises(relgeo.InvalidInput):  # two faces sharing two edges: Loop's refinement is no manifold
        relgeo.limit_evaluate(V[:3], [[0, 1, 2], [0, 2, 1]], 0, 0.1, 0.1)
