// relgeo/mesh/rounding_repair.h — undo what rounding to doubles did to a
// mesh that was valid before it: faces that cross or touch each other, and
// faces that became degenerate, removed by local changes, each decided with
// exact predicates on the doubles (Filtered_exact_kernel).
//
// Rounding an exact result vertex by vertex to the nearest doubles can turn a
// thin triangle over, push a vertex through a nearly tangent face, or put two
// distinct points on one double. Snap rounding (Halperin-Packer in the plane;
// CGAL's snap rounding of triangle soups) re-splits faces at such places; the
// Boolean's output must stay a closed oriented manifold, so this repair works
// by the local operations that keep it one, as Manifold's cleanup does, and
// checks each operation exactly before keeping it:
//   1. move: a rounded vertex may take any double within one unit in the last
//      place of its nearest rounding (27 positions): the one whose star has
//      the fewest defects;
//   2. flip: the edge under a sliver whose apex lies within `tolerance` of it
//      (the surface moves by that height at most);
//   3. collapse: an edge not longer than `tolerance`, or a vertex within
//      `tolerance` of the segment between two of its neighbours onto one of
//      them (the link condition kept: the mesh stays a manifold).
// Rounds of detection and repair repeat until no defect is left or
// max_rounds; the report says which defects remain (never a silent invalid
// mesh) and the largest change made. Only faces with a rounded vertex or a
// changed face can cross: the rest is the exact result, which is valid.
// What the repair keeps per face or vertex of the whole mesh is a few bytes
// (flags, the vertices' stars in one table); its hierarchy for the local
// tests holds the faces near the round's defects, so that a repair of a few
// faces of a large mesh costs little memory.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/internal/diagonal_separation.h"
#include "relgeo/mesh/internal/embedded_stars.h"
#include "relgeo/mesh/internal/face_pair_predicates.h"
#include "relgeo/mesh/rounding_repair_report.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

namespace internal {

// The faces around each vertex: one table for the whole mesh, built once,
// and a copy of each star the repair reads or changes (few: the repair is
// local), kept in the faces' order of the table.
class Vertex_stars {
 public:
  Vertex_stars() = default;
  Vertex_stars(const std::vector<Triangle>& faces, std::size_t vertex_count) : first_(vertex_count + 1, 0) {
    for (const Triangle& t : faces)
      for (Index v : t) ++first_[v + 1];
    std::partial_sum(first_.begin(), first_.end(), first_.begin());
    face_.resize(first_.back());
    std::vector<Index> next(first_.begin(), first_.end() - 1);
    for (Index f = 0; f < faces.size(); ++f)
      for (Index v : faces[f]) face_[next[v]++] = f;
  }
  // The star of v to read and change (its references stay valid).
  std::vector<Index>& operator[](Index v) {
    auto it = copied_.find(v);
    if (it == copied_.end()) it = copied_.emplace(v, std::vector<Index>(table(v).begin(), table(v).end())).first;
    return it->second;
  }
  // The star of v to read only, without copying it.
  std::span<const Index> view(Index v) const {
    const auto it = copied_.find(v);
    return it == copied_.end() ? table(v) : std::span<const Index>(it->second);
  }

 private:
  std::span<const Index> table(Index v) const { return {face_.data() + first_[v], face_.data() + first_[v + 1]}; }
  std::vector<std::size_t> first_;
  std::vector<Index> face_;
  std::unordered_map<Index, std::vector<Index>> copied_;
};

class Rounding_repair {
 public:
  using K = Filtered_exact_kernel;
  using Mesh = Triangle_mesh<Point_3<double>>;
  // The kernel's points are the mesh's vertices themselves.
  static_assert(std::is_same_v<K::Point_3, Point_3<double>>);

  // `regions`: of how many of a round's defect faces the neighbourhood is
  // in its hierarchy (all by default; fewer only for tests: the faces of
  // the others are found by the search of every face).
  Rounding_repair(Mesh& m, const std::vector<char>& movable, const Rounding_repair_options& o,
                  std::size_t regions = std::numeric_limits<std::size_t>::max())
      : m_(m),
        movable_(movable),
        options_(o),
        region_limit_(regions),
        removed_(m.faces.size(), 0),
        active_(m.faces.size(), 0) {
    for (Index f = 0; f < m.faces.size(); ++f)
      for (Index v : m.faces[f]) active_[f] = active_[f] || movable_[v];
  }

