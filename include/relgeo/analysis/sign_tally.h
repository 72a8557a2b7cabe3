// relgeo/analysis/sign_tally.h — how a kernel's answers compare with the exact signs.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/analysis/predicate_workloads.h"

namespace relgeo::analysis {

/// Counts of a kernel's answers against the exact signs. `uncertain` answers
/// are never wrong; every definite answer that differs from the exact sign is
/// wrong, split by kind.
struct Sign_tally {
  std::size_t cases = 0;
  std::size_t correct = 0;        ///< definite and equal to the exact sign
  std::size_t uncertain = 0;      ///< the kernel declined to decide
  std::size_t plus_to_zero = 0;   ///< exact +, answered 0
  std::size_t minus_to_zero = 0;  ///< exact -, answered 0
  std::size_t zero_to_sign = 0;   ///< exact 0, answered + or -
  std::size_t inversions = 0;     ///< exact + answered -, or the reverse

  std::size_t wrong() const { return plus_to_zero + minus_to_zero + zero_to_sign + inversions; }
  double uncertain_rate() const { return cases ? double(uncertain) / double(cases) : 0.0; }
  double wrong_rate() const { return cases ? double(wrong()) / double(cases) : 0.0; }

  /// Records one answer. \pre `exact` is definite.
  void add(Certified_sign exact, Certified_sign answer) {
    if (!is_certain(exact)) throw Precondition_violation("Sign_tally::add: exact sign is uncertain");
    ++cases;
    if (answer == exact) ++correct;
    else if (!is_certain(answer))
      ++uncertain;
    else if (certainly(answer, Certified_sign::zero))
      (certainly(exact, Certified_sign::positive) ? plus_to_zero : minus_to_zero)++;
    else if (certainly(exact, Certified_sign::zero))
      ++zero_to_sign;
    else ++inversions;
  }
  Sign_tally& operator+=(const Sign_tally& o) {
    cases += o.cases, correct += o.correct, uncertain += o.uncertain;
    plus_to_zero += o.plus_to_zero, minus_to_zero += o.minus_to_zero;
    zero_to_sign += o.zero_to_sign, inversions += o.inversions;
    return *this;
  }
};

/// orientation_2 of a case under kernel K (coordinates converted by K).
template <OrientationKernel_2 K>
Certified_sign orientation_2_of(const Orientation_2_case& c, const K& k) {
  const auto pt = k.construct_point_2_object();
  return k.orientation_2_object()(pt(c.px, c.py), pt(c.qx, c.qy), pt(c.rx, c.ry));
}
/// orientation_3 of a case under kernel K.
template <OrientationKernel_3 K>
Certified_sign orientation_3_of(const Orientation_3_case& c, const K& k) {
  const auto pt = k.construct_point_3_object();
  const auto& v = c.c;
  return k.orientation_3_object()(pt(v[0], v[1], v[2]), pt(v[3], v[4], v[5]),
                                  pt(v[6], v[7], v[8]), pt(v[9], v[10], v[11]));
}

/// The exact signs of the cases (Exact_kernel, GMP rationals).
template <class Case>
std::vector<Certified_sign> exact_signs(std::span<const Case> cases) {
  const Exact_kernel exact;
  std::vector<Certified_sign> out;
  out.reserve(cases.size());
  for (const Case& c : cases) {
    if constexpr (std::is_same_v<Case, Orientation_2_case>) out.push_back(orientation_2_of(c, exact));
    else out.push_back(orientation_3_of(c, exact));
  }
  return out;
}

/// Tally of kernel K's answers on `cases` against `exact`.
template <KernelProperties K, class Case>
Sign_tally tally(std::span<const Case> cases, std::span<const Certified_sign> exact, const K& k) {
  if (cases.size() != exact.size()) throw Precondition_violation("tally: sizes differ");
  Sign_tally t;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if constexpr (std::is_same_v<Case, Orientation_2_case>) t.add(exact[i], orientation_2_of(cases[i], k));
    else t.add(exact[i], orientation_3_of(cases[i], k));
  }
  return t;
}

}  // namespace relgeo::analysis
