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
