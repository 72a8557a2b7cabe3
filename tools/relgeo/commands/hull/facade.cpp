// tools/relgeo/commands/hull/facade.cpp — the hull facade without the
// kernels: algorithm names and validation, the exact error measures.
#include "commands/hull/facade.h"

#include <algorithm>

#include "cli/text.h"
#include "kernels/registry.h"

namespace relgeo::tool {

// ---- names -------------------------------------------------------------------

const std::vector<std::string>& hull_algorithm_names() {
  static const std::vector<std::string> names = {"graham-incremental", "graham-fortune",
                                                 "monotone-chain", "cgal"};
  return names;
}

std::string hull_algorithms_help() {
  return "Algorithms (--algorithm):\n"
         "  graham-incremental  relgeo::graham_incremental: the incremental hull of Kettner et al.\n"
         "                      (unstable; non-termination is detected and reported, exit 1)\n"
         "  graham-fortune      relgeo::graham_fortune: Fortune's stable Graham scan, with an\n"
         "                      a-priori backward-error bound\n"
         "  monotone-chain      relgeo::monotone_chain: Andrew's monotone chain\n"
         "  cgal                CGAL::convex_hull_2 through relgeo::cgal_convex_hull (only with\n"
         "                      the kernels cgal-sc, cgal-epick, cgal-epeck); CGAL needs exact\n"
         "                      predicates: under cgal-sc it runs in a child process, and a crash\n"
         "                      (seen: SIGSEGV) is reported as status failed (exit 1)\n";
}

void validate_hull_combination(std::string_view algorithm, std::string_view kernel) {
  const auto& names = hull_algorithm_names();
  if (std::find(names.begin(), names.end(), algorithm) == names.end()) {
    throw Usage_error("unknown algorithm '" + std::string(algorithm) + "'; algorithms: " + comma_list(names));
  }
  if (algorithm == "cgal" && !find_kernel(kernel).cgal)
    throw Usage_error("algorithm 'cgal' (CGAL::convex_hull_2) needs a CGAL kernel (cgal-sc, "
                      "cgal-epick or cgal-epeck), not '" + std::string(kernel) + "'");
}

// ---- measures ----------------------------------------------------------------

Hull_evaluation evaluate_hull(std::string_view algorithm, std::string_view kernel,
                              std::span<const Point_2<double>> points, double min_seconds,
                              const relgeo::Hull_options& options) {
  Hull_evaluation e;
  e.run = run_hull(algorithm, kernel, points, min_seconds, options);
  e.error = hull_error(points, e.run.indices);
  e.backward = hull_backward_error(points, e.run.indices);
  return e;
}

std::vector<Point_2<double>> classroom_example_a1() {
  return {{7.3000000000000194, 7.3000000000000167}, {24.000000000000068, 24.000000000000071},
          {24.00000000000005, 24.000000000000053},  {0.50000000000001621, 0.50000000000001243},
          {8, 4}, {4, 9}, {15, 27}, {26, 25}, {19, 11}};
}

}  // namespace relgeo::tool