  Rounding_repair_report run(Rounding_repair_maps& maps) {
    Rounding_repair_report r;
    std::vector<Face_pair> pairs;
    std::vector<Index> degenerate;
    detect(pairs, degenerate);
    r.defects_before = pairs.size() + degenerate.size();
    if (r.defects_before == 0 || options_.max_rounds <= 0) {  // the mesh is left as it is
      maps.vertex_map.resize(m_.vertices.size());
      std::iota(maps.vertex_map.begin(), maps.vertex_map.end(), Index(0));
      maps.face_origin.resize(m_.faces.size());
      std::iota(maps.face_origin.begin(), maps.face_origin.end(), Index(0));
      r.remaining_pairs = std::move(pairs);
      r.remaining_degenerate_faces = std::move(degenerate);
      return r;
    }
    prepare_repair();
    while ((!pairs.empty() || !degenerate.empty()) && r.rounds < options_.max_rounds) {
      ++r.rounds;
      repair_round(pairs, degenerate, r);
      detect_after_round(pairs, degenerate);
    }
    compact(maps);
    for (auto& [f, g] : pairs) {
      f = face_index_[f], g = face_index_[g];
      if (f > g) std::swap(f, g);
    }
    std::sort(pairs.begin(), pairs.end());
    for (Index& f : degenerate) f = face_index_[f];
    r.remaining_pairs = std::move(pairs);
    r.remaining_degenerate_faces = std::move(degenerate);
    return r;
  }

 private:
  // What only a repair needs: the creases, the tolerance in the mesh's
  // units (and the vertices' stars, which the detection built).
  void prepare_repair() {
    stamp_.assign(m_.faces.size(), 0);
    for (const Edge& e : m_.tags.creases()) creases_.push_back(edge_key(e.a, e.b));
    std::sort(creases_.begin(), creases_.end());
    Box_3 all;
    for (const auto& p : m_.vertices) all.extend(p.x, p.y, p.z);
    if (!all.is_empty())
      tolerance_ = options_.tolerance * std::hypot(all.hi[0] - all.lo[0], all.hi[1] - all.lo[1], all.hi[2] - all.lo[2]);
  }

  // ---- detection ----------------------------------------------------------------

