"""boolean against `relgeo boolean --format json` on the same mesh files."""

import numpy as np
import pytest

import relgeo
from conftest import TESTDATA

# The record's fields that do not depend on timing.
FIELDS = ["operation", "kernel", "kernel_model", "certified", "status", "failure", "undecided_pairs", "output",
          "validation", "exact_self_intersecting_pairs", "rounding_error", "rounding", "counts"]


@pytest.mark.parametrize("kernel", ["filtered", "exact", "double", "interval"])
@pytest.mark.parametrize("op", ["union", "intersection", "difference", "xor"])
@pytest.mark.parametrize("a,b", [("cube.off", "cube_offset.off"), ("icosahedron.off", "icosahedron_moved.off"),
                                 ("cube.off", "cube_touching.off")])
def test_boolean_matches_the_tool(tool, tmp_path, a, b, op, kernel):
    out = tmp_path / "result.off"
    expected = tool.json("boolean", TESTDATA / a, TESTDATA / b, "--op", op, "--kernel", kernel, "--output", out,
                         expect_codes=(0, 1))
    got = relgeo.boolean(relgeo.read_mesh(TESTDATA / a), relgeo.read_mesh(TESTDATA / b), op=op, kernel=kernel)
    for field in FIELDS:
        assert got[field] == expected[field], field
    for operand in ("a", "b"):
        assert got["operands"][operand] == {k: v for k, v in expected["operands"][operand].items() if k != "file"}
    assert set(got["time_s"]) == set(expected["time_s"])
    if expected["status"] == "ok":
        V, F = relgeo.read_mesh(out)
        np.testing.assert_array_equal(got["V"], V)
        np.testing.assert_array_equal(got["F"], F)


def test_union_of_two_cubes_is_a_certified_solid():
    cube = relgeo.read_mesh(TESTDATA / "cube.off")
    offset = relgeo.read_mesh(TESTDATA / "cube_offset.off")
    r = relgeo.boolean(cube, offset, "union")
    assert r["status"] == "ok" and r["validation"]["valid_solid"]
    assert r["validation"]["volume"]["exact"]
    # volume of A + B - A*B, each computed by relgeo on its own
    parts = [relgeo.validate_solid(*m)["volume"]["value"] for m in (cube, offset)]
    common = relgeo.boolean(cube, offset, "intersection")["validation"]["volume"]["value"]
    assert r["validation"]["volume"]["value"] == pytest.approx(sum(parts) - common, rel=1e-15)
    provenance = r["provenance"]
    assert provenance.shape == (len(r["F"]), 2)
    assert set(provenance[:, 0]) == {0, 1}
    for operand, (V, F) in enumerate((cube, offset)):  # every face of the result lies in the plane of its origin
        faces = provenance[:, 0] == operand
        origin = F[provenance[faces, 1]]
        for corner in range(3):
            assert np.all(relgeo.orient3d(V[origin[:, 0]], V[origin[:, 1]], V[origin[:, 2]],
                                          r["V"][r["F"][faces, corner]], kernel="exact") == 0)


def test_bad_operands_raise_invalid_operand(tool):
    cube = relgeo.read_mesh(TESTDATA / "cube.off")
    for name in ("cube_open.off", "cubes_crossing.off"):
        with pytest.raises(relgeo.InvalidOperand) as e:
            relgeo.boolean(cube, relgeo.read_mesh(TESTDATA / name))
        assert isinstance(e.value, relgeo.InvalidMesh) and isinstance(e.value, ValueError)
        assert str(e.value) == tool.error("boolean", TESTDATA / "cube.off", TESTDATA / name)
    V, F = cube
    with pytest.raises(relgeo.InvalidMesh, match="index_out_of_range"):
        relgeo.boolean(cube, (V, np.vstack([F, [[0, 1, 8]]])))
    Vnan = V.copy()
    Vnan[0, 0] = np.nan
    with pytest.raises(relgeo.NonFiniteInput, match="boolean: A: vertex 0"):
        relgeo.boolean((Vnan, F), cube)


def test_bad_names_raise_value_error():
    cube = relgeo.read_mesh(TESTDATA / "cube.off")
    with pytest.raises(ValueError, match="union, intersection, difference or xor"):
        relgeo.boolean(cube, cube, op="merge")
    with pytest.raises(ValueError, match="cannot run a Boolean"):
        relgeo.boolean(cube, cube, kernel="cgal-sc")
    with pytest.raises(ValueError, match="repaired or nearest"):
        relgeo.boolean(cube, cube, rounding="round")
    with pytest.raises(ValueError, match="unknown kernel"):
        relgeo.boolean(cube, cube, kernel="doubel")


