// relgeo/mesh/solid_report.h — the report of validate_solid
// (solid_validation.h) and its options: plain data (strings, numbers,
// vectors), for code that passes reports around, such as the Boolean's
// result, without running the validation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_report.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// The outcome of one check.
enum class Check_status : std::uint8_t {
  pass,        ///< checked: no defect
  fail,        ///< checked: defects found (listed)
  undecided,   ///< the kernel could not decide some cases (listed), none failed
  not_checked  ///< not run: turned off, or its preconditions failed (see the note)
};

constexpr std::string_view to_string(Check_status s) noexcept {
  switch (s) {
    case Check_status::pass:
      return "pass";
    case Check_status::fail:
      return "fail";
    case Check_status::undecided:
      return "undecided";
    case Check_status::not_checked:
      return "not_checked";
  }
  return "unknown";
}

/// One check of the report.
struct Solid_check {
  Check_status status = Check_status::not_checked;
  /// Offending elements found (all of them; 0 when passed).
  std::size_t count = 0;
  /// The first Solid_validation_options::max_listed of them (Mesh_issue:
  /// the defect and its elements, as Mesh_defect documents).
  std::vector<Mesh_issue> where;
  /// Why not checked, or what was left out.
  std::string note;

  bool passed() const { return status == Check_status::pass; }
};

/// One connected component (faces connected through shared vertices).
struct Solid_component {
  Index first_face = 0;
  std::size_t vertices = 0, edges = 0, faces = 0;
  long long euler_characteristic = 0;
  /// (2 - euler_characteristic) / 2 when the mesh is a closed, manifold,
  /// consistently oriented surface.
  std::optional<long long> genus;
  /// Its signed volume, nearest double of the exact value (of the
  /// enclosure's midpoint when not exact); NaN when not computed.
  double volume = std::numeric_limits<double>::quiet_NaN();
  /// The winding number of all other components around it (see
  /// internal/component_winding.h); empty when not computed or undecided.
  std::optional<int> winding;
};

/// The signed volume (1/6 sum of det(a, b, c) over the faces; the volume
/// enclosed for a closed mesh, positive when outward oriented).
struct Solid_volume {
  bool computed = false;
  /// `value` is the nearest double to the exact volume of the coordinates
  /// (double, rational, MPFR input); false: an enclosure (intervals).
  bool exact = false;
  double value = std::numeric_limits<double>::quiet_NaN();
  /// Bounds of the exact volume (equal to `value` or one rounding apart
  /// when exact).
  double lower = std::numeric_limits<double>::quiet_NaN();
  double upper = std::numeric_limits<double>::quiet_NaN();
  /// The exact value as "numerator/denominator" (empty when not exact).
  std::string exact_value;
};

/// Options of validate_solid.
struct Solid_validation_options {
  /// What check_mesh looks at (require_closed, report_isolated_vertices;
  /// check_collinear_faces is ignored: degenerate faces are always found,
  /// under the report's kernel, since the self-intersection test must skip
  /// them).
  Mesh_check_options mesh{};
  bool check_self_intersections = true;
  /// The orientation test (needs the self-intersection test).
  bool check_orientation = true;
  /// The exact volume string (can be long: disable for huge meshes).
  bool exact_volume_string = true;
  /// Most entries in each `where` list and in `component_list`.
  std::size_t max_listed = 100;
  /// Threads for the self-intersection test (1: serial; 0: all; TBB only).
  int threads = 1;
};

/// The validation report (file comment). Every field is plain data.
struct Solid_report {
  std::string kernel;  ///< the kernel that decided the geometric checks
  std::size_t vertices = 0, faces = 0;
  std::optional<std::size_t> edges;  ///< distinct vertex pairs of faces

  Solid_check valid_indices;           ///< index_out_of_range
  Solid_check finite_coordinates;      ///< non_finite_coordinate
  Solid_check non_degenerate_faces;    ///< repeated_vertex_in_face, collinear_face, undecided {face}
  Solid_check no_isolated_vertices;    ///< isolated_vertex
  Solid_check valid_tags;              ///< invalid_tag
  Solid_check closed;                  ///< boundary_edge
  Solid_check edge_manifold;           ///< non_manifold_edge
  Solid_check vertex_manifold;         ///< non_manifold_vertex
  Solid_check consistently_oriented;   ///< inconsistent_orientation
  Solid_check self_intersection_free;  ///< self_intersection, undecided {face, face} / {face}
  /// The mesh is the outward boundary of a solid: each component's volume
  /// sign agrees with its nesting (misoriented_component); for one
  /// component: signed volume > 0.
  Solid_check outward_oriented;

  std::optional<long long> euler_characteristic;  ///< V - E + F (V: vertices used by faces)
  std::size_t components = 0;
  std::optional<long long> genus;  ///< sum over components, when defined
  Solid_volume volume;
  std::vector<Solid_component> component_list;  ///< the first max_listed components
  /// Pairs of faces whose boxes overlap that the self-intersection test
  /// visited (with certified faces, the search may leave out pairs their
  /// certificates decide).
  std::size_t candidate_pairs = 0;
  /// The kernel's points are the coordinates exactly (false: rounded to its
  /// number type first; the geometric checks are about the rounded mesh).
  bool coordinates_exact = true;

  /// f(name, check) for the eleven checks, in the order above.
  template <class F>
  void for_each_check(F&& f) const {
    f("valid_indices", valid_indices), f("finite_coordinates", finite_coordinates);
    f("non_degenerate_faces", non_degenerate_faces), f("no_isolated_vertices", no_isolated_vertices);
    f("valid_tags", valid_tags), f("closed", closed), f("edge_manifold", edge_manifold);
    f("vertex_manifold", vertex_manifold), f("consistently_oriented", consistently_oriented);
    f("self_intersection_free", self_intersection_free), f("outward_oriented", outward_oriented);
  }
  /// Every check passed: a valid solid.
  bool is_valid_solid() const {
    bool ok = true;
    for_each_check([&](std::string_view, const Solid_check& c) { ok = ok && c.passed(); });
    return ok;
  }
  /// The listed issues of every check (for Invalid_mesh).
  std::vector<Mesh_issue> issues() const {
    std::vector<Mesh_issue> all;
    for_each_check(
        [&](std::string_view, const Solid_check& c) { all.insert(all.end(), c.where.begin(), c.where.end()); });
    return all;
  }
  /// One line: "valid solid" or each check that did not pass with its count.
  std::string summary() const {
    std::string s;
    for_each_check([&](std::string_view name, const Solid_check& c) {
      if (c.passed()) return;
      s += (s.empty() ? "" : ", ") + std::string(name) + " " + std::string(to_string(c.status));
      if (c.count) s += " (" + std::to_string(c.count) + ")";
    });
    return s.empty() ? "valid solid" : s;
  }
};

}  // namespace relgeo
