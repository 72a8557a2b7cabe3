"""check_extrusion against `relgeo extrusion --format json` on the same contour files."""

import json

import pytest

import relgeo
from conftest import TESTDATA

GOOD = ["extrusion_bow_tie.json", "extrusion_circle16.json", "extrusion_circle3d.json", "extrusion_folded.json",
        "extrusion_looped.json", "extrusion_thin.json"]
BAD = ["extrusion_degree0.json", "extrusion_nan.json", "extrusion_no_direction.json", "extrusion_off_plane.json",
       "extrusion_open.json", "extrusion_overflow.json"]


def without_time(record):
    return {k: v for k, v in record.items() if k != "time_s"}


@pytest.mark.parametrize("kernel,algorithm", [("failsafe", "graham-fortune"), ("filtered", "monotone-chain"),
                                              ("double", "graham-incremental"), ("interval", "graham-fortune")])
@pytest.mark.parametrize("name", GOOD)
def test_check_extrusion_matches_the_tool(tool, name, kernel, algorithm):
    path = TESTDATA / name
    expected = tool.json("extrusion", path, "--kernel", kernel, "--algorithm", algorithm, expect_codes=(0, 1))
    got = relgeo.check_extrusion(path, algorithm=algorithm, kernel=kernel)
    assert without_time(got) == without_time(expected)


def test_defaults_and_overrides_are_the_tools(tool):
    path = TESTDATA / "extrusion_thin.json"
    assert without_time(relgeo.check_extrusion(path)) == without_time(tool.json("extrusion", path))
    expected = tool.json("extrusion", path, "--uncertainty", "1e-6", "--absolute-uncertainty", "1e-9",
                         "--no-prune", "--max-listed", "3")
    got = relgeo.check_extrusion(path, uncertainty=1e-6, absolute_uncertainty=1e-9, prune=False, max_listed=3)
    assert without_time(got) == without_time(expected)
    # the verdicts differ: the comparisons see the options
    assert got["verdict"] != relgeo.check_extrusion(path)["verdict"]


def test_a_dict_is_the_same_contour():
    path = TESTDATA / "extrusion_circle16.json"
    from_file = relgeo.check_extrusion(path)
    from_dict = relgeo.check_extrusion(json.loads(path.read_text()))
    assert from_dict["input"] == "<dict>"
    assert without_time({**from_dict, "input": None}) == without_time({**from_file, "input": None})


@pytest.mark.parametrize("name", BAD)
def test_bad_contours_raise_with_the_tools_message(tool, name):
    with pytest.raises(relgeo.InvalidInput) as e:
        relgeo.check_extrusion(TESTDATA / name)
    assert isinstance(e.value, ValueError)
    assert str(e.value) == tool.error("extrusion", TESTDATA / name)


def test_bad_arguments():
    with pytest.raises(relgeo.UnreadableFile):
        relgeo.check_extrusion(TESTDATA / "no_such_contour.json")
    with pytest.raises(ValueError, match="needs a CGAL kernel"):
        relgeo.check_extrusion(TESTDATA / GOOD[0], algorithm="cgal")
    with pytest.raises(ValueError, match="unknown kernel"):
        relgeo.check_extrusion(TESTDATA / GOOD[0], kernel="doubel")
    with pytest.raises(ValueError, match="max_listed"):
        relgeo.check_extrusion(TESTDATA / GOOD[0], max_listed=-1)
