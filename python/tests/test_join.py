"""join against `relgeo join --format json --output` on the same surface models
and meshes, given as files and as (V, F) arrays."""

import numpy as np
import pytest

import relgeo
from conftest import TESTDATA

FOLDING = (TESTDATA / "join_folding.json", [TESTDATA / "join_folding_0.off", TESTDATA / "join_folding_1.off"])
TWO_FACES = (TESTDATA / "join_two_faces.json", [TESTDATA / "join_two_faces_0.off", TESTDATA / "join_two_faces_1.off"])


def untimed(value):
    """A record without its timings (keys naming seconds)."""
    if isinstance(value, dict):
        return {k: untimed(v) for k, v in value.items() if "seconds" not in k}
    if isinstance(value, list):
        return [untimed(v) for v in value]
    return value


def mesh_args(meshes):
    return [arg for mesh in meshes for arg in ("--mesh", mesh)]


@pytest.mark.parametrize("case,method,kernel,options,python_options", [
    (FOLDING, "whitney", "filtered", [], {}),
    (FOLDING, "naive", "exact", [], {}),
    (TWO_FACES, "whitney", "filtered", [], {}),
    (TWO_FACES, "whitney", "interval", ["--no-edge-curves", "--layers", 2], {"edge_curves": False, "layers": 2}),
    (TWO_FACES, "whitney", "failsafe", ["--max-normal-error", 1e-6, "--min-angle", 25],
     {"max_normal_error": 1e-6, "min_angle": 25}),
])
def test_join_matches_the_tool(tool, tmp_path, case, method, kernel, options, python_options):
    surface, meshes = case
    out = tmp_path / "joined.off"
    expected = tool.json("join", surface, *mesh_args(meshes), "--method", method, "--kernel", kernel, "--output", out,
                         *options, expect_codes=(0, 1))
    V, F = relgeo.read_mesh(out)
    from_files = relgeo.join(surface, meshes, method=method, kernel=kernel, **python_options)
    from_arrays = relgeo.join(surface, [relgeo.read_mesh(m) for m in meshes], method=method, kernel=kernel,
                              **python_options)
    assert from_files["meshes"] == [str(m) for m in meshes] and from_files["output"] == ""
    assert from_arrays["meshes"] == ["<arrays 0>", "<arrays 1>"]
    for got in (from_files, from_arrays):
        record = {k: v for k, v in got.items() if k not in ("V", "F", "face_of_triangle", "meshes", "output")}
        assert untimed(record) == untimed({k: v for k, v in expected.items() if k not in ("meshes", "output")})
        np.testing.assert_array_equal(got["V"], V)
        np.testing.assert_array_equal(got["F"], F)
        assert got["face_of_triangle"].shape == (len(F),)
        assert set(got["face_of_triangle"]) == {0, 1}


def test_join_takes_the_surface_model_as_a_dict():
    import json

    for surface, meshes in (FOLDING, TWO_FACES):
        document = json.loads(surface.read_text())
        from_dict = relgeo.join(document, meshes)
        from_file = relgeo.join(surface, meshes)
        record = {k: v for k, v in from_dict.items() if k not in ("V", "F", "face_of_triangle", "surface")}
        assert untimed(record) == untimed({k: v for k, v in from_file.items()
                                           if k not in ("V", "F", "face_of_triangle", "surface")})
        for k in ("V", "F", "face_of_triangle"):
            np.testing.assert_array_equal(from_dict[k], from_file[k])
    # a bad document names the dict's file
    bad = json.loads(FOLDING[0].read_text())
    del bad["faces"]
    with pytest.raises(relgeo.UnreadableFile, match="surface-model-dict.json"):
        relgeo.join(bad, FOLDING[1])


def test_join_verdicts_and_output(tmp_path):
    whitney = relgeo.join(*FOLDING, output=tmp_path / "w.off")
    assert whitney["status"] == "ok" and whitney["summary"]["flipped_after"] == 0
    np.testing.assert_array_equal(relgeo.read_mesh(tmp_path / "w.off")[1], whitney["F"])
    naive = relgeo.join(*FOLDING, method="naive", kernel="exact")
    assert naive["status"] == "failed" and naive["failure"] == "flipped-triangles"
    assert naive["summary"]["flipped_after"] > 0


def test_join_bad_input(tool, tmp_path):
    surface, meshes = FOLDING
    out = tmp_path / "x.off"
    cases = [
        (relgeo.UnreadableFile, (surface, [meshes[0], TESTDATA / "no_such_mesh.off"]), {}),
        (relgeo.UnreadableFile, (TESTDATA / "no_such_model.json", meshes[:1]), {}),
        (relgeo.UnreadableFile, (TESTDATA / "join_not_json.json", meshes[:1]), {}),
        (relgeo.InvalidInput, (surface, [TESTDATA / "join_folding_far.off", meshes[1]]), {}),
        (relgeo.InvalidInput, (surface, meshes[:1]), {}),
        (ValueError, (surface, []), {}),
        (ValueError, (surface, meshes), {"layers": 0}),
        (ValueError, (surface, meshes), {"min_angle": 45}),
        (ValueError, (surface, meshes), {"max_absolute_error": -1}),
        (ValueError, (surface, meshes), {"method": "glue"}),
        (ValueError, (surface, meshes), {"kernel": "double"}),
        (ValueError, (surface, meshes), {"kernel": "quadruple"}),
    ]
    flags = {"layers": "--layers", "min_angle": "--min-angle", "max_absolute_error": "--max-absolute-error",
             "method": "--method", "kernel": "--kernel"}
    for error, (s, m), options in cases:
        with pytest.raises(error) as e:
            relgeo.join(s, m, **options)
        tool_args = [a for k, v in options.items() for a in (flags[k], v)]
        if m:
            assert str(e.value) == tool.error("join", s, *mesh_args(m), *tool_args, "--output", out)
        else:
            assert "no mesh" in str(e.value)
    # arrays: a NaN, an index out of range
    V, F = relgeo.read_mesh(meshes[0])
    Vnan = V.copy()
    Vnan[4, 0] = np.nan
    with pytest.raises(relgeo.NonFiniteInput, match="join: mesh 0: vertex 4"):
        relgeo.join(surface, [(Vnan, F), meshes[1]])
    with pytest.raises(relgeo.InvalidMesh, match="index_out_of_range"):
        relgeo.join(surface, [meshes[0], (V, np.vstack([F, [[0, 1, len(V)]]]))])
