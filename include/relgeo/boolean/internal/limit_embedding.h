// relgeo/boolean/internal/limit_embedding.h — certifies that the Loop limit
// surface over the influence region of a control vertex is embedded (no
// intersections other than along the common boundaries of its patches).
//
// The influence region R(b) of control vertex b is the set of faces whose
// limit depends on b (faces with a vertex in b's closed 1-ring). Two faces
// whose supports share a control point b both lie in R(b), so once R(b) is
// certified embedded their limit patches meet only where their faces meet.
//
// Certificate, for a region whose faces form a disc and are all regular
// patches (box splines, ghost points across regular creases: their quartic
// Bezier nets exist), under a linear map P: R^3 -> R^2 (projection onto a
// plane near the region's tangent plane):
//  1. Each patch maps with a positive Jacobian: det(P F_u, P F_v) is a degree
//     6 polynomial whose Bernstein coefficients (products of the cubic
//     derivative nets) are all certified positive.
//  2. The region's boundary (the limit curves of its boundary edges, quartic
//     Bezier curves) is star-shaped around a point y: on each curve the angle
//     around y strictly increases (det(c - y, c') > 0: a degree 7 polynomial,
//     coefficients certified positive) and the curve lies in an open
//     half-plane through y (so it turns by less than pi), and the turns add
//     up to one full turn (no step passes the first boundary point's
//     direction again).
// Then P maps the closed disc R(b) to the plane as an orientation-preserving
// local homeomorphism (across a common edge the two sides map to the two
// sides of the edge's image) whose boundary goes once around a Jordan
// curve: by the degree argument every point inside has exactly one preimage,
// so P, and the limit surface over R(b), is one to one.
//
// Everything is computed in interval arithmetic from the control points, so
// the certificate holds for the exact surface; what it cannot show (a region
// with an irregular patch: extraordinary vertex or irregular crease vertex;
// a region that is not a disc; a sign left uncertain) is reported, never
// assumed. It stands where the thesis (Sec. 5.4.2) puts the Bezier
// convex-hull criteria of its reference [30] (Crit. 3.2.1*, 3.2.2*): it uses
// the explicit Bezier coefficients of regular patches, applies to the union
// of the patches around a point as [28] does, and its degree argument covers
// the supplementary condition of [29] (one to one along the common
// boundaries). [30]'s criteria themselves are not reproduced (the paper was
// not at hand); this certificate and its argument are derived here.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "relgeo/core/interval.h"
#include "relgeo/kernel/interval_kernel.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/subdivision/box_spline.h"
#include "relgeo/subdivision/internal/point_algebra.h"
#include "relgeo/subdivision/limit_evaluation.h"

namespace relgeo::internal {

/// Why a region was or was not certified embedded.
enum class Region_verdict : std::uint8_t {
  embedded,          ///< certified one to one
  irregular_patch,   ///< a face of the region is not a regular patch (no Bezier net)
  not_a_disc,        ///< the region's faces do not form a disc (small or coarse meshes)
  jacobian,          ///< a patch's projected Jacobian not certified positive
  boundary,          ///< the boundary not certified star-shaped around the centre
};

class Limit_embedding {
 public:
  using Point = Point_3<Interval>;
  using Surface = Loop_limit_surface<Interval_kernel>;

  explicit Limit_embedding(const Surface& surface)
      : surface_(surface),
        bezier_(surface.number_of_faces()),
        normals_(surface.number_of_faces()),
        in_region_(surface.number_of_faces(), invalid_index) {}

  /// The verdicts computed so far (per control vertex).
  const std::vector<std::optional<Region_verdict>>& verdicts() const { return verdict_; }

  /// The verdict on R(b), computed once and cached.
  Region_verdict region(Index b) {
    if (verdict_.empty()) verdict_.assign(surface_.number_of_vertices(), std::nullopt);
    if (!verdict_[b]) verdict_[b] = certify(b);
    return *verdict_[b];
  }

