// Face_bvh: pairs and queries against brute force (exact rational slab test
// for segments and rays), thread-count independence, bad input.
#include "relgeo/mesh/face_bvh.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <set>

#include "mesh/solid_fixtures.h"
#include "relgeo/core/dyadic.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

std::vector<Box_3> random_boxes(std::size_t n, std::uint64_t seed, double spread, double size) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-spread, spread), s(0, size);
  std::vector<Box_3> boxes(n);
  for (Box_3& b : boxes)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = u(g);
      b.hi[k] = b.lo[k] + s(g);
    }
  return boxes;
}

std::vector<Face_pair> brute_pairs(const std::vector<Box_3>& a, const std::vector<Box_3>& b) {
  std::vector<Face_pair> out;
  for (Index i = 0; i < a.size(); ++i)
    for (Index j = 0; j < b.size(); ++j)
      if (do_overlap(a[i], b[j])) out.push_back({i, j});
  return out;
}
std::vector<Face_pair> brute_self_pairs(const std::vector<Box_3>& a) {
  std::vector<Face_pair> out;
  for (Index i = 0; i < a.size(); ++i)
    for (Index j = i + 1; j < a.size(); ++j)
      if (do_overlap(a[i], a[j])) out.push_back({i, j});
  return out;
}
std::vector<Face_pair> sorted(std::vector<Face_pair> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(FaceBvh, CrossAndSelfPairsAreExactlyTheOverlappingBoxes) {
  for (Face_bvh_split split : {Face_bvh_split::morton, Face_bvh_split::median})
  for (int leaf : {1, 2, 4, 7, 16, 64})  // 64: the largest leaf, every bit of a leaf's overlap mask
    for (std::size_t n : {std::size_t(1), std::size_t(2), std::size_t(5), std::size_t(300), std::size_t(2000)}) {
      const auto a = random_boxes(n, 3 + n, 1.0, 0.08);
      const auto b = random_boxes(n + 7, 5 + n, 1.0, 0.05);
      const Face_bvh ta(a, {.leaf_size = leaf, .split = split}), tb(b, {.leaf_size = leaf, .split = split});
      ASSERT_EQ(ta.size(), n);
      EXPECT_EQ(sorted(ta.overlapping_pairs(tb)), brute_pairs(a, b)) << "leaf " << leaf << " n " << n;
      EXPECT_EQ(sorted(ta.overlapping_pairs()), brute_self_pairs(a)) << "leaf " << leaf << " n " << n;
      // Boxes without a hierarchy against one: the same pairs, by query box.
      const auto with_boxes = tb.overlapping_pairs_with_boxes(a);
      EXPECT_EQ(sorted(with_boxes), brute_pairs(a, b)) << "leaf " << leaf << " n " << n;
      EXPECT_TRUE(std::is_sorted(with_boxes.begin(), with_boxes.end(),
                                 [](const Face_pair& x, const Face_pair& y) { return x.first < y.first; }));
      // The two hierarchies' search in the queries' order: the same list.
      EXPECT_EQ(ta.overlapping_pairs_in_query_order(tb), with_boxes) << "leaf " << leaf << " n " << n;
      EXPECT_EQ(ta.sorted_overlapping_pairs(tb), brute_pairs(a, b)) << "leaf " << leaf << " n " << n;
      std::size_t calls = 0;
      ta.for_each_overlapping_pair(tb, [&](Index, Index) { ++calls; });
      EXPECT_EQ(calls, brute_pairs(a, b).size());
    }
}

// Groups leave out the pairs within one nonzero group and nothing else:
// spatially coherent groups (whole nodes pruned, group 0 among them) and
// scattered ones (pruned pair by pair), on one and two threads.
TEST(FaceBvh, PairsBetweenGroupsAreThoseOfDifferentOrNoGroups) {
  const auto boxes = random_boxes(3000, 21, 1.0, 0.06);
  const Face_bvh t(boxes);
  const auto pairs_between = [&](const std::vector<std::uint16_t>& group, int threads) {
    std::size_t calls = 0;
    const auto pairs = t.collect_overlapping_pairs_between_groups<Face_pair>(
        group,
        [](Index a, Index b, std::vector<Face_pair>& out) {
          out.push_back({a, b});
        },
        threads, &calls);
    EXPECT_EQ(calls, pairs.size());
    return pairs;
  };
  std::mt19937_64 g(5);
  std::vector<std::uint16_t> by_region(boxes.size()), scattered(boxes.size());
  for (Index f = 0; f < boxes.size(); ++f) {
    by_region[f] = static_cast<std::uint16_t>(boxes[f].lo[0] < -0.5 ? 0 : boxes[f].lo[0] < 0.3 ? 1 : 2);
    scattered[f] = static_cast<std::uint16_t>(g() % 4);
  }
  for (const auto& group : {by_region, scattered}) {
    std::vector<Face_pair> expected;
    for (const Face_pair& p : brute_self_pairs(boxes))
      if (group[p.first] == 0 || group[p.first] != group[p.second]) expected.push_back(p);
    const auto serial = pairs_between(group, 1);
    EXPECT_EQ(sorted(serial), expected);
    EXPECT_EQ(serial, pairs_between(group, 2));  // same pairs in the same order
    EXPECT_LT(expected.size(), brute_self_pairs(boxes).size());
  }
  EXPECT_EQ(sorted(pairs_between(std::vector<std::uint16_t>(boxes.size(), 0), 1)), brute_self_pairs(boxes));
  EXPECT_TRUE(pairs_between(std::vector<std::uint16_t>(boxes.size(), 7), 1).empty());
  EXPECT_THROW((void)pairs_between(std::vector<std::uint16_t>(5, 1), 1), Precondition_violation);
}

// A hierarchy built with clusters (Face_bvh_options::clusters) holds the
// same boxes: every search finds the same pairs, whether the clusters are
// spatially coherent, scattered at random, one, or all zero, and a search
// between groups equal to the clusters leaves out exactly the pairs within a
// nonzero group.
TEST(FaceBvh, ClustersChangeTheTreeNotThePairs) {
  const auto boxes = random_boxes(3000, 23, 1.0, 0.06);
  const auto other = random_boxes(1200, 29, 1.0, 0.05);
  const Face_bvh plain_other(other);
  std::mt19937_64 g(9);
  std::vector<std::uint16_t> by_region(boxes.size()), scattered(boxes.size()), one(boxes.size(), 1),
      none(boxes.size(), 0), wide(boxes.size());
  for (Index f = 0; f < boxes.size(); ++f) {
    by_region[f] = static_cast<std::uint16_t>(boxes[f].lo[0] < -0.5 ? 0 : boxes[f].lo[0] < 0.3 ? 1 : 2);
    scattered[f] = static_cast<std::uint16_t>(g() % 5);
    wide[f] = static_cast<std::uint16_t>(g() % 3 == 0 ? 0 : 1 + g() % 65535);  // every bit of a cluster number
  }
  const auto self = brute_self_pairs(boxes);
  const auto cross = brute_pairs(boxes, other);
  for (const auto& clusters : {by_region, scattered, one, none, wide})
    for (int leaf : {1, 4, 16}) {
      const Face_bvh t(boxes, {.leaf_size = leaf, .clusters = clusters});
      ASSERT_EQ(t.size(), boxes.size());
      EXPECT_EQ(sorted(t.overlapping_pairs()), self) << "leaf " << leaf;
      EXPECT_EQ(sorted(t.overlapping_pairs(plain_other)), cross) << "leaf " << leaf;
      EXPECT_EQ(t.overlapping_pairs(plain_other, 2), t.overlapping_pairs(plain_other, 1));
      // In an order that depends on neither hierarchy, on any thread count.
      EXPECT_EQ(t.sorted_overlapping_pairs(plain_other), cross) << "leaf " << leaf;
      EXPECT_EQ(plain_other.sorted_overlapping_pairs(t, 2), brute_pairs(other, boxes)) << "leaf " << leaf;
      std::vector<Face_pair> expected;
      for (const Face_pair& p : self)
        if (clusters[p.first] == 0 || clusters[p.first] != clusters[p.second]) expected.push_back(p);
      const auto between = t.collect_overlapping_pairs_between_groups<Face_pair>(
          clusters, [](Index a, Index b, std::vector<Face_pair>& out) { out.push_back({a, b}); });
      EXPECT_EQ(sorted(between), expected) << "leaf " << leaf;
    }
  EXPECT_THROW(Face_bvh(boxes, {.clusters = std::vector<std::uint16_t>(5, 1)}), Precondition_violation);
  EXPECT_THROW(Face_bvh(boxes, {.split = Face_bvh_split::median, .clusters = scattered}), Precondition_violation);
}

TEST(FaceBvh, TouchingBoxesOverlapAndEqualCentresDoNotBreakTheSplit) {
  // Every box the same, and boxes touching in one face only.
  std::vector<Box_3> same(50);
  for (Box_3& b : same) b.lo = {0, 0, 0}, b.hi = {1, 1, 1};
  const Face_bvh t(same);
  EXPECT_EQ(t.overlapping_pairs().size(), 50u * 49 / 2);
  std::vector<Box_3> row(40);
  for (int i = 0; i < 40; ++i) row[i].lo = {double(i), 0, 0}, row[i].hi = {double(i + 1), 1, 1};
  EXPECT_EQ(sorted(Face_bvh(row).overlapping_pairs()), brute_self_pairs(row));
  EXPECT_EQ(Face_bvh(row).overlapping_pairs().size(), 39u);
}

// Centres spread by subnormal amounts along an axis: 1023 / spread
// overflows to infinity and 0 * inf is NaN, which the Morton split must not
// convert to an integer (undefined behaviour, caught by UBSan in the
// sanitized run; found by the mesh_boolean fuzz harness), nor miss a pair.
TEST(FaceBvh, SubnormalSpreadsSplitSafely) {
  std::vector<Box_3> tiny(64);
  for (int i = 0; i < 64; ++i) {
    const double t = i * std::numeric_limits<double>::denorm_min();
    tiny[i].lo = {t, double(i % 8), 0}, tiny[i].hi = {t, double(i % 8) + 0.5, 1};
  }
  const Face_bvh t(tiny, {.leaf_size = 1, .split = Face_bvh_split::morton});
  EXPECT_EQ(sorted(t.overlapping_pairs()), brute_self_pairs(tiny));
}

TEST(FaceBvh, OutputDoesNotDependOnThreadCount) {
  const Mesh_d a = cube_sphere(20), b = translated(a, 0.3, 0.2, 0.1);
  const Face_bvh ta(a), tb(b);
  const Face_bvh ta2(a, {.threads = 2}), tb2(b, {.threads = 2});
  const auto pairs1 = ta.overlapping_pairs(tb, 1);
  EXPECT_EQ(pairs1, ta2.overlapping_pairs(tb2, 2));  // same pairs in the same order
  EXPECT_EQ(pairs1, ta.overlapping_pairs(tb, 2));
  EXPECT_EQ(ta.overlapping_pairs(1), ta2.overlapping_pairs(2));
  EXPECT_EQ(sorted(pairs1), brute_pairs(face_boxes(a), face_boxes(b)));
  EXPECT_EQ(sorted(ta.overlapping_pairs()), brute_self_pairs(face_boxes(a)));
  // More query boxes than one chunk (4096): the chunks join in order.
  const std::vector<Box_3> queries = face_boxes(a);
  ASSERT_GT(queries.size(), 4096u);
  const auto with_boxes = tb.overlapping_pairs_with_boxes(queries, 1);
  EXPECT_EQ(with_boxes, tb2.overlapping_pairs_with_boxes(queries, 2));
  EXPECT_EQ(with_boxes, tb.overlapping_pairs_with_boxes(queries, 2));
  EXPECT_EQ(sorted(with_boxes), sorted(pairs1));
  EXPECT_EQ(ta.overlapping_pairs_in_query_order(tb, 1), with_boxes);
  EXPECT_EQ(ta2.overlapping_pairs_in_query_order(tb2, 2), with_boxes);
}

TEST(FaceBvh, BoxQueryFindsExactlyTheOverlappingFaces) {
  const auto a = random_boxes(1500, 11, 1.0, 0.1);
  const Face_bvh t(a);
  for (const Box_3& q : random_boxes(50, 12, 1.2, 0.6)) {
    std::vector<Index> got, want;
    t.for_each_face_in_box(q, [&](Index f) { got.push_back(f); });
    for (Index f = 0; f < a.size(); ++f)
      if (do_overlap(a[f], q)) want.push_back(f);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);
  }
}

