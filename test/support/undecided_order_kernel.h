// test/support/undecided_order_kernel.h — a certified kernel that never
// orders two distinct points: Filtered_exact_kernel with compare_xyz_3
// answering `uncertain` unless the points are equal. The soundness rule
// allows it (a kernel may doubt anything); the algorithms must then answer
// exactly or report the doubt, never read `uncertain` as an order.
#pragma once

#include <string>

#include "relgeo/kernel/filtered_exact_kernel.h"

namespace relgeo::test {

struct Undecided_order_kernel : Filtered_exact_kernel {
  static std::string name() { return "undecided-order"; }
  struct Compare_xyz_3 {
    Certified_sign operator()(const Implicit_point_3& a, const Implicit_point_3& b) const {
      const Certified_sign s = Filtered_exact_kernel::Compare_xyz_3{}(a, b);
      return s == Certified_sign::zero ? s : Certified_sign::uncertain;
    }
  };
  Compare_xyz_3 compare_xyz_3_object() const { return {}; }
};

}  // namespace relgeo::test
