// fuzz/point_pool.h — a pool of 3D points from fuzz bytes, for the harnesses
// of implicit points and triangle intersection: new coordinates, duplicates,
// and points on the line or in the plane of earlier ones, so that touching
// and coplanar configurations are common.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz_support.h"

namespace relgeo::fuzz {

/// From 3 to `most` points (most > 2): a count byte, then per point an
/// operation byte and its operands.
inline std::vector<std::array<double, 3>> decode_point_pool(Input& in, std::size_t most) {
  using Coordinates = std::array<double, 3>;
  std::vector<Coordinates> pool;
  const std::size_t n = 3 + in.byte() % (most - 2);
  while (pool.size() < n) {
    const std::uint8_t op = in.byte();
    if (pool.size() < 2 || op % 4 == 0) {
      Coordinates c;
      for (double& x : c) x = in.coordinate();
      pool.push_back(c);
    } else if (op % 4 == 1) {
      pool.push_back(pool[in.below(pool.size())]);
    } else {  // a + s (b - a) (+ t (c - a) when op % 4 == 3): on a line or in a plane
      const Coordinates a = pool[in.below(pool.size())], b = pool[in.below(pool.size())],
                        c = pool[in.below(pool.size())];
      const double s = static_cast<std::int8_t>(in.byte()) / 8.0, t = op % 4 == 3 ? in.byte() / 16.0 : 0.0;
      Coordinates p;
      for (int i = 0; i < 3; ++i) p[i] = a[i] + s * (b[i] - a[i]) + t * (c[i] - a[i]);
      pool.push_back(p);
    }
  }
  return pool;
}

}  // namespace relgeo::fuzz