  bool degenerate(Index f) const {
    const Triangle& t = m_.faces[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
    for (int plane = 0; plane < 3; ++plane)
      if (!certainly(projected_orientation(k_, m_.vertices, t, plane), Certified_sign::zero))
        return false;  // the filtered exact kernel decides every sign
    return true;
  }
  // Two live, non-degenerate faces meet beyond what they share (undecided
  // cannot happen under the exact kernel; it counts as meeting).
  bool meet(Index f, Index g) const {
    const Maybe x = faces_meet_beyond_shared(k_, m_.vertices, m_.faces[f], m_.faces[g]);
    return !x || *x;
  }
  Box_3 box(Index f) const {
    Box_3 b;
    for (Index v : m_.faces[f]) b.extend(m_.vertices[v].x, m_.vertices[v].y, m_.vertices[v].z);
    return b;
  }

  // Every defect that involves an active face (one with a rounded vertex or
  // changed by a repair). Most faces are inactive and most pairs do not
  // meet: degeneracy is decided only for the faces a test needs.
  void detect(std::vector<Face_pair>& pairs, std::vector<Index>& degenerate_faces) {
    pairs.clear(), degenerate_faces.clear();
    const Index n = static_cast<Index>(m_.faces.size());
    std::vector<Index> active_faces;
    is_degenerate_.assign(n, -1);
    for (Index f = 0; f < n; ++f)
      if (!removed_[f] && active_[f]) active_faces.push_back(f);
    star_ = Vertex_stars(m_.faces, m_.vertices.size());
    const std::vector<unsigned char> embedded = embedded_stars_of(active_faces);
    find_defects_of(
        active_faces, [&](Index f) { return active_[f] != 0; }, pairs, degenerate_faces, &embedded);
  }
  // 1 for each vertex of `faces` whose star a coordinate projection embeds
  // (star_embedded, internal/embedded_stars.h): two faces sharing it meet
  // only in what they share. Most pairs the detection meets are such
  // neighbours, and one test per vertex decides them all (on the elephant's
  // union it leaves 2,950 of 24,620 pairs to test). From the stars as they
  // are before any repair.
  std::vector<unsigned char> embedded_stars_of(const std::vector<Index>& faces) const {
    std::vector<std::array<Certified_sign, 3>> projected(m_.faces.size());
    std::vector<char> known(m_.faces.size(), 0);
    const auto projected_of = [&](Index f) -> const std::array<Certified_sign, 3>& {
      if (!known[f]) {
        for (int plane = 0; plane < 3; ++plane)
          projected[f][plane] = projected_orientation(k_, m_.vertices, m_.faces[f], plane);
        known[f] = 1;
      }
      return projected[f];
    };
    constexpr unsigned char untried = 0, embedded = 1, not_embedded = 2;
    std::vector<unsigned char> state(m_.vertices.size(), untried);
    for (Index f : faces)
      for (Index v : m_.faces[f])
        if (state[v] == untried)
          state[v] = star_embedded(k_, m_.vertices, m_.faces, v, star_.view(v), projected_of) ? embedded : not_embedded;
    for (unsigned char& s : state) s = s == embedded;
    return state;
  }
  // After a round: the defects of the faces it changed, and those found
  // before among the faces it left as they were (which still are).
  void detect_after_round(std::vector<Face_pair>& pairs, std::vector<Index>& degenerate_faces) {
    const auto gone = [&](Index f) { return removed_[f] || dirty_mark(f); };
    std::erase_if(pairs, [&](const Face_pair& p) { return gone(p.first) || gone(p.second); });
    std::erase_if(degenerate_faces, gone);
    std::vector<Index> changed;
    for (Index f : dirty_)
      if (!removed_[f]) changed.push_back(f), is_degenerate_[f] = -1;
    std::sort(changed.begin(), changed.end());
    find_defects_of(
        changed, [&](Index f) { return dirty_mark(f); }, pairs, degenerate_faces);
    std::sort(degenerate_faces.begin(), degenerate_faces.end());
  }
  // Adds the defects of the faces `of` (sorted; in(f): f is one of them):
  // each degenerate one, and each pair of one of them and a live face that
  // meet. Pairs sharing a vertex flagged in `embedded` are left out (that
  // certificate decides them), and so are pairs that a diagonal direction
  // separates (internal/diagonal_separation.h; the extents of the faces of
  // `of` first, of a block's faces when first met, from the mesh as it is
  // now). Pairs of two of them from their hierarchy's own descent, each pair once; the other live faces a block at a
  // time (no box per face of the whole mesh at once), each block's boxes searched in that hierarchy. Two earlier
  // searches were slower: every live face's box searched (each pair of two of them met twice: the elephant's union 5.0
  // against 3.5 ms for the candidates), and one hierarchy of all live faces
  // descended by groups (no pair of two others). With the latter the
  // rounding phase of the benchmark's unions took longer, even with three
  // faces in four to test (best of 40, ms): gear 28.7 against 28.0,
  // elephant 7.9 against 5.5, armadillo 22.2 against 10.3.
  template <class In>
  void find_defects_of(const std::vector<Index>& of, In&& in, std::vector<Face_pair>& pairs,
                       std::vector<Index>& degenerate_faces, const std::vector<unsigned char>* embedded = nullptr) {
    for (Index f : of)
      if (known_degenerate(f)) degenerate_faces.push_back(f);
    std::vector<Box_3> of_boxes;
    std::vector<Diagonal_extents> of_extents;
    for (Index f : of) of_boxes.push_back(box(f)), of_extents.push_back(diagonal_extents(m_.vertices, m_.faces[f]));
    const Face_bvh hierarchy(of_boxes);
    hierarchy.for_each_overlapping_pair([&](Index i, Index j) {
      const Index f = of[i], g = of[j];
      if (diagonally_separated(of_extents[i], of_extents[j])) return;
      if (defect(f, g, embedded)) pairs.push_back({std::min(f, g), std::max(f, g)});
    });
    const Index n = static_cast<Index>(m_.faces.size());
    constexpr Index block = 4096;
    std::vector<Index> faces;
    std::vector<Box_3> boxes;
    std::vector<Diagonal_extents> block_extents(block);
    std::vector<unsigned char> known(block);
    for (Index begin = 0; begin < n; begin += block) {
      faces.clear(), boxes.clear();
      std::fill(known.begin(), known.end(), 0);
      for (Index f = begin; f < std::min(n, begin + block); ++f)
        if (!removed_[f] && !in(f)) faces.push_back(f), boxes.push_back(box(f));
      for (const auto& [j, i] : hierarchy.overlapping_pairs_with_boxes(boxes)) {
        const Index f = faces[j], g = of[i];
        if (!known[j]) block_extents[j] = diagonal_extents(m_.vertices, m_.faces[f]), known[j] = 1;
        if (diagonally_separated(block_extents[j], of_extents[i])) continue;
        if (defect(f, g, embedded)) pairs.push_back({std::min(f, g), std::max(f, g)});
      }
    }
    std::sort(pairs.begin(), pairs.end());
  }
  // Distinct live faces f and g meet beyond what they share; false when
  // one is degenerate (the detection lists those apart).
  bool defect(Index f, Index g, const std::vector<unsigned char>* embedded) {
    if (known_degenerate(f) || known_degenerate(g)) return false;
    if (embedded && share_embedded_star(m_.faces[f], m_.faces[g], *embedded)) return false;
    return meet(f, g);
  }
  // Degeneracy of a face unchanged since the detection, decided once.
  bool known_degenerate(Index f) {
    if (is_degenerate_[f] < 0) is_degenerate_[f] = degenerate(f);
    return is_degenerate_[f] != 0;
  }
  // The hierarchy for the local tests of one round: of the live faces near
  // the round's defect faces. Near: a box around each defect face's two
  // rings of faces (those the round's moves, flips and collapses change or
  // test), widened by what they may move. A test of a face whose box leaves
  // every region (rare: a chain of collapses) builds it over every live face.
  void build_hierarchy(const std::vector<Index>& defect_faces) {
    regions_.clear();
    for (std::size_t i = 0; i < std::min(defect_faces.size(), region_limit_); ++i)
      regions_.push_back(widened(two_rings_box(defect_faces[i])));
    // A tolerance so large (or NaN) that a region is not finite: no region.
    const auto finite = [](const Box_3& r) {
      for (int k = 0; k < 3; ++k)
        if (!std::isfinite(r.lo[k]) || !std::isfinite(r.hi[k])) return false;
      return true;
    };
    if (!std::all_of(regions_.begin(), regions_.end(), finite)) regions_.clear();
    regions_bvh_ = Face_bvh(regions_);
    std::vector<Box_3> boxes;
    live_faces_.clear();
    for (Index f = 0; f < m_.faces.size(); ++f) {
      if (removed_[f]) continue;
      const Box_3 b = box(f);
      bool near = false;
      regions_bvh_.for_each_face_in_box(b, [&](Index) { near = true; });
      if (near) live_faces_.push_back(f), boxes.push_back(b);
    }
    bvh_ = Face_bvh(boxes);
    whole_ = false;
    dirty_.clear();
  }
  void build_whole_hierarchy() {
    std::vector<Box_3> boxes;
    live_faces_.clear();
    for (Index f = 0; f < m_.faces.size(); ++f)
      if (!removed_[f]) live_faces_.push_back(f), boxes.push_back(box(f));
    bvh_ = Face_bvh(boxes);
    whole_ = true;
  }
  // Every face whose box meets b is in the hierarchy (or dirty).
  bool hierarchy_covers(const Box_3& b) const {
    if (whole_) return true;
    bool inside = false;
    regions_bvh_.for_each_face_in_box(b, [&](Index i) {
      const Box_3& r = regions_[i];
      inside = inside || (r.lo[0] <= b.lo[0] && r.lo[1] <= b.lo[1] && r.lo[2] <= b.lo[2] && b.hi[0] <= r.hi[0] &&
                          b.hi[1] <= r.hi[1] && b.hi[2] <= r.hi[2]);
    });
    return inside;
  }
  Box_3 two_rings_box(Index f) const {
    Box_3 b;
    for (Index v : m_.faces[f])
      for (Index g : star_.view(v))
        if (!removed_[g])
          for (Index u : m_.faces[g])
            for (Index h : star_.view(u))
              if (!removed_[h]) b.extend(box(h));
    return b;
  }
  // b grown by twice the tolerance and a few units in the last place.
  Box_3 widened(Box_3 b) const {
    double largest = 0;
    for (int k = 0; k < 3; ++k) largest = std::max({largest, std::abs(b.lo[k]), std::abs(b.hi[k])});
    const double margin = 2 * tolerance_ + 16 * std::numeric_limits<double>::epsilon() * largest;
    for (int k = 0; k < 3; ++k) b.lo[k] -= margin, b.hi[k] += margin;
    return b;
  }

  // Defects of the faces in `s`: each degenerate face, and each pair of a
  // face of s and a face that meets it beyond what they share. The faces of
  // s are tested with each other directly (their boxes in the hierarchy are
  // stale while a vertex of theirs tries positions), and with the dirty faces.
  std::size_t defects(std::vector<Index> s, std::size_t enough = std::numeric_limits<std::size_t>::max()) {
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    std::erase_if(s, [&](Index f) { return removed_[f] != 0; });
    ++current_stamp_;
    std::size_t count = 0;
    std::vector<Index> live;
    for (Index f : s) {
      stamp_[f] = current_stamp_;
      if (degenerate(f)) ++count;
      else live.push_back(f);
    }
    for (std::size_t i = 0; i < live.size() && count < enough; ++i)
      for (std::size_t j = i + 1; j < live.size(); ++j) count += meet(live[i], live[j]);
    for (Index f : live) {
      if (count >= enough) break;  // the caller only needs to know it is not fewer
      const Box_3 b = box(f);
      if (!hierarchy_covers(b)) build_whole_hierarchy();
      const auto test = [&](Index g) {
        if (removed_[g] || stamp_[g] == current_stamp_) return;
        // Faces untouched since the detection keep their degeneracy flag.
        if (dirty_mark(g) ? degenerate(g) : known_degenerate(g)) return;
        count += meet(f, g);
      };
      bvh_.for_each_face_in_box(b, [&](Index i) {
        if (!dirty_mark(live_faces_[i])) test(live_faces_[i]);  // a dirty face's box in the hierarchy is stale
      });
      for (Index g : dirty_)
        if (do_overlap(b, box(g))) test(g);
    }
    return count;
  }
  bool dirty_mark(Index f) const { return f < is_dirty_.size() && is_dirty_[f]; }
  void make_dirty(Index f) {
    if (is_dirty_.size() < m_.faces.size()) is_dirty_.resize(m_.faces.size(), 0);
    if (!is_dirty_[f]) is_dirty_[f] = 1, dirty_.push_back(f);
    active_[f] = 1;
  }

  // ---- one round -------------------------------------------------------------------

  void repair_round(const std::vector<Face_pair>& pairs, const std::vector<Index>& degenerate_faces,
                    Rounding_repair_report& r) {
    std::fill(is_dirty_.begin(), is_dirty_.end(), 0);
    std::vector<Index> faces = degenerate_faces;
    for (const auto& [f, g] : pairs) faces.push_back(f), faces.push_back(g);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    build_hierarchy(faces);
    std::vector<Index> vertices;
    for (Index f : faces)
      for (Index v : m_.faces[f])
        if (movable_[v]) vertices.push_back(v);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    for (Index v : vertices) move_vertex(v, r);
    for (Index f : faces)
      if (!removed_[f] && defects({f})) flip_under_sliver(f, r);
    for (Index f : faces)
      if (!removed_[f] && defects({f})) collapse_shortest_edge(f, r);
    for (Index f : faces)
      if (!removed_[f] && defects({f})) collapse_collinear_vertex(f, r);
  }

  void set_position(Index v, const Point_3<double>& p) {
    home_.try_emplace(v, m_.vertices[v]);
    m_.vertices[v] = p;
  }
  // Where v was before the repair (only set_position moves a vertex).
  Point_3<double> home(Index v) const {
    const auto it = home_.find(v);
    return it == home_.end() ? m_.vertices[v] : it->second;
  }

  // 1. The position whose star has the fewest defects among: the doubles
  // within one unit in the last place of v's first position, and those
  // whose coordinates are taken from v's neighbours within the tolerance
  // (points that should lie on one line or plane, scattered by earlier
  // roundings, are aligned again).
  void move_vertex(Index v, Rounding_repair_report& r) {
    const std::vector<Index>& s = star_[v];
    const Point_3<double> start = m_.vertices[v];
    std::size_t best = defects(s);
    if (best == 0) return;
    Point_3<double> best_position = start;
    const Point_3<double> h = home(v);
    const auto try_each = [&](const std::array<std::vector<double>, 3>& values) {
      for (double x : values[0])
        for (double y : values[1])
          for (double z : values[2]) {
            if (best == 0) return;
            const Point_3<double> p{x, y, z};
            if (p == start || p == best_position) continue;
            set_position(v, p);
            const std::size_t d = defects(s, best);
            if (d < best) best = d, best_position = p;
          }
    };
    // The neighbouring doubles first; neighbours' coordinates only when
    // those leave defects.
    std::array<std::vector<double>, 3> values;
    const double inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const double x = coordinate(h, i);
      values[i] = {x, std::nextafter(x, -inf), std::nextafter(x, inf)};
    }
    try_each(values);
    if (best > 0) {
      for (Index f : s)
        for (Index u : m_.faces[f])
          for (int i = 0; i < 3; ++i) {
            const double x = coordinate(m_.vertices[u], i);
            if (u != v && std::abs(x - coordinate(h, i)) <= tolerance_) values[i].push_back(x);
          }
      for (auto& c : values) {
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
      }
      try_each(values);
    }
    set_position(v, best_position);
    if (best_position == start) return;
    ++r.moved_vertices;
    r.largest_change = std::max(r.largest_change, distance(best_position, h));
    for (Index f : s) make_dirty(f);
  }

