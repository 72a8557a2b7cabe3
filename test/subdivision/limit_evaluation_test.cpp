// Exact limit-surface evaluation (limit_evaluation.h, box_spline.h): the
// regular patch is the box spline (= the limit of regular refinement), limit
// positions lie on the evaluated surface, a subdivided patch evaluates like its
// parent, crease curves are cubic B-splines, normals match finite
// differences, kernels agree, bad input is refused with typed errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "relgeo/kernel.h"
#include "subdivision/limit_test_support.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;
using Mesh_q = Triangle_mesh<Point_3<mpq_class>>;
using Pq = Point_3<mpq_class>;
using Pd = Point_3<double>;
using Exact = Loop_limit_surface<Exact_kernel>;
using Approx = Loop_limit_surface<Naive_kernel<double>>;

double dist(const Pd& a, const Pd& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }
Pd to_d(const Pq& p) { return {p.x.get_d(), p.y.get_d(), p.z.get_d()}; }

TEST(BoxSplineTables, RowsArePartitionsOfUnityAndCornersAreTheLimitMask) {
  for (const auto& row : loop_patch_bezier_x24) {
    int s = 0;
    for (int x : row) {
      s += x;
      EXPECT_GE(x, 0);
    }
    EXPECT_EQ(s, 24);
  }
  for (const auto& child : loop_patch_child_x16)
    for (const auto& row : child) {
      int s = 0;
      for (int x : row) {
        s += x;
        EXPECT_GE(x, 0);
      }
      EXPECT_EQ(s, 16);
    }
  // Bezier corner w^4 = (12 p0 + 2 * six neighbours) / 24 = 1/2 p0 + 1/12 sum.
  const int expected[12] = {12, 2, 2, 2, 2, 2, 0, 0, 0, 0, 0, 2};
  for (int i = 0; i < 12; ++i) EXPECT_EQ(loop_patch_bezier_x24[0][i], expected[i]);
}

// A regular patch is the limit of Loop's regular refinement: at every vertex
// of the level-3 refinement (45 points per face) the evaluation equals the
// refined mesh's limit position, exactly.
TEST(LimitEvaluation, RegularPatchIsTheBoxSplineAtAllLevel3Points) {
  const Mesh_q m = convert<mpq_class>(dyadic_torus(6, 5));
  const Exact S(m);
  for (Index f = 0; f < m.faces.size(); ++f) ASSERT_EQ(S.patch_kind(f), Loop_patch_kind::regular);
  Loop_subdivider<Exact_kernel> sub;
  const Mesh_q r = sub.refine(m, 3);
  const std::vector<Pq> lim = sub.limit_positions(r);
  for (Index g = 0; g < r.faces.size(); ++g)
    for (int k = 0; k < 3; ++k) {
      const auto [u, v] = ancestor_parameters(g, 3, k == 1 ? 1 : 0, k == 2 ? 1 : 0);
      ASSERT_EQ(S.evaluate(g / 64, u, v), lim[r.faces[g][k]]) << g << " corner " << k;
    }
  // Bezier form: evaluation of the 15 coefficients agrees with the one-pass path.
  for (Index f = 0; f < 4; ++f)
    for (const auto& [u, v] : dyadic_grid(8))
      EXPECT_EQ(evaluate_quartic_bezier(S.bezier_patch(f), mpq_class(u), mpq_class(v)), S.evaluate(f, u, v));
}

// Relabelling a face's corners (v1, v2, v0) gives the same surface at the
// rotated parameters: the slot gathering and the table respect the symmetry.
TEST(LimitEvaluation, RotatingTheFaceRotatesTheParameters) {
  Mesh_q m = convert<mpq_class>(dyadic_torus(5, 5));
  Mesh_q rot = m;
  for (auto& f : rot.faces) f = {f[1], f[2], f[0]};
  const Exact S(m), R(rot);
  for (Index f = 0; f < m.faces.size(); f += 7)
    for (const auto& [u, v] : dyadic_grid(8)) EXPECT_EQ(S.evaluate(f, u, v), R.evaluate(f, v, 1 - u - v));
}

