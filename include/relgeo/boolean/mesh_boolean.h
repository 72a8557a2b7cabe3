// relgeo/boolean/mesh_boolean.h — Booleans of two closed triangle meshes,
// exact under exact kernels, the same code under every kernel (thesis Ch. 5,
// SPEC Sec. 5a).
//
// The phases (Boolean_timing names them):
//  1. check     operands are closed, oriented 2-manifolds with finite
//               coordinates, no degenerate face and no self-intersection
//               (their half-edge opposites and face hierarchies are kept
//               for later; the rest is freed);
//  2. broad     face pairs whose boxes overlap (the operands' Face_bvh
//               hierarchies searched against each other);
//  3. narrow    each pair intersected exactly (intersect_triangles): new
//               vertices are implicit points, and the same point reached from
//               several pairs becomes one vertex (by the two cells it joins,
//               then sorted by compare_xyz);
//  4. retriangulation  each face that meets the other operand is
//               triangulated in its plane with those points and the
//               intersection segments as constraints (face_triangulation.h);
//  5. labelling every piece is inside, outside or on the other operand, one
//               decision per patch between curves (labelling.h);
//  6. assembly  the pieces the operation keeps, those of B flipped for a
//               difference, coplanar overlaps kept once, vertices rounded to
//               doubles with the kernel's stated error;
//  7. validation  validate_solid on the output's doubles (exact tests);
//  8. rounding  what the rounding broke (crossings, degenerate faces: the
//               validation finds them, or the repair itself without it) is
//               repaired by local changes decided exactly
//               (mesh/rounding_repair.h), and the output validated again.
// Degenerate input is the normal case: shared vertices and edges, touching,
// coplanar overlapping faces, identical operands are decided exactly under
// exact kernels, and the result is regularised (coplanar pieces of opposite
// orientation, and duplicate ones, are not both kept).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/boolean/compiled.h"
#include "relgeo/boolean/internal/face_triangulation.h"
#include "relgeo/boolean/internal/labelling.h"
#include "relgeo/boolean/internal/point_table.h"
#include "relgeo/core/certified_sort.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/core/internal/union_find.h"
#include "relgeo/core/rounding.h"
#include "relgeo/intersection/triangle_intersection.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/kernel_for_number.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/internal/diagonal_separation.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/rounding_repair.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_validation.h"
#include "relgeo/mesh/validity.h"

namespace relgeo {
namespace internal {

// OP: the operands' point type, doubles or (exact_operands: an exact chain)
// K's own exact points.
template <IntersectionKernel_3 K, class OP = Point_3<double>>
class Boolean_engine {
 public:
  using P = typename K::Point_3;
  using IP = typename K::Implicit_point_3;
  using Mesh = Triangle_mesh<OP>;
  using Result = Boolean_result<K>;
  static constexpr bool exact_operands = !std::same_as<OP, Point_3<double>>;

  Boolean_engine(const Mesh& a, const Mesh& b, Boolean_operation op, const K& k, const Boolean_options& o)
      : mesh_{&a, &b}, op_(op), k_(k), options_(o), points_(k, mesh_) {}

  Result run() {
    // A certified kernel's Boolean is the same in every floating-point
    // environment: its predicates and the face hierarchy hold their own
    // scopes, and this one covers the engine's own double arithmetic (the
    // projection axes and rays it chooses). A naive kernel computes in the
    // caller's environment.
    const Default_fp_environment_if<K::is_certified> environment;
    Result r;
    Stopwatch clock;
    if (options_.check_operands) {
      check_operand(0, "A");
      check_operand(1, "B");
      r.counts.checked_operands = 2;
    }
    r.time.check = clock.lap();
    number_points();
    std::vector<Face_pair> pairs = broad_phase(r.counts.candidate_pairs);
    r.time.broad_phase = clock.lap();
    if (!narrow_phase(pairs, r)) return finish_failed(r, clock, &Boolean_timing::narrow_phase);
    // The validation tests again those of these pairs whose faces are kept whole.
    if (options_.validate_output && operands_certified()) candidate_pairs_ = std::move(pairs);
    r.time.narrow_phase = clock.lap();
    if (!retriangulate(r)) return finish_failed(r, clock, &Boolean_timing::retriangulation);
    r.time.retriangulation = clock.lap();
    if (!label(r)) return finish_failed(r, clock, &Boolean_timing::labelling);
    for (auto& o : opposite_) std::vector<Index>().swap(o);
    r.time.labelling = clock.lap();
    assemble(r);
    release_arrangement();  // the output holds what the later phases need (peak memory)
    r.time.assembly = clock.lap();
    // The validation, when asked for, tells whether the rounding broke
    // anything (most outputs: no): only then does the repair look for it.
    if (options_.validate_output) validate(r);
    r.time.validation = clock.lap();
    // (Exact operands: the validation is the exact result's, which says
    // nothing of what rounding did; the repair looks for it itself.)
    const bool repair = K::is_certified && options_.rounding == Output_rounding::repaired;
    const bool kept = !exact_operands && options_.validate_output && rounding_kept_validity(r.validation);
    if (repair && !kept) {
      repair_rounding_of(r);
      r.time.rounding = clock.lap();
      if (!exact_operands && options_.validate_output && r.rounding.rounds > 0) {
        validate(r);
        r.time.validation += clock.lap();
      }
      // A repair that did not converge fails the Boolean, unless the output
      // is not a closed manifold anyway (a symmetric difference, solids that
      // touch): then the validation says what is wrong, as with nearest
      // rounding, and `rounding` what is left.
      if (!r.rounding.converged() && !(options_.validate_output && !closed_manifold(r.validation)))
        fail_rounding(r);
    }
    return r;
  }

 private:
  Result& finish_failed(Result& r, Stopwatch& clock, double Boolean_timing::*phase) {
    r.status = Result::Status::failed;
    r.time.*phase = clock.lap();
    return r;
  }

  // ---- 1. operands ------------------------------------------------------------

  // The operands' validity is decided exactly, whatever kernel the Boolean
  // itself runs under: double meshes by the filtered kernel, an exact
  // chain's meshes of K's exact points by K. The output in doubles is
  // validated by the filtered kernel.
  using Check_kernel = Filtered_exact_kernel;
  using Operand_check_kernel = std::conditional_t<exact_operands, K, Check_kernel>;

  // The checks build the operand's topology and (with the self-intersection
  // test) its face hierarchy. The later phases reuse the half-edge opposites
  // and the hierarchy; the rest of the topology (four fifths of it) is freed
  // before the operand's hierarchy is built (check_solid): the peak memory
  // is one topology or the two hierarchies, never a topology and two
  // hierarchies.
  void check_operand(int m, const char* name) {
    // check_solid adds the exact self-intersection test (Face_bvh pairs,
    // pairs sharing a vertex or an edge allowed exactly that) to check_mesh.
    internal::Checked_mesh checked;
    Mesh_report report;
    if (options_.check_self_intersections) {
      report = internal::check_solid<Operand_check_kernel>(*mesh_[m], {}, checked, options_.threads);
    } else {
      Mesh_topology topology;
      report = internal::check_mesh<Operand_check_kernel>(*mesh_[m], {}, topology);
      checked.opposites = std::move(topology).take_opposites();
    }
    if (!report.is_valid()) throw Invalid_operand(name, std::move(report.issues));
    opposite_[m] = std::move(checked.opposites);
    bvh_[m] = std::move(checked.bvh);
  }

