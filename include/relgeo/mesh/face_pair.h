// relgeo/mesh/face_pair.h — a pair of face indices, the unit of every
// report of crossing or undecided faces (self-intersection, Boolean,
// rounding repair).
#pragma once

#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// Two face indices (of two meshes, or of one mesh with first < second).
struct Face_pair {
  Index first = 0, second = 0;
  friend constexpr bool operator==(const Face_pair&, const Face_pair&) = default;
  friend constexpr auto operator<=>(const Face_pair&, const Face_pair&) = default;
};

}  // namespace relgeo