// The nearest face by branch and bound is the brute-force minimum, for
// points on, near and far from the mesh (a growing box search, its
// predecessor, visited every face for far points: a fuzzing timeout).
TEST(FaceBvh, NearestFaceIsTheBruteForceMinimum) {
  const Mesh_d m = jitter(cube_sphere(12), 0.01);
  const Face_bvh t(m);
  const auto squared = [&](const Point_3<double>& p, Index f) {  // to the face's nearest corner: a stand-in distance
    double best = std::numeric_limits<double>::infinity();
    for (Index v : m.faces[f]) {
      const Point_3<double>& c = m.vertices[v];
      best = std::min(best, (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y) + (p.z - c.z) * (p.z - c.z));
    }
    return best;
  };
  std::mt19937_64 g(21);
  for (const double spread : {0.5, 2.0, 1e3, 1e8}) {
    std::uniform_real_distribution<double> u(-spread, spread);
    for (int i = 0; i < 40; ++i) {
      const Point_3<double> p{u(g), u(g), u(g)};
      double want = std::numeric_limits<double>::infinity();
      for (Index f = 0; f < m.faces.size(); ++f) want = std::min(want, squared(p, f));
      const auto [face, got] = t.nearest_face(p, [&](Index f) { return squared(p, f); });
      EXPECT_EQ(got, want) << "spread " << spread << " point " << i;
      ASSERT_LT(face, m.faces.size());
      EXPECT_EQ(squared(p, face), got);
    }
  }
  EXPECT_EQ(Face_bvh(std::span<const Box_3>{}).nearest_face({0, 0, 0}, [](Index) { return 0.0; }).first, invalid_index);
}

