// tools/relgeo/kernel_names.cpp
#include "kernel_names.h"

#include <charconv>

#include "tool_common.h"

namespace relgeo::tool {

const std::vector<Kernel_entry>& kernel_entries() {
  static const std::vector<Kernel_entry> entries = [] {
    std::vector<Kernel_entry> e = {
        {"float", "Naive_kernel<float>: sign of the float value (coordinates rounded to float)", false},
        {"double", "Naive_kernel<double>: sign of the double value (the unreliable baseline)", false},
        {"long-double", "Naive_kernel<long double>: sign of the long double value", false},
        {"failsafe", "Failsafe_kernel<double>: Fortune's epsilon test, 'uncertain' near zero", false},
        {"interval", "Interval_kernel: interval arithmetic, 'uncertain' when 0 is enclosed", false},
        {"filtered", "Filtered_exact_kernel: semi-static filter, intervals, exact fallback", false},
        {"exact", "Exact_kernel: GMP rationals, the ground truth", true},
    };
    for (int bits : mpfr_bits)
      e.push_back({"mpfr-" + std::to_string(bits),
                   "Mpfr_kernel<" + std::to_string(bits) + ">: naive at " + std::to_string(bits) +
                       " bits of precision",
                   true});
    e.push_back({"cgal-sc", "Cgal_kernel<CGAL::Simple_cartesian<double>>: CGAL, naive double", false});
    e.push_back({"cgal-epick", "Cgal_kernel<CGAL::Epick>: CGAL, filtered exact predicates", false});
    e.push_back({"cgal-epeck", "Cgal_kernel<CGAL::Epeck>: CGAL, lazy exact", true});
    return e;
  }();
  return entries;
}

namespace {
std::string bits_list() {
  std::string s;
  for (int b : mpfr_bits) s += (s.empty() ? "" : ", ") + std::to_string(b);
  return s;
}
}  // namespace

std::string kernel_names_summary() {
  std::string s;
  bool mpfr_done = false;
  for (const auto& k : kernel_entries()) {
    if (k.name.starts_with("mpfr-")) {
      if (mpfr_done) continue;
      mpfr_done = true;
      s += (s.empty() ? "" : ", ") + std::string("mpfr-BITS (BITS in ") + bits_list() + ")";
      continue;
    }
    s += (s.empty() ? "" : ", ") + k.name;
  }
  return s;
}

std::string kernel_help_text() {
  std::string s = "Kernels (--kernel):\n";
  bool mpfr_done = false;
  for (const auto& k : kernel_entries()) {
    std::string name = k.name, desc = k.description;
    if (k.name.starts_with("mpfr-")) {
      if (mpfr_done) continue;
      mpfr_done = true;
      name = "mpfr-BITS";
      desc = "Mpfr_kernel<BITS>: naive at BITS bits, BITS in {" + bits_list() + "}";
    }
    s += "  " + name + std::string(name.size() < 13 ? 13 - name.size() : 1, ' ') + desc + "\n";
  }
  return s;
}

void validate_kernel_name(std::string_view name) {
  if (name.starts_with("mpfr-")) {
    const std::string_view b = name.substr(5);
    int bits = 0;
    const auto [end, ec] = std::from_chars(b.data(), b.data() + b.size(), bits);
    bool ok = ec == std::errc() && end == b.data() + b.size() && std::to_string(bits) == b;
    if (ok) {
      ok = false;
      for (int allowed : mpfr_bits) ok = ok || allowed == bits;
    }
    if (!ok)
      throw Usage_error("unknown kernel '" + std::string(name) + "': mpfr-BITS needs BITS in {" +
                        bits_list() + "}");
    return;
  }
  for (const auto& k : kernel_entries())
    if (k.name == name) return;
  throw Usage_error("unknown kernel '" + std::string(name) + "'; valid kernels: " +
                    kernel_names_summary());
}

bool is_slow_kernel(std::string_view name) {
  for (const auto& k : kernel_entries())
    if (k.name == name) return k.slow;
  return false;
}

}  // namespace relgeo::tool
