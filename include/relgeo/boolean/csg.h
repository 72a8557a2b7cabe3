// relgeo/boolean/csg.h — CSG trees: an expression of unions, intersections
// and differences over many solids, evaluated with relgeo::boolean, every
// intermediate result a valid solid in doubles (the repaired rounding) and
// reported node by node.
//
// The leaves are checked once, before any Boolean (closed, oriented,
// manifold, no degenerate face, no self-intersection); an intermediate result
// is validated by the Boolean that made it, and that certificate travels with
// it: the next Boolean does not check it again (operand checks are a third to
// a half of a Boolean's time). Unions and intersections of n arguments are
// reduced pairwise as a balanced tree (small pieces first, as Manifold's
// batch Boolean does); a difference takes the first argument minus each of
// the others in turn.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/boolean/mesh_boolean.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/self_intersection.h"

namespace relgeo {

/// A node of a CSG tree: a solid (a leaf) or an operation on two or more nodes.
struct Csg_node {
  enum class Kind : std::uint8_t { solid, union_of, intersection, difference };
  Kind kind = Kind::solid;
  /// A solid: its boundary (shared, not copied, by the nodes that use it).
  std::shared_ptr<const Mesh_double> mesh;
  /// A solid: its name in messages (the tool: the file).
  std::string name;
  /// An operation: its arguments (difference: the first minus all the others).
  std::vector<Csg_node> args;

  static Csg_node solid(Mesh_double m, std::string name = {}) {
    return {Kind::solid, std::make_shared<const Mesh_double>(std::move(m)), std::move(name), {}};
  }
  static Csg_node operation(Kind kind, std::vector<Csg_node> args) { return {kind, nullptr, {}, std::move(args)}; }
};

constexpr std::string_view to_string(Csg_node::Kind k) {
  switch (k) {
    case Csg_node::Kind::solid: return "solid";
    case Csg_node::Kind::union_of: return "union";
    case Csg_node::Kind::intersection: return "intersection";
    case Csg_node::Kind::difference: return "difference";
  }
  return "?";
}

/// A tree that cannot be evaluated: an operation with fewer than two
/// arguments, a leaf without a mesh or without faces, a leaf that is not a
/// valid solid.
/// `node()` names it by its path: "root", "root.1" (root's second
/// argument), "root.1.0", ...
class Invalid_csg_node : public Invalid_input {
 public:
  Invalid_csg_node(std::string node, const std::string& what)
      : Invalid_input("csg: node " + node + ": " + what), node_(std::move(node)) {}
  const std::string& node() const { return node_; }

 private:
  std::string node_;
};

/// Options of relgeo::csg.
struct Csg_options {
  /// Options of each Boolean. `check_operands` and `check_self_intersections`
  /// apply to the leaves (checked once); an intermediate result is not
  /// checked again when `validate_output` is on (its validation is its
  /// certificate), and is checked as an operand when it is off.
  Boolean_options boolean;
};

/// One Boolean of the evaluation.
struct Csg_step {
  std::string node;       ///< the operation's path
  Csg_node::Kind operation = Csg_node::Kind::union_of;
  bool ok = false;
  std::string failure;    ///< empty when ok
  std::size_t faces = 0;  ///< of the result
  double volume = 0;      ///< of the result (its validation)
  std::string validation; ///< the validation's summary ("valid solid")
  Rounding_repair_report rounding;
  double seconds = 0;
};

/// The result of relgeo::csg.
struct Csg_result {
  enum class Status : std::uint8_t { ok, failed };
  Status status = Status::ok;
  /// Which node failed and why (empty when ok).
  std::string failure;
  /// The root's solid (the last valid result when a step failed).
  Mesh_double mesh;
  /// Every Boolean, in the order evaluated.
  std::vector<Csg_step> steps;
  double seconds = 0;

  bool ok() const { return status == Status::ok; }
};

namespace internal {

template <IntersectionKernel_3 K>
class Csg_evaluator {
 public:
  Csg_evaluator(const K& k, const Csg_options& o) : k_(k), options_(o) {
    // Every result is validated, so every operand after the leaves is certified.
    inner_ = o.boolean;
    if (inner_.validate_output) inner_.check_operands = false;
  }

  void check(const Csg_node& n, const std::string& path) {
    if (n.kind == Csg_node::Kind::solid) {
      if (!n.mesh) throw Invalid_csg_node(path, "a solid without a mesh");
      if (n.mesh->faces.empty()) throw Invalid_csg_node(path, "solid '" + n.name + "' has no faces");
      if (!options_.boolean.check_operands) return;
      internal::Checked_mesh checked;
      const Mesh_report report = options_.boolean.check_self_intersections
                                     ? internal::check_solid<Filtered_exact_kernel>(*n.mesh, {}, checked)
                                     : check_mesh(*n.mesh);
      if (!report.is_valid())
        throw Invalid_csg_node(path, "not a valid solid: " + std::string(Invalid_mesh("'" + n.name + "'", report.issues).what()));
      if (report.self_intersections_checked)
        leaf_opposites_[n.mesh.get()] =
            std::make_shared<const std::vector<Index>>(std::move(checked.topology).take_opposites());
      return;
    }
    if (n.args.size() < 2)
      throw Invalid_csg_node(path, std::string(to_string(n.kind)) + " of " + std::to_string(n.args.size()) +
                                       " argument(s): two or more are needed");
    for (std::size_t i = 0; i < n.args.size(); ++i) check(n.args[i], path + "." + std::to_string(i));
  }