  static double distance(const Point_3<double>& a, const Point_3<double>& b) {
    return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
  }
  // Distance from p to the segment [a, b] (doubles: only compared with the tolerance).
  static double distance_to_segment(const Point_3<double>& p, const Point_3<double>& a, const Point_3<double>& b) {
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const double len2 = ux * ux + uy * uy + uz * uz;
    double t = len2 > 0 ? ((p.x - a.x) * ux + (p.y - a.y) * uy + (p.z - a.z) * uz) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return distance(p, {a.x + t * ux, a.y + t * uy, a.z + t * uz});
  }
  static std::pair<Index, Index> edge_key(Index a, Index b) { return a < b ? std::pair{a, b} : std::pair{b, a}; }
  bool is_crease(Index a, Index b) const {
    return std::binary_search(creases_.begin(), creases_.end(), edge_key(a, b));
  }
  // The live faces that contain both a and b.
  std::vector<Index> faces_on_edge(Index a, Index b) const {
    std::vector<Index> out;
    for (Index f : star_.view(a))
      if (!removed_[f] && std::find(m_.faces[f].begin(), m_.faces[f].end(), b) != m_.faces[f].end()) out.push_back(f);
    return out;
  }
  static Index third(const Triangle& t, Index a, Index b) {
    for (Index v : t)
      if (v != a && v != b) return v;
    return invalid_index;
  }
  void erase_from_star(Index v, Index f) {
    auto& s = star_[v];
    s.erase(std::remove(s.begin(), s.end(), f), s.end());
  }

