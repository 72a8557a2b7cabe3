// python/src/mesh_arrays.h — triangle meshes as (V, F) numpy arrays: V an
// (n, 3) float64 array, F an (m, 3) int64 array of vertex indices.
#pragma once

#include <pybind11/numpy.h>

#include <cstdint>
#include <string>

#include "numpy_arrays.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::python {

/// Any array convertible to int64.
using Index_array = py::array_t<std::int64_t, py::array::forcecast>;

/// The mesh of (V, F), checked as relgeo's readers check a file: every
/// coordinate finite (Non_finite_input), every face index a vertex
/// (Invalid_mesh listing the index_out_of_range faces). `who` names the caller.
Mesh_double checked_mesh(const Double_array& v, const Index_array& f, const std::string& who);

/// The mesh of (V, F) with the indices taken as they are, only required to be
/// representable (ValueError otherwise): for validate_solid, which reports
/// out-of-range indices itself.
Mesh_double unchecked_mesh(const Double_array& v, const Index_array& f, const std::string& who);

/// (V, F) of a mesh.
py::tuple mesh_arrays(const Mesh_double& m);

}  // namespace relgeo::python