 private:
  using P2 = std::array<Interval, 2>;

  static Interval det(const P2& a, const P2& b) { return a[0] * b[1] - a[1] * b[0]; }

  // The Bezier net of a regular patch, computed once.
  const Quartic_bezier_patch<Interval>& bezier(Index f) {
    auto& b = bezier_[f];
    if (!b) b = surface_.bezier_patch(f);
    return *b;
  }

  // The Bernstein coefficients (degree 6, up to positive factors) of
  // F_u x F_v of a regular patch: the normal of the projected Jacobian is
  // their dot product with the projection's normal.
  const std::array<Point, 28>& jacobian_normals(Index f) {
    auto& n = normals_[f];
    if (n) return *n;
    const Quartic_bezier_patch<Interval>& b = bezier(f);
    // The cubic derivative nets, each coefficient times its multinomial:
    // the product of two Bernstein polynomials is the sextic one times
    // m(a) m(e) / m(a + e), and the positive divisor does not change signs.
    std::array<Point, 10> du, dv;
    int c = 0;
    for (int k = 0; k <= 3; ++k)
      for (int j = 0; j + k <= 3; ++j, ++c) {
        const Point& w = b[quartic_bezier_index(j, k)];
        const Interval m{static_cast<double>(cubic_multinomial[c])};
        const Point u = point_difference(b[quartic_bezier_index(j + 1, k)], w);
        const Point v = point_difference(b[quartic_bezier_index(j, k + 1)], w);
        du[c] = {m * u.x, m * u.y, m * u.z};
        dv[c] = {m * v.x, m * v.y, m * v.z};
      }
    std::array<Point, 28> s;
    s.fill(Point{Interval(0), Interval(0), Interval(0)});
    for (int k1 = 0, a = 0; k1 <= 3; ++k1)
      for (int j1 = 0; j1 + k1 <= 3; ++j1, ++a)
        for (int k2 = 0, e = 0; k2 <= 3; ++k2)
          for (int j2 = 0; j2 + k2 <= 3; ++j2, ++e) {
            const int j = j1 + j2, k = k1 + k2, g = 7 * k - k * (k - 1) / 2 + j;  // sextic index
            const Point x = point_cross(du[a], dv[e]);
            s[g] = {s[g].x + x.x, s[g].y + x.y, s[g].z + x.z};
          }
    n = s;
    return *n;
  }

