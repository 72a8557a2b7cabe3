// Fuzz harness: exact limit-surface evaluation (Loop_limit_surface) and the
// error bounds of limit meshes (loop_limit_mesh_bounds) on arbitrary small
// meshes (fuzz/mesh_builder.h) under relgeo's kernels.
//
// Input: byte 0 the kernel, byte 1 the operation (evaluation or bounds at
// level 0 or 1), then the mesh (mesh_builder.h), then queries: a face index
// and (u, v) (small binary fractions, or fuzz_support.h coordinates: NaN,
// negative, outside the triangle).
//
// Contract (doc/reliability.md, harness loop_limit):
//  * the surface is built exactly for the meshes Loop subdivision accepts
//    (as in loop_subdivision_fuzzer.cpp) and refused with a relgeo::Error
//    otherwise;
//  * a query outside the face range or the parameter triangle is an
//    Invalid_surface_parameter, a NaN or infinite one Non_finite_input
//    (with both defects, either), any other gives a finite point;
//    Interval_kernel's point encloses Exact_kernel's where both use Loop's
//    weights (valences 3, 4, 6);
//  * bounds: lower <= upper on every non-degenerate face (floating-point
//    kernels up to their rounding, 2^-40 times the largest coordinate; they
//    may refuse, Error(computation_failure), where a face normal's squared
//    length can overflow: coordinates beyond 2^-3 DBL_MAX^(1/4)); under
//    Exact_kernel (meshes of at most 12 limit-mesh faces: cost) the exact
//    limit surface (evaluated at the centre and near the corners of each
//    face, one point per face on at most 16 faces) lies between them, for
//    each method.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fuzz_support.h"
#include "loop_input.h"
#include "mesh_builder.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/validity.h"
#include "relgeo/subdivision.h"