// Limit positions lie on the surface: every vertex of the level-2 refinement
// (15 per face) at valences 3, 4, 6 and, with Loop's weights made rational
// by the number hook, 5 and 7..12 (the limit mask is the exact eigenvector of
// the rule applied, so equality is exact everywhere).
TEST(LimitEvaluation, LimitPositionsLieOnTheSurfaceExactlyAtValences3To12) {
  std::vector<std::pair<int, Mesh_d>> cases = valence_meshes();
  cases.push_back({6, dyadic_torus(4, 4)});
  for (const auto& [n, md] : cases) {
    const Mesh_q m = convert<mpq_class>(md);
    const Exact S(m);
    Loop_subdivider<Exact_kernel> sub;
    const unsigned level = n <= 4 || n == 6 ? 2 : 1;
    const Mesh_q r = sub.refine(m, level);
    const std::vector<Pq> lim = sub.limit_positions(r);
    const Index per = level == 2 ? 16 : 4;
    for (Index g = 0; g < r.faces.size(); ++g)
      for (int k = 0; k < 3; ++k) {
        const auto [u, v] = ancestor_parameters(g, level, k == 1 ? 1 : 0, k == 2 ? 1 : 0);
        ASSERT_EQ(S.evaluate(g / per, u, v), lim[r.faces[g][k]]) << "valence " << n << " face " << g;
      }
    // the apex (valence n) itself: limit_position == limit mask
    EXPECT_EQ(S.limit_position(Index(n)), lim[n]);
  }
}

// Evaluation of a subdivided patch equals evaluation of the parent at the
// corresponding parameters: exactly, for every patch kind, Hoppe's and BLZ's
// rules, creases, corners, darts, boundaries.
TEST(LimitEvaluation, SubdividedPatchEvaluatesLikeItsParent) {
  const std::vector<std::pair<const char*, Mesh_d>> meshes = {
      {"creased box", creased_box()}, {"disk 7, crease sectors 3/4", disk(7, 3)}, {"half fan 5", half_fan(5)},
      {"open grid", open_grid(3)},    {"dart", dart_disk(7)},                   {"bipyramid 5", bipyramid(5)}};
  const auto grid = dyadic_grid(4);
  for (const Loop_options& o : {hoppe, blz})
    for (const auto& [name, md] : meshes) {
      const Mesh_q m = convert<mpq_class>(md);
      const Exact S0(m, o);
      const Mesh_q r = Loop_subdivider<Exact_kernel>(o).refine(m, 1);
      const Exact S1(r, o);
      for (Index g = 0; g < r.faces.size(); ++g) {
        for (const auto& [s, t] : grid) {
          const auto [u, v] = ancestor_parameters(g, 1, s, t);
          ASSERT_EQ(S1.evaluate(g, s, t), S0.evaluate(g / 4, u, v)) << name << " face " << g << " (" << s << ", " << t << ")";
        }
        // deep next to corner 0 (an old vertex for children 0..2): many
        // repeated local steps (the reused-stencil path) on both sides
        if (g % 4 != 3)
          for (const auto& [s, t] : {std::pair{0x1p-12, 0x1p-13}, std::pair{0x3p-9, 0.0}}) {
            const auto [u, v] = ancestor_parameters(g, 1, s, t);
            ASSERT_EQ(S1.evaluate(g, s, t), S0.evaluate(g / 4, u, v)) << name << " face " << g << " deep (" << s << ", " << t << ")";
          }
      }
    }
}

// Where the limit mask is exact the exact limit equals it; at darts and
// BLZ-modified vertices the exact limit is invariant under refinement (the
// fixed point of the vertex's subdivision), which the mask is not.
TEST(LimitEvaluation, ExactLimitPositionsAreInvariantUnderRefinement) {
  for (const Loop_options& o : {hoppe, blz})
    for (const Mesh_d& md : {dart_disk(7), disk(7, 3), creased_box(), half_fan(4)}) {
      const Mesh_q m = convert<mpq_class>(md);
      Loop_subdivider<Exact_kernel> sub(o);
      const Mesh_q r = sub.refine(m, 1);
      const Exact S0(m, o), S1(r, o);
      const std::vector<Pq> mask = sub.limit_positions(m);
      const Mesh_topology t = Mesh_topology::build(m);
      const internal::Loop_rule_data& d = S0.rule_data();
      int differ = 0;
      for (Index v = 0; v < m.vertices.size(); ++v) {
        EXPECT_EQ(S0.limit_position(v), S1.limit_position(v)) << v;
        if (internal::limit_mask_is_exact(t, d, o, v) && d.kind[v] != Vertex_kind::dart) {
          EXPECT_EQ(S0.limit_position(v), mask[v]) << v;
        } else {
          differ += !(S0.limit_position(v) == mask[v]);
        }
      }
      if (md.tags.creases().size() == 1) {
        EXPECT_GT(differ, 0) << "darts: the smooth mask is only an approximation";
      }
    }
}

