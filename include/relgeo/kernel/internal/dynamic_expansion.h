// relgeo/kernel/internal/dynamic_expansion.h — a floating-point expansion
// whose length is only known at run time, as a number type for generic
// formulas (the implicit-point predicates of implicit_coordinates.h, whose
// degrees reach 28 in the inputs: Expansion<N>'s compile-time capacities,
// which multiply at each product, would not fit on a stack).
//
// The arithmetic is expansion.h's (Shewchuk's exact sums, scalings and
// products with zero elimination), so the same preconditions hold: default
// floating-point environment, no overflow, every two_product exact. The
// caller establishes them from the range of its inputs (implicit_staged.h).
// As a safeguard, a component that overflowed makes the sign `uncertain`:
// overflow gives an infinite or NaN component, and later operations keep
// one (a sum or product with an infinite or NaN operand is never finite and
// never zero, so zero elimination does not drop it).
#pragma once

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/internal/expansion.h"

namespace relgeo::internal {

/// \brief An exact sum of doubles of any length (see the file comment).
class Dynamic_expansion {
  // Compressed, the values of the implicit predicates have a few components;
  // the products' partial sums before compression reach a few dozen.
  using Storage = boost::container::small_vector<double, 12>;

 public:
  Dynamic_expansion() = default;  ///< zero
  /// The double v (exactly).
  explicit Dynamic_expansion(double v) {
    if (v != 0) c_.push_back(v);
  }

  std::size_t size() const { return c_.size(); }
  /// The components, in increasing magnitude.
  const double* begin() const { return c_.data(); }
  const double* end() const { return c_.data() + c_.size(); }
  /// The exact sign; `uncertain` when a component overflowed.
  Certified_sign sign() const {
    if (!std::all_of(c_.begin(), c_.end(), [](double x) { return std::isfinite(x); })) return Certified_sign::uncertain;
    return c_.empty() ? Certified_sign::zero : (c_.back() > 0 ? Certified_sign::positive : Certified_sign::negative);
  }

  // Every result is compressed: the operands of the next product are short.
  friend Dynamic_expansion operator+(const Dynamic_expansion& e, const Dynamic_expansion& f) { return sum(e, f, 1.0); }
  friend Dynamic_expansion operator-(const Dynamic_expansion& e, const Dynamic_expansion& f) { return sum(e, f, -1.0); }
  /// e * f: the longer scaled by each component of the shorter, the partial
  /// products summed.
  friend Dynamic_expansion operator*(const Dynamic_expansion& e, const Dynamic_expansion& f) {
    const Dynamic_expansion& longer = e.size() >= f.size() ? e : f;
    const Dynamic_expansion& shorter = e.size() >= f.size() ? f : e;
    Dynamic_expansion product;
    const std::size_t n = longer.size(), m = shorter.size();
    if (m == 0) return product;
    product.c_.resize(2 * n * m, boost::container::default_init);
    Storage scaled(2 * n, boost::container::default_init), spare(m > 1 ? 2 * n * m : 0, boost::container::default_init);
    const std::size_t k = expansion::product(longer.data(), n, shorter.data(), m, product.c_.data(), scaled.data(),
                                             spare.data());
    product.c_.resize(expansion::compress(product.c_.data(), k, product.c_.data()));
    return product;
  }

 private:
  const double* data() const { return c_.data(); }
  static Dynamic_expansion sum(const Dynamic_expansion& e, const Dynamic_expansion& f, double f_sign) {
    Dynamic_expansion r;
    r.c_.resize(e.size() + f.size(), boost::container::default_init);
    const std::size_t k = expansion::sum(e.data(), e.size(), f.data(), f.size(), r.c_.data(), f_sign);
    r.c_.resize(expansion::compress(r.c_.data(), k, r.c_.data()));
    return r;
  }

  Storage c_;  // nonoverlapping, increasing magnitude, no zeros
};

inline Certified_sign certified_sign_of(const Dynamic_expansion& v) { return v.sign(); }

}  // namespace relgeo::internal
