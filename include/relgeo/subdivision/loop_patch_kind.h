// relgeo/subdivision/loop_patch_kind.h — how the limit surface over a face is
// evaluated (regular box spline, box spline over ghost points, local
// subdivision).
#pragma once

#include <cstdint>

namespace relgeo {

/// How the limit surface over a face is evaluated.
enum class Loop_patch_kind : std::uint8_t {
  regular,         ///< box spline of 12 control points (all smooth valence 6, standard rules)
  regular_crease,  ///< box spline of the net extended across regular creases by ghost points
  irregular        ///< local subdivision until the sub-patch holding (u, v) is regular
};

inline const char* to_string(Loop_patch_kind k) {
  switch (k) {
    case Loop_patch_kind::regular: return "regular";
    case Loop_patch_kind::regular_crease: return "regular_crease";
    case Loop_patch_kind::irregular: return "irregular";
  }
  return "unknown";
}

}  // namespace relgeo
