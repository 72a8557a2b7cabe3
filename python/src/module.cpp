// python/src/module.cpp — the extension module relgeo._relgeo. Users import
// the package `relgeo` (python/relgeo/__init__.py), which wraps these
// functions with numpy broadcasting and keyword defaults.
#include "bindings.h"

PYBIND11_MODULE(_relgeo, m) {
  m.doc() = "relgeo's C++ core: kernels named at run time, numpy arrays in and out (doc/python.md)";
  relgeo::python::bind_errors(m);
  relgeo::python::bind_kernels(m);
  relgeo::python::bind_predicates(m);
  relgeo::python::bind_hull(m);
  relgeo::python::bind_linear(m);
  relgeo::python::bind_mesh(m);
  relgeo::python::bind_boolean(m);
  relgeo::python::bind_csg(m);
  relgeo::python::bind_extrusion(m);
  relgeo::python::bind_subdivision(m);
  relgeo::python::bind_join(m);
}
