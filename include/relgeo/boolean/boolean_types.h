// relgeo/boolean/boolean_types.h — what a mesh Boolean takes and gives:
// the operation, the options, the result with its provenance, intersection
// curves and timings, and the error for invalid operands.
#pragma once

#include <array>
#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/point.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/rounding_repair_report.h"
#include "relgeo/mesh/solid_report.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// A regularised Boolean operation on two solids A and B.
enum class Boolean_operation : std::uint8_t {
  union_of,             ///< A u B
  intersection,         ///< A n B
  difference,           ///< A - B
  symmetric_difference  ///< (A - B) u (B - A)
};

constexpr std::string_view to_string(Boolean_operation op) {
  switch (op) {
    case Boolean_operation::union_of: return "union";
    case Boolean_operation::intersection: return "intersection";
    case Boolean_operation::difference: return "difference";
    case Boolean_operation::symmetric_difference: return "xor";
  }
  return "?";
}

/// How a Boolean writes its new vertices in doubles (Boolean_options::rounding).
enum class Output_rounding : std::uint8_t { nearest, repaired };

/// \concept ExactChainingKernel
/// A kernel whose Booleans can chain without rounding: exact constructions,
/// implicit points that are exact points of K::Point_3 (`.point`), and
/// points that are not doubles (Exact_kernel, Cgal_kernel<CGAL::Epeck>).
/// relgeo::boolean takes meshes of K's points under such a kernel, and
/// Boolean_result::exact_mesh() gives one.
template <class K>
concept ExactChainingKernel =
    IntersectionKernel_3<K> && K::has_exact_constructions && !std::same_as<typename K::Point_3, Point_3<double>> &&
    requires(const typename K::Implicit_point_3& p) {
  { p.point } -> std::convertible_to<typename K::Point_3>;
};

class Valid_solid;
namespace internal {
template <IntersectionKernel_3 K>
class Csg_evaluator;
template <ExactChainingKernel K>
class Exact_csg_evaluator;
}

/// That two meshes are valid solids certified by relgeo's exact checks
/// (Valid_solids: checked once, or Boolean results whose validation
/// passed), bound to those two mesh objects. A caller cannot make one for
/// meshes relgeo did not certify (only Valid_solid::certificate and
/// relgeo::csg make them), and the Boolean uses it only when its operands
/// are those very objects: the output's validation skips what the
/// certificates prove (Boolean_options::certified_operands), so a claim
/// nobody checked would make it certify what it did not test.
///
/// It may also carry each mesh's half-edge opposites (from the check or the
/// validation that certified it): the Boolean then does not build that
/// operand's topology again. The meshes are of doubles, or of an exact
/// kernel's points (an exact chain's, relgeo::csg's exact intermediates).
class Operand_certificate {
 public:
  Operand_certificate() = default;
  /// The certificate holds for operands `a` and `b` (the same objects).
  template <class P>
  bool covers(const Triangle_mesh<P>& a, const Triangle_mesh<P>& b) const {
    return a_ == &a && b_ == &b;
  }
  /// The half-edge opposites of operand m (0: a, 1: b) when the certificate
  /// carries them (entry 3 f + i: the half-edge across edge i of face f);
  /// nullptr otherwise.
  const std::vector<Index>* opposites(int m) const { return opposites_[m]; }

 private:
  friend class Valid_solid;
  template <IntersectionKernel_3 K>
  friend class internal::Csg_evaluator;
  template <ExactChainingKernel K>
  friend class internal::Exact_csg_evaluator;
  template <class P>
  Operand_certificate(const Triangle_mesh<P>* a, const Triangle_mesh<P>* b,
                      const std::vector<Index>* opposites_a = nullptr, const std::vector<Index>* opposites_b = nullptr)
      : a_(a), b_(b), opposites_{opposites_a, opposites_b} {}
  const void* a_ = nullptr;  // (identity only: the mesh objects certified)
  const void* b_ = nullptr;
  std::array<const std::vector<Index>*, 2> opposites_{};
};

