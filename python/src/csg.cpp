// python/src/csg.cpp — csg(tree) through the tool's CSG facade
// (tools/relgeo/commands/csg/facade.h): the tree of a TREE.json file, or of
// the same document whose leaves may also be (V, F) arrays, evaluated by
// relgeo::csg; the root's mesh and the record of `relgeo csg --format json`.
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "commands/csg/facade.h"
#include "json_to_python.h"
#include "mesh_arrays.h"
#include "relgeo/core/internal/stopwatch.h"

namespace relgeo::python {

namespace {

using Leaf_arrays = std::vector<std::pair<Double_array, Index_array>>;

/// The solid of an array leaf: relgeo.csg writes it as {"mesh": {"arrays": k}},
/// k into `arrays`. Called without the GIL (the tree is read without it).
std::optional<Csg_node> array_leaf(const io::Json& mesh, const Leaf_arrays& arrays, const std::string& node) {
  if (!mesh.is_object() || mesh.size() != 1 || !mesh.contains("arrays") || !mesh["arrays"].is_number_unsigned())
    return std::nullopt;
  const auto k = mesh["arrays"].get<std::size_t>();
  if (k >= arrays.size()) throw Invalid_csg_node(node, "no arrays " + std::to_string(k));
  py::gil_scoped_acquire gil;
  try {
    return Csg_node::solid(checked_mesh(arrays[k].first, arrays[k].second, "(V, F)"), "(V, F)");
  } catch (const Invalid_input& e) {
    throw Invalid_csg_node(node, e.what());
  } catch (const py::value_error& e) {  // a wrong shape
    throw py::value_error("csg: node " + node + ": " + e.what());
  }
}

}  // namespace

void bind_csg(py::module_& m) {
  m.def(
      "csg",
      [](const std::optional<std::string>& file, const std::optional<std::string>& text, const Leaf_arrays& arrays,
         const std::string& base, const std::string& kernel, const std::string& rounding,
         const std::string& retriangulation, bool check_self_intersections, const std::string& intermediates) {
        tool::validate_csg_kernel(kernel);  // before any file is read, as the tool
        const Csg_options options =
            tool::csg_options(rounding, retriangulation, check_self_intersections, intermediates, kernel);
        internal::Stopwatch clock;
        Csg_result result;
        {
          py::gil_scoped_release release;
          Csg_node tree;
          if (file) {
            tree = tool::parse_csg_tree(*file);
          } else {
            tree = tool::parse_csg_tree(io::parse_json(text.value_or(""), "the CSG tree"),
                                        [&](const io::Json& mesh, const std::string& node) {
                                          if (auto leaf = array_leaf(mesh, arrays, node)) return std::move(*leaf);
                                          return tool::read_csg_mesh_file(mesh, std::filesystem::path(base), node);
                                        });
          }
          result = tool::evaluate_csg(kernel, tree, options);
        }
        auto d = json_to_python(tool::csg_report_json(file.value_or(""), kernel, rounding, result, clock.elapsed(),
                                                      options.intermediates))
                     .cast<py::dict>();
        if (!file) d.attr("pop")("tree");
        const py::tuple mesh = mesh_arrays(result.mesh);
        d["V"] = mesh[0];
        d["F"] = mesh[1];
        return d;
      },
      py::arg("file"), py::arg("text"), py::arg("arrays"), py::arg("base"), py::arg("kernel"), py::arg("rounding"),
      py::arg("retriangulation"), py::arg("check_self_intersections"), py::arg("intermediates"),
      "The tool's `csg` on a TREE.json file, or on the tree's JSON `text` whose leaves {\"mesh\": {\"arrays\": k}} "
      "are arrays[k] = (V, F) and whose files are relative to `base`: the record of `relgeo csg --format json` "
      "with the root's mesh as V, F.");
}

}  // namespace relgeo::python