// Boundary curves of Hoppe's rules are uniform cubic B-splines of the
// boundary polygon (an independent formula), including next to the grid's
// corners (boundary vertices with 1 or 2 faces).
TEST(LimitEvaluation, BoundaryCurvesAreCubicBSplines) {
  const Mesh_q m = convert<mpq_class>(open_grid(4));
  const Exact S(m);
  const Mesh_topology& t = S.topology();
  // boundary successor: the boundary half-edge h runs a -> b
  std::map<Index, Index> next;
  for (Index h = 0; h < t.number_of_halfedges(); ++h)
    if (t.is_boundary_halfedge(h)) next[t.source(h)] = t.target(h);
  std::map<Index, Index> prev;
  for (const auto& [a, b] : next) prev[b] = a;
  int checked = 0;
  for (Index h = 0; h < t.number_of_halfedges(); ++h) {
    if (!t.is_boundary_halfedge(h)) continue;
    const Index f = h / 3, i = h % 3, a = t.source(h), b = t.target(h);
    const Pq &p0 = m.vertices[prev[a]], &p1 = m.vertices[a], &p2 = m.vertices[b], &p3 = m.vertices[next[b]];
    for (int k = 0; k <= 8; ++k) {
      const mpq_class s = mpq_class(k) / 8, s2 = s * s, s3 = s2 * s;
      const mpq_class w0 = (1 - s) * (1 - s) * (1 - s) / 6, w1 = (3 * s3 - 6 * s2 + 4) / 6,
                      w2 = (-3 * s3 + 3 * s2 + 3 * s + 1) / 6, w3 = s3 / 6;
      const Pq bs{w0 * p0.x + w1 * p1.x + w2 * p2.x + w3 * p3.x, w0 * p0.y + w1 * p1.y + w2 * p2.y + w3 * p3.y,
                  w0 * p0.z + w1 * p1.z + w2 * p2.z + w3 * p3.z};
      const double sd = k / 8.0;
      const auto [u, v] = i == 0 ? std::pair{sd, 0.0} : i == 1 ? std::pair{1 - sd, sd} : std::pair{0.0, 1 - sd};
      ASSERT_EQ(S.evaluate(f, u, v), bs) << "face " << f << " edge " << i << " s " << sd;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 16 * 9);
}

TEST(LimitEvaluation, PatchKinds) {
  const Approx grid(open_grid(4));
  int kinds[3] = {0, 0, 0};
  for (Index f = 0; f < grid.number_of_faces(); ++f) ++kinds[int(grid.patch_kind(f))];
  EXPECT_GT(kinds[int(Loop_patch_kind::regular)], 0);
  EXPECT_GT(kinds[int(Loop_patch_kind::regular_crease)], 0);
  EXPECT_GT(kinds[int(Loop_patch_kind::irregular)], 0);  // at the grid's corners
  const Mesh_d sphere = icosphere(1);
  const Approx ico(sphere);
  for (Index f = 0; f < ico.number_of_faces(); ++f) {
    const auto& tr = sphere.faces[f];
    bool ev = false;
    for (Index v : tr) ev |= ico.topology().valence(v) != 6;
    EXPECT_EQ(ico.patch_kind(f), ev ? Loop_patch_kind::irregular : Loop_patch_kind::regular) << f;
  }
}

// Evaluation converges to the exact limit position at every irregular vertex
// (valences 3..12, darts, corners, crease vertices of irregular sectors).
TEST(LimitEvaluation, ContinuousAtIrregularVertices) {
  std::vector<Mesh_d> meshes;
  for (auto& [n, m] : valence_meshes()) meshes.push_back(m);
  meshes.push_back(dart_disk(9));
  meshes.push_back(creased_box());
  meshes.push_back(disk(9, 4));
  for (const Loop_options& o : {hoppe, blz})
    for (const Mesh_d& m : meshes) {
      const Approx S(m, o);
      for (Index f = 0; f < m.faces.size(); ++f) {
        if (S.patch_kind(f) != Loop_patch_kind::irregular) continue;
        const Pd c = S.evaluate(f, 0, 0);
        EXPECT_LT(dist(c, S.limit_position(m.faces[f][0])), 1e-13);
        double prev = INFINITY;
        for (int k = 4; k <= 48; k += 4) {
          const double d = dist(S.evaluate(f, std::ldexp(1.0, -k), std::ldexp(1.0, -k - 1)), c);
          EXPECT_LT(d, prev * 0.9 + 1e-15) << "face " << f << " k " << k;
          prev = d;
        }
        EXPECT_LT(prev, 1e-9) << "face " << f;
      }
    }
}

// du, dv against central differences; the normal du x dv; at an irregular
// vertex the tangent-mask normal against the normals nearby.
TEST(LimitEvaluation, DerivativesAndNormalsMatchFiniteDifferences) {
  for (const Mesh_d& m : {jitter(torus(7, 6), 0.05), bipyramid(7), disk(9, 4), open_grid(3), creased_box()}) {
    const Approx S(m);
    for (Index f = 0; f < m.faces.size(); ++f)
      for (const auto& [u, v] : {std::pair{0.25, 0.25}, std::pair{0.5, 0.125}, std::pair{0.125, 0.625}}) {
        const auto j = S.evaluate_with_derivatives(f, u, v);
        ASSERT_TRUE(j.has_derivatives);
        const double h = 1e-5;
        const Pd pu = S.evaluate(f, u + h, v), mu = S.evaluate(f, u - h, v);
        const Pd pv = S.evaluate(f, u, v + h), mv = S.evaluate(f, u, v - h);
        const Pd fu{(pu.x - mu.x) / (2 * h), (pu.y - mu.y) / (2 * h), (pu.z - mu.z) / (2 * h)};
        const Pd fv{(pv.x - mv.x) / (2 * h), (pv.y - mv.y) / (2 * h), (pv.z - mv.z) / (2 * h)};
        const double su = std::hypot(j.du.x, j.du.y, j.du.z), sv = std::hypot(j.dv.x, j.dv.y, j.dv.z);
        EXPECT_LT(dist(j.du, fu), 1e-6 * (1 + su)) << "face " << f;
        EXPECT_LT(dist(j.dv, fv), 1e-6 * (1 + sv)) << "face " << f;
        const Pd n = j.normal;
        EXPECT_NEAR(n.x, j.du.y * j.dv.z - j.du.z * j.dv.y, 1e-12 * (1 + su * sv));
      }
    // irregular corners: the normal nearby turns towards the tangent-mask normal
    for (Index f = 0; f < m.faces.size(); ++f) {
      if (S.patch_kind(f) != Loop_patch_kind::irregular) continue;
      const auto c = S.evaluate_with_derivatives(f, 0, 0);
      const auto near = S.evaluate_with_derivatives(f, 1e-9, 1e-9);
      if (c.has_derivatives) continue;  // a regular corner of an irregular face
      if (S.features().vertex_kind[m.faces[f][0]] == Vertex_kind::dart) continue;  // masks approximate there
      const Pd a = c.normal, b = near.normal;
      const double cosang = (a.x * b.x + a.y * b.y + a.z * b.z) / (std::hypot(a.x, a.y, a.z) * std::hypot(b.x, b.y, b.z));
      EXPECT_GT(cosang, 1 - 1e-4) << "face " << f;
    }
  }
}

// The same points under every kind of number: double within 1e-13 of the
// exact value, intervals enclose it, MPFR-53 within 1e-13.
TEST(LimitEvaluation, KernelsAgreeAndIntervalsEnclose) {
  const Mesh_d md = jitter(disk(5, 2), 0.01);
  const Mesh_q mq = convert<mpq_class>(md);
  const Exact E(mq);
  const Approx D(md);
  const Loop_limit_surface<Interval_kernel> I(convert<Interval>(md));
  const Loop_limit_surface<Mpfr_kernel<53>> M(convert<Mpfr_number<53>>(md));
  for (Index f = 0; f < md.faces.size(); f += 2)
    for (const auto& [u, v] : {std::pair{0.0, 0.0}, std::pair{0.3, 0.2}, std::pair{0.001, 0.002}, std::pair{0.5, 0.5}}) {
      const Pq e = E.evaluate(f, u, v);
      EXPECT_LT(dist(D.evaluate(f, u, v), to_d(e)), 1e-13);
      const Point_3<Interval> i = I.evaluate(f, u, v);
      for (const auto& [iv, ev] : {std::pair{i.x, e.x}, std::pair{i.y, e.y}, std::pair{i.z, e.z}}) {
        EXPECT_LE(mpq_class(iv.inf()), ev);
        EXPECT_GE(mpq_class(iv.sup()), ev);
        EXPECT_LT(iv.sup() - iv.inf(), 1e-12);
      }
      const auto mp = M.evaluate(f, u, v);
      EXPECT_LT(dist(Pd{mp.x.to_double(), mp.y.to_double(), mp.z.to_double()}, to_d(e)), 1e-13);
    }
}

// The child parameters of local subdivision are exact rationals; each is
// rounded once to the kernel's type. Rounding to 64 bits first and then to
// the target (the former route) turns these into ties and rounds them the
// wrong way: q = 1 + 2^-53 + 2^-80 gave 1 in double, q = 1 + 2^-24 + 2^-60
// gave 1 in float, (1/2 + 2^-70) 2^-1074 gave 0 in double.
TEST(LimitEvaluation, ParametersAreRoundedOnceToTheKernelsType) {
  const auto two_to = [](int e) {  // 2^e, e < 0, as an exact rational
    mpq_class r(1);
    mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), mp_bitcnt_t(-e));
    return r;
  };
  const mpq_class one(1), q53 = one + two_to(-53) + two_to(-80);
  EXPECT_EQ(internal::ft_from_rational<double>(q53), 1 + 0x1p-52);
  EXPECT_EQ(internal::ft_from_rational<Mpfr_number<53>>(q53).to_double(), 1 + 0x1p-52);
  const Interval i = internal::ft_from_rational<Interval>(q53);  // the tightest enclosure
  EXPECT_EQ(i.inf(), 1.0);
  EXPECT_EQ(i.sup(), 1 + 0x1p-52);
  const mpq_class q24 = one + two_to(-24) + two_to(-60);
  EXPECT_EQ(internal::ft_from_rational<float>(q24), 1 + 0x1p-23f);
  const mpq_class sub = two_to(-1075) + two_to(-1144);  // just above half the smallest subnormal
  EXPECT_EQ(internal::ft_from_rational<double>(sub), 0x1p-1074);
  EXPECT_EQ(internal::ft_from_rational<mpq_class>(q53), q53);
}

