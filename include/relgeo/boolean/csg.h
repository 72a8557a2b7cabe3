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
//
// Under a kernel of exact constructions the intermediates can instead stay
// exact (Csg_intermediates::exact): each a mesh of the kernel's points,
// validated exactly, and the root's exact solid rounded once at the end.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/boolean/mesh_boolean.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/rounding_repair.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_validation.h"

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

/// What the intermediate results of a CSG tree are.
enum class Csg_intermediates : std::uint8_t {
  /// Rounded to doubles at every step (with the Boolean's rounding, by
  /// default repaired: each a valid solid in doubles). Fast; the size of the
  /// numbers stays that of doubles.
  rounded,
  /// Kept exact as meshes of the kernel's points (an ExactChainingKernel:
  /// Exact_kernel, Cgal_kernel<CGAL::Epeck>), each validated exactly; the
  /// root's exact solid is rounded once, at the end, with the Boolean's
  /// rounding. The root is then the exact result of the whole tree rounded
  /// once, but the coordinates' size grows with every step, and with it the
  /// time (doc/boolean.md, "Exact chains").
  exact
};

constexpr std::string_view to_string(Csg_intermediates i) {
  return i == Csg_intermediates::exact ? "exact" : "rounded";
}

/// Options of relgeo::csg.
struct Csg_options {
  /// Options of each Boolean. `check_operands` and `check_self_intersections`
  /// apply to the leaves (checked once); an intermediate result is not
  /// checked again when `validate_output` is on (its validation is its
  /// certificate), and is checked as an operand when it is off. With exact
  /// intermediates, every intermediate is validated exactly (whatever
  /// `validate_output` says: that validation is what certifies it), and
  /// `rounding`, `repair` and `validate_output` apply to the root's rounding.
  Boolean_options boolean;
  Csg_intermediates intermediates = Csg_intermediates::rounded;
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
  /// Exact intermediates: the largest size of a coordinate of the result, in
  /// bits (numerator and denominator; 0 when not known: rounded
  /// intermediates, a kernel whose numbers are not GMP rationals).
  std::size_t coordinate_bits = 0;
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
  /// Exact intermediates: the rounding of the root's exact solid to `mesh`
  /// (its repair, and the validation's summary of `mesh` when
  /// `validate_output`); empty with rounded intermediates (the last step
  /// has them).
  Rounding_repair_report rounding;
  std::string validation;
  double seconds = 0;

  bool ok() const { return status == Status::ok; }
};

