// test/kernel/fp_environment_soundness.h — the soundness rule in every
// floating-point environment a caller can set (flush-to-zero,
// denormals-are-zero, directed rounding): no certified kernel gives a wrong
// definite answer, on the near-degenerate workloads and on families built to
// meet the environment (subnormal coordinates, products that underflow, the
// coordinates whose differences both flush to zero).
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "relgeo/analysis/sign_tally.h"
#include "support/fp_environments.h"
#include "support/soundness_data.h"

namespace relgeo::test {

/// The inputs and their exact signs (computed in the default environment).
struct Environment_data {
  Labelled_cases<analysis::Orientation_2_case> orientation_2;
  Labelled_cases<analysis::Orientation_3_case> orientation_3;
  Labelled_cases<Compare_case> compare_xy;
};
const Environment_data& environment_data(Input_precision precision);

/// Wrong definite answers of K per environment (summed over every predicate
/// and family), printing each family's tally.
template <class K>
std::size_t wrong_answers_in(const Fp_environment_setting& setting, const Environment_data& d, const K& k = K{}) {
  std::size_t wrong = 0;
  auto run = [&](const char* predicate, const auto& data, auto eval) {
    std::vector<Certified_sign> answers(data.cases.size());
    {
      const Scoped_fp_environment environment(setting);
      for (std::size_t i = 0; i < data.cases.size(); ++i) answers[i] = eval(data.cases[i]);
    }
    for (std::size_t f = 0; f < data.family.size(); ++f) {
      analysis::Sign_tally t;
      for (std::size_t i = data.begin[f]; i < data.begin[f + 1]; ++i) t.add(data.exact[i], answers[i]);
      if (t.wrong() > 0 || f == 0)
        std::printf("[ tally    ] %-18s %-20s %-14s %-22s cases=%zu wrong=%zu uncertain=%zu\n", K::name().c_str(),
                    setting.name.c_str(), predicate, data.family[f].c_str(), t.cases, t.wrong(), t.uncertain);
      wrong += t.wrong();
    }
  };
  run("orientation_2", d.orientation_2,
      [&](const analysis::Orientation_2_case& c) { return analysis::orientation_2_of(c, k); });
  run("orientation_3", d.orientation_3,
      [&](const analysis::Orientation_3_case& c) { return analysis::orientation_3_of(c, k); });
  const auto pt = k.construct_point_2_object();
  const auto compare = k.compare_xy_2_object();
  run("compare_xy", d.compare_xy, [&](const Compare_case& c) { return compare(pt(c.x1, c.y1), pt(c.x2, c.y2)); });
  return wrong;
}

/// Every environment: a certified kernel is never wrong.
template <class K>
void expect_sound_in_every_environment(Input_precision precision = Input_precision::binary64) {
  static_assert(K::is_certified);
  const Environment_data& d = environment_data(precision);
  for (const auto& setting : non_default_fp_environments())
    EXPECT_EQ(wrong_answers_in<K>(setting, d), 0u) << K::name() << " under " << setting.name;
}

}  // namespace relgeo::test