  // 2. Flip an edge of f under a sliver: the corner opposite it in f or
  // across lies within the tolerance of it. A crease under a sliver is
  // rerouted through the sliver's apex (the curve moves by the sliver's
  // height, as snap rounding routes a segment through a hot pixel). Kept
  // when it removes defects of the two faces without making new ones.
  void flip_under_sliver(Index f, Rounding_repair_report& r) {
    for (int e = 0; e < 3; ++e) {
      const Triangle t = m_.faces[f];
      const Index a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
      const std::vector<Index> on_edge = faces_on_edge(a, b);
      if (on_edge.size() != 2) continue;
      const Index g = on_edge[0] == f ? on_edge[1] : on_edge[0];
      const Index d = third(m_.faces[g], a, b);
      if (d == c || !faces_on_edge(c, d).empty()) continue;
      const double hc = distance_to_segment(m_.vertices[c], m_.vertices[a], m_.vertices[b]);
      const double hd = distance_to_segment(m_.vertices[d], m_.vertices[a], m_.vertices[b]);
      const Index apex = hc <= hd ? c : d;
      const double height = std::min(hc, hd);
      if (height > tolerance_) continue;
      const std::size_t before = defects({f, g});
      const Triangle old_f = m_.faces[f], old_g = m_.faces[g];
      // f = (a, b, c) and g = (b, a, d) become (c, a, d) and (d, b, c).
      m_.faces[f] = {c, a, d}, m_.faces[g] = {d, b, c};
      if (defects({f, g}) < before) {
        erase_from_star(b, f), erase_from_star(a, g);
        star_[d].push_back(f), star_[c].push_back(g);
        make_dirty(f), make_dirty(g);
        if (is_crease(a, b)) reroute_crease(a, b, apex);
        ++r.flips;
        r.largest_change = std::max(r.largest_change, height);
        return;
      }
      m_.faces[f] = old_f, m_.faces[g] = old_g;
    }
  }
  void reroute_crease(Index a, Index b, Index through) {
    std::erase(creases_, edge_key(a, b));
    creases_.push_back(edge_key(a, through)), creases_.push_back(edge_key(through, b));
    std::sort(creases_.begin(), creases_.end());
    creases_.erase(std::unique(creases_.begin(), creases_.end()), creases_.end());
  }