/// Options of relgeo::boolean.
struct Boolean_options {
  /// Refuse operands that are not closed, oriented 2-manifolds with finite
  /// coordinates and no degenerate face (Invalid_operand, before any work).
  bool check_operands = true;
  /// Also refuse self-intersecting operands (an exact test on all face pairs
  /// of each operand through the bounding-volume hierarchy: the most
  /// expensive check; switch it off only for operands known to be clean).
  bool check_self_intersections = true;
  /// A kernel that names a Double_point_kernel (Exact_kernel: the filtered
  /// exact kernel, whose predicates answer the same exact signs on double
  /// input) runs the Boolean with it and converts the result's vertices to
  /// its own exact points. False: the kernel's own arithmetic throughout
  /// (Exact_kernel: GMP rationals everywhere, the reference path).
  bool use_double_point_kernel = true;
  /// How the new vertices become doubles. `repaired` (the default under a
  /// certified kernel): nearest doubles, then the crossings and degenerate
  /// faces that rounding made are repaired (repair_rounding,
  /// mesh/rounding_repair.h), so that the output is a valid solid whenever
  /// the exact result is one; Boolean_result::rounding reports it, and a
  /// repair that does not converge fails the Boolean (unless the output is
  /// not a closed manifold anyway: a symmetric difference, solids that touch
  /// along an edge; the validation says so). `nearest`: each new
  /// vertex its nearest doubles, nothing more. A kernel that is not certified
  /// always rounds to nearest (its result is not exact to begin with).
  Output_rounding rounding = Output_rounding::repaired;
  /// Options of the repair (its rounds and the largest change allowed).
  Rounding_repair_options repair{};
  /// Retriangulate each split face as a constrained Delaunay triangulation
  /// in its plane (Lawson's flips after the constraints; the flips' validity
  /// is exact, their choice approximate). False: the triangulation that the
  /// insertion order gives, with needles that rounding can turn over; kept
  /// for comparison (doc/boolean.md, "Retriangulation quality").
  bool delaunay_retriangulation = true;
  /// Validate the output mesh (validate_solid on its doubles, exact
  /// predicates whatever the kernel): Boolean_result::validation. Rounding
  /// to doubles can make an exact result touch or cross itself; the report
  /// says so and where.
  bool validate_output = true;
  /// Options of that validation (the exact volume string is off by default:
  /// it can be long).
  Solid_validation_options validation{.exact_volume_string = false};
  /// Set by the Boolean of two Valid_solids and by relgeo::csg
  /// (Operand_certificate): both operands are certified valid solids, these
  /// very objects. Then, as when this Boolean checks
  /// its operands itself (check_operands and check_self_intersections), the
  /// output's validation tests no pair of output faces that are, unchanged,
  /// faces of one operand: that operand's exact self-intersection test
  /// already decided them (Boolean_counts::unchanged_certified_faces).
  Operand_certificate certified_operands{};
  /// Threads for the operand checks, the broad and the narrow phase, the
  /// retriangulation (not under CGAL's lazy exact kernels, whose points
  /// compute their exact value when read) and the output's validation (unless
  /// `validation.threads` is set to another count than 1) (1: serial; 0:
  /// every hardware thread; more than one only when the target links
  /// relgeo::tbb, see mesh/internal/parallel.h). The result does not depend
  /// on it.
  int threads = 1;
};

/// An operand is not a valid solid boundary: which one ("A" or "B") and
/// every defect found, with where (mesh_errors.h).
class Invalid_operand : public Invalid_mesh {
 public:
  Invalid_operand(std::string operand, std::vector<Mesh_issue> issues)
      : Invalid_mesh("boolean: operand " + operand, std::move(issues)), operand_(std::move(operand)) {}
  const std::string& operand() const { return operand_; }

 private:
  std::string operand_;
};

/// Where an output face comes from: operand 0 (A) or 1 (B) and its face there.
struct Face_origin {
  std::uint8_t operand = 0;
  Index face = 0;
  friend bool operator==(const Face_origin&, const Face_origin&) = default;
};

/// Where an output vertex lies on an operand's input mesh: at one of its
/// vertices, inside one of its edges, inside one of its faces, or not on it.
/// Exact: read from the narrow phase's exact classification, not from
/// rounded coordinates.
struct Surface_location {
  enum class Kind : std::uint8_t { none, vertex, edge, face };
  Kind kind = Kind::none;
  /// vertex: {v, invalid}; edge: its two ends; face: the face's first two
  /// vertices (see `face`).
  std::array<Index, 2> vertices{invalid_index, invalid_index};
  /// face: the face; edge: a face containing the edge; vertex: invalid.
  Index face = invalid_index;
  friend bool operator==(const Surface_location&, const Surface_location&) = default;
};

/// Seconds spent in each phase.
struct Boolean_timing {
  double check = 0, broad_phase = 0, narrow_phase = 0, retriangulation = 0, labelling = 0, assembly = 0,
         rounding = 0, validation = 0;
  /// The Boolean itself: every phase but the output's validation.
  double total() const {
    return check + broad_phase + narrow_phase + retriangulation + labelling + assembly + rounding;
  }
};

/// How many of each thing the computation met.
struct Boolean_counts {
  std::size_t candidate_pairs = 0;     ///< face pairs whose boxes overlap
  std::size_t intersecting_pairs = 0;  ///< face pairs that intersect
  std::size_t coplanar_pairs = 0;      ///< of which coplanar overlaps
  std::size_t new_vertices = 0;        ///< intersection points that are not input vertices
  std::size_t split_faces = 0;         ///< input faces retriangulated
  std::size_t patches = 0;             ///< pieces labelled by one decision each
  std::size_t checked_operands = 0;    ///< operands checked first (0: check_operands off, or Valid_solid operands)
  /// Output faces that are, unchanged, faces of a certified operand (the
  /// same three points and vertices); the validation tests no pair of two
  /// of them from one operand (Boolean_options::certified_operands). 0 when
  /// the operands are not certified.
  std::size_t unchanged_certified_faces = 0;
};

