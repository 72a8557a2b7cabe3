// relgeo/boolean/subdivision_boolean_types.h — what a Boolean of two Loop
// subdivision solids takes and gives (thesis Sec. 5.3-5.4, SPEC Sec. 5b):
// the options, the certified validation of a subdivision solid, the sampled
// distances and the result.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/mesh/solid_validation.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo {

/// Options of validate_subdivision_solid.
struct Subdivision_validation_options {
  /// Most entries in each `where` list and in `undecided_pairs`.
  std::size_t max_listed = 100;
  /// A pair of far pieces no plane separates is split into its children
  /// (Loop refinement in interval arithmetic, so the children's hulls still
  /// enclose the exact surface) up to this many levels before it is
  /// reported undecided. Only undecided pairs are refined. Measured: two
  /// crossing Loop spheres are decided after 1 level; a creased cube minus a
  /// sphere (flat, coplanar far pieces) leaves 6 pairs after 2, none after 3.
  unsigned refinement_levels = 3;
  /// At most this many child pairs tested in all (pairs left when it runs
  /// out are undecided): thin features whose sides come close need many.
  /// Measured on CGAL's pinion.off (14K faces): 74 s without a limit.
  std::size_t refinement_budget = 2'000'000;
};

/// \brief The a-posteriori validation of a Loop subdivision solid (thesis
/// Sec. 5.4.2): its control mesh and whether its limit surface can have
/// intersections other than along common boundaries.
///
/// The limit surface over a control face lies in the convex hull of the
/// control points its limit depends on (the face's vertices and their
/// neighbours: Loop's masks, Hoppe's and BLZ's crease rules have no negative
/// weight). Two far pieces (their supports share no control point) are
/// certified disjoint when a plane separates those hulls, or when every
/// pair of their children (Loop refinement, up to
/// Subdivision_validation_options::refinement_levels) is; refinement and
/// projections run in interval arithmetic, so the answer holds for the exact
/// surface and does not depend on the caller's rounding mode. Neighbouring
/// pieces (supports sharing a control point: faces within two rings) meet
/// along common boundaries or come close: a pair is certified to meet only
/// where its faces meet when the limit surface over the influence region of
/// a shared control point (the faces whose limit depends on it) is certified
/// one to one, from the quartic Bezier nets of its patches (where the
/// thesis, Sec. 5.4.2, puts its Bezier criteria; method and argument in
/// boolean/internal/limit_embedding.h).
/// That needs regular patches: regions around an extraordinary vertex or an
/// irregular crease vertex stay undecided, and so do the pairs and pieces no
/// certified region holds (listed in `adjacent_pieces`). A report is
/// therefore never "valid" by omission: is_certified() requires every check
/// to pass.
struct Subdivision_validation {
  std::size_t vertices = 0, faces = 0;
  Solid_check closed;                 ///< boundary_edge
  Solid_check edge_manifold;          ///< non_manifold_edge
  Solid_check vertex_manifold;        ///< non_manifold_vertex
  Solid_check consistently_oriented;  ///< inconsistent_orientation
  /// Crease tags are edges of the mesh, corner tags are vertices, and no
  /// face has two edges in common with another (Loop's rules need that).
  Solid_check valid_tags;
  /// Far pieces whose supports' boxes meet: each pair certified disjoint
  /// (pass) or listed as undecided.
  Solid_check separated_pieces;
  /// Neighbouring pieces and each piece on its own (see the class comment):
  /// pass when all are certified, else undecided with their number and the
  /// first max_listed as `undecided` issues: (f, g) a pair, (f) a piece.
  Solid_check adjacent_pieces;
  /// Face pairs the separation test looked at, and how they ended.
  std::size_t candidate_pairs = 0, separated_pairs = 0, adjacent_pairs = 0;
  /// Neighbouring pairs certified to meet only where their faces meet, and
  /// influence regions (one per control vertex) certified one to one.
  std::size_t certified_adjacent_pairs = 0, certified_regions = 0;
  /// The first max_listed undecided pairs (control faces).
  std::vector<std::pair<Index, Index>> undecided_pairs;

  template <class F>
  void for_each_check(F&& f) const {
    f("closed", closed), f("edge_manifold", edge_manifold), f("vertex_manifold", vertex_manifold);
    f("consistently_oriented", consistently_oriented), f("valid_tags", valid_tags);
    f("separated_pieces", separated_pieces), f("adjacent_pieces", adjacent_pieces);
  }
  /// Every check passed.
  bool is_certified() const {
    bool ok = true;
    for_each_check([&](const char*, const Solid_check& c) { ok = ok && c.passed(); });
    return ok;
  }
  /// No check failed (some may be undecided or not checked).
  bool has_no_defect() const {
    bool ok = true;
    for_each_check([&](const char*, const Solid_check& c) { ok = ok && c.status != Check_status::fail; });
    return ok;
  }
  /// One line: each check that did not pass, with its status and count.
  std::string summary() const {
    std::string s;
    for_each_check([&](const char* name, const Solid_check& c) {
      if (c.passed()) return;
      s += (s.empty() ? "" : ", ") + std::string(name) + " " + std::string(to_string(c.status));
      if (c.count) s += " (" + std::to_string(c.count) + ")";
    });
    return s.empty() ? "certified" : s;
  }
};

