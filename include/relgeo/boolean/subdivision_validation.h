// relgeo/boolean/subdivision_validation.h — a-posteriori validation of a
// Loop subdivision solid (thesis Sec. 5.4.2): its control mesh is a closed,
// oriented 2-manifold with consistent tags, and pieces of its limit surface
// that should be disjoint are certified disjoint (see Subdivision_validation
// for what is and is not certified).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/boolean/internal/limit_embedding.h"
#include "relgeo/boolean/subdivision_boolean_types.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/interval.h"
#include "relgeo/kernel/interval_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/vector_3.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/solid_validation.h"
#include "relgeo/subdivision/loop_features.h"
#include "relgeo/subdivision/loop_subdivision.h"

namespace relgeo {
namespace internal {

inline bool share_a_point(const std::vector<Index>& a, const std::vector<Index>& b) {
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i] == b[j]) return true;
    a[i] < b[j] ? ++i : ++j;
  }
  return false;
}

using Interval_point = Point_3<Interval>;

// Whether a plane normal to `axis` separates the hulls of the two point
// sets: each projection is an interval enclosing the exact one, so a
// reported separation holds for the exact hulls.
inline bool separated_along(const std::array<double, 3>& axis, std::span<const Index> a, std::span<const Index> b,
                            const std::vector<Interval_point>& p) {
  const auto range = [&](std::span<const Index> s) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (Index v : s) {
      const Interval d = Interval(axis[0]) * p[v].x + Interval(axis[1]) * p[v].y + Interval(axis[2]) * p[v].z;
      if (d.has_nan()) return std::pair{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
      lo = std::min(lo, d.inf()), hi = std::max(hi, d.sup());
    }
    return std::pair{lo, hi};
  };
  const auto [alo, ahi] = range(a);
  const auto [blo, bhi] = range(b);
  return ahi < blo || bhi < alo;
}

inline std::array<double, 3> midpoint(const Interval_point& p) {
  return {(p.x.inf() + p.x.sup()) / 2, (p.y.inf() + p.y.sup()) / 2, (p.z.inf() + p.z.sup()) / 2};
}

// Whether a plane separates the hulls of two point sets. The direction is
// searched in double by Gilbert's algorithm (Frank-Wolfe on the distance
// from the origin to the hull of the differences b - a: each step takes the
// difference least along the current direction, then the closest point of
// the segment to it); any direction that separates the midpoints is then
// certified by separated_along in interval arithmetic (the search itself
// needs no care: a bad direction only fails to certify).
inline bool separated(std::span<const Index> a, std::span<const Index> b, const std::vector<Interval_point>& p) {
  using V = std::array<double, 3>;
  using internal::dot;
  const auto extreme = [&](std::span<const Index> s, const V& dir, bool largest) {
    V best = midpoint(p[s[0]]);
    double value = dot(dir, best);
    for (Index i : s) {
      const V m = midpoint(p[i]);
      const double x = dot(dir, m);
      if (largest ? x > value : x < value) best = m, value = x;
    }
    return best;
  };
  V ca{0, 0, 0}, cb{0, 0, 0};
  for (Index i : a) {
    const V m = midpoint(p[i]);
    ca = {ca[0] + m[0], ca[1] + m[1], ca[2] + m[2]};
  }
  for (Index i : b) {
    const V m = midpoint(p[i]);
    cb = {cb[0] + m[0], cb[1] + m[1], cb[2] + m[2]};
  }
  const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
  V x{cb[0] / nb - ca[0] / na, cb[1] / nb - ca[1] / na, cb[2] / nb - ca[2] / na};
  for (int step = 0; step < 48; ++step) {
    const double xx = dot(x, x);
    if (!(xx > 0) || !std::isfinite(xx)) return false;  // the hulls (nearly) meet
    // The difference least along x: the lowest b minus the highest a.
    const V lo_b = extreme(b, x, false), hi_a = extreme(a, x, true);
    const V s{lo_b[0] - hi_a[0], lo_b[1] - hi_a[1], lo_b[2] - hi_a[2]};
    if (dot(x, s) > 0) return separated_along(x, a, b, p);  // every difference is above 0 along x
    const V d{x[0] - s[0], x[1] - s[1], x[2] - s[2]};
    const double dd = dot(d, d);
    if (!(dd > 0)) return false;
    const double t = std::clamp(dot(x, d) / dd, 0.0, 1.0);
    x = {x[0] - t * d[0], x[1] - t * d[1], x[2] - t * d[2]};
  }
  return false;
}

