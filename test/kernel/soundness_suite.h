// test/kernel/soundness_suite.h — the soundness rule, checked empirically.
//
// For a kernel K, every predicate is evaluated on ~10^6 random, near-degenerate,
// extreme-magnitude and exactly degenerate inputs (test/support/soundness_data.h)
// and compared with an independent exact oracle:
//  * certified kernels: no definite answer differs from the exact sign;
//  * kernels with exact predicates: never `uncertain` either;
//  * naive kernels: never `uncertain`; their wrong answers are counted and
//    printed, not hidden.
// Instantiate with INSTANTIATE_TYPED_TEST_SUITE_P(Name, Soundness, Types), one
// translation unit per group of kernels (STYLE rule 12).
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <type_traits>

#include "relgeo/analysis/sign_tally.h"
#include "relgeo/kernel/concepts.h"
#include "support/soundness_data.h"

namespace relgeo::test {

template <class K>
constexpr Input_precision input_precision_of() {
  if constexpr (std::is_same_v<typename K::FT, float>) return Input_precision::binary32;
  else return Input_precision::binary64;
}

template <class K, class Case, class Eval>
void check_soundness(const char* predicate, const Labelled_cases<Case>& data, Eval eval) {
  for (std::size_t f = 0; f < data.family.size(); ++f) {
    analysis::Sign_tally t;
    for (std::size_t i = data.begin[f]; i < data.begin[f + 1]; ++i)
      t.add(data.exact[i], eval(data.cases[i]));
    std::printf("[ tally    ] %-22s %-14s %-18s cases=%zu wrong=%zu (+>0 %zu, ->0 %zu, 0>+- %zu, inv %zu) uncertain=%zu (%.4f%%)\n",
                K::name().c_str(), predicate, data.family[f].c_str(), t.cases, t.wrong(),
                t.plus_to_zero, t.minus_to_zero, t.zero_to_sign, t.inversions, t.uncertain,
                100.0 * t.uncertain_rate());
    const std::string where = K::name() + " " + predicate + " on " + data.family[f];
    if constexpr (K::is_certified) {
      EXPECT_EQ(t.wrong(), 0u) << "soundness rule broken: " << where;
    } else {
      EXPECT_EQ(t.uncertain, 0u) << "a naive kernel answered uncertain: " << where;
    }
    if constexpr (K::has_exact_predicates) {
      EXPECT_EQ(t.uncertain, 0u) << "exact predicates answered uncertain: " << where;
    }
    EXPECT_GT(t.cases, 0u);
  }
}

template <class K>
class Soundness : public ::testing::Test {
 protected:
  const Soundness_data& data() { return soundness_data(input_precision_of<K>()); }
  K kernel;
};

TYPED_TEST_SUITE_P(Soundness);

TYPED_TEST_P(Soundness, Orientation2) {
  using K = TypeParam;
  const K& k = this->kernel;
  check_soundness<K>("orientation_2", this->data().orientation_2,
                     [&](const analysis::Orientation_2_case& c) { return analysis::orientation_2_of(k, c); });
}

TYPED_TEST_P(Soundness, Orientation3) {
  using K = TypeParam;
  const K& k = this->kernel;
  check_soundness<K>("orientation_3", this->data().orientation_3,
                     [&](const analysis::Orientation_3_case& c) { return analysis::orientation_3_of(k, c); });
}

TYPED_TEST_P(Soundness, CoplanarOrientation) {
  using K = TypeParam;
  const K& k = this->kernel;
  const auto pt = k.construct_point_3_object();
  const auto coplanar = k.coplanar_orientation_3_object();
  check_soundness<K>("coplanar_orient", this->data().coplanar, [&](const Coplanar_case& c) {
    const auto& v = c.c;
    return coplanar(pt(v[0], v[1], v[2]), pt(v[3], v[4], v[5]), pt(v[6], v[7], v[8]));
  });
}

TYPED_TEST_P(Soundness, CompareXy) {
  using K = TypeParam;
  const K& k = this->kernel;
  const auto pt = k.construct_point_2_object();
  const auto compare = k.compare_xy_2_object();
  check_soundness<K>("compare_xy", this->data().compare_xy, [&](const Compare_case& c) {
    return compare(pt(c.x1, c.y1), pt(c.x2, c.y2));
  });
}

REGISTER_TYPED_TEST_SUITE_P(Soundness, Orientation2, Orientation3, CoplanarOrientation, CompareXy);

/// gtest type-name generator printing K::name().
struct Kernel_name {
  template <class K>
  static std::string GetName(int) {
    std::string n = K::name();
    for (char& ch : n)
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return n;
  }
};

}  // namespace relgeo::test
