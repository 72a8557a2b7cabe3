// Fuzz harness: intersect_triangles and do_intersect_triangles
// (relgeo/intersection/triangle_intersection.h) on arbitrary triangle pairs
// under relgeo's kernels, against CGAL's Epeck.
//
// Input: byte 0 the kernel, then a pool of up to 8 points (as in
// implicit_point_fuzzer.cpp: new, duplicate, on a line or in a plane of
// earlier ones, so that touching and coplanar pairs are common), then the
// six vertex indices.
//
// Contract (doc/reliability.md, harness triangle_intersection):
//  * finite, non-degenerate triangles: a result and no exception; every
//    certified kernel that decides (kind not undecided, nothing perturbed;
//    do_intersect_triangles not empty) agrees with CGAL's exact
//    do_intersect; under Exact_kernel the points are CGAL's intersection
//    points exactly (every CGAL point is one of relgeo's; up to a segment,
//    the same set);
//  * a degenerate triangle (collinear corners) breaks the precondition: a
//    Precondition_violation where the library needs the plane (coplanar
//    pairs), otherwise an answer; non-finite coordinates end in a typed
//    error or an undecided result; naive kernels only have to not crash.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fuzz_support.h"
#include "point_pool.h"
#include "relgeo/intersection/triangle_intersection.h"
#include "relgeo/kernel.h"

namespace {

using namespace relgeo;
using namespace relgeo::fuzz;
using Epeck = CGAL::Epeck;
using Coordinates = std::array<double, 3>;
using Kind = Triangle_intersection_kind;
using Exact_xyz = std::array<mpq_class, 3>;

mpq_class exact_value(const Epeck::FT& x) {
  std::ostringstream s;
  s << CGAL::exact(x);
  return mpq_class(s.str());
}
Exact_xyz exact_point(const Epeck::Point_3& p) { return {exact_value(p.x()), exact_value(p.y()), exact_value(p.z())}; }

template <class K>
void check(const std::array<Coordinates, 6>& v, bool finite, bool degenerate, bool intersect,
           const std::vector<Exact_xyz>& cgal_points) {
  const K k;
  const std::string who = K::name();
  const auto make = k.construct_point_3_object();
  std::array<typename K::Point_3, 3> a, b;
  try {
    for (int i = 0; i < 3; ++i) {
      a[i] = make(v[i][0], v[i][1], v[i][2]);
      b[i] = make(v[i + 3][0], v[i + 3][1], v[i + 3][2]);
    }
  } catch (const Non_finite_input&) {  // kernels with exact coordinates refuse NaN at construction
    require(!finite, who + ": refused finite coordinates");
    return;
  }
  std::optional<bool> fast;
  const bool fast_ok = typed_errors_only([&] { fast = do_intersect_triangles(a, b, k); }, who + " do_intersect");
  Triangle_intersection<K> r;
  const bool full_ok = typed_errors_only([&] { r = intersect_triangles(a, b, k); }, who + " intersect");
  if (!finite || !K::is_certified) return;
  // A degenerate triangle breaks the precondition: the library checks it
  // where its answer depends on it (the coplanar path) and otherwise
  // answers; only "typed errors only" applies.
  if (degenerate) return;
  require(fast_ok && full_ok, who + ": refused a valid pair");
  if (fast) require(*fast == intersect, who + ": do_intersect_triangles disagrees with CGAL");
  if (K::has_exact_predicates) require(fast.has_value(), who + ": an exact kernel decides");
  if (r.kind == Kind::undecided || !r.perturbations.empty()) {
    require(!K::has_exact_predicates, who + ": an exact kernel decides without perturbing");
    return;
  }
  require((r.kind != Kind::disjoint) == intersect, who + ": intersect_triangles disagrees with CGAL");
  if constexpr (std::is_same_v<K, Exact_kernel>) {
    std::vector<Exact_xyz> ours;
    for (const auto& p : r.points) ours.push_back({p.point.x, p.point.y, p.point.z});
    const auto sorted_unique = [](std::vector<Exact_xyz> s) {
      std::sort(s.begin(), s.end());
      s.erase(std::unique(s.begin(), s.end()), s.end());
      return s;
    };
    const auto e = sorted_unique(cgal_points), o = sorted_unique(ours);
    for (const auto& x : e) require(std::binary_search(o.begin(), o.end(), x), who + ": a CGAL point is missing");
    if (e.size() <= 2) require(o == e, who + ": the points of a point or segment intersection are CGAL's");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const int kernel = in.byte() % 5;
  const auto pool = decode_point_pool(in, 8);
  std::array<Coordinates, 6> v;
  for (auto& p : v) p = pool[in.below(pool.size())];
  bool finite = true;
  for (const auto& p : v) finite = finite && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);

  bool degenerate = false, intersect = false;
  std::vector<Exact_xyz> cgal_points;
  if (finite) {
    const auto P = [&](int i) { return Epeck::Point_3(v[i][0], v[i][1], v[i][2]); };
    degenerate = CGAL::collinear(P(0), P(1), P(2)) || CGAL::collinear(P(3), P(4), P(5));
    if (!degenerate) {
      const Epeck::Triangle_3 ta(P(0), P(1), P(2)), tb(P(3), P(4), P(5));
      intersect = CGAL::do_intersect(ta, tb);
      if (kernel == 3 && intersect) {
        const auto c = CGAL::intersection(ta, tb);
        require(c.has_value(), "CGAL: do_intersect and intersection agree");
        if (const auto* p = boost::get<Epeck::Point_3>(&*c)) cgal_points = {exact_point(*p)};
        else if (const auto* s = boost::get<Epeck::Segment_3>(&*c))
          cgal_points = {exact_point(s->source()), exact_point(s->target())};
        else if (const auto* t = boost::get<Epeck::Triangle_3>(&*c))
          cgal_points = {exact_point(t->vertex(0)), exact_point(t->vertex(1)), exact_point(t->vertex(2))};
        else
          for (const auto& q : boost::get<std::vector<Epeck::Point_3>>(*c)) cgal_points.push_back(exact_point(q));
      }
    }
  }
  switch (kernel) {
    case 0: check<Failsafe_kernel<double>>(v, finite, degenerate, intersect, cgal_points); break;
    case 1: check<Interval_kernel>(v, finite, degenerate, intersect, cgal_points); break;
    case 2: check<Filtered_exact_kernel>(v, finite, degenerate, intersect, cgal_points); break;
    case 3: check<Exact_kernel>(v, finite, degenerate, intersect, cgal_points); break;
    default: check<Naive_kernel<double>>(v, finite, degenerate, intersect, cgal_points);
  }
  return 0;
}
