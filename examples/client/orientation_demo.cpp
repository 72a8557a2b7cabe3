// The smallest relgeo program: one orientation query, answered by three kernels.
// Point p is one ulp right of the line through q and r: naive double cannot
// tell, the fail-safe kernel says it cannot tell, the filtered kernel knows.
#include <relgeo/kernel.h>

#include <cstdio>

template <relgeo::Kernel K>
relgeo::Certified_sign orientation_of_example(const K& k = K{}) {
  const auto pt = k.construct_point_2_object();
  return k.orientation_2_object()(pt(0.5 + 0x1p-53, 0.5), pt(12, 12), pt(24, 24));
}

int main() {
  const auto naive = orientation_of_example<relgeo::Naive_kernel<double>>();
  const auto failsafe = orientation_of_example<relgeo::Failsafe_kernel<double>>();
  const auto filtered = orientation_of_example<relgeo::Filtered_exact_kernel>();
  std::printf("double:           %s\n", relgeo::to_string(naive).data());
  std::printf("failsafe<double>: %s\n", relgeo::to_string(failsafe).data());
  std::printf("filtered:         %s\n", relgeo::to_string(filtered).data());
  // The exact answer is negative; a definite answer of a certified kernel must be it.
  const bool ok = filtered == relgeo::Certified_sign::negative &&
                  failsafe != relgeo::Certified_sign::positive;
  return ok ? 0 : 1;
}
