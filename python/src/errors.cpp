// python/src/errors.cpp — relgeo's C++ exceptions as the Python exceptions of
// relgeo.errors (python/relgeo/errors.py), message unchanged, most derived
// class first. Bad input is a ValueError (an unreadable or unwritable file an
// OSError as well); a bad kernel or algorithm name, the tool's Usage_error, is
// a plain ValueError, as for any bad argument in Python.
#include "relgeo/core/errors.h"

#include <exception>
#include <string>

#include "bindings.h"
#include "cli/text.h"
#include "relgeo/boolean/boolean_types.h"
#include "relgeo/boolean/csg.h"
#include "relgeo/io/errors.h"
#include "relgeo/linear/gaussian_elimination.h"
#include "relgeo/mesh/mesh_errors.h"

namespace relgeo::python {

namespace {

/// Raises relgeo.errors.<class_name>(e.what()) with `code` = e.code()'s name
/// (and `node` = the CSG node's path for InvalidCsgNode).
void raise_as(const char* class_name, const Error& e, const std::string* node = nullptr) {
  py::object cls = py::module_::import("relgeo.errors").attr(class_name);
  py::object exception = cls(e.what());
  exception.attr("code") = std::string(to_string(e.code()));
  if (node) exception.attr("node") = *node;
  PyErr_SetObject(cls.ptr(), exception.ptr());
}

void translate(std::exception_ptr p) {
  try {
    std::rethrow_exception(p);
  } catch (const tool::Usage_error& e) {
    PyErr_SetString(PyExc_ValueError, e.what());
  } catch (const Invalid_csg_node& e) {
    raise_as("InvalidCsgNode", e, &e.node());
  } catch (const Invalid_operand& e) {
    raise_as("InvalidOperand", e);
  } catch (const Invalid_mesh& e) {
    raise_as("InvalidMesh", e);
  } catch (const io::Unwritable_file& e) {
    raise_as("UnwritableFile", e);
  } catch (const Unreadable_file& e) {
    raise_as("UnreadableFile", e);
  } catch (const Non_finite_input& e) {
    raise_as("NonFiniteInput", e);
  } catch (const Invalid_input& e) {
    raise_as("InvalidInput", e);
  } catch (const Singular_matrix& e) {
    raise_as("SingularMatrix", e);
  } catch (const Precondition_violation& e) {
    raise_as("PreconditionViolation", e);
  } catch (const Error& e) {
    raise_as("Error", e);
  }
  // Anything else falls through to pybind11's own translators (RuntimeError...).
}

}  // namespace

void bind_errors(py::module_&) { py::register_exception_translator(&translate); }

}  // namespace relgeo::python
