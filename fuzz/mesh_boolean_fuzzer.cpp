// Fuzz harness: mesh Booleans (relgeo::boolean) and Booleans of Loop
// subdivision solids (relgeo::subdivision_boolean) on small closed meshes
// moved by fuzzed rigid motions and translations, including the degenerate
// placements users hit daily (coplanar faces, shared vertices and edges,
// touching, identical operands) and edited, invalid operands.
//
// Input: byte 0 the operation (union, intersection, difference, xor) and
// what runs (mesh Boolean, or subdivision Boolean at level 0 or 1), bytes 1-2
// the two base shapes (fuzz/mesh_builder.h's closed bases, a cube, or an
// arbitrary/edited mesh from mesh_builder.h), then per operand a motion: a
// rotation by a multiple of pi/2 or a fuzzed angle, and a translation whose
// components are multiples of 1/8 (contacts and coplanar faces) or fuzz
// coordinates (NaN, huge, subnormal).
//
// Contract (doc/reliability.md, harness mesh_boolean):
//  * invalid operands (open, non-manifold, misoriented, self-intersecting,
//    non-finite) end in a relgeo::Error (Invalid_operand), never a crash;
//  * under Exact_kernel a result always exists (status ok) and its exact
//    volumes satisfy, exactly in rationals,
//      V(A u B) + V(A n B) = V(A) + V(B),  V(A - B) = V(A) - V(A n B),
//    and the exact result has no self-intersection (exact test on its
//    rational vertices) and is a closed oriented surface: every directed
//    edge (u, v) is used as often as (v, u). (Not necessarily a manifold: a
//    regularised result may pinch along an edge, e.g. A - B for B a copy of
//    A moved by a subnormal amount, where faces parallel to the motion
//    overlap — found by this harness.)
//  * on valid operands the filtered kernel succeeds (any operation) and
//    gives the same faces as Exact_kernel;
//  * on valid operands the fail-safe and naive kernels return a result (ok
//    or failed), never an exception, typed or not;
//  * subdivision Booleans: a result, or a relgeo::Error; a result's control
//    mesh has no failed check in its validation.
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "fuzz_support.h"
#include "mesh_builder.h"
#include "relgeo/boolean.h"
#include "relgeo/boolean/subdivision_boolean.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/shapes.h"
#include "relgeo/mesh/validity.h"

