// python/src/kernels.cpp — the tool's kernel registry (tools/relgeo/kernels/
// registry.h), so Python accepts exactly the names `relgeo --help` lists.
#include <string>

#include "bindings.h"
#include "kernels/registry.h"

namespace relgeo::python {

namespace {

py::dict kernel_entry_dict(const tool::Kernel_entry& k) {
  py::dict d;
  d["name"] = k.label();
  d["model"] = k.name;
  d["description"] = k.description;
  d["certified"] = k.certified;
  d["exact_predicates"] = k.exact_predicates;
  d["exact_constructions"] = k.exact_constructions;
  d["cgal"] = k.cgal;
  d["mpfr_bits"] = k.mpfr_bits;
  return d;
}

}  // namespace

void bind_kernels(py::module_& m) {
  m.def(
      "kernels",
      [] {
        py::list out;
        for (const auto& k : tool::kernel_registry()) out.append(kernel_entry_dict(k));
        return out;
      },
      "Every kernel as a dict (name, model, description, certified, exact_predicates, exact_constructions, cgal, "
      "mpfr_bits), in the tool's order.");
  m.def(
      "kernel", [](const std::string& name) { return kernel_entry_dict(tool::find_kernel(name)); }, py::arg("name"),
      "The kernel called `name` (its name or K::name()) as a dict; ValueError listing the valid names otherwise.");
}

}  // namespace relgeo::python