namespace {

using namespace relgeo;
using namespace relgeo::fuzz;

bool loop_weights_everywhere(const Mesh_d& m) {
  const Mesh_topology t = Mesh_topology::build(m);
  for (Index v = 0; v < m.vertices.size(); ++v) {
    const Index n = t.valence(v);
    if (!t.is_isolated(v) && !t.is_boundary_vertex(v) && n != 3 && n != 4 && n != 6) return false;
  }
  return m.tags.empty();
}

struct Query {
  Index face;
  double u, v;
};

std::vector<Query> decode_queries(Input& in, std::size_t faces) {
  std::vector<Query> q;
  while (!in.empty() && q.size() < 8) {
    const Index f = static_cast<Index>(in.below(faces + 1));
    if (in.flag()) {
      const double u = in.coordinate();
      q.push_back({f, u, in.coordinate()});
    } else {  // k / 256 pairs, inside the triangle more often than not
      const double u = in.byte() / 256.0, v = in.byte() / 512.0;
      q.push_back({f, u, v});
    }
  }
  return q;
}

template <class P>
bool finite_point(const P& p) {
  return is_finite_number(p.x) && is_finite_number(p.y) && is_finite_number(p.z);
}

template <class K>
void check_queries(const Mesh_d& m, bool accept, const std::vector<Query>& queries, bool compare_exact) {
  const std::string who = K::name();
  std::optional<Loop_limit_surface<K>> s;
  try {
    s.emplace(to_kernel<K>(m));
  } catch (const relgeo::Error& e) {
    require(!accept, who + ": refused a mesh Loop subdivision accepts: " + e.what());
    return;
  } catch (const std::exception& e) {
    require(false, who + ": untyped exception " + e.what());
  }
  require(accept, who + ": built the limit surface of a mesh Loop subdivision refuses");
  std::optional<Loop_limit_surface<Exact_kernel>> exact;
  if (compare_exact) exact.emplace(to_kernel<Exact_kernel>(m));
  for (const Query& q : queries) {
    const bool finite = std::isfinite(q.u) && std::isfinite(q.v);
    const bool face_exists = q.face < m.faces.size();
    const bool inside = finite && face_exists && internal::in_parameter_triangle(q.u, q.v);
    typename K::Point_3 p;
    try {
      p = s->evaluate(q.face, q.u, q.v);
    } catch (const Non_finite_input&) {
      require(!finite, who + ": Non_finite_input for finite parameters");
      continue;
    } catch (const Invalid_surface_parameter&) {
      // A query with a face out of range and a non-finite parameter has two
      // defects: the face is checked first; either error names a real one.
      require(!face_exists || (finite && !inside), who + ": Invalid_surface_parameter for a valid parameter");
      continue;
    } catch (const std::exception& e) {
      require(false, who + ": evaluate threw " + e.what());
    }
    require(inside, who + ": evaluated outside the face range or the triangle");
    require(finite_point(p), who + ": a finite limit point");
    if constexpr (std::is_same_v<K, Interval_kernel>) {
      if (exact) {
        const auto e = exact->evaluate(q.face, q.u, q.v);
        for (int c = 0; c < 3; ++c) {
          const mpq_class& x = c == 0 ? e.x : c == 1 ? e.y : e.z;
          const Interval& i = c == 0 ? p.x : c == 1 ? p.y : p.z;
          require(mpq_class(i.inf()) <= x && x <= mpq_class(i.sup()), "interval limit point encloses the exact one");
        }
      }
    }
  }
}

/// Whether a face normal's squared length |n|^2 may overflow FT in the
/// bounds, which then refuse (Error(computation_failure), doc/reliability.md
/// Sec. 1). Limit-mesh coordinates stay within the control mesh's largest
/// magnitude M (Loop's masks are convex), so |n|^2 <= 192 M^4: below
/// 2^-3 DBL_MAX^(1/4) it cannot overflow (floating-point FT; intervals are
/// doubles; rationals do not overflow).
template <class FT>
bool normal_may_overflow(const Mesh_d& m) {
  if constexpr (!std::is_floating_point_v<FT> && !std::is_same_v<FT, Interval>) {
    return false;
  } else {
    return largest_magnitude(m) > std::ldexp(std::pow(std::numeric_limits<double>::max(), 0.25), -3);
  }
}

template <class K>
void check_bounds(const Mesh_d& m, bool accept, unsigned level) {
  const std::string who = K::name() + " bounds";
  // Shallow enclosures: the statement holds at any depth, and the harness
  // must stay fast.
  const Loop_bound_options b{.irregular_depth = 2, .regular_depth = 1, .universal_depth = 2};
  std::optional<Loop_limit_mesh_bounds<K>> r;
  try {
    r.emplace(Loop_error_bounds<K>(Loop_options{}, b).compute(to_kernel<K>(m), level));
  } catch (const relgeo::Error& e) {
    const bool overflow = e.code() == Error_code::computation_failure && normal_may_overflow<typename K::FT>(m);
    require(!accept || overflow, who + ": refused a mesh Loop subdivision accepts: " + e.what());
    return;
  } catch (const std::exception& e) {
    require(false, who + ": untyped exception " + e.what());
  }
  require(accept, who + ": bounded a mesh Loop subdivision refuses");
  // Floating-point kernels' bounds are not certified (doc/subdivision.md,
  // "What is certified"): where the surface is the face itself, lower and
  // upper are both 0 up to the rounding of their computation and may cross
  // by it: by at most 2^-40 times the largest coordinate, as in the stress
  // test (doc/reliability.md, Sec. 5). Certified kernels exactly.
  const double rounding = std::is_floating_point_v<typename K::FT> ? 0x1p-40 * largest_magnitude(m) : 0;
  const std::size_t nf = r->limit_mesh.faces.size();
  require(r->basis_range.size() == nf && r->tangent_plane.size() == nf, who + ": one bound per face");
  for (Index g = 0; g < nf; ++g) {
    if (r->degenerate[g]) continue;
    for (const auto* method : {&r->basis_range, &r->tangent_plane, &r->direct}) {
      if (method->empty()) continue;
      const auto& fb = (*method)[g];
      require(fb.lower_distance <= fb.upper_distance + rounding, who + ": lower <= upper (distances)");
    }
  }
  if constexpr (std::is_same_v<K, Exact_kernel>) {
    // The scheme with the kernel's own weights: evaluated exactly, its surface
    // over each face lies between the bounds.
    const Loop_limit_surface<K> surface(r->refined);
    // Exact evaluation at an irregular patch costs a local subdivision per
    // level in rationals: one point per face (the centre, or near a corner
    // in turn), on at most 16 faces, keeps an input within the time limit.
    const std::pair<double, double> at[] = {{1.0 / 3, 1.0 / 3}, {0.0625, 0.0625}, {0.875, 0.0625}, {0.0625, 0.875}};
    for (Index g = 0; g < nf && g < 16; ++g) {
      if (r->degenerate[g]) continue;
      {
        const auto [u, v] = at[g % 4];
        const mpq_class t = r->height(g, surface.evaluate(g, u, v));
        for (const auto* method : {&r->basis_range, &r->tangent_plane, &r->direct}) {
          if (method->empty()) continue;
          const auto& fb = (*method)[g];
          require(fb.lower <= t && t <= fb.upper, who + ": the exact surface lies within the bounds (face " +
                                                      std::to_string(g) + ")");
        }
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const int kernel = in.byte() % 5;
  const std::uint8_t mode = in.byte();
  const Mesh_d m = build_mesh(in);
  if (m.faces.size() > 64) return 0;
  bool accept = false;
  require(typed_errors_only([&] { accept = loop_acceptable(m); }, "check_mesh"), "check_mesh never throws");
  if (mode % 2 == 0) {
    const auto queries = decode_queries(in, m.faces.size());
    switch (kernel) {
      case 0: check_queries<Naive_kernel<double>>(m, accept, queries, false); break;
      case 1: check_queries<Failsafe_kernel<double>>(m, accept, queries, false); break;
      case 2: check_queries<Interval_kernel>(m, accept, queries, accept && loop_weights_everywhere(m)); break;
      case 3: check_queries<Exact_kernel>(m, accept, queries, false); break;
      default: check_queries<Mpfr_kernel<53>>(m, accept, queries, false);
    }
  } else {
    const unsigned level = (mode >> 1) % 2;
    switch (kernel) {
      case 0: check_bounds<Naive_kernel<double>>(m, accept, level); break;
      case 1: check_bounds<Failsafe_kernel<double>>(m, accept, level); break;
      case 2: check_bounds<Interval_kernel>(m, accept, level); break;
      default:
        // Exact bounds cost about 0.4 s of CPU per limit-mesh face in
        // rationals under the sanitizers (20 faces at level 0: 8 s): at most
        // 12 faces (level 0 beyond 3 faces), so that an input stays well
        // below the per-input time limit on a loaded machine.
        if (m.faces.size() <= 12) check_bounds<Exact_kernel>(m, accept, m.faces.size() * 4 <= 12 ? level : 0);
    }
  }
  return 0;
}
