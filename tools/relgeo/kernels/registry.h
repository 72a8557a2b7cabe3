// tools/relgeo/kernels/registry.h — the kernels of kernels/list.h at run
// time, keyed by their own name K::name(), without including any kernel
// (cheap: for help texts, option validation and reports).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace relgeo::tool {

/// One kernel of the list, with the facts the tool reports about it.
struct Kernel_entry {
  std::string name;         ///< K::name(): the key ("failsafe<double>", "mpfr-53")
  std::string alias;        ///< shorter command-line name ("failsafe"), or empty
  std::string description;  ///< one line for the help text
  bool certified = false;   ///< K::is_certified: never a wrong definite answer
  bool exact_predicates = false;
  bool exact_constructions = false;
  bool cgal = false;        ///< a Cgal_kernel<...> (needed by the `cgal` hull algorithm)
  bool slow = false;        ///< the experiment gives it n/10 cases with --quick
  int mpfr_bits = 0;        ///< Mpfr_kernel<Bits>: Bits, else 0
  std::size_t index = 0;    ///< position in kernels/list.h

  /// The name the tool prints and users type: the alias when there is one.
  const std::string& label() const { return alias.empty() ? name : alias; }
};

/// Every kernel, in list order.                         [kernels/registry.cpp]
const std::vector<Kernel_entry>& kernel_registry();

/// The kernel called `name` (K::name() or the alias).
/// \throws Usage_error listing the valid names (for a malformed mpfr-BITS,
///   the valid BITS).
const Kernel_entry& find_kernel(std::string_view name);

/// The labels, comma-separated, mpfr-BITS collapsed: for error messages.
std::string kernel_names_summary();

/// The help paragraph: every kernel with its description, the aliases.
std::string kernel_help_text();

}  // namespace relgeo::tool
