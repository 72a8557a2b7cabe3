"""csg against `relgeo csg --format json --output` on the same trees: the tool's
tree files, and the same trees with (V, F) arrays as leaves."""

import json

import numpy as np
import pytest

import relgeo
from conftest import TESTDATA

CSG = TESTDATA / "csg"

# The record's fields that do not depend on timing (steps without their seconds).
FIELDS = ["kernel", "intermediates", "status", "failure", "output"]


def untimed_steps(record):
    return [{k: v for k, v in step.items() if k != "seconds"} for step in record["steps"]]


def tool_csg(tool, tmp_path, tree, kernel, *options):
    out = tmp_path / "root.off"
    expected = tool.json("csg", tree, "--kernel", kernel, "--output", out, *options, expect_codes=(0, 1))
    return expected, relgeo.read_mesh(out)


def assert_same(got, expected, mesh):
    for field in FIELDS:
        assert got[field] == expected[field], field
    assert untimed_steps(got) == untimed_steps(expected)
    assert got["seconds"] >= 0 and got["total_seconds"] >= got["seconds"]
    np.testing.assert_array_equal(got["V"], mesh[0])
    np.testing.assert_array_equal(got["F"], mesh[1])


def with_array_leaves(node):
    """The tree of a TREE.json file (in CSG) with every leaf read into (V, F) arrays."""
    if "mesh" in node:
        return relgeo.read_mesh(CSG / node["mesh"])
    return {"op": node["op"], "args": [with_array_leaves(arg) for arg in node["args"]]}


@pytest.mark.parametrize("kernel", ["filtered", "exact", "double"])
@pytest.mark.parametrize("name", ["cubes.json", "slab_and_boxes.json"])
def test_tree_files_match_the_tool(tool, tmp_path, name, kernel):
    expected, mesh = tool_csg(tool, tmp_path, CSG / name, kernel)
    got = relgeo.csg(CSG / name, kernel=kernel)
    assert got["tree"] == str(CSG / name) == expected["tree"]
    assert_same(got, expected, mesh)


@pytest.mark.parametrize("kernel", ["filtered", "double"])
def test_array_leaves_match_the_tool(tool, tmp_path, kernel):
    tree = json.loads((CSG / "cubes.json").read_text())
    expected, mesh = tool_csg(tool, tmp_path, CSG / "cubes.json", kernel)
    got = relgeo.csg(with_array_leaves(tree), kernel=kernel)
    assert "tree" not in got
    assert_same(got, expected, mesh)
    # the same leaves as file names (relative to base) and as {"vertices", "faces"} dicts
    cube = relgeo.read_mesh(CSG / "../cube.off")
    mixed = {"op": "difference", "args": [
        {"op": "union", "args": [{"vertices": cube[0], "faces": cube[1]}, {"mesh": "../cube_offset.off"}]},
        {"mesh": CSG / "../cube_touching.off"}]}
    assert_same(relgeo.csg(mixed, kernel=kernel, base=CSG), expected, mesh)


def test_rounding_and_options_reach_the_tool(tool, tmp_path):
    options = ["--rounding", "nearest", "--retriangulation", "insertion", "--skip-self-intersection-check"]
    expected, mesh = tool_csg(tool, tmp_path, CSG / "cubes.json", "exact", *options)
    got = relgeo.csg(CSG / "cubes.json", kernel="exact", rounding="nearest", retriangulation="insertion",
                     check_self_intersections=False)
    assert_same(got, expected, mesh)
    assert {step["rounding"]["method"] for step in got["steps"]} == {"nearest"}


def test_exact_intermediates_match_the_tool(tool, tmp_path):
    expected, mesh = tool_csg(tool, tmp_path, CSG / "exact_slab.json", "exact", "--intermediates", "exact")
    got = relgeo.csg(CSG / "exact_slab.json", kernel="exact", intermediates="exact")
    assert_same(got, expected, mesh)
    assert got["intermediates"] == "exact" and got["output"]["validation"] == "valid solid"
    bits = [step["coordinate_bits"] for step in got["steps"]]
    assert len(bits) == 3 and bits[0] > 53 and bits[-1] >= bits[0]
    with pytest.raises(ValueError) as e:
        relgeo.csg(CSG / "exact_slab.json", intermediates="exact")
    assert str(e.value) == tool.error("csg", CSG / "exact_slab.json", "--intermediates", "exact")