  // 3. Collapse f's shortest edge (w onto u, an input vertex kept when there
  // is one) if it is within the tolerance.
  void collapse_shortest_edge(Index f, Rounding_repair_report& r) {
    const Triangle t = m_.faces[f];
    int e = 0;
    for (int i = 1; i < 3; ++i)
      if (distance(m_.vertices[t[i]], m_.vertices[t[(i + 1) % 3]]) <
          distance(m_.vertices[t[e]], m_.vertices[t[(e + 1) % 3]]))
        e = i;
    Index u = t[e], w = t[(e + 1) % 3];
    const double length = distance(m_.vertices[u], m_.vertices[w]);
    if (length > tolerance_) return;
    if (movable_[u] && !movable_[w]) std::swap(u, w);
    try_collapse(w, u, length, r);
  }

  // 4. Collapse a rounded vertex v of f that lies within the tolerance of
  // the segment between two of its neighbours onto one of them (Manifold's
  // collapse of collinear edges): the surface moves by that distance, the
  // edge may be long. Rounded chains of nearly collinear points (an
  // intersection curve across faces that earlier roundings left a unit in
  // the last place out of plane) leave slivers that no move or flip fixes.
  void collapse_collinear_vertex(Index f, Rounding_repair_report& r) {
    for (Index v : m_.faces[f]) {
      if (!movable_[v]) continue;
      std::vector<Index> neighbours;
      for (Index g : star_[v])
        for (Index x : m_.faces[g])
          if (x != v) neighbours.push_back(x);
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      for (std::size_t i = 0; i < neighbours.size(); ++i)
        for (std::size_t j = i + 1; j < neighbours.size(); ++j) {
          const Index u = neighbours[i], x = neighbours[j];
          if (distance_to_segment(m_.vertices[v], m_.vertices[u], m_.vertices[x]) > tolerance_) continue;
          for (Index onto : {u, x}) {
            const double change = collapse_change(v, onto);
            if (change <= tolerance_ && try_collapse(v, onto, change, r)) return;
          }
        }
    }
  }