// Exact: whether p + t d, t in [0, t_max] (t_max < 0: unbounded) meets the box.
bool exact_line_meets(const Box_3& b, const std::array<double, 3>& p, const std::array<mpq_class, 3>& d,
                      bool bounded) {
  mpq_class enter = 0, leave = 1;
  bool has_leave = bounded;
  for (int k = 0; k < 3; ++k) {
    const mpq_class pk = exact_rational(p[k]);
    if (sgn(d[k]) == 0) {
      if (pk < exact_rational(b.lo[k]) || pk > exact_rational(b.hi[k])) return false;
      continue;
    }
    mpq_class t0 = (exact_rational(b.lo[k]) - pk) / d[k], t1 = (exact_rational(b.hi[k]) - pk) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > enter) enter = t0;
    if (!has_leave || t1 < leave) leave = t1, has_leave = true;
  }
  return !has_leave || enter <= leave;
}

TEST(FaceBvh, SegmentAndRayQueriesNeverMissABoxTheyMeet) {
  const Mesh_d m = jitter(cube_sphere(12), 0.01);
  const Face_bvh t(m);
  const auto boxes = face_boxes(m);
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::size_t hits = 0;
  for (int trial = 0; trial < 120; ++trial) {
    Point_3<double> p{u(g), u(g), u(g)}, q{u(g), u(g), u(g)};
    if (trial % 3 == 0) q.y = p.y;  // constant along an axis
    if (trial % 5 == 0) p = m.vertices[trial % m.vertices.size()], q = m.vertices[(trial * 7 + 1) % m.vertices.size()];
    std::set<Index> seg, ray;
    t.for_each_face_on_segment(p, q, [&](Index f) { seg.insert(f); });
    t.for_each_face_on_ray(p, {q.x - p.x, q.y - p.y, q.z - p.z}, [&](Index f) { ray.insert(f); });
    const std::array<mpq_class, 3> d{exact_rational(q.x) - exact_rational(p.x),
                                     exact_rational(q.y) - exact_rational(p.y),
                                     exact_rational(q.z) - exact_rational(p.z)};
    // The ray's direction is q - p rounded: compare with the exact rounded one.
    const std::array<mpq_class, 3> dr{exact_rational(q.x - p.x), exact_rational(q.y - p.y),
                                      exact_rational(q.z - p.z)};
    for (Index f = 0; f < boxes.size(); ++f) {
      if (exact_line_meets(boxes[f], {p.x, p.y, p.z}, d, true)) {
        EXPECT_TRUE(seg.count(f)) << "segment missed face " << f;
        ++hits;
      }
      if (exact_line_meets(boxes[f], {p.x, p.y, p.z}, dr, false)) {
        EXPECT_TRUE(ray.count(f)) << "ray missed face " << f;
      }
    }
    // Reported faces are ones the segment meets up to the interval rounding:
    // never more than a handful extra.
    std::size_t extra = 0;
    for (Index f : seg) extra += !exact_line_meets(boxes[f], {p.x, p.y, p.z}, d, true);
    EXPECT_LE(extra, 2u);
  }
  EXPECT_GT(hits, 120u);  // the family is not trivially empty
}

