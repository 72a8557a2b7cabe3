// fuzz/fuzz_support.h — what every relgeo fuzz harness shares: the contract
// check (a failed check aborts with a message, which libFuzzer reports as a
// crash with the input), the typed-error rule (bad input may only end in a
// relgeo::Error), a reader of structured input, and temporary files for the
// readers that take a path.
//
// The contract each harness asserts (doc/reliability.md): no crash, no hang
// (libFuzzer's -timeout), no sanitizer report, and either a result that the
// harness's oracle accepts or a relgeo::Error. Any other exception is a
// finding too.
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

#include "relgeo/core/errors.h"

namespace relgeo::fuzz {

/// Aborts (a libFuzzer crash) when `ok` is false: the library broke its contract.
inline void require(bool ok, std::string_view what) {
  if (ok) return;
  std::fprintf(stderr, "relgeo fuzz: contract violated: %.*s\n", static_cast<int>(what.size()), what.data());
  std::abort();
}

/// Runs f; a relgeo::Error is the library's answer to bad input (returned as
/// false), any other exception is a finding (abort). True when f returned.
template <class F>
bool typed_errors_only(F&& f, std::string_view context) {
  try {
    f();
    return true;
  } catch (const relgeo::Error&) {
    return false;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "relgeo fuzz: %.*s: untyped exception: %s\n", static_cast<int>(context.size()),
                 context.data(), e.what());
    std::abort();
  }
}

/// Runs f where the contract allows no exception at all (a call on input
/// already found valid): any exception, typed or not, is a finding (abort).
template <class F>
void no_exception(F&& f, std::string_view context) {
  try {
    f();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "relgeo fuzz: %.*s: exception on valid input: %s\n", static_cast<int>(context.size()),
                 context.data(), e.what());
    std::abort();
  }
}

/// Structured input from the fuzzer's bytes: integers, choices and doubles,
/// zero once the bytes run out (so every input means something).
class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}

  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }
  bool empty() const { return p_ == end_; }

  std::uint8_t byte() { return p_ < end_ ? *p_++ : 0; }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(byte()) << (8 * i);
    return v;
  }
  /// A value in [0, n) (n > 0).
  std::size_t below(std::size_t n) { return n <= 256 ? byte() % n : u32() % n; }
  bool flag() { return byte() & 1; }

  /// The raw bits of a double: every value, NaN and infinities included.
  double raw_double() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(byte()) << (8 * i);
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
  }

  /// A coordinate: one tag byte chooses between raw bits, small integers,
  /// special values (signed zeros, subnormals, the extremes of the range,
  /// NaN, infinities) and values one ulp away from a small grid, which is
  /// where predicates are near-degenerate.
  double coordinate() {
    const std::uint8_t tag = byte();
    switch (tag % 8) {
      case 0:
      case 1: return raw_double();
      case 2: return static_cast<double>(static_cast<std::int8_t>(byte()));
      case 3: {
        static constexpr double specials[] = {0.0,
                                              -0.0,
                                              std::numeric_limits<double>::denorm_min(),
                                              -std::numeric_limits<double>::denorm_min(),
                                              std::numeric_limits<double>::min(),
                                              std::numeric_limits<double>::max(),
                                              -std::numeric_limits<double>::max(),
                                              1e300,
                                              -1e300,
                                              1e-300,
                                              -1e-300,
                                              0.5,
                                              0.1,
                                              1.0 / 3.0,
                                              std::numeric_limits<double>::quiet_NaN(),
                                              std::numeric_limits<double>::infinity(),
                                              -std::numeric_limits<double>::infinity(),
                                              0x1p-53,
                                              0x1p-1022,
                                              0x1p511,
                                              0x1p-511,
                                              0x1p1000};
        return specials[byte() % (sizeof specials / sizeof specials[0])];
      }
      default: {
        // k / 8 plus a few ulps: points on or next to lines and planes.
        const double base = static_cast<double>(static_cast<std::int8_t>(byte())) / 8.0;
        const int ulps = static_cast<std::int8_t>(byte()) % 5;
        double v = base;
        for (int i = 0; i < std::abs(ulps); ++i) v = std::nextafter(v, ulps > 0 ? 1e300 : -1e300);
        return v;
      }
    }
  }

 private:
  const std::uint8_t* p_;
  const std::uint8_t* end_;
};

/// A file holding `size` bytes of `data`, named with `extension` (".off"),
/// removed when the object dies: for the readers that take a path. One per
/// process (libFuzzer runs one input at a time), in $TMPDIR or /tmp.
class Temporary_file {
 public:
  Temporary_file(const std::uint8_t* data, std::size_t size, std::string_view extension) {
    const char* dir = std::getenv("TMPDIR");
    path_ = std::string(dir && *dir ? dir : "/tmp") + "/relgeo-fuzz-" + std::to_string(::getpid()) +
            std::string(extension);
    std::ofstream out(path_, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    require(static_cast<bool>(out), "cannot write the temporary file");
  }
  ~Temporary_file() { std::remove(path_.c_str()); }
  Temporary_file(const Temporary_file&) = delete;
  Temporary_file& operator=(const Temporary_file&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace relgeo::fuzz
