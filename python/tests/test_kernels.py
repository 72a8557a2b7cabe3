"""Kernels by name: the tool's registry, its names, its error message."""

import pytest

import relgeo


def test_names_are_the_tools(tool):
    names = relgeo.kernel_names()
    assert names[:7] == ["float", "double", "long-double", "failsafe", "interval", "filtered", "exact"]
    assert {"mpfr-53", "cgal-sc", "cgal-epick", "cgal-epeck"} <= set(names)
    for name in names:  # each one the tool accepts, under the same name
        assert tool.json("orient-grid", "--kernel", name, "--size", "1")["kernel"] == name


def test_kernel_model_name_is_accepted_too():
    assert relgeo.kernel("failsafe<double>")["name"] == "failsafe"
    info = relgeo.kernel("exact")
    assert info["certified"] and info["exact_predicates"] and info["exact_constructions"]
    assert not relgeo.kernel("double")["certified"]


def test_default_kernel_is_filtered():
    assert relgeo.DEFAULT_KERNEL == "filtered"
    assert relgeo.convex_hull([[0, 0], [1, 0], [0, 1]])["kernel"] == "filtered"


@pytest.mark.parametrize("call", [
    lambda k: relgeo.kernel(k),
    lambda k: relgeo.orient2d([0, 0], [1, 0], [0, 1], kernel=k),
    lambda k: relgeo.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], kernel=k),
    lambda k: relgeo.convex_hull([[0, 0], [1, 0], [0, 1]], kernel=k),
    lambda k: relgeo.orientation_grid(size=2, kernel=k),
])
def test_wrong_name_is_a_value_error_listing_the_valid_ones(tool, call):
    with pytest.raises(ValueError) as raised:
        call("doubel")
    message = str(raised.value)
    assert message == tool.error("orient-grid", "--kernel", "doubel")
    for name in ["float", "double", "failsafe", "filtered", "exact", "cgal-epeck", "mpfr-BITS"]:
        assert name in message


def test_wrong_mpfr_precision_lists_the_precisions():
    with pytest.raises(ValueError, match=r"mpfr-BITS needs BITS in \{11, 24, 53"):
        relgeo.orient2d([0, 0], [1, 0], [0, 1], kernel="mpfr-7")