namespace {

using namespace relgeo;
using namespace relgeo::fuzz;

Mesh_d shape(Input& in) {
  const int which = in.byte() % 8;
  if (which < 5) return base_mesh(which == 3 ? 0 : which);  // closed bases only (3 is the open grid)
  if (which == 5) return cube(0, 0, 0, 1);
  if (which == 6) return icosphere(0);
  return build_mesh(in);  // arbitrary or edited: mostly invalid operands
}

Mesh_d moved(const Mesh_d& m, Input& in) {
  Mesh_d r = m;
  const int kind = in.byte() % 4;
  const double angle = kind == 0 ? 0 : kind == 1 ? in.byte() % 4 * (M_PI / 2) : in.byte() / 40.0;
  const double c = kind == 1 ? std::round(std::cos(angle)) : std::cos(angle);
  const double s = kind == 1 ? std::round(std::sin(angle)) : std::sin(angle);
  double t[3];
  for (double& x : t) x = in.flag() ? in.coordinate() : static_cast<double>(static_cast<std::int8_t>(in.byte()) % 17) / 8;
  for (auto& p : r.vertices) {
    const double x = c * p.x - s * p.y, y = s * p.x + c * p.y;
    p = {x + t[0], y + t[1], p.z + t[2]};
  }
  return r;
}

mpq_class exact_volume(const Boolean_result<Exact_kernel>& r) {
  mpq_class v = 0;
  const auto vertices = r.exact_vertices();
  for (const Triangle& f : r.mesh.faces) {
    const auto &a = vertices[f[0]].point, &b = vertices[f[1]].point, &c = vertices[f[2]].point;
    v += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
  }
  return v;
}
mpq_class exact_volume(const Mesh_d& m) {
  mpq_class v = 0;
  for (const Triangle& f : m.faces) {
    const mpq_class ax = m.vertices[f[0]].x, ay = m.vertices[f[0]].y, az = m.vertices[f[0]].z;
    const mpq_class bx = m.vertices[f[1]].x, by = m.vertices[f[1]].y, bz = m.vertices[f[1]].z;
    const mpq_class cx = m.vertices[f[2]].x, cy = m.vertices[f[2]].y, cz = m.vertices[f[2]].z;
    v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  }
  return v;
}

// Every directed edge (u, v) used as often as (v, u): a closed, oriented
// surface (a 2-cycle), manifold or not.
bool balanced_directed_edges(const Mesh_d& m) {
  std::map<std::pair<Index, Index>, int> count;
  for (const Triangle& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      const Index u = f[k], v = f[(k + 1) % 3];
      count[{std::min(u, v), std::max(u, v)}] += u < v ? 1 : -1;
    }
  for (const auto& [e, c] : count)
    if (c != 0) return false;
  return true;
}

// The exact result's properties, on its faces with its exact vertices: the
// nearest rounding (the repair of the rounding changes faces; the default
// Boolean is checked in LLVMFuzzerTestOneInput).
void check_exact(const Mesh_d& a, const Mesh_d& b) {
  Boolean_options o;
  o.use_double_point_kernel = true;
  o.rounding = Output_rounding::nearest;
  const auto u = boolean(a, b, Boolean_operation::union_of, Exact_kernel{}, o);
  const auto i = boolean(a, b, Boolean_operation::intersection, Exact_kernel{}, o);
  const auto d = boolean(a, b, Boolean_operation::difference, Exact_kernel{}, o);
  require(u.ok() && i.ok() && d.ok(), "the exact kernel failed on valid operands");
  const mpq_class va = exact_volume(a), vb = exact_volume(b), vu = exact_volume(u), vi = exact_volume(i), vd = exact_volume(d);
  require(vu + vi == va + vb, "V(A u B) + V(A n B) != V(A) + V(B)");
  require(vd == va - vi, "V(A - B) != V(A) - V(A n B)");
  for (const auto* r : {&u, &i, &d}) {
    Triangle_mesh<Point_3<mpq_class>> exact;
    exact.faces = r->mesh.faces;
    for (const auto& v : r->exact_vertices()) exact.vertices.push_back(v.point);
    require(find_self_intersections<Exact_kernel>(exact).pairs.empty(), "the exact result crosses itself");
    require(balanced_directed_edges(r->mesh), "the exact result is not a closed oriented surface");
  }
  const auto f = boolean(a, b, Boolean_operation::union_of, Filtered_exact_kernel{}, o);
  require(f.ok() && f.mesh.faces == u.mesh.faces, "the filtered kernel differs from the exact one");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const std::uint8_t head = in.byte();
  const auto op = static_cast<Boolean_operation>(head % 4);
  const int mode = (head / 4) % 4;  // 0, 1: mesh Boolean; 2, 3: subdivision Boolean at level 0, 1
  const Mesh_d a0 = shape(in), b0 = shape(in);
  const Mesh_d a = moved(a0, in), b = moved(b0, in);
  if (mode < 2) {
    bool valid = false, exact = false;
    typed_errors_only(
        [&] {
          // Refuses invalid operands before any work. On valid ones the engine
          // does not fail; the repair of its rounding may give up, and then
          // says so on an output its validation finds invalid.
          const auto r = boolean(a, b, op);
          exact = r.ok() || (r.failure.rfind("rounding:", 0) == 0 && !r.validation.is_valid_solid());
          const Solid_report& v = r.validation;
          const bool closed_manifold = v.closed.passed() && v.edge_manifold.passed() && v.vertex_manifold.passed();
          require(!r.ok() || r.rounding.converged() || !closed_manifold,
                  "an ok closed manifold result with defects left after the repair");
          valid = true;
        },
        "boolean (filtered)");
    if (!valid) return 0;
    require(exact, "the filtered kernel failed on valid operands");
    if (mode == 0) check_exact(a, b);
    // On valid operands the other kernels answer with a result (a failure
    // status at worst), never an exception.
    no_exception([&] { (void)boolean(a, b, op, Failsafe_kernel<double>{}); }, "boolean (failsafe)");
    no_exception([&] { (void)boolean(a, b, op, Naive_kernel<double>{}); }, "boolean (naive)");
    return 0;
  }
  typed_errors_only(
      [&] {
        Subdivision_boolean_options o;
        o.distance_samples = 1;
        o.fit = in.flag();
        const auto r = subdivision_boolean(a, b, op, mode - 2u, Filtered_exact_kernel{}, o);
        if (r.ok()) require(r.validation.has_no_defect(), "a subdivision result's control mesh has a defect");
      },
      "subdivision_boolean");
  return 0;
}
