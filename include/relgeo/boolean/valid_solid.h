// relgeo/boolean/valid_solid.h — a mesh that carries its certificate: a
// closed, consistently oriented 2-manifold without degenerate faces, finite
// coordinates or self-intersections, decided by relgeo's exact tests. A
// Boolean of two Valid_solids skips the operand checks (a third to a half of
// a Boolean's time): a result that relgeo produced and validated, or a mesh
// checked once, is not checked again when it is used again (issue 28).
//
//   relgeo::Valid_solid part(relgeo::read_mesh("part.off"));    // checked here, once
//   for (const relgeo::Mesh_double& hole : holes) {
//     const auto r = relgeo::boolean(part, relgeo::Valid_solid(hole), relgeo::Boolean_operation::difference);
//     part = relgeo::Valid_solid::of(r).value();                // certified by r's validation
//   }
//
// The certificate is only made by those two checks, and the mesh cannot be
// changed afterwards (it is held const and shared: copies are cheap).
#pragma once

#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/boolean/mesh_boolean.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

class Valid_solid {
 public:
  /// Checks m as the Boolean checks an operand (check_solid, exact). The
  /// empty mesh passes: it bounds the empty solid, an operand the Boolean
  /// accepts (A union nothing is A).
  /// \throws Invalid_operand (operand "solid") naming every defect.
  explicit Valid_solid(Mesh_double m) {
    internal::Checked_mesh checked;
    Mesh_report report = internal::check_solid<Filtered_exact_kernel>(m, {}, checked);
    if (!report.is_valid()) throw Invalid_operand("solid", std::move(report.issues));
    held_ = std::make_shared<const Held>(Held{std::move(m), std::move(checked.opposites)});
  }

  /// The output of a Boolean as a certified solid when the Boolean succeeded
  /// and its validation ran and found a valid solid (validate_solid: exact
  /// tests on the output's doubles, under every kernel), or the output is
  /// empty (the exact result is the empty solid: operands apart, say, which
  /// the validation does not count as a solid); nothing otherwise.
  template <IntersectionKernel_3 K>
  static std::optional<Valid_solid> of(const Boolean_result<K>& r) {
    if (!r.ok() || r.validation.kernel.empty()) return std::nullopt;
    if (!r.mesh.faces.empty() && !r.validation.is_valid_solid()) return std::nullopt;
    Mesh_double m;
    m.vertices = r.mesh.vertices;
    m.faces = r.mesh.faces;
    return Valid_solid(Held{std::move(m), r.halfedge_opposites});
  }

  const Mesh_double& mesh() const { return held_->mesh; }

  /// That the meshes of `a` and `b` are certified: what a Boolean of two
  /// Valid_solids tells the engine (Boolean_options::certified_operands),
  /// with their half-edge opposites.
  static Operand_certificate certificate(const Valid_solid& a, const Valid_solid& b) {
    return Operand_certificate(&a.held_->mesh, &b.held_->mesh, &a.held_->opposites, &b.held_->opposites);
  }

 private:
  // The mesh and its half-edge opposites (empty when not known), never
  // changed once certified.
  struct Held {
    Mesh_double mesh;
    std::vector<Index> opposites;
  };
  explicit Valid_solid(Held h) : held_(std::make_shared<const Held>(std::move(h))) {}

  std::shared_ptr<const Held> held_;
};

/// relgeo::boolean of two certified solids: the same result as on their
/// meshes, without the operand checks (options.check_operands is ignored),
/// and a validation that does not test again what the certificates prove
/// (Boolean_options::certified_operands).
template <IntersectionKernel_3 K = Filtered_exact_kernel>
Boolean_result<K> boolean(const Valid_solid& a, const Valid_solid& b, Boolean_operation op, const K& k = K{},
                          Boolean_options options = {}) {
  options.check_operands = false;
  options.certified_operands = Valid_solid::certificate(a, b);
  return boolean(a.mesh(), b.mesh(), op, k, options);
}

}  // namespace relgeo
