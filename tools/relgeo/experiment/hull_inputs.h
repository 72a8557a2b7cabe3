// tools/relgeo/experiment/hull_inputs.h — the point sets of the experiment's hull
// section: the classroom example A1, Kettner et al.'s failure construction,
// and families of near-degenerate inputs. Deterministic: std::mt19937_64 and
// doubles built from its integers with + - * / only (no std::uniform_real_
// distribution, no libm), so every machine generates the same points.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "relgeo/kernel/point.h"

namespace relgeo::tool {

struct Hull_input {
  std::string name;         ///< short, file-name safe ("line-ulps")
  std::string description;  ///< one line
  std::uint64_t seed = 0;   ///< of the generator (0: fixed data)
  std::vector<Point_2<double>> points;
};

/// SPEC Sec. 3.1's A1, nine points in insertion order.
Hull_input classroom_a1_input();

/// What Kettner et al.'s construction searches for.
enum class Kettner_failure {
  lost_point,       ///< output a convex polygon, but not the exact hull (an extreme point lost)
  non_convex,       ///< output not a simple, strictly convex, counterclockwise polygon
  non_termination,  ///< graham_incremental reports non-termination
};

/// Kettner et al.'s failure construction, as A1 was found: three points at
/// random on the segment (0.5, 0.5)-(24, 24) (parameter in [0.2, 1]) and a
/// fourth near its lower end (parameter in [0, 0.05]), each coordinate moved
/// by a random number of ulps in [-8, 8], followed by A1's five outer points
/// (8, 4), (4, 9), (15, 27), (26, 25), (19, 11). Configurations are drawn
/// from seeds base_seed, base_seed + 1, ... until graham_incremental under
/// Naive_kernel<double> fails in the requested way (at most `max_attempts`;
/// the result's `seed` is the one found; empty points if none).
Hull_input kettner_construction_input(Kettner_failure failure, std::uint64_t base_seed = 1000,
                                      std::size_t max_attempts = 100000);

/// n points on the segment (0.5, 0.5)-(24.25, 17.3), rounded, each coordinate
/// then moved by a random number of ulps in [-4, 4]; random order.
Hull_input line_ulps_input(std::size_t n, std::uint64_t seed);

/// n points on the circle of radius 1 centred at (2^e, 2^e), e = 
/// centre_exponent, rounded to double (one ulp there is 2^(e-52)); random
/// order. Points are made with the rational parametrisation
/// ((1-t^2)/(1+t^2), 2t/(1+t^2)), t uniform in [-1, 1], mirrored to the left
/// half for every other point. Name "circle-2^e".
Hull_input circle_input(std::size_t n, int centre_exponent, std::uint64_t seed);

/// n points in `clusters` clusters: copies of a few random points of
/// [0, 1]^2, half of them exact duplicates, the others moved by up to 2 ulps
/// per coordinate; random order.
Hull_input clustered_input(std::size_t n, std::size_t clusters, std::uint64_t seed);

/// A large coordinate range: n/2 points (x, 0.7 x) rounded, |x| up to 1e12,
/// and n - n/2 points uniform in [-1e-3, 1e-3]^2 near the origin (so near the
/// line, far below its rounding error, yet extreme points of the exact hull);
/// interleaved in random order.
Hull_input large_range_input(std::size_t n, std::uint64_t seed);

}  // namespace relgeo::tool