  // How far collapsing v onto u moves the surface, at most: v's distance
  // from the plane of each face that v's faces become (a face of v's star
  // across an edge of the operand's mesh is not in one plane with v's
  // neighbours: then this is large and the collapse is not made).
  double collapse_change(Index v, Index u) const {
    double change = 0;
    const Point_3<double>& p = m_.vertices[v];
    for (Index g : star_.view(v)) {
      if (removed_[g]) continue;
      const Triangle& t = m_.faces[g];
      if (std::find(t.begin(), t.end(), u) != t.end()) continue;  // removed by the collapse
      std::array<Point_3<double>, 3> c;
      for (int i = 0; i < 3; ++i) c[i] = t[i] == v ? m_.vertices[u] : m_.vertices[t[i]];
      const double ux = c[1].x - c[0].x, uy = c[1].y - c[0].y, uz = c[1].z - c[0].z;
      const double wx = c[2].x - c[0].x, wy = c[2].y - c[0].y, wz = c[2].z - c[0].z;
      const double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
      const double n = std::hypot(nx, ny, nz);
      if (!(n > 0)) return std::numeric_limits<double>::infinity();
      change = std::max(change, std::abs(nx * (p.x - c[0].x) + ny * (p.y - c[0].y) + nz * (p.z - c[0].z)) / n);
    }
    return change;
  }

  // Collapses edge (w, u) onto u when it is an edge of two faces, the link
  // condition holds and the defects around u do not increase (not more is
  // enough: the mesh has one vertex fewer, so collapses cannot cycle, and a
  // cluster of near-equal points needs several before the defects go).
  // `change`: how far the surface moves.
  bool try_collapse(Index w, Index u, double change, Rounding_repair_report& r) {
    const std::vector<Index> on_edge = faces_on_edge(u, w);
    if (on_edge.size() != 2 || !link_condition(u, w, on_edge)) return false;
    std::vector<Index> around = star_[u];
    around.insert(around.end(), star_[w].begin(), star_[w].end());
    const std::size_t before = defects(around);
    const std::vector<Index> old_u = star_[u], old_w = star_[w];
    std::vector<std::pair<Index, Triangle>> old_faces;
    for (Index g : star_[w]) old_faces.push_back({g, m_.faces[g]});
    for (Index g : on_edge) removed_[g] = 1;
    for (Index g : star_[w]) {
      if (removed_[g]) continue;
      for (Index& v : m_.faces[g])
        if (v == w) v = u;
      star_[u].push_back(g);
    }
    star_[w].clear();
    for (Index g : on_edge) erase_from_star(u, g), erase_from_star(third(m_.faces[g], u, w), g);
    if (defects(star_[u]) <= before) {
      for (Index g : star_[u]) make_dirty(g);
      rename_creases(w, u);
      ++r.collapses;
      r.largest_change = std::max(r.largest_change, change);
      return true;
    }
    for (Index g : on_edge) {
      removed_[g] = 0;
      const Index x = third(m_.faces[g], u, w);
      if (std::find(star_[x].begin(), star_[x].end(), g) == star_[x].end()) star_[x].push_back(g);
    }
    for (const auto& [g, tri] : old_faces) m_.faces[g] = tri;
    star_[u] = old_u, star_[w] = old_w;
    return false;
  }
  // u and w have exactly the two common neighbours of the faces on their edge.
  bool link_condition(Index u, Index w, const std::vector<Index>& on_edge) const {
    std::vector<Index> nu, nw;
    for (Index g : star_.view(u))
      if (!removed_[g]) nu.insert(nu.end(), m_.faces[g].begin(), m_.faces[g].end());
    for (Index g : star_.view(w))
      if (!removed_[g]) nw.insert(nw.end(), m_.faces[g].begin(), m_.faces[g].end());
    std::sort(nu.begin(), nu.end()), nu.erase(std::unique(nu.begin(), nu.end()), nu.end());
    std::sort(nw.begin(), nw.end()), nw.erase(std::unique(nw.begin(), nw.end()), nw.end());
    std::vector<Index> common;
    std::set_intersection(nu.begin(), nu.end(), nw.begin(), nw.end(), std::back_inserter(common));
    std::erase_if(common, [&](Index x) { return x == u || x == w; });
    const Index x = third(m_.faces[on_edge[0]], u, w), y = third(m_.faces[on_edge[1]], u, w);
    return common.size() == 2 && x != y && std::find(common.begin(), common.end(), x) != common.end() &&
           std::find(common.begin(), common.end(), y) != common.end();
  }
  void rename_creases(Index from, Index to) {
    for (auto& c : creases_) {
      if (c.first == from) c.first = to;
      if (c.second == from) c.second = to;
      c = edge_key(c.first, c.second);
    }
    std::erase_if(creases_, [](const std::pair<Index, Index>& c) { return c.first == c.second; });
    std::sort(creases_.begin(), creases_.end());
    creases_.erase(std::unique(creases_.begin(), creases_.end()), creases_.end());
  }