/// The kernel-free part of a Boolean's result: the mesh in doubles and
/// everything measured about it (what the tool, reports and CSG steps keep).
struct Boolean_output {
  enum class Status : std::uint8_t { ok, failed };
  Status status = Status::ok;
  /// Why it failed (empty when ok): the phase and what could not be decided.
  std::string failure;
  /// Face pairs the kernel could not decide (fail-safe and interval kernels;
  /// no vertex is moved to decide them: doc/boolean.md, "The kernels").
  std::vector<std::pair<Index, Index>> undecided_pairs;
  /// The output mesh in doubles (each new vertex the nearest the kernel can
  /// give, or moved by the rounding repair: `rounding`), the intersection
  /// curves tagged as creases. Its vertices are the
  /// input vertices it keeps (exactly), then from `first_new_vertex` on the
  /// new ones (intersection points, rounded).
  Triangle_mesh<Point_3<double>> mesh;
  /// The index of the first new output vertex.
  Index first_new_vertex = 0;
  /// The largest error of a rounded output coordinate (0 when every vertex is
  /// an input vertex; infinite when the kernel cannot bound it); with the
  /// repaired rounding, it includes the repair's largest change.
  double rounding_error = 0;
  /// What the repair of the rounding found and did (all zero when the
  /// rounding is `nearest` or nothing needed repair).
  Rounding_repair_report rounding;
  /// Per output face: operand and input face.
  std::vector<Face_origin> provenance;
  /// Per output vertex: where it lies on A (index 0) and on B (index 1).
  std::vector<std::array<Surface_location, 2>> vertex_locations;
  Boolean_counts counts;
  Boolean_timing time;
  /// The validation report of `mesh` (Boolean_options::validate_output;
  /// empty kernel name when not run).
  Solid_report validation;
  /// The half-edge opposites of `mesh` (entry 3 f + i: the half-edge across
  /// edge i of face f) from its validation's topology, when the validation
  /// found a valid solid; empty otherwise. Valid_solid::of and relgeo::csg
  /// hand them to the next Boolean with the certificate, so that it does
  /// not build this mesh's topology again.
  std::vector<Index> halfedge_opposites;

  bool ok() const { return status == Status::ok; }
};

/// The result of relgeo::boolean under kernel K: the output, and its new
/// vertices as K's points.
template <IntersectionKernel_3 K>
struct Boolean_result : Boolean_output {
  /// The new output vertices as the kernel's points (exact under exact
  /// kernels): new_vertex_points[j] is output vertex first_new_vertex + j.
  std::vector<typename K::Implicit_point_3> new_vertex_points;

  /// Output vertex i as the kernel's point: exact under exact kernels (an
  /// input vertex is its own coordinates, a new one its implicit point).
  typename K::Implicit_point_3 exact_vertex(Index i) const {
    if (i >= first_new_vertex) return new_vertex_points[i - first_new_vertex];
    const Point_3<double>& v = mesh.vertices[i];
    // The kernels' constructions are stateless function objects.
    using Make_point = decltype(std::declval<const K&>().construct_point_3_object());
    using Make_implicit = decltype(std::declval<const K&>().construct_implicit_point_3_object());
    return Make_implicit{}(Make_point{}(v.x, v.y, v.z));
  }
  /// Every output vertex as the kernel's point (exact_vertex of each).
  std::vector<typename K::Implicit_point_3> exact_vertices() const {
    std::vector<typename K::Implicit_point_3> v;
    v.reserve(mesh.vertices.size());
    for (Index i = 0; i < mesh.vertices.size(); ++i) v.push_back(exact_vertex(i));
    return v;
  }
  /// The exact result as a mesh of K's points: the output's faces, vertex i
  /// exact_vertex(i). Under an exact kernel this is the operand of the next
  /// Boolean of an exact chain (relgeo::boolean on meshes of K's points).
  /// \throws Precondition_violation for a failed Boolean, and when the
  /// repair of the rounding flipped or collapsed edges: those faces are not
  /// the exact result's (Output_rounding::nearest keeps the exact faces).
  Triangle_mesh<typename K::Point_3> exact_mesh() const requires ExactChainingKernel<K> {
    if (!ok()) throw Precondition_violation("Boolean_result::exact_mesh: the Boolean failed (" + failure + ")");
    if (rounding.flips != 0 || rounding.collapses != 0)
      throw Precondition_violation(
          "Boolean_result::exact_mesh: the rounding repair changed faces (run with Output_rounding::nearest)");
    Triangle_mesh<typename K::Point_3> m;
    m.faces = mesh.faces;
    m.vertices.reserve(mesh.vertices.size());
    for (Index i = 0; i < mesh.vertices.size(); ++i) m.vertices.push_back(exact_vertex(i).point);
    return m;
  }
};

}  // namespace relgeo
