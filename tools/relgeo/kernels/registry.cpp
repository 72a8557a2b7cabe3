// tools/relgeo/kernels/registry.cpp — the run-time registry, built from
// kernels/list.h with the kernel types complete (their names and flags are
// read from the types).
#include "kernels/registry.h"

#include "cli/text.h"
#include "kernels/cgal_kernels.h"
#include "kernels/list.h"

namespace relgeo::tool {

namespace {

template <std::size_t I>
Kernel_entry entry_of() {
  using K = kernel_at<I>;
  const auto& row = std::get<I>(kernel_list);
  Kernel_entry e;
  e.name = K::name();
  e.alias = std::string(row.alias);
  e.description = std::string(row.description);
  e.mpfr_bits = mpfr_bits_v<K>;
  if (e.mpfr_bits > 0)
    e.description = "Mpfr_kernel<" + std::to_string(e.mpfr_bits) + ">: naive at " + std::to_string(e.mpfr_bits) +
                    " bits of precision";
  e.certified = K::is_certified;
  e.exact_predicates = K::has_exact_predicates;
  e.exact_constructions = K::has_exact_constructions;
  e.cgal = is_cgal_kernel_v<K>;
  e.slow = row.slow;
  e.index = I;
  return e;
}

template <std::size_t... I>
std::vector<Kernel_entry> entries(std::index_sequence<I...>) {
  return {entry_of<I>()...};
}

std::string mpfr_bits_list() {
  std::string s;
  for (const auto& k : kernel_registry())
    if (k.mpfr_bits > 0) s += (s.empty() ? "" : ", ") + std::to_string(k.mpfr_bits);
  return s;
}

}  // namespace

const std::vector<Kernel_entry>& kernel_registry() {
  static const std::vector<Kernel_entry> registry = entries(std::make_index_sequence<kernel_count>{});
  return registry;
}

const Kernel_entry& find_kernel(std::string_view name) {
  for (const auto& k : kernel_registry())
    if (k.name == name || (!k.alias.empty() && k.alias == name)) return k;
  if (name.starts_with("mpfr-"))
    throw Usage_error("unknown kernel '" + std::string(name) + "': mpfr-BITS needs BITS in {" + mpfr_bits_list() + "}");
  throw Usage_error("unknown kernel '" + std::string(name) + "'; valid kernels: " + kernel_names_summary());
}

std::string kernel_names_summary() {
  std::string s;
  bool mpfr_done = false;
  for (const auto& k : kernel_registry()) {
    if (k.mpfr_bits > 0) {
      if (mpfr_done) continue;
      mpfr_done = true;
      s += (s.empty() ? "" : ", ") + std::string("mpfr-BITS (BITS in ") + mpfr_bits_list() + ")";
      continue;
    }
    s += (s.empty() ? "" : ", ") + k.label();
  }
  return s;
}

std::string kernel_help_text() {
  std::string s = "Kernels (--kernel):\n";
  bool mpfr_done = false;
  for (const auto& k : kernel_registry()) {
    std::string name = k.label(), desc = k.description;
    if (k.mpfr_bits > 0) {
      if (mpfr_done) continue;
      mpfr_done = true;
      name = "mpfr-BITS";
      desc = "Mpfr_kernel<BITS>: naive at BITS bits, BITS in {" + mpfr_bits_list() + "}";
    }
    s += "  " + name + std::string(name.size() < 13 ? 13 - name.size() : 1, ' ') + desc + "\n";
  }
  s += "Aliases: ";
  bool first = true;
  for (const auto& k : kernel_registry())
    if (!k.alias.empty()) {
      s += (first ? "" : ", ") + k.alias + " = " + k.name;
      first = false;
    }
  s += " (the kernel's own name K::name(), reported as kernel_model, is accepted too).\n";
  return s;
}

}  // namespace relgeo::tool