  // ---- broad phase ------------------------------------------------------------

  // The pairs (face of A, face of B) whose boxes overlap: the two operands'
  // hierarchies, those the checks built or built here, searched against
  // each other. The pairs, whose order numbers the new points, come sorted
  // by (face of A, face of B): the Boolean does not depend on how the
  // hierarchies were built (the checks' are clustered by patch, the others
  // not), nor on whether the checks ran. On the armadillo against a 20K
  // sphere 0.7 ms against 4.2 with the checks (doc/boolean.md, "The broad
  // phase from the checks' hierarchies").
  // The pairs of faces whose boxes overlap (their number: box_pairs), less
  // those a diagonal direction separates (internal/diagonal_separation.h:
  // most of a gear's pairs), in the order of A's faces.
  std::vector<Face_pair> broad_phase(std::size_t& box_pairs) {
    for (int m = 0; m < 2; ++m)
      if (!bvh_[m]) bvh_[m].emplace(*mesh_[m], Face_bvh_options{.threads = options_.threads});
    std::vector<Face_pair> pairs = bvh_[0]->sorted_overlapping_pairs(*bvh_[1], options_.threads);
    for (auto& h : bvh_) h.reset();  // each phase frees what no later one needs (peak memory)
    box_pairs = pairs.size();
    if constexpr (!exact_operands) {
      // A's faces come in order: each one's extents once, B's when first met.
      internal::Lazy_diagonal_extents b_extents(mesh_[1]->vertices, mesh_[1]->faces);
      Index a_face = invalid_index;
      internal::Diagonal_extents a_extents;
      std::erase_if(pairs, [&](const Face_pair& p) {
        if (p.first != a_face)
          a_face = p.first, a_extents = internal::diagonal_extents(mesh_[0]->vertices, mesh_[0]->faces[a_face]);
        return internal::diagonally_separated(a_extents, b_extents[p.second]);
      });
    }
    return pairs;
  }

  // ---- points -----------------------------------------------------------------

