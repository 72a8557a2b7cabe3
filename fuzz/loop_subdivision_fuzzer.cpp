// Fuzz harness: Loop refinement, limit meshes and limit positions
// (relgeo/subdivision.h) on arbitrary small meshes (fuzz/mesh_builder.h)
// under relgeo's kernels.
//
// Input: byte 0 the kernel, byte 1 the operation, its level and the crease
// rules, then the mesh (mesh_builder.h).
//
// Contract (doc/reliability.md, harness loop_subdivision):
//  * exactly the meshes Loop subdivision requires are accepted: those
//    check_mesh finds free of every topological defect and invalid tag, with
//    finite coordinates and no two faces sharing two edges; every other one
//    ends in a relgeo::Error, and nothing else is thrown;
//  * a refinement has 4^L times the faces, V + E vertices per level, is
//    again free of topological defects and its tags are valid; limit meshes
//    have the same faces; every coordinate is finite;
//  * Interval_kernel refinement encloses Exact_kernel's wherever both use
//    Loop's own weights (every smooth vertex of valence 3, 4 or 6; Hoppe's
//    crease rules).
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

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

enum class Operation { refine, limit_mesh, limit_positions };

template <class P>
bool finite_point(const P& p) {
  return is_finite_number(p.x) && is_finite_number(p.y) && is_finite_number(p.z);
}

/// A coordinate within 2^10 of FT's largest finite value (floating-point FT;
/// intervals are doubles; MPFR and rationals do not overflow).
template <class FT>
bool near_overflow(const Mesh_d& m) {
  double largest = 0;
  if constexpr (std::is_floating_point_v<FT>) largest = static_cast<double>(std::numeric_limits<FT>::max());
  else if constexpr (std::is_same_v<FT, Interval>) largest = std::numeric_limits<double>::max();
  else return false;
  return largest_magnitude(m) > std::ldexp(largest, -10);
}

template <class K>
void check(const Mesh_d& m, Operation op, unsigned levels, const Loop_options& options, bool accept) {
  using Mesh = Triangle_mesh<typename K::Point_3>;
  const std::string who = K::name();
  Loop_subdivider<K> loop(options);
  Mesh in;
  try {
    in = to_kernel<K>(m);
  } catch (const Non_finite_input&) {  // kernels with exact coordinates refuse NaN at construction
    require(!accept, who + ": refused finite coordinates");
    return;
  }
  for (const auto& p : in.vertices) accept = accept && finite_point(p);  // float may overflow
  // refine(m, 0) is a copy: it checks coordinates only.
  const bool validates = levels > 0 || op != Operation::refine;
  Mesh out;
  std::vector<typename K::Point_3> positions;
  bool ok = false;
  try {
    if (op == Operation::refine) out = loop.refine(in, levels);
    else if (op == Operation::limit_mesh) out = loop.limit_mesh(in, levels);
    else positions = loop.limit_positions(in);
    ok = true;
  } catch (const relgeo::Error& e) {
    // Finite coordinates whose refinement overflows the number type are
    // refused with computation_failure (doc/reliability.md): allowed when a
    // coordinate is within a factor 2^10 of the largest finite value (ring
    // sums of up to ~1000 neighbours).
    const bool overflow = e.code() == Error_code::computation_failure && near_overflow<typename K::FT>(m);
    require(!accept || !validates || overflow, who + ": refused a mesh Loop subdivision accepts: " + e.what());
  } catch (const std::exception& e) {
    require(false, who + ": untyped exception " + e.what());
  }
  if (!ok) return;
  if (validates) require(accept, who + ": accepted a mesh Loop subdivision must refuse");
  if (op == Operation::limit_positions) {
    require(positions.size() == in.vertices.size(), who + ": one limit position per vertex");
    for (const auto& p : positions) require(finite_point(p), who + ": finite limit positions");
    return;
  }
  std::size_t faces = in.faces.size(), vertices = in.vertices.size();
  for (unsigned l = 0; l < levels; ++l) faces *= 4;
  require(out.faces.size() == faces, who + ": 4^L faces per face");
  if (levels == 1) vertices += Mesh_topology::build(in).number_of_edges();
  if (levels <= 1) require(out.vertices.size() == vertices, who + ": V + E vertices");
  for (const auto& p : out.vertices) require(finite_point(p), who + ": finite coordinates");
  Mesh_d combinatorial;
  combinatorial.vertices.resize(out.vertices.size());
  combinatorial.faces = out.faces;
  combinatorial.tags = out.tags;
  if (levels > 0) require(loop_topology_report(combinatorial).is_valid(), who + ": the result is a valid mesh");
}

/// Interval refinement encloses exact refinement where both use Loop's weights.
void check_enclosure(const Mesh_d& m) {
  const Mesh_topology t = Mesh_topology::build(m);
  for (Index v = 0; v < m.vertices.size(); ++v) {
    const Index n = t.valence(v);
    if (!t.is_isolated(v) && !t.is_boundary_vertex(v) && n != 3 && n != 4 && n != 6) return;
  }
  const auto exact = Loop_subdivider<Exact_kernel>().refine(to_kernel<Exact_kernel>(m), 1);
  // Near the largest double, interval refinement may refuse (typed) what
  // exact refinement computes: its outward rounding overflows first. That
  // refusal is the contract check<Interval_kernel> checks; nothing to compare.
  Triangle_mesh<Interval_kernel::Point_3> interval;
  if (!typed_errors_only([&] { interval = Loop_subdivider<Interval_kernel>().refine(to_kernel<Interval_kernel>(m), 1); },
                         "interval refinement"))
    return;
  require(exact.faces == interval.faces, "interval and exact refinement: same faces");
  for (std::size_t i = 0; i < exact.vertices.size(); ++i) {
    const auto& e = exact.vertices[i];
    const auto& iv = interval.vertices[i];
    for (int c = 0; c < 3; ++c) {
      const mpq_class& q = c == 0 ? e.x : c == 1 ? e.y : e.z;
      const Interval& x = c == 0 ? iv.x : c == 1 ? iv.y : iv.z;
      require(mpq_class(x.inf()) <= q && q <= mpq_class(x.sup()),
              "Interval refinement encloses the exact refinement (vertex " + std::to_string(i) + ")");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const int kernel = in.byte() % 6;
  const std::uint8_t mode = in.byte();
  const auto op = static_cast<Operation>(mode % 3);
  const unsigned levels = (mode >> 2) % 3;
  Loop_options options;
  if (mode & 0x40) options.crease_rules = Loop_crease_rules::biermann_levin_zorin;
  if (mode & 0x80) options.vertex_weights = Loop_vertex_weights::warren;
  const Mesh_d m = build_mesh(in);
  bool accept = false;
  require(typed_errors_only([&] { accept = loop_acceptable(m); }, "check_mesh"), "check_mesh never throws");
  switch (kernel) {
    case 0: check<Naive_kernel<double>>(m, op, levels, options, accept); break;
    case 1: check<Failsafe_kernel<double>>(m, op, levels, options, accept); break;
    case 2: check<Interval_kernel>(m, op, levels, options, accept); break;
    case 3: check<Exact_kernel>(m, op, std::min(levels, 1u), options, accept); break;
    case 4: check<Mpfr_kernel<53>>(m, op, levels, options, accept); break;
    default:
      check<Naive_kernel<float>>(m, op, levels, options, accept);
  }
  if (accept && m.faces.size() <= 64 && kernel == 2 && options.crease_rules == Loop_crease_rules::hoppe &&
      options.vertex_weights == Loop_vertex_weights::loop && m.tags.empty())
    check_enclosure(m);
  return 0;
}