// The control mesh and its Loop refinements in interval arithmetic, built
// on demand, with the supports of the faces asked about.
class Refinement_ladder {
 public:
  Refinement_ladder(const Triangle_mesh<Point_3<double>>& control, const Mesh_topology& t, const Loop_options& loop,
                    std::size_t budget)
      : loop_(loop), budget_(budget) {
    Level l;
    l.mesh.faces = control.faces;
    l.mesh.tags = control.tags;
    for (const auto& v : control.vertices) l.mesh.vertices.push_back({Interval(v.x), Interval(v.y), Interval(v.z)});
    l.topology = t;
    levels_.push_back(std::move(l));
  }

  // Pieces f and g of level l (faces without a common vertex) are
  // disjoint: their supports are disjoint and a plane separates their
  // hulls, or every pair of their children is disjoint (children of faces
  // without a common vertex have none either, and their ring distance
  // doubles per level).
  bool disjoint(unsigned l, Index f, Index g, unsigned max_level) {
    if (l > 0 && !spend()) return false;  // refinement's tests count against the budget
    const std::vector<Index>&a = support(l, f), &b = support(l, g);
    const Level& lv = levels_[l];
    if (!share_a_point(a, b) && separated(a, b, lv.mesh.vertices)) return true;
    if (l >= max_level || !refine_to(l + 1)) return false;
    for (Index i = 0; i < 4; ++i)
      for (Index j = 0; j < 4; ++j)
        if (!disjoint(l + 1, 4 * f + i, 4 * g + j, max_level)) return false;
    return true;
  }
  const Loop_options& options() const { return loop_; }
  const std::vector<Index>& support(unsigned l, Index f) {
    Level& lv = levels_[l];
    if (lv.support.empty()) lv.support.resize(lv.mesh.faces.size());
    std::vector<Index>& s = lv.support[f];
    if (s.empty()) {
      for (Index v : lv.mesh.faces[f]) {
        s.push_back(v);
        for (Index w : lv.topology.vertex_ring(v)) s.push_back(w);
      }
      std::sort(s.begin(), s.end());
      s.erase(std::unique(s.begin(), s.end()), s.end());
    }
    return s;
  }

  /// The control mesh of level l (refined in interval arithmetic).
  const Triangle_mesh<Interval_point>& mesh(unsigned l) const { return levels_[l].mesh; }
  /// Takes one pair test from the budget; false when it is spent.
  bool spend() {
    if (budget_ == 0) return false;
    --budget_;
    return true;
  }
  /// Refines up to level l (false when the intervals overflow).
  bool refine_to(unsigned l) {
    while (levels_.size() <= l) {
      Level next;
      try {
        next.mesh = Loop_subdivider<Interval_kernel>(loop_).refine(levels_.back().mesh, 1);
      } catch (const Error&) {  // intervals overflowing: nothing finer to learn
        return false;
      }
      next.topology = Mesh_topology::refined(levels_.back().topology, next.mesh.faces);
      levels_.push_back(std::move(next));
    }
    return true;
  }

 private:
  struct Level {
    Triangle_mesh<Interval_point> mesh;
    Mesh_topology topology;
    std::vector<std::vector<Index>> support;
  };
  Loop_options loop_;
  std::size_t budget_;  // pair tests left
  std::vector<Level> levels_;
};

// The adjacent_pieces check. A pair of neighbouring pieces (supports sharing
// a control point) is certified when the limit surface over the influence
// region of a shared control point is certified one to one
// (internal/limit_embedding.h), a piece on its own when one of the regions
// holding it is. A pair or piece left over is refined (Loop, in interval
// arithmetic, up to refinement_levels): it is certified when all pairs of
// its children are, near ones by regions of the finer level, far ones by
// separation (their limit is the same surface). The rest is undecided.
class Adjacent_piece_check {
 public:
  Adjacent_piece_check(Refinement_ladder& ladder, unsigned max_level) : ladder_(ladder), max_level_(max_level) {}

