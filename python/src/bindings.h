// python/src/bindings.h — the areas of the module relgeo._relgeo, one
// translation unit each; module.cpp calls them in order.
#pragma once

#include <pybind11/pybind11.h>

namespace relgeo::python {

namespace py = pybind11;

void bind_errors(py::module_& m);       // errors.cpp: C++ exceptions -> relgeo.errors
void bind_kernels(py::module_& m);      // kernels.cpp: the tool's kernel registry
void bind_predicates(py::module_& m);   // predicates.cpp: orient2d/3d, orientation grids
void bind_hull(py::module_& m);         // hull.cpp: convex_hull
void bind_linear(py::module_& m);       // linear.cpp: solve
void bind_mesh(py::module_& m);         // mesh.cpp: read_mesh, write_mesh, validate_solid
void bind_boolean(py::module_& m);      // boolean.cpp: boolean, subdivision_boolean
void bind_csg(py::module_& m);          // csg.cpp: csg
void bind_extrusion(py::module_& m);    // extrusion.cpp: check_extrusion
void bind_subdivision(py::module_& m);  // subdivision.cpp: subdivide, limit_evaluate
void bind_join(py::module_& m);         // join.cpp: join

}  // namespace relgeo::python