TEST(FaceBvh, RationalCoordinatesGetOutwardRoundedBoxes) {
  Triangle_mesh<Point_3<mpq_class>> m;
  m.vertices = {{mpq_class(1, 3), mpq_class(-1, 3), mpq_class(2, 7)},
                {mpq_class(1, 10), mpq_class(1, 5), mpq_class(-2, 3)},
                {mpq_class(7, 9), mpq_class(5, 11), mpq_class(1, 1)}};
  m.faces = {{0, 1, 2}};
  const Box_3 b = face_boxes(m)[0];
  for (const auto& p : m.vertices) {
    const mpq_class c[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(exact_rational(b.lo[k]), c[k]);
      EXPECT_GE(exact_rational(b.hi[k]), c[k]);
    }
  }
  EXPECT_LT(exact_rational(b.lo[0]), mpq_class(1, 10));  // 1/10 is not a double: rounded down
}

TEST(FaceBvh, BadInputIsATypedError) {
  Mesh_d m = tetrahedron();
  m.vertices[2].y = std::numeric_limits<double>::quiet_NaN();
  try {
    (void)Face_bvh(m);
    FAIL() << "no exception";
  } catch (const Invalid_mesh& e) {
    EXPECT_EQ(e.defect(), Mesh_defect::non_finite_coordinate);
    EXPECT_EQ(e.issues().front().elements[0], 2u);
  }
  Mesh_d bad = tetrahedron();
  bad.faces[1][2] = 9;
  try {
    (void)Face_bvh(bad);
    FAIL() << "no exception";
  } catch (const Invalid_mesh& e) {
    EXPECT_EQ(e.defect(), Mesh_defect::index_out_of_range);
  }
  std::vector<Box_3> boxes(3);
  boxes[0].lo = boxes[0].hi = {0, 0, 0};
  boxes[1].lo = boxes[1].hi = {1, 1, 1};  // boxes[2] empty
  EXPECT_THROW((void)Face_bvh(boxes), Precondition_violation);
  EXPECT_THROW(Face_bvh(cube_sphere(2)).for_each_face_on_ray({0, 0, 0}, {0, 0, 0}, [](Index) {}),
               Precondition_violation);
  const Face_bvh empty(std::vector<Box_3>{});
  EXPECT_TRUE(empty.overlapping_pairs().empty());
  EXPECT_TRUE(empty.overlapping_pairs(Face_bvh(cube_sphere(2))).empty());
  EXPECT_TRUE(empty.overlapping_pairs_with_boxes(face_boxes(cube_sphere(2))).empty());
  EXPECT_TRUE(Face_bvh(cube_sphere(2)).overlapping_pairs_with_boxes({}).empty());
  EXPECT_TRUE(empty.overlapping_pairs_in_query_order(Face_bvh(cube_sphere(2))).empty());
  EXPECT_TRUE(Face_bvh(cube_sphere(2)).overlapping_pairs_in_query_order(empty).empty());
  EXPECT_TRUE(empty.sorted_overlapping_pairs(Face_bvh(cube_sphere(2))).empty());
  EXPECT_TRUE(Face_bvh(cube_sphere(2)).sorted_overlapping_pairs(empty).empty());
  EXPECT_THROW(Face_bvh(std::vector<Box_3>{}, {.clusters = std::vector<std::uint16_t>(1, 1)}), Precondition_violation);
  EXPECT_TRUE(empty.bounds().is_empty());
}

}  // namespace
