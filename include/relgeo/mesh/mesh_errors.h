// relgeo/mesh/mesh_errors.h — what can be wrong with a triangle mesh, and the
// typed error the mesh and subdivision entries throw for it.
//
// Channel (STYLE rule 9): functions that *check* a mesh (check_mesh,
// validity.h) return a Mesh_report listing every issue; functions that
// *require* a valid mesh (Mesh_topology::build, loop_subdivide ...) throw
// Invalid_mesh carrying the issues that made them refuse (or Non_finite_input
// for NaN/infinite coordinates, Unreadable_file for files). All derive from
// relgeo::Error.
#pragma once

#include <array>
#include <cstddef>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// One kind of mesh defect. The comment says what Mesh_issue::elements holds.
enum class Mesh_defect {
  index_out_of_range,        ///< {face, bad vertex index}: a face names a vertex that does not exist
  non_finite_coordinate,     ///< {vertex, -}: a coordinate is NaN or infinite
  repeated_vertex_in_face,   ///< {face, -}: a face uses one vertex twice (combinatorially degenerate)
  collinear_face,            ///< {face, -}: the three points are collinear (geometrically degenerate; exact test)
  isolated_vertex,           ///< {vertex, -}: no face uses the vertex
  boundary_edge,             ///< {a, b}: edge with one face (the mesh is not closed)
  non_manifold_edge,         ///< {a, b}: edge with three or more faces
  inconsistent_orientation,  ///< {a, b}: two faces traverse the edge in the same direction
  non_manifold_vertex,       ///< {vertex, number of fans}: the faces at the vertex form several fans
  invalid_tag,               ///< {a, b} crease tag that is not an edge, or {vertex, -} corner out of range
  self_intersection,         ///< {face, face}: two faces intersect other than in shared vertices/edges
  misoriented_component,     ///< {first face, component}: a component's orientation and nesting do not
                             ///< bound a solid (inverted shell, or a shell nested without being a cavity)
  undecided                  ///< {face, -} or {face, face}: a non-exact kernel could not decide a test
};

constexpr std::string_view to_string(Mesh_defect d) noexcept {
  switch (d) {
    case Mesh_defect::index_out_of_range: return "index_out_of_range";
    case Mesh_defect::non_finite_coordinate: return "non_finite_coordinate";
    case Mesh_defect::repeated_vertex_in_face: return "repeated_vertex_in_face";
    case Mesh_defect::collinear_face: return "collinear_face";
    case Mesh_defect::isolated_vertex: return "isolated_vertex";
    case Mesh_defect::boundary_edge: return "boundary_edge";
    case Mesh_defect::non_manifold_edge: return "non_manifold_edge";
    case Mesh_defect::inconsistent_orientation: return "inconsistent_orientation";
    case Mesh_defect::non_manifold_vertex: return "non_manifold_vertex";
    case Mesh_defect::invalid_tag: return "invalid_tag";
    case Mesh_defect::self_intersection: return "self_intersection";
    case Mesh_defect::misoriented_component: return "misoriented_component";
    case Mesh_defect::undecided: return "undecided";
  }
  return "unknown";
}

/// One defect and where it is (see Mesh_defect for the meaning of elements;
/// unused entries are invalid_index).
struct Mesh_issue {
  Mesh_defect defect;
  std::array<Index, 2> elements{invalid_index, invalid_index};
  friend bool operator==(const Mesh_issue&, const Mesh_issue&) = default;
};

inline std::string to_string(const Mesh_issue& i) {
  std::ostringstream s;
  s << to_string(i.defect) << " (";
  for (std::size_t k = 0; k < 2; ++k)
    if (i.elements[k] != invalid_index) s << (k ? ", " : "") << i.elements[k];
  s << ")";
  return s.str();
}

/// A mesh an algorithm requires to be valid is not: defect() is the first
/// issue found, issues() all of them (capped at `max_listed` per call site).
class Invalid_mesh : public Invalid_input {
 public:
  Invalid_mesh(const std::string& context, std::vector<Mesh_issue> issues)
      : Invalid_input(message(context, issues)), issues_(std::move(issues)) {}
  /// The first issue's defect (\pre at least one issue was given).
  Mesh_defect defect() const { return issues_.front().defect; }
  const std::vector<Mesh_issue>& issues() const { return issues_; }

 private:
  static std::string message(const std::string& context, const std::vector<Mesh_issue>& issues) {
    std::string m = context;
    m.append(": invalid mesh:");
    for (std::size_t k = 0; k < issues.size() && k < 5; ++k) m.append(" ").append(to_string(issues[k]));
    if (issues.size() > 5) m.append(" ... (").append(std::to_string(issues.size())).append(" issues)");
    if (issues.empty()) m.append(" (no issue listed)");
    return m;
  }
  std::vector<Mesh_issue> issues_;
};

}  // namespace relgeo
