// relgeo/core/certified_sign.h — the answer type of every predicate.
#pragma once

#include <string_view>

namespace relgeo {

/// The sign a predicate reports.
///
/// `uncertain` means the kernel knows it cannot decide (its error bound does
/// not separate the computed value from zero). Soundness rule: for every kernel
/// except the naive ones, a definite answer equals the exact sign. Naive
/// kernels never answer `uncertain`.
enum class Certified_sign : signed char { negative = -1, zero = 0, positive = 1, uncertain = 2 };

/// True for negative, zero and positive.
constexpr bool is_certain(Certified_sign s) noexcept { return s != Certified_sign::uncertain; }

/// The sign of an arithmetic value; NaN gives `zero` (naive kernels only use
/// this on values they already trust, or trust blindly). Computed without a
/// branch: a predicate's sign is data-dependent, and a mispredicted branch
/// costs more than the whole determinant (benchmark/kernel/predicate_benchmark.h).
template <class T>
constexpr Certified_sign sign_of(const T& v) {
  return static_cast<Certified_sign>(static_cast<int>(v > 0) - static_cast<int>(v < 0));
}

/// Sign of a product: definite when both factors are definite, or when one is zero.
constexpr Certified_sign operator*(Certified_sign a, Certified_sign b) noexcept {
  if (a == Certified_sign::zero || b == Certified_sign::zero) return Certified_sign::zero;
  if (!is_certain(a) || !is_certain(b)) return Certified_sign::uncertain;
  return a == b ? Certified_sign::positive : Certified_sign::negative;
}

/// The opposite sign; `uncertain` stays `uncertain`.
constexpr Certified_sign operator-(Certified_sign s) noexcept {
  switch (s) {
    case Certified_sign::negative: return Certified_sign::positive;
    case Certified_sign::positive: return Certified_sign::negative;
    default: return s;
  }
}

/// Integer value -1, 0, +1 of a definite sign (2 for uncertain).
constexpr int to_int(Certified_sign s) noexcept { return static_cast<int>(s); }

constexpr std::string_view to_string(Certified_sign s) noexcept {
  switch (s) {
    case Certified_sign::negative: return "negative";
    case Certified_sign::zero: return "zero";
    case Certified_sign::positive: return "positive";
    case Certified_sign::uncertain: return "uncertain";
  }
  return "?";
}

/// Streams the sign's name (for tests and logs); any stream that takes a string_view.
template <class Stream>
  requires requires(Stream& os, std::string_view v) { os << v; }
Stream& operator<<(Stream& os, Certified_sign s) {
  os << to_string(s);
  return os;
}

// The idiom for testing an answer: every test says how it treats doubt.
// `certainly(s, v)` where an action needs the sign to be v for sure,
// `possibly(s, v)` where it must also happen when the kernel does not know,
// `is_certain(s)` for the doubt itself. relgeo does not compare a sign with
// `==` or `!=` outside this header (`s != v` quietly counts `uncertain` as
// "not v"): `scripts/api_rules.py signs`, run by the tests, lists any such
// comparison and prints none. Where an algorithm needs a definite answer it
// tests is_certain first and reports the doubt as a failure (the hulls' sort,
// the Boolean's `undecided` pairs) or throws.

/// `certainly(s, v)`: the kernel has decided that the sign is v.
constexpr bool certainly(Certified_sign s, Certified_sign v) noexcept { return s == v; }
/// `possibly(s, v)`: the sign may be v (it is v, or the kernel does not know).
constexpr bool possibly(Certified_sign s, Certified_sign v) noexcept {
  return s == v || s == Certified_sign::uncertain;
}

}  // namespace relgeo