  Region_verdict certify(Index b) {
    const Mesh_topology& t = surface_.topology();
    // The faces with a vertex in b's closed 1-ring.
    std::vector<Index> faces;
    const auto add_faces_around = [&](Index w) {
      t.for_each_outgoing(w, [&](Index h) {
        const Index f = Mesh_topology::face(h);
        if (in_region_[f] != b) in_region_[f] = b, faces.push_back(f);
      });
    };
    add_faces_around(b);
    for (Index w : t.vertex_ring(b)) add_faces_around(w);
    for (Index f : faces)
      if (!surface_.patch_slots(f)) return Region_verdict::irregular_patch;
    // Boundary half-edges (region on their left), one outgoing per vertex.
    std::vector<Index> boundary;
    std::vector<Index> vertices;
    for (Index f : faces)
      for (Index k = 0; k < 3; ++k) {
        const Index h = 3 * f + k, o = t.opposite(h);
        vertices.push_back(t.source(h));
        if (o == invalid_index || in_region_[Mesh_topology::face(o)] != b) boundary.push_back(h);
      }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    const std::size_t nf = faces.size(), nb = boundary.size();
    // A disc: one boundary loop and Euler characteristic V - E + F = 1.
    const long long euler = static_cast<long long>(vertices.size()) - static_cast<long long>((3 * nf + nb) / 2) +
                            static_cast<long long>(nf);
    std::vector<Index> loop = boundary_loop(boundary);
    if (euler != 1 || nb < 3 || loop.size() != nb) return Region_verdict::not_a_disc;
    // The projection: onto a plane normal to the region's mean control normal.
    std::array<double, 3> d{0, 0, 0};
    const auto& cp = surface_.control_points();
    for (Index f : faces) {
      const auto mid = [&](Index v) {
        return std::array<double, 3>{(cp[v].x.inf() + cp[v].x.sup()) / 2, (cp[v].y.inf() + cp[v].y.sup()) / 2,
                                     (cp[v].z.inf() + cp[v].z.sup()) / 2};
      };
      const auto p = mid(t.source(3 * f)), q = mid(t.source(3 * f + 1)), r = mid(t.source(3 * f + 2));
      const std::array<double, 3> u{q[0] - p[0], q[1] - p[1], q[2] - p[2]}, v{r[0] - p[0], r[1] - p[1], r[2] - p[2]};
      d[0] += u[1] * v[2] - u[2] * v[1], d[1] += u[2] * v[0] - u[0] * v[2], d[2] += u[0] * v[1] - u[1] * v[0];
    }
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 0) || !std::isfinite(len)) return Region_verdict::jacobian;
    for (double& x : d) x /= len;
    // e1 perpendicular to d (from the coordinate axis least along d), e2 = d x e1.
    const int least = std::fabs(d[0]) <= std::fabs(d[1]) ? (std::fabs(d[0]) <= std::fabs(d[2]) ? 0 : 2)
                                                          : (std::fabs(d[1]) <= std::fabs(d[2]) ? 1 : 2);
    std::array<double, 3> axis{0, 0, 0};
    axis[least] = 1;
    std::array<double, 3> e1{axis[1] * d[2] - axis[2] * d[1], axis[2] * d[0] - axis[0] * d[2], axis[0] * d[1] - axis[1] * d[0]};
    const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (double& x : e1) x /= l1;
    const std::array<double, 3> e2{d[1] * e1[2] - d[2] * e1[1], d[2] * e1[0] - d[0] * e1[2], d[0] * e1[1] - d[1] * e1[0]};
    const Point E1{Interval(e1[0]), Interval(e1[1]), Interval(e1[2])}, E2{Interval(e2[0]), Interval(e2[1]), Interval(e2[2])};
    // det(P a, P b) = (e1 x e2) . (a x b): the normal of the projection.
    const Point normal = point_cross(E1, E2);
    for (Index f : faces)
      for (const Point& n : jacobian_normals(f))
        if (!(point_dot(normal, n).inf() > 0)) return Region_verdict::jacobian;
    const auto project = [&](const Point& p) { return P2{point_dot(E1, p), point_dot(E2, p)}; };
    // The centre: b's limit point (a Bezier corner), rounded to a double point.
    const Index hb = t.vertex_halfedge(b);
    const P2 centre_enclosure = project(bezier(Mesh_topology::face(hb))[corner_index(hb % 3)]);
    const P2 y{Interval((centre_enclosure[0].inf() + centre_enclosure[0].sup()) / 2),
               Interval((centre_enclosure[1].inf() + centre_enclosure[1].sup()) / 2)};
    // Each boundary curve: angle monotone around y, within a half-plane; the
    // loop's first point P0 is passed by no intermediate step.
    std::vector<P2> starts;
    starts.reserve(nb);
    for (Index h : loop) {
      const Quartic_bezier_patch<Interval>& bez = bezier(Mesh_topology::face(h));
      std::array<P2, 5> a;
      for (int i = 0; i < 5; ++i) {
        const P2 p = project(bez[edge_curve_index(h % 3, i)]);
        a[i] = {p[0] - y[0], p[1] - y[1]};
      }
      if (!angle_increases(a) || !in_open_half_plane(a)) return Region_verdict::boundary;
      starts.push_back(a[0]);
    }
    const P2& p0 = starts[0];
    for (std::size_t k = 1; k + 1 < nb; ++k)  // step from starts[k] to starts[k+1]
      if (!(det(starts[k], p0).sup() < 0) && !(det(p0, starts[k + 1]).sup() < 0)) return Region_verdict::boundary;
    return Region_verdict::embedded;
  }

  // The boundary half-edges chained into one loop (empty when a vertex has
  // more than one outgoing boundary half-edge).
  std::vector<Index> boundary_loop(const std::vector<Index>& boundary) const {
    const Mesh_topology& t = surface_.topology();
    std::vector<std::pair<Index, Index>> by_source;
    by_source.reserve(boundary.size());
    for (Index h : boundary) by_source.emplace_back(t.source(h), h);
    std::sort(by_source.begin(), by_source.end());
    for (std::size_t i = 1; i < by_source.size(); ++i)
      if (by_source[i].first == by_source[i - 1].first) return {};
    std::vector<Index> loop;
    Index h = by_source.empty() ? invalid_index : by_source[0].second;
    while (h != invalid_index && loop.size() <= boundary.size()) {
      loop.push_back(h);
      const auto it = std::lower_bound(by_source.begin(), by_source.end(), std::pair{t.target(h), Index(0)});
      if (it == by_source.end() || it->first != t.target(h)) return {};
      h = it->second;
      if (h == loop[0]) break;
    }
    return loop;
  }

  // The Bezier index of the patch corner at the face's vertex `corner`.
  static int corner_index(Index corner) {
    return corner == 0 ? quartic_bezier_index(0, 0) : corner == 1 ? quartic_bezier_index(4, 0) : quartic_bezier_index(0, 4);
  }
  // The i-th control point of the boundary curve of the face's edge `k`
  // (from vertex k to vertex k+1): v0 -> v1 along v = 0, v1 -> v2 along
  // w = 0, v2 -> v0 along u = 0.
  static int edge_curve_index(Index k, int i) {
    return k == 0 ? quartic_bezier_index(i, 0) : k == 1 ? quartic_bezier_index(4 - i, i) : quartic_bezier_index(0, 4 - i);
  }

  // det(c(t) - y, c'(t)) > 0 on [0, 1] for the quartic with control points
  // a (relative to y): its degree 7 Bernstein coefficients (up to positive
  // factors) sum C(4,i) C(3,j) det(a_i, a_{j+1} - a_j) over i + j = k.
  static bool angle_increases(const std::array<P2, 5>& a) {
    static constexpr int c4[5] = {1, 4, 6, 4, 1}, c3[4] = {1, 3, 3, 1};
    std::array<P2, 4> d;
    for (int j = 0; j < 4; ++j) d[j] = {a[j + 1][0] - a[j][0], a[j + 1][1] - a[j][1]};
    for (int k = 0; k <= 7; ++k) {
      Interval s(0);
      for (int i = std::max(0, k - 3); i <= std::min(4, k); ++i) s = s + Interval(double(c4[i] * c3[k - i])) * det(a[i], d[k - i]);
      if (!(s.inf() > 0)) return false;
    }
    return true;
  }
  // All control points strictly on one side of a line through y (the
  // bisector of the end directions as the side's normal).
  static bool in_open_half_plane(const std::array<P2, 5>& a) {
    const auto unit_mid = [](const P2& p) {
      const double x = (p[0].inf() + p[0].sup()) / 2, y = (p[1].inf() + p[1].sup()) / 2, l = std::hypot(x, y);
      return std::array<double, 2>{x / l, y / l};
    };
    const auto u = unit_mid(a[0]), v = unit_mid(a[4]);
    const P2 m{Interval(u[0] + v[0]), Interval(u[1] + v[1])};
    for (const P2& p : a)
      if (!((m[0] * p[0] + m[1] * p[1]).inf() > 0)) return false;
    return true;
  }

  const Surface& surface_;
  std::vector<std::optional<Quartic_bezier_patch<Interval>>> bezier_;
  std::vector<std::optional<std::array<Point, 28>>> normals_;
  std::vector<Index> in_region_;  // the last region a face was marked for
  std::vector<std::optional<Region_verdict>> verdict_;
};

}  // namespace relgeo::internal