  // Pieces f and g (f == g: the piece alone) of level l.
  bool certified(unsigned l, Index f, Index g) {
    const std::vector<Index>&a = ladder_.support(l, f), &b = ladder_.support(l, g);
    if (f != g && !share_a_point(a, b)) return ladder_.disjoint(l, f, g, max_level_);
    Limit_embedding* e = embedding(l);
    if (!e) return false;
    bool worth_refining = false;
    for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
      if (a[i] != b[j]) {
        a[i] < b[j] ? ++i : ++j;
        continue;
      }
      const Region_verdict v = e->region(a[i]);
      if (v == Region_verdict::embedded) return true;
      // Refinement leaves an irregular patch irregular next to its vertex;
      // other failures (a coarse or curved region) may go away.
      worth_refining = worth_refining || v != Region_verdict::irregular_patch;
      ++i, ++j;
    }
    if (!worth_refining || l >= max_level_ || !ladder_.refine_to(l + 1)) return false;
    for (Index i = 0; i < 4; ++i)
      for (Index j = f == g ? i : 0; j < 4; ++j)
        if (!ladder_.spend() || !certified(l + 1, 4 * f + i, 4 * g + j)) return false;
    return true;
  }
  // Counts of the verdicts on the regions of level 0 (Region_verdict order).
  std::array<std::size_t, 5> verdicts_at_control_level() const {
    std::array<std::size_t, 5> n{};
    if (!levels_.empty() && levels_[0])
      for (const auto& v : levels_[0]->embedding.verdicts())
        if (v) ++n[static_cast<std::size_t>(*v)];
    return n;
  }
  // Why level 0's limit surface could not be set up (empty if it could).
  const std::string& failure() const { return failure_; }

 private:
  struct Level {
    Loop_limit_surface<Interval_kernel> surface;
    Limit_embedding embedding;
    Level(const Triangle_mesh<Interval_point>& m, const Loop_options& o) : surface(m, o), embedding(surface) {}
  };
  Limit_embedding* embedding(unsigned l) {
    if (levels_.size() <= l) levels_.resize(l + 1);
    if (!levels_[l] && !tried_[l]) {
      tried_[l] = true;
      try {
        levels_[l] = std::make_unique<Level>(ladder_.mesh(l), ladder_.options());
      } catch (const Error& x) {
        if (l == 0) failure_ = x.what();
      }
    }
    return levels_[l] ? &levels_[l]->embedding : nullptr;
  }
  Refinement_ladder& ladder_;
  unsigned max_level_;
  std::vector<std::unique_ptr<Level>> levels_;
  std::array<bool, 64> tried_{};
  std::string failure_;
};

inline void check_adjacent_pieces(Refinement_ladder& ladder, const std::vector<std::pair<Index, Index>>& near,
                                  Index faces, const Subdivision_validation_options& options,
                                  Subdivision_validation& r) {
  Adjacent_piece_check check(ladder, std::min(options.refinement_levels, 63u));
  Solid_check& c = r.adjacent_pieces;
  c = Solid_check{};
  std::size_t pairs_left = 0, pieces_left = 0;
  for (const auto& [f, g] : near)
    if (!check.certified(0, f, g)) ++pairs_left, record(c, {Mesh_defect::undecided, {f, g}}, options.max_listed);
  for (Index f = 0; f < faces; ++f)
    if (!check.certified(0, f, f)) ++pieces_left, record(c, {Mesh_defect::undecided, {f, invalid_index}}, options.max_listed);
  if (!check.failure().empty()) {
    not_checked(c, "the limit surface cannot be set up: " + check.failure());
    return;
  }
  conclude(c, true);
  const std::array<std::size_t, 5> v = check.verdicts_at_control_level();
  r.certified_regions = v[0];
  r.certified_adjacent_pairs = near.size() - pairs_left;
  c.note = std::to_string(near.size() - pairs_left) + " of " + std::to_string(near.size()) + " neighbouring pairs and " +
           std::to_string(faces - pieces_left) + " of " + std::to_string(faces) +
           " pieces certified one to one (influence regions of control points: " + std::to_string(v[0]) +
           " certified; not certified: " + std::to_string(v[1]) + " with an irregular patch, " + std::to_string(v[2]) +
           " not a disc, " + std::to_string(v[3]) + " Jacobian sign, " + std::to_string(v[4]) +
           " boundary not star-shaped; refining up to " + std::to_string(options.refinement_levels) + " levels)";
}

}  // namespace internal