def test_volume_of_the_cubes_tree():
    r = relgeo.csg(CSG / "cubes.json")
    assert r["status"] == "ok" and [s["node"] for s in r["steps"]] == ["root.0", "root"]
    # (cube u cube moved by (0.5, 0.25, 0.125)) - the cube next to the first, measured on the result mesh
    assert relgeo.validate_solid(r["V"], r["F"])["volume"]["value"] == r["output"]["volume"] == 1.34375


@pytest.mark.parametrize("name,node", [("bad_unknown_op.json", "root"), ("bad_one_argument.json", "root"),
                                       ("bad_missing_file.json", "root.1"), ("bad_open_leaf.json", "root.1.1")])
def test_bad_tree_files_name_the_node(tool, name, node):
    with pytest.raises(relgeo.InvalidCsgNode) as e:
        relgeo.csg(CSG / name)
    assert str(e.value) == tool.error("csg", CSG / name)
    assert e.value.node == node and isinstance(e.value, ValueError)


def test_not_json_and_bad_names(tool):
    with pytest.raises(relgeo.UnreadableFile) as e:
        relgeo.csg(CSG / "bad_not_json.json")
    assert str(e.value) == tool.error("csg", CSG / "bad_not_json.json")
    with pytest.raises(ValueError) as e:
        relgeo.csg(CSG / "cubes.json", kernel="interval")
    assert str(e.value) == tool.error("csg", CSG / "cubes.json", "--kernel", "interval")
    with pytest.raises(ValueError, match="repaired or nearest"):
        relgeo.csg(CSG / "cubes.json", rounding="round")
    with pytest.raises(relgeo.UnreadableFile):
        relgeo.csg(CSG / "no_such_tree.json")


def test_bad_dict_trees_name_the_node(tool):
    cube = relgeo.read_mesh(TESTDATA / "cube.off")
    open_cube = relgeo.read_mesh(TESTDATA / "cube_open.off")
    offset = relgeo.read_mesh(TESTDATA / "cube_offset.off")
    # the tool's bad_open_leaf.json with arrays: the same defect, at the same node
    with pytest.raises(relgeo.InvalidCsgNode, match=r"^csg: node root\.1\.1: not a valid solid: .*boundary_edge") as e:
        relgeo.csg({"op": "intersection", "args": [cube, {"op": "union", "args": [offset, open_cube]}]})
    assert e.value.node == "root.1.1"
    cases = [({"op": "merge", "args": [cube, offset]}, "root", "unknown op 'merge'"),
             ({"op": "union", "args": [cube]}, "root", "union of 1 argument"),
             ({"op": "union", "args": [cube, [1, 2]]}, "root.1", "not an object"),
             ({"op": "union", "args": cube}, "root.0", "not an object"),  # args = (V, F): V is no node
             ({"op": "union", "args": {"a": cube}}, "root", "\"args\" must be an array"),
             ({"op": "union", "args": [cube, {"mesh": 3}]}, "root.1", "\"mesh\" must be a file name"),
             ({"args": [cube, offset]}, "root", "neither \"mesh\" nor \"op\""),
             ({"op": "union", "args": [cube, (cube[0], np.vstack([cube[1], [[0, 1, 8]]]))]}, "root.1",
              "index_out_of_range"),
             ({"op": "union", "args": [cube, {"mesh": "no_such_file.off"}]}, "root.1", "cannot read")]
    for tree, node, message in cases:
        with pytest.raises(relgeo.InvalidCsgNode, match=message) as e:
            relgeo.csg(tree)
        assert e.value.node == node and str(e.value).startswith(f"csg: node {node}: ")
    V = cube[0].copy()
    V[2, 1] = np.inf
    with pytest.raises(relgeo.InvalidCsgNode, match=r"node root\.0: \(V, F\): vertex 2 has a NaN or infinite"):
        relgeo.csg({"op": "union", "args": [(V, cube[1]), offset]})
    with pytest.raises(ValueError, match=r"csg: node root\.1: \(V, F\): V must have shape \(n, 3\)"):
        relgeo.csg({"op": "union", "args": [cube, (cube[0][:, :2], cube[1])]})
