// tools/relgeo/commands/linsolve/facade.cpp — names and validation of the
// linear solvers and scalars (no instantiation: see dispatch.cpp).
#include "commands/linsolve/facade.h"

#include <algorithm>

#include "cli/text.h"

namespace relgeo::tool {

const std::vector<std::string>& linear_method_names() {
  static const std::vector<std::string> names = {"none", "partial", "complete", "eigen-partial", "eigen-full"};
  return names;
}

std::string linear_methods_help() {
  return "Methods (--method):\n"
         "  none           Gaussian elimination without pivoting (relgeo::gaussian_elimination):\n"
         "                 unstable, the thesis' example\n"
         "  partial        with partial pivoting (largest |a(i,k)| in the column; default)\n"
         "  complete       with complete ('total') pivoting (largest |a(i,j)| of the trailing block)\n"
         "  eigen-partial  Eigen::PartialPivLU (blocked; a peer)\n"
         "  eigen-full     Eigen::FullPivLU (a peer; not with mpfr-BITS)\n";
}

const std::vector<std::string>& linear_scalar_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"float", "double", "long-double"};
    for (int b : linear_mpfr_bits()) n.push_back("mpfr-" + std::to_string(b));
    n.push_back("rational");
    return n;
  }();
  return names;
}

std::string linear_scalars_summary() {
  std::string bits;
  for (int b : linear_mpfr_bits()) bits += (bits.empty() ? "" : ", ") + std::to_string(b);
  return "float, double, long-double, mpfr-BITS (BITS in " + bits + "), rational";
}

void validate_linear_combination(std::string_view method, std::string_view scalar) {
  const auto& m = linear_method_names();
  if (std::find(m.begin(), m.end(), method) == m.end())
    throw Usage_error("--method: unknown method '" + std::string(method) +
                      "'; methods: none, partial, complete, eigen-partial, eigen-full");
  const auto& s = linear_scalar_names();
  if (std::find(s.begin(), s.end(), scalar) == s.end())
    throw Usage_error("--scalar: unknown scalar '" + std::string(scalar) + "'; scalars: " +
                      linear_scalars_summary());
}

}  // namespace relgeo::tool
