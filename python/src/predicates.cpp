// python/src/predicates.cpp — orient2d / orient3d over (n, 2) / (n, 3)
// arrays, and Kettner's orientation grids (the tool's `orient-grid`).
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "commands/orient_grid/facade.h"
#include "numpy_arrays.h"
#include "predicates_dispatch.h"
#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/analysis/sign_tally.h"

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

/// The counts of relgeo::analysis::Sign_tally, named as the tool names them.
py::dict tally_dict(const analysis::Sign_tally& t) {
  py::dict d;
  d["cells"] = t.cases;
  d["correct"] = t.correct;
  d["uncertain"] = t.uncertain;
  d["wrong"] = t.wrong();
  d["plus_to_zero"] = t.plus_to_zero;
  d["minus_to_zero"] = t.minus_to_zero;
  d["zero_to_sign"] = t.zero_to_sign;
  d["inversions"] = t.inversions;
  return d;
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
  d.attr("update")(tally_dict(g.tally));
  return d;
}

/// The coordinates of a case, point after point.
std::array<double, 6> case_coordinates(const analysis::Orientation_2_case& c) {
  return {c.px, c.py, c.qx, c.qy, c.rx, c.ry};
}
const std::array<double, 12>& case_coordinates(const analysis::Orientation_3_case& c) { return c.c; }

/// A workload's cases as one (n, Dimension) array per point: (p, q, r) or (p, q, r, s).
template <std::size_t Dimension, class Case>
py::tuple workload_arrays(const std::vector<Case>& cases) {
  constexpr std::size_t points = Dimension + 1;
  py::tuple out(points);
  for (std::size_t k = 0; k < points; ++k) {
    py::array_t<double> a({static_cast<py::ssize_t>(cases.size()), static_cast<py::ssize_t>(Dimension)});
    double* data = a.mutable_data();
    for (std::size_t i = 0; i < cases.size(); ++i)
      for (std::size_t j = 0; j < Dimension; ++j)
        data[i * Dimension + j] = case_coordinates(cases[i])[k * Dimension + j];
    out[k] = a;
  }
  return out;
}

/// The standard workloads of n cases as {name: arrays}, or the one named
/// `family` alone (ValueError listing the names when there is none).
template <std::size_t Dimension, class Makers>
py::dict workload_dict(const Makers& makers, std::size_t n, std::uint64_t seed,
                       const std::optional<std::string>& family) {
  py::dict d;
  std::string names;
  for (std::size_t k = 0; k < makers.size(); ++k) {
    const std::string name = makers[k](0, seed + k).name;  // no cases: just the name
    names += (k ? ", " : "") + name;
    if (!family || *family == name) d[py::str(name)] = workload_arrays<Dimension>(makers[k](n, seed + k).cases);
  }
  if (family && d.empty())
    throw py::value_error("orientation_workloads: unknown family '" + *family + "' (valid: " + names + ")");
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
      "orientation_workloads",
      [](int dimension, std::size_t n, std::uint64_t seed, const std::optional<std::string>& family) {
        if (dimension == 2) return workload_dict<2>(analysis::standard_workload_makers_2, n, seed, family);
        if (dimension == 3) return workload_dict<3>(analysis::standard_workload_makers_3, n, seed, family);
        throw py::value_error("orientation_workloads: dimension must be 2 or 3");
      },
      py::arg("dimension"), py::arg("n"), py::arg("seed"), py::arg("family") = py::none(),
      "relgeo::analysis::standard_workloads_2/3(n, seed): {name: (p, q, r[, s])} of (n, dimension) arrays, the "
      "families of the tool's experiment and the predicate benchmark; with family, that one alone (the same "
      "cases).");
  m.def(
      "sign_tally",
      [](const py::array_t<std::int8_t, py::array::forcecast>& answers,
         const py::array_t<std::int8_t, py::array::forcecast>& exact) {
        if (answers.ndim() != 1 || exact.ndim() != 1 || answers.shape(0) != exact.shape(0))
          throw py::value_error("sign_tally: answers and exact must be 1-d arrays of one length");
        const auto a = answers.unchecked<1>();
        const auto e = exact.unchecked<1>();
        analysis::Sign_tally t;
        for (py::ssize_t i = 0; i < a.shape(0); ++i) {
          if (a(i) < -1 || a(i) > 2 || e(i) < -1 || e(i) > 2)
            throw py::value_error("sign_tally: signs are -1, 0, 1 or 2 (uncertain)");
          t.add(static_cast<Certified_sign>(e(i)), static_cast<Certified_sign>(a(i)));
        }
        return tally_dict(t);
      },
      py::arg("answers"), py::arg("exact"),
      "relgeo::analysis::Sign_tally of a kernel's signs against the exact ones (the counts of orientation_grid).");
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