namespace internal {

// The Booleans of a tree in their order, whatever a node's solid is (Part:
// false when empty): `leaf(n)` gives a leaf's, `step(a, b, kind, path)` a
// Boolean's; an empty part (a failed step) stops the evaluation.
template <class Part, class Leaf, class Step>
Part reduce_tree(const Csg_node& n, const std::string& path, const Leaf& leaf, const Step& step) {
  if (n.kind == Csg_node::Kind::solid) return leaf(n);
  std::vector<Part> parts;
  for (std::size_t i = 0; i < n.args.size(); ++i) {
    Part p = reduce_tree<Part>(n.args[i], path + "." + std::to_string(i), leaf, step);
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

// The record of one Boolean of the tree (its coordinate bits and time are
// the caller's).
inline Csg_step step_record(const std::string& path, Csg_node::Kind kind, const Boolean_output& r) {
  return {.node = path,
          .operation = kind,
          .ok = r.ok(),
          .failure = r.failure,
          .faces = r.mesh.faces.size(),
          .volume = r.validation.volume.value,
          .validation = r.validation.summary(),
          .rounding = r.rounding};
}

// Whether a validated result certifies the solid its mesh bounds: a valid
// solid, or no face at all (the empty solid, as Valid_solid takes it: the
// validation does not call a mesh without faces a solid).
inline bool certified_solid(const Boolean_output& r) { return r.mesh.faces.empty() || r.validation.is_valid_solid(); }

constexpr Boolean_operation boolean_operation(Csg_node::Kind kind) {
  return kind == Csg_node::Kind::union_of       ? Boolean_operation::union_of
         : kind == Csg_node::Kind::intersection ? Boolean_operation::intersection
                                                : Boolean_operation::difference;
}

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
        leaf_opposites_[n.mesh.get()] = std::make_shared<const std::vector<Index>>(std::move(checked.opposites));
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
    const auto leaf = [&](const Csg_node& solid) -> Part {
      const auto it = leaf_opposites_.find(solid.mesh.get());
      return {solid.mesh, it == leaf_opposites_.end() ? nullptr : it->second};
    };
    const auto boolean_step = [&](const Part& a, const Part& b, Csg_node::Kind kind, const std::string& at) {
      return step(a, b, kind, at);
    };
    return reduce_tree<Part>(n, path, leaf, boolean_step);
  }

  Csg_result& result() { return result_; }

 private:
  Part step(const Part& pa, const Part& pb, Csg_node::Kind kind, const std::string& path) {
    const Mesh_double& a = *pa.mesh;
    const Mesh_double& b = *pb.mesh;
    const Boolean_operation op = boolean_operation(kind);
    internal::Stopwatch clock;
    // The leaves checked in full (check) and every result validated (here):
    // both operands are certified solids.
    Boolean_options options = inner_;
    if (options_.boolean.check_operands && options_.boolean.check_self_intersections && inner_.validate_output)
      options.certified_operands = Operand_certificate(&a, &b, pa.opposites.get(), pb.opposites.get());
    auto r = boolean(a, b, op, k_, options);
    Csg_step s = step_record(path, kind, r);
    if (s.ok && inner_.validate_output && !certified_solid(r)) {
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

// The largest coordinate of m in bits (numerator and denominator), for
// GMP rationals; 0 for other numbers.
template <class P>
std::size_t coordinate_bits(const Triangle_mesh<P>& m) {
  std::size_t bits = 0;
  if constexpr (std::same_as<P, Point_3<mpq_class>>)
    for (const P& p : m.vertices)
      for (const mpq_class* c : {&p.x, &p.y, &p.z})
        bits = std::max(bits, mpz_sizeinbase(c->get_num_mpz_t(), 2) + mpz_sizeinbase(c->get_den_mpz_t(), 2));
  return bits;
}

// Exact intermediates (Csg_intermediates::exact): the leaves (checked in
// doubles by Csg_evaluator::check) as K's points, each Boolean on exact
// operands with the nearest rounding (which keeps the exact faces), its
// exact result validated under K with the operands' certificates (the
// certificate of the next step, which does not check it again), and the
// root rounded once.
template <ExactChainingKernel K>
class Exact_csg_evaluator {
 public:
  using Exact_mesh = Triangle_mesh<typename K::Point_3>;
  // A node's exact solid and, once validated, its half-edge opposites.
  struct Part {
    std::shared_ptr<const Exact_mesh> mesh;
    std::shared_ptr<const std::vector<Index>> opposites;
    explicit operator bool() const { return mesh != nullptr; }
  };

  Exact_csg_evaluator(const K& k, const Csg_options& o) : k_(k), options_(o) {
    // The leaves are certified when they were checked in full; every result
    // is validated (exactly), so every later operand is certified too.
    leaves_checked_ = o.boolean.check_operands && o.boolean.check_self_intersections;
    step_options_ = o.boolean;
    step_options_.check_operands = false;
    step_options_.validate_output = true;
    step_options_.rounding = Output_rounding::nearest;
  }

  // The root's exact solid; empty when a step failed.
  Part evaluate(const Csg_node& tree) {
    const auto leaf = [&](const Csg_node& n) { return exact_leaf(n); };
    const auto boolean_step = [&](const Part& a, const Part& b, Csg_node::Kind kind, const std::string& path) {
      return step(a, b, kind, path);
    };
    return reduce_tree<Part>(tree, "root", leaf, boolean_step);
  }

  // The root's exact solid in doubles: each vertex its nearest double, what
  // that broke repaired (Output_rounding::repaired: every vertex may move),
  // and the result validated in doubles.
  void round_root(const Exact_mesh& root) {
    Mesh_double& m = result_.mesh;
    m.faces = root.faces;
    m.vertices.clear();
    m.vertices.reserve(root.vertices.size());
    const auto implicit = k_.construct_implicit_point_3_object();
    const auto approximate = k_.approximate_point_3_object();
    for (const auto& p : root.vertices) m.vertices.push_back(approximate(implicit(p)).point);
    if (options_.boolean.rounding == Output_rounding::repaired) {
      result_.rounding = repair_rounding(m, std::vector<char>(m.vertices.size(), 1), options_.boolean.repair);
      if (!result_.rounding.converged())
        return fail("root (rounding): " + std::to_string(result_.rounding.remaining_pairs.size()) +
                    " face pairs still meet and " + std::to_string(result_.rounding.remaining_degenerate_faces.size()) +
                    " faces are degenerate after the repair");
    }
    if (options_.boolean.validate_output) {
      const Solid_report v = validate_solid(m, Filtered_exact_kernel{}, options_.boolean.validation);
      result_.validation = v.summary();
      if (!m.faces.empty() && !v.is_valid_solid())
        fail("root (rounding): the rounded solid is not a valid solid: " + result_.validation);
    }
  }

  Csg_result& result() { return result_; }

 private:
  Part exact_leaf(const Csg_node& n) {
    Part& p = leaves_[n.mesh.get()];
    if (!p) p.mesh = std::make_shared<const Exact_mesh>(exact_operand(*n.mesh, k_));
    return p;
  }

  Part step(const Part& a, const Part& b, Csg_node::Kind kind, const std::string& path) {
    internal::Stopwatch clock;
    Boolean_options options = step_options_;
    if (leaves_checked_)
      options.certified_operands =
          Operand_certificate(a.mesh.get(), b.mesh.get(), a.opposites.get(), b.opposites.get());
    auto r = boolean(*a.mesh, *b.mesh, boolean_operation(kind), k_, options);
    Csg_step s = step_record(path, kind, r);
    Part out;
    if (s.ok) {
      auto exact = std::make_shared<const Exact_mesh>(r.exact_mesh());
      s.coordinate_bits = coordinate_bits(*exact);
      if (certified_solid(r)) {
        out.mesh = std::move(exact);
        out.opposites = std::make_shared<const std::vector<Index>>(std::move(r.halfedge_opposites));
      } else {
        s.ok = false;
        s.failure = "the exact result is not a valid solid: " + s.validation;
      }
    }
    s.seconds = clock.elapsed();
    result_.steps.push_back(s);
    if (!s.ok) {
      fail("node " + path + " (" + std::string(to_string(kind)) + ", step " + std::to_string(result_.steps.size()) +
           "): " + s.failure);
      result_.mesh = std::move(r.mesh);
    }
    return out;
  }

  void fail(std::string why) {
    result_.status = Csg_result::Status::failed;
    result_.failure = std::move(why);
  }

  const K& k_;
  Csg_options options_;
  Boolean_options step_options_;
  bool leaves_checked_ = false;
  Csg_result result_;
  std::unordered_map<const Mesh_double*, Part> leaves_;  // a leaf used twice is converted once
};

}  // namespace internal

/// \brief Evaluates the CSG tree `tree` with relgeo::boolean under kernel K
/// (see the file comment): the root's solid in `mesh`, every Boolean with
/// its status, validation, volume and rounding repair in `steps`. A step
/// that fails (a kernel that cannot decide, a rounding that cannot be
/// repaired, a result that is not a valid solid) stops the evaluation: the
/// result says which node, and `mesh` is that step's output.
/// With exact intermediates (Csg_options::intermediates) the steps are
/// Booleans of exact solids and `rounding` and `validation` describe the
/// root's one rounding.
/// \throws Invalid_csg_node (before any Boolean) for an operation with fewer
/// than two arguments, a leaf without a mesh, and, with
/// `options.boolean.check_operands`, a leaf that is not a valid solid.
/// \throws Invalid_input for exact intermediates under a kernel that is not
/// an ExactChainingKernel.
template <IntersectionKernel_3 K = Filtered_exact_kernel>
Csg_result csg(const Csg_node& tree, const K& k = K{}, const Csg_options& options = {}) {
  internal::Stopwatch clock;
  const bool exact_intermediates = options.intermediates == Csg_intermediates::exact;
  if (exact_intermediates && !ExactChainingKernel<K>)
    throw Invalid_input("csg: exact intermediates need a kernel of exact constructions whose points are exact (" +
                        K::name() + " is not one; Exact_kernel and Cgal_kernel<CGAL::Epeck> are)");
  internal::Csg_evaluator<K> e(k, options);
  e.check(tree, "root");
  Csg_result r;
  if (exact_intermediates) {
    if constexpr (ExactChainingKernel<K>) {
      internal::Exact_csg_evaluator<K> exact(k, options);
      if (const auto root = exact.evaluate(tree)) exact.round_root(*root.mesh);
      r = std::move(exact.result());
    }
  } else {
    const auto root = e.evaluate(tree, "root");
    r = std::move(e.result());
    if (root) r.mesh = *root.mesh;
  }
  r.seconds = clock.elapsed();
  return r;
}

}  // namespace relgeo
