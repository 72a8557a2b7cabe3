// python/src/predicates.cpp — orient2d / orient3d over (n, 2) / (n, 3)
// arrays, and Kettner's orientation grids (the tool's `orient-grid`).
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.h"
#include "commands/orient_grid/facade.h"
#include "numpy_arrays.h"
#include "predicates_dispatch.h"
#include "relgeo/analysis/predicate_workloads.h"

namespace relgeo::python {

namespace {

/// Signs of n tuples of `Dimension`-d points (already broadcast to one n by
/// the package), computed without the GIL.
template <int Dimension, class Signs, class... Arrays>
py::array_t<std::int8_t> orientation_signs(const Signs& signs, const std::string& kernel, const char* who,
                                           const Arrays&... points) {
  const std::vector<std::size_t> rows{require_rows(points, Dimension, who)...};
  for (std::size_t n : rows)
    if (n != rows.front()) throw py::value_error(std::string(who) + ": the point arrays have different lengths");
  py::array_t<std::int8_t> out(static_cast<py::ssize_t>(rows.front()));
  std::int8_t* data = out.mutable_data();
  {
    py::gil_scoped_release release;
    signs(kernel, coordinate_rows(points)..., rows.front(), data);
  }
  return out;
}

py::dict grid_dict(const analysis::Orientation_grid_result& g) {
  const auto n = static_cast<std::size_t>(g.size);
  py::dict d;
  d["kernel"] = g.kernel;
  d["size"] = g.size;
  d["p"] = py::make_tuple(g.triple.px, g.triple.py);
  d["q"] = py::make_tuple(g.triple.qx, g.triple.qy);
  d["r"] = py::make_tuple(g.triple.rx, g.triple.ry);
  d["answers"] = matrix_array<std::int8_t>(g.answers, n, n);
  d["exact"] = matrix_array<std::int8_t>(g.exact, n, n);
  d["cells"] = g.tally.cases;
  d["correct"] = g.tally.correct;
  d["uncertain"] = g.tally.uncertain;
  d["wrong"] = g.tally.wrong();
  d["plus_to_zero"] = g.tally.plus_to_zero;
  d["minus_to_zero"] = g.tally.minus_to_zero;
  d["zero_to_sign"] = g.tally.zero_to_sign;
  d["inversions"] = g.tally.inversions;
  return d;
}

}  // namespace

void bind_predicates(py::module_& m) {
  m.def(
      "orient2d",
      [](const Double_array& p, const Double_array& q, const Double_array& r, const std::string& kernel) {
        return orientation_signs<2>(orientation_2_signs, kernel, "orient2d", p, q, r);
      },
      py::arg("p"), py::arg("q"), py::arg("r"), py::arg("kernel"),
      "Signs (int8: -1, 0, 1, 2 = uncertain) of orientation_2 over three (n, 2) arrays.");
  m.def(
      "orient3d",
      [](const Double_array& p, const Double_array& q, const Double_array& r, const Double_array& s,
         const std::string& kernel) {
        return orientation_signs<3>(orientation_3_signs, kernel, "orient3d", p, q, r, s);
      },
      py::arg("p"), py::arg("q"), py::arg("r"), py::arg("s"), py::arg("kernel"),
      "Signs (int8: -1, 0, 1, 2 = uncertain) of orientation_3 over four (n, 3) arrays.");

  m.def(
      "kettner_triples",
      [] {
        py::dict d;
        for (const auto& t : analysis::kettner_grid_triples())
          d[py::str(t.name)] =
              py::make_tuple(py::make_tuple(t.px, t.py), py::make_tuple(t.qx, t.qy), py::make_tuple(t.rx, t.ry));
        return d;
      },
      "Kettner et al.'s grid triples {name: (p, q, r)} (the tool's --triple).");
  m.def(
      "orientation_grid",
      [](std::pair<double, double> p, std::pair<double, double> q, std::pair<double, double> r, int size,
         const std::string& kernel) {
        const analysis::Orientation_grid_triple triple{"", p.first, p.second, q.first, q.second, r.first, r.second};
        analysis::Orientation_grid_result g;
        {
          py::gil_scoped_release release;
          g = tool::evaluate_grid(kernel, triple, size);
        }
        return grid_dict(g);
      },
      py::arg("p"), py::arg("q"), py::arg("r"), py::arg("size"), py::arg("kernel"),
      "relgeo::analysis::evaluate_orientation_grid under the named kernel (the tool's orient-grid).");
}

}  // namespace relgeo::python