# ---- levels=K: Booleans of Loop subdivision solids ------------------------------------

LEVEL_FIELDS = ["operation", "kernel", "kernel_model", "certified", "status", "failure", "level", "fitted", "output",
                "counts", "distance", "validation"]


def read_tags(path):
    """The crease edges and corners of a tag file ('crease a b', 'corner v' lines)."""
    creases, corners = [], []
    for line in path.read_text().splitlines():
        words = line.split()
        if words and words[0] == "crease":
            creases.append([int(words[1]), int(words[2])])
        elif words and words[0] == "corner":
            corners.append(int(words[1]))
    return np.array(creases, dtype=np.int64).reshape(-1, 2), np.array(corners, dtype=np.int64)


@pytest.mark.parametrize("op,kernel,levels,fit", [("union", "filtered", 1, False), ("intersection", "filtered", 1, False),
                                                  ("difference", "double", 1, False), ("union", "filtered", 1, True),
                                                  ("intersection", "filtered", 2, False)])
def test_subdivision_boolean_matches_the_tool(tool, tmp_path, op, kernel, levels, fit):
    a, b = TESTDATA / "icosahedron.off", TESTDATA / "icosahedron_moved.off"
    out, tags, polyhedral = tmp_path / "r.off", tmp_path / "r.tags", tmp_path / "p.off"
    expected = tool.json("boolean", a, b, "--levels", levels, "--op", op, "--kernel", kernel, "--output", out,
                         "--tags-output", tags, "--polyhedral-output", polyhedral, *(["--fit"] if fit else []),
                         expect_codes=(0, 1))
    got = relgeo.boolean(relgeo.read_mesh(a), relgeo.read_mesh(b), op=op, kernel=kernel, levels=levels, fit=fit)
    for field in LEVEL_FIELDS:
        assert got[field] == expected[field], field
    for operand in ("a", "b"):
        assert got["operands"][operand] == {k: v for k, v in expected["operands"][operand].items() if k != "file"}
    assert set(got["time_s"]) == set(expected["time_s"])
    plain = {k: v for k, v in got["polyhedral"].items() if k not in ("time_s", "V", "F")}
    assert plain == {k: v for k, v in expected["polyhedral"].items() if k != "time_s"}
    assert expected["status"] == "ok"  # these pairs succeed under the tool
    V, F = relgeo.read_mesh(out)
    np.testing.assert_array_equal(got["V"], V)
    np.testing.assert_array_equal(got["F"], F)
    creases, corners = read_tags(tags)
    np.testing.assert_array_equal(got["creases"], creases)
    np.testing.assert_array_equal(got["corners"], corners)
    assert len(got["creases"]) == got["output"]["creases"] > 0
    PV, PF = relgeo.read_mesh(polyhedral)
    np.testing.assert_array_equal(got["polyhedral"]["V"], PV)
    np.testing.assert_array_equal(got["polyhedral"]["F"], PF)


def test_subdivision_boolean_bad_input(tool):
    a, b = TESTDATA / "icosahedron.off", TESTDATA / "icosahedron_moved.off"
    ico, moved, open_cube = (relgeo.read_mesh(p) for p in (a, b, TESTDATA / "cube_open.off"))
    with pytest.raises(relgeo.InvalidOperand) as e:
        relgeo.boolean(ico, open_cube, levels=1)
    assert str(e.value) == tool.error("boolean", "--levels", 1, a, TESTDATA / "cube_open.off")
    with pytest.raises(ValueError) as e:
        relgeo.boolean(ico, moved, op="xor", levels=1)
    assert str(e.value) == tool.error("boolean", "--levels", 1, "--op", "xor", a, b)
    with pytest.raises(ValueError) as e:
        relgeo.boolean(ico, moved, kernel="cgal-epick", levels=1)
    assert str(e.value) == tool.error("boolean", "--levels", 1, "--kernel", "cgal-epick", a, b)
    with pytest.raises(ValueError, match="fit needs levels"):
        relgeo.boolean(ico, moved, fit=True)
    with pytest.raises(ValueError, match="levels must be >= 1"):
        relgeo.boolean(ico, moved, levels=-1)
    with pytest.raises(ValueError, match="not options of the subdivision Boolean"):
        relgeo.boolean(ico, moved, levels=1, rounding="nearest")
    Vnan = ico[0].copy()
    Vnan[1, 2] = np.nan
    with pytest.raises(relgeo.NonFiniteInput, match="boolean: B: vertex 1"):
        relgeo.boolean(moved, (Vnan, ico[1]), levels=1)