/// Sampled distance between the limit surface of a subdivision result and
/// the polyhedral result (doubles; a measurement, not a bound).
struct Surface_distance {
  /// Largest distance from a sample of the limit surface to the polyhedral
  /// mesh (exact limit evaluation at `samples` points).
  double limit_to_polyhedral = std::numeric_limits<double>::quiet_NaN();
  /// Largest distance from a vertex or face centre of the polyhedral mesh to
  /// the limit surface, measured to the result's limit mesh two levels finer.
  double polyhedral_to_limit = std::numeric_limits<double>::quiet_NaN();
  /// Mean of the first direction's distances.
  double mean = std::numeric_limits<double>::quiet_NaN();
  std::size_t samples = 0;
  /// The symmetric (sampled Hausdorff) distance.
  double hausdorff() const { return std::max(limit_to_polyhedral, polyhedral_to_limit); }
  bool measured() const { return samples > 0; }
};

/// Options of relgeo::subdivision_boolean.
struct Subdivision_boolean_options {
  /// Options of the polyhedral Boolean (operand checks, output validation).
  Boolean_options mesh{};
  /// Loop's rules, for both operands and for the result.
  Loop_options loop{};
  /// Fit the control points near the curves (thesis eq. 5.4) and keep the
  /// fitted mesh when its distance to the polyhedral result is smaller.
  bool fit = false;
  /// Rings of control vertices around the curves that the fitting moves
  /// (0: the curve vertices only; on two Loop spheres at levels 1-3 that
  /// gained 16-22% and one ring lost up to 2.5x: test/boolean).
  unsigned fit_rings = 0;
  /// Weight of the pull towards the unfitted positions (keeps the least
  /// squares problem well posed; relative to the limit equations' weight 1).
  double fit_regularisation = 1e-3;
  /// Measure the distances (subdivisions per face edge of the sample grid:
  /// (n + 1)(n + 2) / 2 samples per face; 0 turns the measurement off).
  unsigned distance_samples = 2;
  /// Validate the result (validate_subdivision_solid).
  bool validate = true;
  Subdivision_validation_options validation{};
};

/// Seconds per phase of a subdivision Boolean.
struct Subdivision_boolean_timing {
  double limit_meshes = 0;  ///< refinement and limit meshes of both operands
  double boolean = 0;       ///< the polyhedral Boolean (its own phases: polyhedral.time)
  double mapping = 0;       ///< curves to the control meshes, merging, tagging
  double fitting = 0, distance = 0, validation = 0;
  /// The subdivision layer: mapping, cutting, merging and tagging (fitting,
  /// distances and validation excluded).
  double layer() const { return mapping; }
  double total() const { return limit_meshes + boolean + mapping + fitting + distance + validation; }
};

/// Counts of the mapping (thesis Sec. 5.3).
struct Subdivision_boolean_counts {
  std::size_t curve_vertices = 0, curve_edges = 0;
  /// Level-k control faces the curves cross badly (thesis: more than twice,
  /// twice through one edge, or not through the boundary at all), per operand.
  std::size_t bad_faces[2] = {0, 0};
  /// Control vertices the fitting moved.
  std::size_t fitted_vertices = 0;
};

/// The kernel-free part of relgeo::subdivision_boolean's result: all of it
/// but the polyhedral Boolean, whose vertices are K's points.
struct Subdivision_boolean_output {
  enum class Status : std::uint8_t { ok, failed };
  Status status = Status::ok;
  /// Why it failed (empty when ok).
  std::string failure;
  unsigned level = 0;
  /// The subdivision result: a Loop control mesh, the intersection curves and
  /// the operands' own creases tagged (fitted when options.fit and better).
  Triangle_mesh<Point_3<double>> control;
  /// The control mesh before fitting (equal to `control` without fitting).
  Triangle_mesh<Point_3<double>> unfitted;
  /// Whether `control` is the fitted mesh.
  bool fitted = false;
  /// Vertices of `control` on the intersection curves (sorted).
  std::vector<Index> curve_vertices;
  /// distance.subdivision_to_polyhedral (and _fitted when options.fit).
  Surface_distance distance_to_polyhedral, distance_to_polyhedral_fitted;
  Subdivision_validation validation;
  Subdivision_boolean_counts counts;
  Subdivision_boolean_timing time;

  bool ok() const { return status == Status::ok; }
};

/// The result of relgeo::subdivision_boolean under kernel K.
template <IntersectionKernel_3 K>
struct Subdivision_boolean_result : Subdivision_boolean_output {
  /// The Boolean of the two limit meshes at `level` (the polyhedral result).
  Boolean_result<K> polyhedral;
};

}  // namespace relgeo
