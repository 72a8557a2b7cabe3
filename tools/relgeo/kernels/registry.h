// tools/relgeo/kernel_names.h — the kernels the tool knows by name, without
// including any kernel (cheap: for help texts and option validation).
// kernel_dispatch.h maps these names to kernel types.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace relgeo::tool {

/// The precisions accepted in `mpfr-BITS`: half, single, double, x87 extended,
/// 80, double-double, quadruple, 128 and 256 bits of significand.
inline constexpr std::array<int, 9> mpfr_bits = {11, 24, 53, 64, 80, 106, 113, 128, 256};

/// One kernel the tool offers.
struct Kernel_entry {
  std::string name;         ///< command-line name ("double", "mpfr-53", "cgal-epeck"...)
  std::string description;  ///< one line for the help text
  bool slow;                ///< `relgeo experiment --quick` gives it n/10 cases of each workload
};

/// Every kernel, in the order of the help text and of the experiment tables
/// (each mpfr-BITS listed separately).
const std::vector<Kernel_entry>& kernel_entries();

/// The names only, comma-separated, with mpfr-BITS collapsed ("..., mpfr-BITS
/// (BITS in 11, 24, ...), ...") — for error messages.
std::string kernel_names_summary();

/// The help paragraph listing the kernels with their descriptions.
std::string kernel_help_text();

/// Throws Usage_error unless `name` is a known kernel (the message lists the
/// valid names, or the allowed BITS for a malformed mpfr-BITS).
void validate_kernel_name(std::string_view name);

/// \pre validate_kernel_name(name) passed.
bool is_slow_kernel(std::string_view name);

}  // namespace relgeo::tool
