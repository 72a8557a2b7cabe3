"""(V, F) meshes: reading and writing files, validate_solid against the
validation the tool reports for a Boolean's output, and known answers."""

import numpy as np
import pytest

import relgeo
from conftest import TESTDATA

TETRAHEDRON = (np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]),
               np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))


@pytest.mark.parametrize("extension", ["off", "obj", "ply", "stl"])
def test_write_then_read_round_trips(tmp_path, extension):
    V = np.random.default_rng(7).uniform(-1, 1, (4, 3))  # 17 digits: every double comes back
    F = TETRAHEDRON[1]
    path = tmp_path / f"tet.{extension}"
    relgeo.write_mesh(path, V, F)
    V2, F2 = relgeo.read_mesh(path)
    assert V2.dtype == np.float64 and F2.dtype == np.int64
    if extension == "stl":  # STL stores triangles with float coordinates, vertices merged
        np.testing.assert_allclose(V2[F2], V[F], rtol=1e-7)
    else:
        np.testing.assert_array_equal(V2, V)
        np.testing.assert_array_equal(F2, F)


def test_read_mesh_matches_the_file():
    V, F = relgeo.read_mesh(TESTDATA / "cube.off")
    assert V.shape == (8, 3) and F.shape == (12, 3)
    lines = (TESTDATA / "cube.off").read_text().split("\n")
    np.testing.assert_array_equal(V[1], [float(x) for x in lines[3].split()])


@pytest.mark.parametrize("op", ["union", "intersection", "difference"])
@pytest.mark.parametrize("a,b", [("cube.off", "cube_offset.off"), ("icosahedron.off", "icosahedron_moved.off")])
def test_validate_solid_matches_the_tools_validation(tool, tmp_path, a, b, op):
    """The tool validates a Boolean's output with validate_solid under the
    filtered kernel; the output file read back gives the same report, but
    that the Boolean leaves the pairs of faces kept whole from one checked
    operand to that operand's certificate (fewer candidate pairs, a note)."""
    out = tmp_path / "result.off"
    expected = tool.json("boolean", TESTDATA / a, TESTDATA / b, "--op", op, "--output", out)
    report = relgeo.validate_solid(*relgeo.read_mesh(out))

    def certificate_fields(r):
        return r.pop("candidate_pairs"), r["checks"]["self_intersection_free"].pop("note", "")

    (pairs, note), (boolean_pairs, boolean_note) = certificate_fields(report), certificate_fields(expected["validation"])
    assert report == expected["validation"]
    assert boolean_pairs <= pairs and note == ""
    if expected["counts"]["unchanged_certified_faces"]:
        assert "kept unchanged from one certified mesh" in boolean_note


def test_validate_solid_known_answers():
    V, F = TETRAHEDRON
    report = relgeo.validate_solid(V, F)
    assert report["valid_solid"] and report["kernel"] == "filtered"
    assert report["volume"]["value"] == pytest.approx(1 / 6) and report["volume"]["exact"]
    assert (report["vertices"], report["faces"], report["edges"], report["genus"]) == (4, 4, 6, 0)

    open_report = relgeo.validate_solid(*relgeo.read_mesh(TESTDATA / "cube_open.off"))
    assert not open_report["valid_solid"]
    assert open_report["checks"]["closed"]["status"] == "fail"
    assert open_report["checks"]["closed"]["count"] > 0

    crossing = relgeo.validate_solid(*relgeo.read_mesh(TESTDATA / "cubes_crossing.off"))
    assert crossing["checks"]["self_intersection_free"]["status"] == "fail"

    inverted = relgeo.validate_solid(V, F[:, ::-1])
    assert inverted["checks"]["outward_oriented"]["status"] == "fail"


def test_validate_solid_reports_bad_indices_and_coordinates():
    V, F = TETRAHEDRON
    report = relgeo.validate_solid(V, np.vstack([F, [[0, 1, 9]]]))
    assert report["checks"]["valid_indices"]["status"] == "fail"
    assert report["checks"]["valid_indices"]["count"] == 1
    Vnan = V.copy()
    Vnan[2, 0] = np.nan
    assert relgeo.validate_solid(Vnan, F)["checks"]["finite_coordinates"]["status"] == "fail"
    with pytest.raises(ValueError, match="face 1 has the index -1"):
        relgeo.validate_solid(V, np.array([[0, 2, 1], [0, -1, 3]]))


def test_bad_files(tmp_path):
    with pytest.raises(relgeo.UnreadableFile, match="cannot open mesh file") as e:
        relgeo.read_mesh(tmp_path / "missing.off")
    assert isinstance(e.value, OSError) and isinstance(e.value, ValueError)
    assert e.value.code == "unreadable_file"
    garbage = tmp_path / "garbage.off"
    garbage.write_text("OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n")
    with pytest.raises(relgeo.UnreadableFile, match="garbage.off"):
        relgeo.read_mesh(garbage)
    with pytest.raises(relgeo.UnreadableFile, match="empty"):
        (tmp_path / "empty.obj").write_text("")
        relgeo.read_mesh(tmp_path / "empty.obj")
    with pytest.raises(relgeo.InvalidMesh, match="index_out_of_range"):
        bad = tmp_path / "bad_index.off"
        bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
        relgeo.read_mesh(bad)
    with pytest.raises(OSError):
        relgeo.write_mesh(tmp_path / "no_such_dir" / "t.off", *TETRAHEDRON)


def test_write_mesh_bad_arrays(tmp_path):
    V, F = TETRAHEDRON
    with pytest.raises(relgeo.InvalidMesh, match=r"index_out_of_range \(1, 4\)") as e:
        relgeo.write_mesh(tmp_path / "t.off", V, np.array([[0, 1, 2], [1, 2, 4]]))
    assert isinstance(e.value, ValueError)
    with pytest.raises(relgeo.InvalidMesh, match="index_out_of_range"):
        relgeo.write_mesh(tmp_path / "t.off", V, np.array([[0, 1, -1]]))
    Vnan = V.copy()
    Vnan[1, 2] = np.inf
    with pytest.raises(relgeo.NonFiniteInput, match="vertex 1"):
        relgeo.write_mesh(tmp_path / "t.off", Vnan, F)
    with pytest.raises(ValueError, match=r"V must have shape \(n, 3\)"):
        relgeo.write_mesh(tmp_path / "t.off", V[:, :2], F)
    with pytest.raises(ValueError, match=r"F must have shape \(n, 3\)"):
        relgeo.write_mesh(tmp_path / "t.off", V, F.ravel())