  // A node's solid and, when known, its half-edge opposites (from the
  // leaf's check or the validation of the Boolean that made it): the next
  // Boolean takes them with the certificate instead of building them.
  struct Part {
    std::shared_ptr<const Mesh_double> mesh;
    std::shared_ptr<const std::vector<Index>> opposites;
    explicit operator bool() const { return mesh != nullptr; }
  };

  // The node's solid; empty when a step failed (result_.failure says which).
  Part evaluate(const Csg_node& n, const std::string& path) {
    if (n.kind == Csg_node::Kind::solid) {
      const auto it = leaf_opposites_.find(n.mesh.get());
      return {n.mesh, it == leaf_opposites_.end() ? nullptr : it->second};
    }
    std::vector<Part> parts;
    for (std::size_t i = 0; i < n.args.size(); ++i) {
      Part p = evaluate(n.args[i], path + "." + std::to_string(i));
      if (!p) return {};
      parts.push_back(std::move(p));
    }
    if (n.kind == Csg_node::Kind::difference) {
      Part result = parts[0];
      for (std::size_t i = 1; i < parts.size() && result; ++i) result = step(result, parts[i], n.kind, path);
      return result;
    }
    // Balanced pairwise reduction: small operands meet first.
    while (parts.size() > 1) {
      std::vector<Part> next;
      for (std::size_t i = 0; i + 1 < parts.size(); i += 2) {
        Part r = step(parts[i], parts[i + 1], n.kind, path);
        if (!r) return {};
        next.push_back(std::move(r));
      }
      if (parts.size() % 2) next.push_back(parts.back());
      parts = std::move(next);
    }
    return parts[0];
  }

  Csg_result& result() { return result_; }

 private:
  Part step(const Part& pa, const Part& pb, Csg_node::Kind kind, const std::string& path) {
    const Mesh_double& a = *pa.mesh;
    const Mesh_double& b = *pb.mesh;
    const Boolean_operation op = kind == Csg_node::Kind::union_of       ? Boolean_operation::union_of
                                 : kind == Csg_node::Kind::intersection ? Boolean_operation::intersection
                                                                         : Boolean_operation::difference;
    internal::Stopwatch clock;
    // The leaves checked in full (check) and every result validated (here):
    // both operands are certified solids.
    Boolean_options options = inner_;
    if (options_.boolean.check_operands && options_.boolean.check_self_intersections && inner_.validate_output)
      options.certified_operands = Operand_certificate(&a, &b, pa.opposites.get(), pb.opposites.get());
    auto r = boolean(a, b, op, k_, options);
    Csg_step s{path, kind, r.ok(), r.failure, r.mesh.faces.size(), r.validation.volume.value,
               r.validation.summary(), r.rounding, 0};
    if (s.ok && inner_.validate_output && !r.validation.is_valid_solid()) {
      s.ok = false;
      s.failure = "the result is not a valid solid: " + s.validation;
    }
    s.seconds = clock.elapsed();
    result_.steps.push_back(s);
    if (!s.ok) {
      result_.status = Csg_result::Status::failed;
      result_.failure = "node " + path + " (" + std::string(to_string(kind)) + ", step " +
                        std::to_string(result_.steps.size()) + "): " + s.failure;
      result_.mesh = std::move(r.mesh);
      return {};
    }
    auto out = std::make_shared<Mesh_double>();
    out->vertices = std::move(r.mesh.vertices);
    out->faces = std::move(r.mesh.faces);
    return {std::move(out), std::make_shared<const std::vector<Index>>(std::move(r.halfedge_opposites))};
  }

  const K& k_;
  Csg_options options_;
  Boolean_options inner_;
  Csg_result result_;
  // Leaves checked by check(), by mesh (the tree holds them).
  std::unordered_map<const Mesh_double*, std::shared_ptr<const std::vector<Index>>> leaf_opposites_;
};

}  // namespace internal

/// \brief Evaluates the CSG tree `tree` with relgeo::boolean under kernel K
/// (see the file comment): the root's solid in `mesh`, every Boolean with
/// its status, validation, volume and rounding repair in `steps`. A step
/// that fails (a kernel that cannot decide, a rounding that cannot be
/// repaired, a result that is not a valid solid) stops the evaluation: the
/// result says which node, and `mesh` is that step's output.
/// \throws Invalid_csg_node (before any Boolean) for an operation with fewer
/// than two arguments, a leaf without a mesh, and, with
/// `options.boolean.check_operands`, a leaf that is not a valid solid.
template <IntersectionKernel_3 K = Filtered_exact_kernel>
Csg_result csg(const Csg_node& tree, const K& k = K{}, const Csg_options& options = {}) {
  internal::Stopwatch clock;
  internal::Csg_evaluator<K> e(k, options);
  e.check(tree, "root");
  const auto root = e.evaluate(tree, "root");
  Csg_result r = std::move(e.result());
  if (root) r.mesh = *root.mesh;
  r.seconds = clock.elapsed();
  return r;
}

}  // namespace relgeo