  std::array<P, 3> triangle(const Mesh& m, Index f) const {
    const Triangle& t = m.faces[f];
    if constexpr (exact_operands) {
      return {m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    } else {
      const auto p = k_.construct_point_3_object();
      std::array<P, 3> corners;
      for (int i = 0; i < 3; ++i) {
        const Point_3<double>& v = m.vertices[t[i]];
        corners[i] = p(v.x, v.y, v.z);
      }
      return corners;
    }
  }
  // Vertex v of operand m in doubles: itself, or an exact point's
  // approximation (for choices that any answer keeps correct).
  Point_3<double> vertex_in_doubles(int m, Index v) const {
    if constexpr (exact_operands)
      return points_.approximation(offset_[m] + v).point;
    else
      return mesh_[m]->vertices[v];
  }

  // Global points: A's vertices, then B's, then the new ones (points_ makes
  // an input vertex the kernel's point when a phase first reads it).
  void number_points() {
    offset_[0] = 0;
    offset_[1] = static_cast<Index>(mesh_[0]->vertices.size());
    equal_points_ = Union_find<Index>(points_.size());
  }
  // Equal points are one set; the smaller index (an input vertex first) represents it.
  Index find(Index x) { return equal_points_.find(x); }
  void unite(Index x, Index y) { equal_points_.unite(x, y); }

  // ---- 3. narrow phase ---------------------------------------------------------

  // One point of one pair's intersection: its temporary index and where it
  // lies on face fa of A and face fb of B.
  struct Located_point {
    Index point;
    Index face[2];
    Triangle_location where[2];
  };

  // One pair's intersection when it is not disjoint (or a face is degenerate).
  struct Met_pair {
    std::size_t pair;
    Triangle_intersection<K> x;
    bool degenerate_input;
  };

  bool narrow_phase(const std::vector<Face_pair>& pairs, Result& r) {
    // No fail-safe perturbation (thesis eq. 5.3) here: a vertex moved for one
    // pair and not for the others would make an arrangement of no operand at
    // all (doc/boolean.md, "The kernels").
    const Triangle_intersection_options no_perturbation{.perturb_ambiguous_vertices = false};
    if (internal::thread_count(options_.threads) <= 1) {
      // Each pair registered as soon as it is intersected (holding the
      // intersections, as the threads must, cost a tenth of the phase).
      internal::Triangle_intersector<K> intersector(k_, no_perturbation);
      for (const Face_pair& pair : pairs) {
        const Triangle_intersection<K> x =
            intersector.run(triangle(*mesh_[0], pair.first), triangle(*mesh_[1], pair.second));
        if (!register_intersection(pair, x, intersector.degenerate_input(), r)) return false;
      }
    } else {
      // Each pair's intersection is a function of its two triangles alone:
      // the pairs of a block are intersected in parts of a fixed size on the
      // threads, then registered in pair order, as above, so the points'
      // numbering does not depend on the thread count. A block bounds what is
      // held at once (an intersection takes about a kilobyte).
      constexpr std::size_t block = 16384, part = 512;
      std::vector<std::vector<Met_pair>> met;
      for (std::size_t begin = 0; begin < pairs.size(); begin += block) {
        const std::size_t end = std::min(pairs.size(), begin + block);
        met.assign((end - begin + part - 1) / part, {});
        internal::parallel_for_each_index(met.size(), options_.threads, [&](std::size_t i) {
          internal::Triangle_intersector<K> intersector(k_, no_perturbation);
          for (std::size_t j = begin + i * part; j < std::min(end, begin + (i + 1) * part); ++j) {
            Triangle_intersection<K> x =
                intersector.run(triangle(*mesh_[0], pairs[j].first), triangle(*mesh_[1], pairs[j].second));
            if (intersector.degenerate_input() || x.kind != Triangle_intersection_kind::disjoint)
              met[i].push_back({j, std::move(x), intersector.degenerate_input()});
          }
        });
        for (const auto& in_part : met)
          for (const Met_pair& m : in_part)
            if (!register_intersection(pairs[m.pair], m.x, m.degenerate_input, r)) return false;
      }
    }
    if (!r.undecided_pairs.empty()) {
      r.failure = "narrow phase: " + std::to_string(r.undecided_pairs.size()) +
                  " face pairs the kernel cannot decide (see undecided_pairs)";
      return false;
    }
    if (!merge_equal_points()) {
      r.failure = "narrow phase: the kernel cannot order the new points (an uncertain compare_xyz)";
      return false;
    }
    for (Index p = points_.input_count(); p < points_.size(); ++p)
      r.counts.new_vertices += find(p) == p;
    return true;
  }

  // The points and curve segments of one pair's intersection x; false (with
  // r.failure) for a face the kernel finds degenerate.
  bool register_intersection(const Face_pair& pair, const Triangle_intersection<K>& x, bool degenerate_input,
                             Result& r) {
    const auto [fa, fb] = pair;
    if (degenerate_input) {
      // A valid face that the kernel's arithmetic finds degenerate (a naive
      // kernel's products underflow or overflow; the exact operand check
      // passed), or a degenerate face of an unchecked operand.
      r.failure = "narrow phase: face " + std::to_string(fa) + " of A or face " + std::to_string(fb) +
                  " of B is degenerate in the kernel's arithmetic (intersect_triangles: a degenerate triangle)";
      return false;
    }
    if (x.kind == Triangle_intersection_kind::undecided) {
      r.undecided_pairs.emplace_back(fa, fb);
      return true;
    }
    if (x.kind == Triangle_intersection_kind::disjoint) return true;
    ++r.counts.intersecting_pairs;
    if (x.kind == Triangle_intersection_kind::coplanar_overlap) {
      ++r.counts.coplanar_pairs;
      coplanar_[0][fa].push_back(fb);
      coplanar_[1][fb].push_back(fa);
    }
    std::array<Index, 6> ids{};
    for (std::size_t i = 0; i < x.points.size(); ++i) ids[i] = register_point(x.points[i], fa, fb, x.locations[i]);
    // Curve segments: a segment, or the boundary of a coplanar polygon.
    const std::size_t n = x.points.size();
    if (n == 2) segments_.push_back({ids[0], ids[1], fa, fb});
    if (n >= 3)
      for (std::size_t i = 0; i < n; ++i) segments_.push_back({ids[i], ids[(i + 1) % n], fa, fb});
    return true;
  }

  Index register_point(const IP& p, Index fa, Index fb, const std::array<Triangle_location, 2>& where) {
    Index id = invalid_index;
    // An input vertex keeps its index (both, if a vertex of A is one of B).
    for (int m = 0; m < 2; ++m)
      if (where[m].kind == Triangle_location::Kind::vertex) {
        const Index v = offset_[m] + mesh_[m]->faces[m == 0 ? fa : fb][where[m].index];
        if (id == invalid_index) id = v;
        else unite(id, v);
      }
    if (id == invalid_index) {
      const std::optional<Cell_pair> cells = meeting_cells(fa, fb, where);
      if (cells) {
        const auto [it, inserted] = point_of_cells_.try_emplace(*cells, static_cast<Index>(points_.size()));
        if (!inserted) id = it->second;
      }
    }
    if (id == invalid_index) {
      id = points_.add(p);
      equal_points_.add();
    }
    located_.push_back({id, {fa, fb}, {where[0], where[1]}});
    return id;
  }

  // A new point is where an open edge of one operand meets an open edge or
  // the open interior of a face of the other. Such two cells meet in one
  // point at most (an edge lying in the other's plane ends on its edges or
  // at vertices, never inside), so every pair of faces around the same two
  // cells gives the same point: one vertex without arithmetic. The cells of
  // operand m are keyed by (face, invalid_index) for an interior and by the
  // sorted vertices of an edge; two interiors are no such pair (nullopt).
  using Cell_pair = std::array<Index, 4>;
  struct Cell_pair_hash {
    std::size_t operator()(const Cell_pair& c) const {
      std::uint64_t h = 0x9e3779b97f4a7c15ull;
      for (Index x : c) h = (h ^ x) * 0xff51afd7ed558ccdull;
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  std::optional<Cell_pair> meeting_cells(Index fa, Index fb, const std::array<Triangle_location, 2>& where) const {
    Cell_pair key{};
    bool some_edge = false;
    for (int m = 0; m < 2; ++m) {
      const Index f = m == 0 ? fa : fb;
      if (where[m].kind == Triangle_location::Kind::edge) {
        const Triangle& t = mesh_[m]->faces[f];
        const Index u = t[where[m].index], v = t[(where[m].index + 1) % 3];
        key[2 * m] = std::min(u, v), key[2 * m + 1] = std::max(u, v);
        some_edge = true;
      } else {
        key[2 * m] = f, key[2 * m + 1] = invalid_index;
      }
    }
    if (!some_edge) return std::nullopt;
    return key;
  }

  // Equal points that register_point did not recognise by their cells (an
  // operand that crosses itself, when the checks are off) become one: sorted
  // by the exact lexicographic order. After the cells, the points compared
  // are distinct, which the kernels' filters decide without exact arithmetic.
  // False when the kernel cannot order two of them (fail-safe, interval).
  // A certified kernel's points are first put in runs by their
  // approximations' x ranges (within the stated error of the exact x): two
  // points of different runs have different x, and the exact order is needed
  // within a run only, nearly always a single point (on the elephant against
  // its moved copy, sorting all 1,029 points exactly was 4% of the union).
  // The approximations are those the retriangulation reads.
  bool merge_equal_points() {
    std::vector<Index> ids;
    for (const auto& l : located_) ids.push_back(find(l.point));
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    if constexpr (K::is_certified) {
      struct X_range {
        double lo, hi;
        Index id;
      };
      std::vector<X_range> range(ids.size());
      for (std::size_t i = 0; i < ids.size(); ++i) {
        const Approximate_point_3& a = points_.approximation(ids[i]);
        constexpr double infinity = std::numeric_limits<double>::infinity();
        range[i] = a.error <= std::numeric_limits<double>::max() && std::isfinite(a.point.x)  // false for NaN
                       ? X_range{sub_down(a.point.x, a.error), add_up(a.point.x, a.error), ids[i]}
                       : X_range{-infinity, infinity, ids[i]};
      }
      std::sort(range.begin(), range.end(),
                [](const X_range& a, const X_range& b) { return a.lo < b.lo || (a.lo == b.lo && a.id < b.id); });
      std::vector<Index> run;
      for (std::size_t begin = 0; begin < range.size();) {
        std::size_t end = begin + 1;
        for (double reach = range[begin].hi; end < range.size() && !(reach < range[end].lo); ++end)
          reach = std::max(reach, range[end].hi);
        if (end - begin > 1) {
          run.clear();
          for (std::size_t i = begin; i < end; ++i) run.push_back(range[i].id);
          if (!merge_equal_points_of(run)) return false;
        }
        begin = end;
      }
      return true;
    } else {
      return merge_equal_points_of(ids);
    }
  }
  // The exact lexicographic order of `ids`, equal neighbours united.
  bool merge_equal_points_of(std::vector<Index>& ids) {
    const auto compare = k_.compare_xyz_3_object();
    const auto by_point = [&](Index a, Index b) { return compare(points_[a], points_[b]); };
    if (!certified_sort(ids.begin(), ids.end(), by_point)) return false;
    for (std::size_t i = 1; i < ids.size(); ++i) {
      const Certified_sign s = by_point(ids[i - 1], ids[i]);
      if (!is_certain(s)) return false;
      if (certainly(s, Certified_sign::zero)) unite(ids[i - 1], ids[i]);
    }
    return true;
  }

  // ---- 4. retriangulation ---------------------------------------------------------

  struct Segment {
    Index a, b;
    Index fa, fb;
  };

  bool retriangulate(Result& r) {
    // What lies on each face that is split (face -> slot) and on its edges
    // (listed by both faces of an edge, through the opposites: no list per
    // edge of the operand, which was a third of the peak memory on large
    // operands).
    for (int m = 0; m < 2; ++m) {
      const std::size_t halfedges = 3 * mesh_[m]->faces.size();
      if (opposite_[m].size() == halfedges) continue;  // kept from this Boolean's check
      // Operands certified before (a chain's earlier result, a Valid_solid)
      // bring their opposites with the certificate; others are built here.
      const std::vector<Index>* carried =
          options_.certified_operands.covers(*mesh_[0], *mesh_[1]) ? options_.certified_operands.opposites(m) : nullptr;
      if (carried && carried->size() == halfedges) opposite_[m] = *carried;
      else opposite_[m] = Mesh_topology::build(*mesh_[m]).take_opposites();
    }
    std::array<std::vector<Index>, 2> slot{std::vector<Index>(mesh_[0]->faces.size(), invalid_index),
                                           std::vector<Index>(mesh_[1]->faces.size(), invalid_index)};
    std::array<std::vector<Face_constraints>, 2> faces;
    const auto constraints = [&](int m, Index f) -> Face_constraints& {
      if (slot[m][f] == invalid_index) {
        slot[m][f] = static_cast<Index>(faces[m].size());
        faces[m].emplace_back();
      }
      return faces[m][slot[m][f]];
    };
    for (const auto& l : located_) {
      const Index id = find(l.point);
      for (int m = 0; m < 2; ++m) {
        if (l.where[m].kind == Triangle_location::Kind::vertex) continue;
        if (l.where[m].kind == Triangle_location::Kind::edge) {
          // On edge h of this face and on its opposite, of the face across:
          // both faces are split, each lists the point on its own edge.
          const Index h = 3 * l.face[m] + l.where[m].index, o = opposite_[m][h];
          constraints(m, l.face[m]).edge_points[h % 3].push_back(id);
          if (o != invalid_index) constraints(m, o / 3).edge_points[o % 3].push_back(id);
        } else {
          constraints(m, l.face[m]).interior_points.push_back(id);
        }
      }
    }
    for (const Segment& s : segments_) {
      const Index a = find(s.a), b = find(s.b);
      if (a == b) continue;
      curves_.insert(a, b);
      constraints(0, s.fa).segments.push_back({a, b});
      constraints(1, s.fb).segments.push_back({a, b});
    }
    curves_.finish(points_.size());
    for (int m = 0; m < 2; ++m) pieces_[m].piece_of_face.assign(mesh_[m]->faces.size(), invalid_index);
    // A face that is not split is a piece; a split face is retriangulated.
    const auto corners_of = [&](int m, Index f) {
      const Triangle& t = mesh_[m]->faces[f];
      return std::array<Index, 3>{find(offset_[m] + t[0]), find(offset_[m] + t[1]), find(offset_[m] + t[2])};
    };
    const auto keep_whole = [&](int m, Index f) {
      pieces_[m].piece_of_face[f] = static_cast<Index>(pieces_[m].triangles.size());
      pieces_[m].triangles.push_back(corners_of(m, f));
      pieces_[m].input_face.push_back(f);
    };
    // The constraints of split face f, its points listed once, not its corners.
    const auto prepared = [&](int m, Index f) -> Face_constraints& {
      Face_constraints& c = constraints(m, f);
      c.corners = corners_of(m, f);
      const auto not_corner = [&](std::vector<Index>& v) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
        std::erase_if(v, [&](Index p) { return p == c.corners[0] || p == c.corners[1] || p == c.corners[2]; });
      };
      for (auto& on_edge : c.edge_points) not_corner(on_edge);
      not_corner(c.interior_points);
      return c;
    };
    const auto add_pieces = [&](int m, Index f, const Face_triangulation& tri) {
      if (!tri.ok) {
        r.failure = "retriangulation of face " + std::to_string(f) + " of " + (m == 0 ? "A" : "B") + ": " + tri.failure;
        return false;
      }
      ++r.counts.split_faces;
      for (const Triangle& x : tri.triangles) {
        pieces_[m].triangles.push_back(x);
        pieces_[m].input_face.push_back(f);
      }
      return true;
    };
    if (internal::thread_count(options_.threads) > 1 && concurrent_point_reads)
      return retriangulate_in_parallel(slot, prepared, keep_whole, add_pieces);
    Face_triangulator<K, Point_table<K, OP>> triangulator(k_, points_);
    triangulator.set_delaunay(options_.delaunay_retriangulation);
    for (int m = 0; m < 2; ++m)
      for (Index f = 0; f < mesh_[m]->faces.size(); ++f) {
        if (slot[m][f] == invalid_index)
          keep_whole(m, f);
        else if (!add_pieces(m, f, triangulator.run(prepared(m, f), projection_axis(m, f))))
          return false;
      }
    return true;
  }

  // Whether the retriangulation reads the kernel's points on several threads:
  // relgeo's points are values; CGAL's lazy exact ones (Epeck's) compute and
  // keep their exact value on a read, which only CGAL 5.4 and later make safe
  // (std::call_once under CGAL_HAS_THREADS), so their faces stay on one thread.
  static constexpr bool concurrent_point_reads = !(requires { typename K::Cgal; } && K::has_exact_constructions);

  // The split faces triangulated on the threads, a block at a time, in parts
  // of a fixed size; each face's triangles are a function of its constraints
  // and the points alone, and the pieces are added in face order as on one
  // thread: the result does not depend on the thread count. The points of a
  // block are made and approximated first (the point table makes an input
  // vertex the kernel's point, and approximates a point, on its first read).
  template <class Prepared, class Keep, class Add>
  bool retriangulate_in_parallel(const std::array<std::vector<Index>, 2>& slot, Prepared& prepared, Keep& keep_whole,
                                 Add& add_pieces) {
    struct Job {  // a split face
      const Face_constraints* constraints;
      int axis;
    };
    constexpr std::size_t block = 1024, part = 64;
    std::vector<Job> jobs;
    std::vector<Face_triangulation> done;
    std::vector<Index> used;
    const auto run_block = [&] {
      used.clear();
      for (const Job& j : jobs) {
        const Face_constraints& c = *j.constraints;
        used.insert(used.end(), c.corners.begin(), c.corners.end());
        for (const auto& on_edge : c.edge_points) used.insert(used.end(), on_edge.begin(), on_edge.end());
        used.insert(used.end(), c.interior_points.begin(), c.interior_points.end());
        for (const auto& s : c.segments) used.insert(used.end(), s.begin(), s.end());
      }
      std::sort(used.begin(), used.end());
      used.erase(std::unique(used.begin(), used.end()), used.end());
      for (Index p : used) (void)points_[p];  // the table grows here, on one thread
      // Each point approximated by one thread (one entry of the table each).
      internal::parallel_for_each_index((used.size() + 511) / 512, options_.threads, [&](std::size_t i) {
        for (std::size_t j = i * 512; j < std::min(used.size(), (i + 1) * 512); ++j)
          (void)points_.approximation(used[j]);
      });
      done.assign(jobs.size(), {});
      internal::parallel_for_each_index((jobs.size() + part - 1) / part, options_.threads, [&](std::size_t i) {
        Face_triangulator<K, Point_table<K, OP>> triangulator(k_, points_);
        triangulator.set_delaunay(options_.delaunay_retriangulation);
        for (std::size_t j = i * part; j < std::min(jobs.size(), (i + 1) * part); ++j)
          done[j] = triangulator.run(*jobs[j].constraints, jobs[j].axis);
      });
    };
    // Faces in order; a block of split faces is triangulated when full, and
    // the faces up to its last are added then.
    std::array<Index, 2> added{0, 0};
    const auto add_up_to = [&](int m_end, Index f_end) {  // every face before (m_end, f_end)
      std::size_t next = 0;
      for (int m = 0; m < 2; ++m)
        for (Index& f = added[m]; (m < m_end || (m == m_end && f < f_end)) && f < mesh_[m]->faces.size(); ++f) {
          if (slot[m][f] == invalid_index)
            keep_whole(m, f);
          else if (!add_pieces(m, f, done[next++]))
            return false;
        }
      return true;
    };
    for (int m = 0; m < 2; ++m)
      for (Index f = 0; f < mesh_[m]->faces.size(); ++f) {
        if (slot[m][f] == invalid_index) continue;
        jobs.push_back({&prepared(m, f), projection_axis(m, f)});
        if (jobs.size() < block) continue;
        run_block();
        if (!add_up_to(m, f + 1)) return false;
        jobs.clear();
      }
    run_block();
    return add_up_to(2, 0);
  }

  // The axis to project face f of operand m along: the one along which its
  // normal is largest in doubles (the best-conditioned projection), unless
  // the kernel finds the face degenerate in that projection; then the next
  // axis whose projection it certifies. Doubles can choose wrongly: the
  // normal of a face of subnormal size underflows to zero (a fuzzing
  // finding). A valid face has an axis; when none is certified (a
  // degenerate face, unchecked operands, an undecided kernel) the first is
  // returned and the triangulation reports it.
  int projection_axis(int m, Index f) const {
    const Triangle& t = mesh_[m]->faces[f];
    const Point_3<double> a = vertex_in_doubles(m, t[0]), b = vertex_in_doubles(m, t[1]),
                          c = vertex_in_doubles(m, t[2]);
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const double n[3] = {std::abs(uy * vz - uz * vy), std::abs(uz * vx - ux * vz), std::abs(ux * vy - uy * vx)};
    const int first = n[0] >= n[1] && n[0] >= n[2] ? 0 : (n[1] >= n[2] ? 1 : 2);
    const int second = (first + 1) % 3, third = (first + 2) % 3;
    const std::array<int, 3> order{first, n[second] >= n[third] ? second : third, n[second] >= n[third] ? third : second};
    const auto orient2 = k_.implicit_orientation_2_object();
    for (int axis : order) {
      const Certified_sign s = orient2(points_[offset_[m] + t[0]], points_[offset_[m] + t[1]], points_[offset_[m] + t[2]], axis);
      if (is_certain(s) && !certainly(s, Certified_sign::zero)) return axis;
    }
    return first;
  }

  // ---- 5. labelling ---------------------------------------------------------------

  bool label(Result& r) {
    std::array<Piece_adjacency, 2> adjacency;
    for (int m = 0; m < 2; ++m)
      if (!adjacency[m].build(pieces_[m], opposite_[m]))  // only a naive kernel's inconsistent answers can do that
        return fail(r, "labelling: the pieces of an operand are not consistently oriented");
    for (int m = 0; m < 2; ++m) {
      const auto [patch, count] = patches(pieces_[m], adjacency[m], curves_);
      r.counts.patches += count;
      std::vector<Piece_label> patch_label(count, Piece_label::unknown);
      // Coplanar pieces first, then a curve edge of each patch, then rays.
      for (Index t = 0; t < pieces_[m].triangles.size(); ++t) {
        if (patch_label[patch[t]] != Piece_label::unknown) continue;
        const auto c = coplanar_label(m, t);
        if (!c) return fail(r, "labelling: a coplanar piece the kernel cannot place");
        if (*c != Piece_label::unknown) patch_label[patch[t]] = *c;
      }
      for (Index t = 0; t < pieces_[m].triangles.size(); ++t) {
        if (patch_label[patch[t]] != Piece_label::unknown) continue;
        for (int k = 0; k < 3; ++k) {
          const Index u = pieces_[m].triangles[t][k], w = pieces_[m].triangles[t][(k + 1) % 3];
          if (!curves_.contains(u, w)) continue;
          const Piece_label l = edge_label(m, t, k, adjacency[1 - m]);
          if (l != Piece_label::unknown) {
            patch_label[patch[t]] = l;
            break;
          }
        }
      }
      for (Index t = 0; t < pieces_[m].triangles.size(); ++t) {
        if (patch_label[patch[t]] != Piece_label::unknown) continue;
        const auto l = ray_label(m, t);
        if (!l) return fail(r, "labelling: a patch no ray from its vertices decides");
        patch_label[patch[t]] = *l;
      }
      labels_[m].resize(pieces_[m].triangles.size());
      for (Index t = 0; t < pieces_[m].triangles.size(); ++t) labels_[m][t] = patch_label[patch[t]];
    }
    return true;
  }
  bool fail(Result& r, const char* why) {
    r.failure = why;
    return false;
  }

  // On the other operand's boundary? unknown when not coplanar with any
  // face it overlaps; nullopt when undecided.
  std::optional<Piece_label> coplanar_label(int m, Index t) {
    const Index f = pieces_[m].input_face[t];
    const auto it = coplanar_[m].find(f);
    if (it == coplanar_[m].end()) return Piece_label::unknown;
    const Triangle& piece = pieces_[m].triangles[t];
    const Mesh& mine = *mesh_[m];
    const Mesh& other = *mesh_[1 - m];
    const int axis = projection_axis(m, f);
    const auto orient2 = k_.implicit_orientation_2_object();
    const auto corner = [&](int mesh, Index face, int i) -> const IP& {
      return points_[offset_[mesh] + (mesh == m ? mine : other).faces[face][i]];
    };
    const Certified_sign mine_sign = orient2(corner(m, f, 0), corner(m, f, 1), corner(m, f, 2), axis);
    for (Index g : it->second) {
      const Certified_sign other_sign = orient2(corner(1 - m, g, 0), corner(1 - m, g, 1), corner(1 - m, g, 2), axis);
      if (!is_certain(mine_sign) || !is_certain(other_sign)) return std::nullopt;
      // The piece lies in g iff its three points do (g is convex).
      bool inside = true;
      for (int v = 0; v < 3 && inside; ++v)
        for (int e = 0; e < 3 && inside; ++e) {
          const Certified_sign s = orient2(corner(1 - m, g, e), corner(1 - m, g, (e + 1) % 3), points_[piece[v]], axis);
          if (!is_certain(s)) return std::nullopt;
          inside = certainly(s, Certified_sign::zero) || s == other_sign;
        }
      if (inside) return mine_sign == other_sign ? Piece_label::on_same : Piece_label::on_opposite;
    }
    return Piece_label::unknown;
  }

  // Decided at curve edge k of piece t: the other operand's pieces on it.
  Piece_label edge_label(int m, Index t, int k, const Piece_adjacency& other) {
    const Triangle& piece = pieces_[m].triangles[t];
    const Index u = piece[k], w = piece[(k + 1) % 3], x = piece[(k + 2) % 3];
    const Index h1 = other.find(u, w), h2 = other.find(w, u);
    if (h1 == invalid_index || h2 == invalid_index) return Piece_label::unknown;
    const Index b1 = h1 / 3, b2 = h2 / 3;
    const int o = 1 - m;
    const Index y2 = third(pieces_[o].triangles[b2], w, u);
    const auto side = [&](Index piece_of_other, Index point) {  // orientation against the input face's plane
      const std::array<P, 3> f = triangle(*mesh_[o], pieces_[o].input_face[piece_of_other]);
      return k_.implicit_orientation_3_object()(f[0], f[1], f[2], points_[point]);
    };
    const Certified_sign o1 = side(b1, x), o2 = side(b2, x), edge = side(b1, y2);
    if (!is_certain(o1) || !is_certain(o2) || !is_certain(edge)) return Piece_label::unknown;
    if (certainly(o1, Certified_sign::zero) || certainly(o2, Certified_sign::zero))
      return Piece_label::unknown;  // coplanar locally
    const bool below1 = certainly(o1, Certified_sign::negative), below2 = certainly(o2, Certified_sign::negative);
    bool inside;
    if (certainly(edge, Certified_sign::negative))
      inside = below1 && below2;  // convex edge
    else if (certainly(edge, Certified_sign::positive))
      inside = below1 || below2;                                           // concave edge
    else inside = below1;                                                  // flat
    return inside ? Piece_label::inside : Piece_label::outside;
  }
  static Index third(const Triangle& t, Index a, Index b) {
    for (Index v : t)
      if (v != a && v != b) return v;
    return t[0];
  }

  // Parity of the other operand's faces crossed by a segment from an input
  // vertex of piece t to a point above the other's box; nullopt if no vertex
  // of t gives a clean segment in a few directions.
  enum class Crossing { none, once, recast, on_surface, undecided };

  std::optional<Piece_label> ray_label(int m, Index t) {
    const Mesh& other = *mesh_[1 - m];
    if (other.faces.empty()) return Piece_label::outside;  // the empty solid (no point above it to cast to)
    // q lies above the other operand: an exact point's approximation is
    // within a relative 2^-52 of it, far below the lift.
    double zmax = -std::numeric_limits<double>::infinity();
    for (Index v = 0; v < other.vertices.size(); ++v) zmax = std::max(zmax, vertex_in_doubles(1 - m, v).z);
    const auto point = k_.construct_point_3_object();
    const Index first = offset_[m], last = offset_[m] + static_cast<Index>(mesh_[m]->vertices.size());
    for (Index v : pieces_[m].triangles[t]) {
      if (v < first || v >= last) continue;  // not an input vertex of this operand
      const Point_3<double> pv = vertex_in_doubles(m, v - first);
      const P p = [&] {
        if constexpr (exact_operands)
          return mesh_[m]->vertices[v - first];
        else
          return point(pv.x, pv.y, pv.z);
      }();
      for (int attempt = 0; attempt < 8; ++attempt) {
        const double lift = std::max(1.0, std::abs(zmax)) * (2 + attempt);
        const P q = point(pv.x + attempt * 0.37 * lift, pv.y + attempt * 0.61 * lift, zmax + lift);
        int crossings = 0;
        Crossing c = Crossing::none;
        for (Index g = 0; g < other.faces.size(); ++g) {
          c = crossing(triangle(other, g), p, q);
          if (c == Crossing::once) ++crossings;
          else if (c != Crossing::none) break;
        }
        if (c == Crossing::undecided) return std::nullopt;
        if (c == Crossing::on_surface) break;  // this vertex lies on the other surface: try another
        if (c == Crossing::recast) continue;
        return crossings % 2 ? Piece_label::inside : Piece_label::outside;
      }
    }
    return std::nullopt;
  }

  // How segment pq (p an input vertex, q off every plane of interest) meets triangle f.
  Crossing crossing(const std::array<P, 3>& f, const P& p, const P& q) const {
    const auto orient = k_.orientation_3_object();
    const Certified_sign sp = orient(f[0], f[1], f[2], p), sq = orient(f[0], f[1], f[2], q);
    if (!is_certain(sp) || !is_certain(sq)) return Crossing::undecided;
    if (certainly(sq, Certified_sign::zero)) return Crossing::recast;
    if (!certainly(sp, Certified_sign::zero) && sp == sq) return Crossing::none;
    // The line pq against the triangle's edges: all the same strict sign iff
    // it passes through the interior.
    const Certified_sign e0 = orient(p, q, f[0], f[1]), e1 = orient(p, q, f[1], f[2]), e2 = orient(p, q, f[2], f[0]);
    if (!is_certain(e0) || !is_certain(e1) || !is_certain(e2)) return Crossing::undecided;
    const bool through_interior = e0 == e1 && e1 == e2 && !certainly(e0, Certified_sign::zero);
    const bool misses = (certainly(e0, Certified_sign::positive) || certainly(e1, Certified_sign::positive) ||
                         certainly(e2, Certified_sign::positive)) &&
                        (certainly(e0, Certified_sign::negative) || certainly(e1, Certified_sign::negative) ||
                         certainly(e2, Certified_sign::negative));
    if (certainly(sp, Certified_sign::zero)) return misses ? Crossing::none : Crossing::on_surface;  // p in the plane
    if (misses) return Crossing::none;
    return through_interior ? Crossing::once : Crossing::recast;  // through an edge or a vertex: cast again
  }

  // ---- 6. assembly -------------------------------------------------------------------

  bool keeps(int m, Piece_label l, bool& flip) const {
    flip = false;
    switch (op_) {
      case Boolean_operation::union_of:
        return l == Piece_label::outside || (m == 0 && l == Piece_label::on_same);
      case Boolean_operation::intersection:
        return l == Piece_label::inside || (m == 0 && l == Piece_label::on_same);
      case Boolean_operation::difference:
        if (m == 0) return l == Piece_label::outside || l == Piece_label::on_opposite;
        flip = true;
        return l == Piece_label::inside;
      case Boolean_operation::symmetric_difference:
        flip = l == Piece_label::inside;
        return l == Piece_label::outside || l == Piece_label::inside;
    }
    return false;
  }

  void assemble(Result& r) {
    // Output vertices: the input vertices kept, then the new ones (so that
    // only the new ones need the kernel's points), each numbered on first use.
    // Exact operands' vertices are not doubles: all are "new", rounded, and
    // kept as K's points (first_new_vertex 0).
    std::vector<Index> new_index(points_.size(), invalid_index);
    const Index inputs = exact_operands ? 0 : points_.input_count();
    Index next_input = 0, next_new = 0;
    const auto use = [&](Index g) {
      Index& n = new_index[g];
      if (n == invalid_index) {
        if (g < inputs) {
          n = next_input++;
          const int m = g < offset_[1] ? 0 : 1;
          if constexpr (!exact_operands) r.mesh.vertices[n] = mesh_[m]->vertices[g - offset_[m]];
        } else {
          n = r.first_new_vertex + next_new++;
          const Approximate_point_3& a = points_.approximation(g);
          r.mesh.vertices[n] = a.point;
          r.rounding_error = std::max(r.rounding_error, a.error);
          r.new_vertex_points.push_back(points_[g]);
        }
      }
      return n;
    };
    // The output's sizes first, so that its arrays are allocated once (no
    // copy on growth: the copies were the peak of the run's memory).
    {
      std::size_t faces = 0, new_vertices = 0;
      std::vector<char> used(points_.size(), 0);
      for (int m = 0; m < 2; ++m)
        for (Index t = 0; t < pieces_[m].triangles.size(); ++t) {
          bool flip = false;
          if (!keeps(m, labels_[m][t], flip)) continue;
          ++faces;
          for (Index g : pieces_[m].triangles[t])
            if (!used[g]) used[g] = 1, g < inputs ? ++r.first_new_vertex : ++new_vertices;
        }
      r.mesh.faces.reserve(faces), r.provenance.reserve(faces);
      r.mesh.vertices.resize(r.first_new_vertex + new_vertices), r.new_vertex_points.reserve(new_vertices);
    }
    // The curves that are edges of the output are its creases.
    std::vector<Edge> creases;
    for (int m = 0; m < 2; ++m)
      for (Index t = 0; t < pieces_[m].triangles.size(); ++t) {
        bool flip = false;
        if (!keeps(m, labels_[m][t], flip)) continue;
        Triangle tri = pieces_[m].triangles[t];
        if (flip) std::swap(tri[1], tri[2]);
        r.mesh.faces.push_back({use(tri[0]), use(tri[1]), use(tri[2])});
        r.provenance.push_back({static_cast<std::uint8_t>(m), pieces_[m].input_face[t]});
        for (int k = 0; k < 3; ++k) {
          const Index u = tri[k], w = tri[(k + 1) % 3];
          if (curves_.contains(u, w)) creases.push_back({new_index[u], new_index[w]});
        }
      }
    locate_output_vertices(new_index, r);
    r.mesh.tags.set_creases(std::move(creases));  // sorted, each once
  }

  // Everything between the operands and the output: the points, their
  // locations, the curves and the pieces. The validation and the repair read
  // the output (and the broad phase's pairs), not these.
  void release_arrangement() {
    points_.clear();
    equal_points_ = Union_find<Index>();
    std::vector<Located_point>().swap(located_);
    std::unordered_map<Cell_pair, Index, Cell_pair_hash>().swap(point_of_cells_);
    std::vector<Segment>().swap(segments_);
    for (auto& c : coplanar_) std::unordered_map<Index, std::vector<Index>>().swap(c);
    curves_ = Edge_set();
    for (auto& p : pieces_) p = Pieces();
    for (auto& l : labels_) std::vector<Piece_label>().swap(l);
  }

  // ---- 7. validation -------------------------------------------------------------------

  // The operands are certified valid solids: checked here (the exact
  // self-intersection test included) or by relgeo before (Valid_solid, csg).
  bool operands_certified() const {
    return options_.certified_operands.covers(*mesh_[0], *mesh_[1]) ||
           (options_.check_operands && options_.check_self_intersections);
  }

  // validate_solid on the output's doubles, under the exact predicates
  // whatever K; with exact operands, on the exact result (exact_mesh())
  // under K, the certificate of an exact chain's next operand. With
  // certified operands, no pair of faces kept unchanged from one operand is
  // tested again: that operand's certificate decided it. A valid output
  // keeps the validation's half-edge opposites
  // (Boolean_output::halfedge_opposites): its next Boolean reuses them.
  void validate(Result& r) const {
    std::vector<Index> opposites;
    // On the Boolean's threads, unless the validation's options ask for
    // another count than the default one.
    Solid_validation_options o = options_.validation;
    if (o.threads == 1) o.threads = options_.threads;
    const auto validate_with = [&](const auto& mesh, const auto& kernel) {
      if (!operands_certified()) {
        r.validation = internal::validate_solid(mesh, kernel, o, nullptr, &opposites);
        return;
      }
      const Certified_faces certified = unchanged_operand_faces(r);
      r.counts.unchanged_certified_faces = static_cast<std::size_t>(
          std::count_if(certified.group.begin(), certified.group.end(), [](std::uint8_t g) { return g != 0; }));
      r.validation = internal::validate_solid(mesh, kernel, o, &certified, &opposites);
    };
    if constexpr (exact_operands)
      validate_with(r.exact_mesh(), k_);
    else
      validate_with(r.mesh, Check_kernel{});
    r.halfedge_opposites.clear();
    if (r.validation.is_valid_solid()) r.halfedge_opposites = std::move(opposites);
  }
  // Output vertex v as the operands' points are: its double, or (exact
  // operands: every output vertex is a new one) its exact point.
  const OP& output_point(const Result& r, Index v) const {
    if constexpr (exact_operands)
      return r.new_vertex_points[v].point;
    else
      return r.mesh.vertices[v];
  }

  // Per output face: 1 + its operand when it is, unchanged, a face of that
  // operand, else 0. Unchanged: its three points are the input face's (in
  // either orientation), no other output face is that input face, and each
  // of the input face's vertices is one output vertex (none split). Two
  // such faces of one operand then meet in the output exactly as they meet
  // in the operand: in their shared vertices and edge at most. The pairs of
  // such faces across the operands whose boxes overlap are among the broad
  // phase's pairs (the same boxes): the validation tests them, and every
  // pair with a new or moved face.
  Certified_faces unchanged_operand_faces(const Result& r) const {
    const Triangle_mesh<Point_3<double>>& out = r.mesh;  // (its faces; the points: output_point)
    constexpr Index none = invalid_index, conflict = invalid_index - 1;
    const auto claim = [](Index& slot, Index value) { slot = slot == none || slot == value ? value : conflict; };
    std::array<std::vector<Index>, 2> face_of, vertex_of;  // input face -> output face, input vertex -> output vertex
    for (int m = 0; m < 2; ++m) {
      face_of[m].assign(mesh_[m]->faces.size(), none);
      vertex_of[m].assign(mesh_[m]->vertices.size(), none);
    }
    std::vector<std::uint8_t> group(out.faces.size(), 0);
    for (Index f = 0; f < out.faces.size(); ++f) {
      const Face_origin o = r.provenance[f];
      const Mesh& in = *mesh_[o.operand];
      const Triangle& t = in.faces[o.face];
      std::array<Index, 3> corner{};  // the input vertex at each output corner
      bool same = true;
      for (int i = 0; i < 3 && same; ++i) {
        const OP& p = output_point(r, out.faces[f][i]);
        int j = 0;
        while (j < 3 && !(in.vertices[t[j]] == p)) ++j;
        same = j < 3;
        if (same) corner[i] = t[j];
      }
      if (!same || corner[0] == corner[1] || corner[1] == corner[2] || corner[0] == corner[2]) continue;
      group[f] = static_cast<std::uint8_t>(1 + o.operand);
      claim(face_of[o.operand][o.face], f);
      for (int i = 0; i < 3; ++i) claim(vertex_of[o.operand][corner[i]], out.faces[f][i]);
    }
    for (Index f = 0; f < out.faces.size(); ++f) {
      if (!group[f]) continue;
      const Face_origin o = r.provenance[f];
      bool unique = face_of[o.operand][o.face] == f;
      for (Index v : mesh_[o.operand]->faces[o.face]) unique = unique && vertex_of[o.operand][v] != conflict;
      if (!unique) group[f] = 0;
    }
    Certified_faces certified;
    for (const Face_pair& p : candidate_pairs_) {
      const Index f = face_of[0][p.first], g = face_of[1][p.second];
      if (f < conflict && g < conflict && group[f] && group[g])
        certified.cross_pairs.push_back({std::min(f, g), std::max(f, g)});
    }
    certified.group = std::move(group);
    return certified;
  }

  // ---- 8. rounding ---------------------------------------------------------------------

  static bool closed_manifold(const Solid_report& v) {
    return v.closed.passed() && v.edge_manifold.passed() && v.vertex_manifold.passed();
  }
  static void fail_rounding(Result& r) {
    r.status = Result::Status::failed;
    r.failure = "rounding: " + std::to_string(r.rounding.remaining_pairs.size()) + " face pairs still meet and " +
                std::to_string(r.rounding.remaining_degenerate_faces.size()) + " faces are degenerate after " +
                std::to_string(r.rounding.rounds) +
                " rounds of repair (Boolean_result::rounding lists them; Output_rounding::nearest skips the repair)";
  }

  // No crossing and no degenerate face: nothing rounding can have broken.
  static bool rounding_kept_validity(const Solid_report& v) {
    return v.self_intersection_free.passed() && v.non_degenerate_faces.passed();
  }

  // The new vertices may move (by one unit in the last place, or within the
  // repair's tolerance); the per-vertex and per-face data follow the repair's
  // renumbering.
  void repair_rounding_of(Result& r) {
    std::vector<char> movable(r.mesh.vertices.size(), 0);
    std::fill(movable.begin() + r.first_new_vertex, movable.end(), 1);
    Rounding_repair_maps maps;
    r.rounding = repair_rounding(r.mesh, movable, options_.repair, &maps);
    if (r.rounding.rounds == 0) return;  // nothing changed: nothing renumbered
    std::vector<Face_origin> provenance(maps.face_origin.size());
    for (Index f = 0; f < provenance.size(); ++f) provenance[f] = r.provenance[maps.face_origin[f]];
    r.provenance = std::move(provenance);
    std::vector<IP> new_points;
    std::vector<std::array<Surface_location, 2>> locations(r.mesh.vertices.size());
    Index first_new = 0;
    for (Index v = 0; v < maps.vertex_map.size(); ++v) {
      const Index w = maps.vertex_map[v];
      if (w == invalid_index) continue;
      locations[w] = r.vertex_locations[v];
      if (v < r.first_new_vertex) ++first_new;
      else new_points.push_back(std::move(r.new_vertex_points[v - r.first_new_vertex]));
    }
    r.first_new_vertex = first_new;
    r.new_vertex_points = std::move(new_points);
    r.vertex_locations = std::move(locations);
    r.rounding_error += r.rounding.largest_change;
  }

  // Where each output vertex lies on A and on B: input vertices are at
  // themselves; every intersection point was located exactly on its two
  // faces (the most specific location wins: vertex, then edge, then face).
  void locate_output_vertices(const std::vector<Index>& new_index, Result& r) {
    using Kind = Surface_location::Kind;
    r.vertex_locations.assign(r.mesh.vertices.size(), {});
    const auto set = [&](Index out, int m, const Surface_location& l) {
      Surface_location& x = r.vertex_locations[out][m];
      if (x.kind == Kind::none || l.kind < x.kind) x = l;
    };
    for (int m = 0; m < 2; ++m)
      for (Index v = 0; v < mesh_[m]->vertices.size(); ++v)
        if (const Index g = new_index[offset_[m] + v]; g != invalid_index) set(g, m, {Kind::vertex, {v, invalid_index}});
    for (const Located_point& l : located_) {
      const Index g = new_index[find(l.point)];
      if (g == invalid_index) continue;
      for (int m = 0; m < 2; ++m) {
        const Index f = l.face[m];
        const Triangle& t = mesh_[m]->faces[f];
        const Triangle_location& w = l.where[m];
        switch (w.kind) {
          case Triangle_location::Kind::vertex: set(g, m, {Kind::vertex, {t[w.index], invalid_index}}); break;
          case Triangle_location::Kind::edge: set(g, m, {Kind::edge, {t[w.index], t[(w.index + 1) % 3]}, f}); break;
          case Triangle_location::Kind::interior: set(g, m, {Kind::face, {t[0], t[1]}, f}); break;
        }
      }
    }
  }

  std::array<const Mesh*, 2> mesh_;
  // The operands' half-edge opposites (Mesh_topology::opposite) and face
  // hierarchies, built once (by the checks when they run).
  std::array<std::vector<Index>, 2> opposite_;
  std::array<std::optional<Face_bvh>, 2> bvh_;
  // The broad phase's pairs (face of A, face of B), kept for the validation
  // when the operands are certified.
  std::vector<Face_pair> candidate_pairs_;
  Boolean_operation op_;
  const K& k_;
  Boolean_options options_;
  std::array<Index, 2> offset_{};
  Point_table<K, OP> points_;
  Union_find<Index> equal_points_;
  std::vector<Located_point> located_;
  std::unordered_map<Cell_pair, Index, Cell_pair_hash> point_of_cells_;
  std::vector<Segment> segments_;
  std::array<std::unordered_map<Index, std::vector<Index>>, 2> coplanar_;
  Edge_set curves_;
  std::array<Pieces, 2> pieces_;
  std::array<std::vector<Piece_label>, 2> labels_;
};

/// The result under K's Double_point_kernel D as a result of K: the same
/// output, the new vertices as K's points (the kernel hook,
/// Has_implicit_double_point_kernel).
template <IntersectionKernel_3 K, IntersectionKernel_3 D = typename K::Double_point_kernel>
Boolean_result<K> with_kernel_points(Boolean_result<D>&& r) {
  Boolean_result<K> out;
  out.new_vertex_points.reserve(r.new_vertex_points.size());
  for (const auto& v : r.new_vertex_points) out.new_vertex_points.push_back(K::from_double_point_kernel(v));
  static_cast<Boolean_output&>(out) = std::move(static_cast<Boolean_output&>(r));
  return out;
}

}  // namespace internal

// relgeo::boolean (declared with its documentation and defaults in
// boolean/compiled.h).
template <IntersectionKernel_3 K>
Boolean_result<K> boolean(const Triangle_mesh<Point_3<double>>& a, const Triangle_mesh<Point_3<double>>& b,
                          Boolean_operation op, const K& k, const Boolean_options& options) {
  if constexpr (Has_implicit_double_point_kernel<K>) {
    if (options.use_double_point_kernel) {
      // The engine is gone (its memory freed) before the points are converted.
      using D = typename K::Double_point_kernel;
      Boolean_result<D> r = internal::Boolean_engine<D>(a, b, op, D{}, options).run();
      return internal::with_kernel_points<K>(std::move(r));
    }
  }
  return internal::Boolean_engine<K>(a, b, op, k, options).run();
}

/// \brief The Boolean of two solids whose vertices are K's exact points:
/// one step of an exact chain, whose results stay exact and are rounded once
/// at the end (doc/boolean.md, "Exact chains"). The engine, the options and
/// the result are those of the Boolean on doubles, except:
/// - the operand checks decide under K (exactly, on K's points);
/// - every output vertex is rounded (first_new_vertex is 0, and
///   new_vertex_points holds every vertex's exact point);
/// - `validation` (validate_output) is the exact result's, under K, with
///   the operands' certificates (an Operand_certificate for these two
///   meshes, or the operand checks): what certifies exact_mesh() as the next
///   operand. The rounded `mesh` is not validated (validate_solid does it);
/// - use_double_point_kernel does not apply.
/// exact_operand() makes a mesh of doubles one. The result's exact_mesh() is
/// the next step's operand (run the steps with
/// Output_rounding::nearest, which keeps the exact faces; the last one with
/// the rounding wanted in doubles). Coordinates grow with every step: see the
/// documentation for the cost.
/// \throws Invalid_operand as the Boolean on doubles does.
template <ExactChainingKernel K>
Boolean_result<K> boolean(const Triangle_mesh<typename K::Point_3>& a, const Triangle_mesh<typename K::Point_3>& b,
                          Boolean_operation op, const K& k, const Boolean_options& options = {}) {
  return internal::Boolean_engine<K, typename K::Point_3>(a, b, op, k, options).run();
}

/// A mesh of doubles as a mesh of K's points (exactly: every double is a
/// rational): an operand of an exact chain.
template <ExactChainingKernel K>
Triangle_mesh<typename K::Point_3> exact_operand(const Triangle_mesh<Point_3<double>>& m, const K& k) {
  Triangle_mesh<typename K::Point_3> e;
  e.faces = m.faces;
  e.vertices.reserve(m.vertices.size());
  const auto point = k.construct_point_3_object();
  for (const Point_3<double>& v : m.vertices) e.vertices.push_back(point(v.x, v.y, v.z));
  return e;
}

}  // namespace relgeo