  // ---- the repaired mesh -----------------------------------------------------------

  // Live faces and the vertices they use, in their first order (in place:
  // each moves down, never up).
  void compact(Rounding_repair_maps& r) {
    const Index nv = static_cast<Index>(m_.vertices.size());
    std::vector<char> used(nv, 0);
    for (Index f = 0; f < m_.faces.size(); ++f)
      if (!removed_[f])
        for (Index v : m_.faces[f]) used[v] = 1;
    r.vertex_map.assign(nv, invalid_index);
    Index kept = 0;
    for (Index v = 0; v < nv; ++v)
      if (used[v]) r.vertex_map[v] = kept, m_.vertices[kept++] = m_.vertices[v];
    m_.vertices.resize(kept);
    face_index_.assign(m_.faces.size(), invalid_index);
    r.face_origin.clear();
    kept = 0;
    for (Index f = 0; f < m_.faces.size(); ++f) {
      if (removed_[f]) continue;
      face_index_[f] = kept;
      r.face_origin.push_back(f);
      const Triangle t = m_.faces[f];
      m_.faces[kept++] = {r.vertex_map[t[0]], r.vertex_map[t[1]], r.vertex_map[t[2]]};
    }
    m_.faces.resize(kept);
    std::vector<Edge> creases;
    for (const auto& [a, b] : creases_)
      if (used[a] && used[b]) creases.push_back({r.vertex_map[a], r.vertex_map[b]});
    m_.tags.set_creases(std::move(creases));
  }

  Mesh& m_;
  const std::vector<char>& movable_;
  Rounding_repair_options options_;
  std::size_t region_limit_;
  K k_;
  double tolerance_ = 0;
  std::unordered_map<Index, Point_3<double>> home_;  // of the vertices moved
  Vertex_stars star_;
  std::vector<char> removed_, active_, is_dirty_;
  std::vector<signed char> is_degenerate_;  // -1: not decided yet
  std::vector<Index> dirty_;
  std::vector<unsigned> stamp_;
  unsigned current_stamp_ = 0;
  std::vector<std::pair<Index, Index>> creases_;
  Face_bvh bvh_;  // of live faces at the round's start: those near its defects, or all (whole_)
  std::vector<Index> live_faces_;
  bool whole_ = false;
  std::vector<Box_3> regions_;  // near the round's defects
  Face_bvh regions_bvh_;
  std::vector<Index> face_index_;
};

}  // namespace internal

/// \brief Repairs, in place, the defects that rounding its vertices to
/// doubles made in a closed, oriented triangle mesh (see the file comment):
/// face pairs that meet beyond what they share, and degenerate faces.
///
/// `movable[v]` (one per vertex): v is a rounded point and may move to any
/// double within one unit in the last place of its coordinates; the other
/// vertices move only by a collapse within the tolerance. Only defects that
/// involve a face with a movable vertex are looked for. The mesh's creases
/// are kept (never flipped; renamed through collapses). The result is
/// decided exactly, in every floating-point environment.
/// \pre m is edge-manifold where it is repaired (non-manifold edges are left
/// alone), movable.size() == m.vertices.size().
/// `maps`, when given, receives how vertices and faces were renumbered.
/// \throws Invalid_input for a face index out of range, a coordinate that
/// is not finite, or a tolerance that is negative, NaN or infinite.
inline Rounding_repair_report repair_rounding(Triangle_mesh<Point_3<double>>& m, const std::vector<char>& movable,
                                              const Rounding_repair_options& options = {},
                                              Rounding_repair_maps* maps = nullptr) {
  if (movable.size() != m.vertices.size())
    throw Precondition_violation("repair_rounding: one movable flag per vertex");
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
    throw Invalid_input("repair_rounding: the tolerance must be finite and not negative (it is " +
                        std::to_string(options.tolerance) + ")");
  for (const Triangle& t : m.faces)
    for (Index v : t)
      if (v >= m.vertices.size()) throw Invalid_input("repair_rounding: a face index is out of range");
  for (const auto& p : m.vertices)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Invalid_input("repair_rounding: a vertex coordinate is not finite");
  const Default_fp_environment environment;  // the tolerance and boxes in doubles
  Rounding_repair_maps local;
  return internal::Rounding_repair(m, movable, options).run(maps ? *maps : local);
}

}  // namespace relgeo