TEST(LimitEvaluation, BadInputIsRefusedWithTypedErrors) {
  const Approx S(icosphere(1));
  const auto code = [](auto&& f) {
    try {
      f();
    } catch (const Error& e) {
      return e.code();
    }
    return Error_code::computation_failure;
  };
  EXPECT_THROW((void)S.evaluate(Index(S.number_of_faces()), 0.1, 0.1), Invalid_surface_parameter);
  EXPECT_THROW((void)S.evaluate(0, -0.0001, 0.1), Invalid_surface_parameter);
  EXPECT_THROW((void)S.evaluate(0, 0.1, -1e-300), Invalid_surface_parameter);
  EXPECT_THROW((void)S.evaluate(0, 0.5, std::nextafter(0.5, 1.0)), Invalid_surface_parameter);  // u + v > 1 by one ulp
  EXPECT_THROW((void)S.evaluate(0, 0.75, 0.25 + 0x1p-54), Invalid_surface_parameter);  // 1 + 2^-54
  EXPECT_NO_THROW((void)S.evaluate(0, 0.25, 0.75));  // on the edge
  EXPECT_NO_THROW((void)S.evaluate(0, 0, 1));
  EXPECT_EQ(code([&] { (void)S.evaluate(0, std::nan(""), 0.1); }), Error_code::non_finite_coordinate);
  EXPECT_EQ(code([&] { (void)S.evaluate(0, 0.1, INFINITY); }), Error_code::non_finite_coordinate);
  EXPECT_EQ(code([&] { (void)S.evaluate(0, 2, 0); }), Error_code::invalid_input);
  EXPECT_THROW((void)S.evaluate_with_derivatives(99999, 0, 0), Invalid_surface_parameter);
  EXPECT_THROW((void)S.limit_position(99999), Invalid_surface_parameter);
  EXPECT_THROW((void)S.control_net(0), Invalid_surface_parameter);  // irregular: an icosahedron vertex
  Mesh_d bad = icosphere(0);
  bad.vertices[3].z = std::nan("");
  EXPECT_THROW((void)Approx(bad), Non_finite_input);
  Mesh_d nm = tetrahedron();
  nm.faces.push_back({0, 1, 2});  // edge (0, 1) in three faces
  EXPECT_THROW((void)Approx(nm), Invalid_mesh);
  Mesh_d pillow;  // two faces on the same three vertices
  pillow.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  pillow.faces = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_EQ(code([&] { (void)Approx(pillow); }), Error_code::invalid_input);
  Mesh_d tags = icosphere(0);
  tags.tags.add_crease(0, 3);  // not an edge
  EXPECT_THROW((void)Approx(tags), Invalid_mesh);
}

}  // namespace