/// \brief Validates a Loop subdivision solid given by its control mesh and
/// crease/corner tags (see Subdivision_validation for what each check
/// certifies). Never throws for bad input: every defect is reported.
/// Complexity O(n log n + k) for n faces and k pairs of overlapping support
/// boxes (each pair O(support size)).
inline Subdivision_validation validate_subdivision_solid(const Triangle_mesh<Point_3<double>>& control,
                                                         const Loop_options& loop = {},
                                                         const Subdivision_validation_options& options = {}) {
  const Default_fp_environment environment;  // interval refinement relies on the default environment
  Subdivision_validation r;
  r.vertices = control.vertices.size(), r.faces = control.faces.size();
  Solid_validation_options so{.check_self_intersections = false, .check_orientation = false,
                              .exact_volume_string = false, .max_listed = options.max_listed};
  const Solid_report s = validate_solid<Filtered_exact_kernel>(control, so);
  r.closed = s.closed, r.edge_manifold = s.edge_manifold, r.vertex_manifold = s.vertex_manifold;
  r.consistently_oriented = s.consistently_oriented, r.valid_tags = s.valid_tags;
  const bool usable = s.valid_indices.passed() && s.finite_coordinates.passed() && r.closed.passed() &&
                      r.edge_manifold.passed() && r.vertex_manifold.passed() && r.consistently_oriented.passed() &&
                      r.valid_tags.passed();
  if (!usable) {
    internal::not_checked(r.separated_pieces, "needs a closed, oriented, manifold control mesh with valid tags");
    r.adjacent_pieces = r.separated_pieces;
    return r;
  }
  const Mesh_topology t = Mesh_topology::build(control);
  try {
    require_no_faces_sharing_two_edges(t, "subdivision solid");
  } catch (const Invalid_input& e) {
    internal::record(r.valid_tags, {Mesh_defect::invalid_tag, {invalid_index, invalid_index}}, options.max_listed);
    r.valid_tags.status = Check_status::fail;
    r.valid_tags.note = e.what();
    internal::not_checked(r.separated_pieces, "Loop's rules do not apply to this control mesh");
    r.adjacent_pieces = r.separated_pieces;
    return r;
  }
  if (loop.crease_rules != Loop_crease_rules::hoppe && loop.crease_rules != Loop_crease_rules::biermann_levin_zorin) {
    internal::not_checked(r.separated_pieces, "unknown crease rules");
    r.adjacent_pieces = r.separated_pieces;
    return r;
  }
  internal::Refinement_ladder ladder(control, t, loop, options.refinement_budget);
  std::vector<Box_3> boxes(control.faces.size());
  for (Index f = 0; f < boxes.size(); ++f)
    for (Index v : ladder.support(0, f)) boxes[f].extend(control.vertices[v].x, control.vertices[v].y, control.vertices[v].z);
  const Face_bvh bvh(boxes);
  std::vector<std::pair<Index, Index>> far, near;
  bvh.for_each_overlapping_pair([&](Index f, Index g) {
    ++r.candidate_pairs;
    (internal::share_a_point(ladder.support(0, f), ladder.support(0, g)) ? near : far)
        .emplace_back(std::min(f, g), std::max(f, g));
  });
  r.adjacent_pairs = near.size();
  // Iterative deepening: every far pair at the control level, those left at
  // one level of refinement, and so on, so that the budget goes to the
  // hardest pairs last.
  for (unsigned level = 0; level <= options.refinement_levels && !far.empty(); ++level) {
    std::vector<std::pair<Index, Index>> left;
    for (const auto& p : far)
      if (ladder.disjoint(0, p.first, p.second, level)) ++r.separated_pairs;
      else left.push_back(p);
    far = std::move(left);
  }
  const std::size_t undecided = far.size();
  for (const auto& [f, g] : far) {
    if (r.undecided_pairs.size() < options.max_listed) r.undecided_pairs.emplace_back(f, g);
    internal::record(r.separated_pieces, {Mesh_defect::undecided, {f, g}}, options.max_listed);
  }
  internal::conclude(r.separated_pieces, undecided > 0);
  r.separated_pieces.note = std::to_string(r.separated_pairs) + " pairs separated by planes (refining up to " +
                            std::to_string(options.refinement_levels) + " levels), " + std::to_string(undecided) +
                            " undecided";
  internal::check_adjacent_pieces(ladder, near, static_cast<Index>(control.faces.size()), options, r);
  return r;
}

}  // namespace relgeo
