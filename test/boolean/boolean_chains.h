// test/boolean/boolean_chains.h — the three CSG chains of issue 28, the way
// people use Booleans (each operation on the result of the last): a sphere
// drilled by square prisms at random orientations through its centre, the
// union of spheres of random sizes and places, and a slab alternately
// intersected and united with boxes rotated about one axis. Rounding each
// exact result to its nearest doubles makes all three cross themselves
// within a few steps; used by the rounding tests and the Boolean benchmark.
#pragma once

#include <random>
#include <string_view>
#include <utility>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/boolean/csg.h"
#include "relgeo/mesh/shapes.h"

namespace relgeo::test {

enum class Chain_family { drilled_sphere, fused_spheres, slab_and_boxes };

inline std::string_view to_string(Chain_family f) {
  switch (f) {
    case Chain_family::drilled_sphere: return "drilled_sphere";
    case Chain_family::fused_spheres: return "fused_spheres";
    case Chain_family::slab_and_boxes: return "slab_and_boxes";
  }
  return "?";
}

/// One chain: the first operand, then (operation, operand) per step.
struct Boolean_chain {
  Mesh_double start;
  std::vector<std::pair<Boolean_operation, Mesh_double>> steps;
};

/// `steps` steps of the family, its random choices drawn from `seed`;
/// `sphere_levels`: the icospheres' subdivision levels (3: 1280 faces).
inline Boolean_chain make_chain(Chain_family family, int steps, unsigned seed = 7, int sphere_levels = 3) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1), angle(0, 6.283);
  Boolean_chain c;
  switch (family) {
    case Chain_family::drilled_sphere: c.start = icosphere(sphere_levels); break;
    case Chain_family::fused_spheres: c.start = icosphere(sphere_levels, {0, 0, 0}, 0.6); break;
    case Chain_family::slab_and_boxes: c.start = box(-1, -1, -0.25, 2, 2, 0.5); break;
  }
  for (int i = 1; i <= steps; ++i) {
    switch (family) {
      case Chain_family::drilled_sphere: {
        const double a = angle(random), t = angle(random);
        c.steps.push_back({Boolean_operation::difference, rigidly_moved(box(-0.15, -0.15, -2, 0.3, 0.3, 4), a, t, {0, 0, 0})});
        break;
      }
      case Chain_family::fused_spheres: {
        const double x = 2 * unit(random) - 1, y = 2 * unit(random) - 1, z = 2 * unit(random) - 1;
        const double r = 0.3 + 0.5 * unit(random);
        c.steps.push_back({Boolean_operation::union_of, icosphere(sphere_levels, {x, y, z}, r)});
        break;
      }
      case Chain_family::slab_and_boxes:
        c.steps.push_back({i % 2 ? Boolean_operation::intersection : Boolean_operation::union_of,
                           rigidly_moved(box(-0.9, -0.9, -0.6 + 0.02 * i, 1.8, 1.8, 1.2 - 0.04 * i), 0.37 * i, 0, {0, 0, 0})});
        break;
    }
  }
  return c;
}

/// The chain as one CSG tree, the steps nested in their order:
/// ((start op1 m1) op2 m2) ...
inline Csg_node csg_tree(const Boolean_chain& c) {
  Csg_node tree = Csg_node::solid(c.start);
  for (const auto& [op, m] : c.steps) {
    const auto kind = op == Boolean_operation::union_of       ? Csg_node::Kind::union_of
                      : op == Boolean_operation::intersection ? Csg_node::Kind::intersection
                                                              : Csg_node::Kind::difference;
    tree = Csg_node::operation(kind, {std::move(tree), Csg_node::solid(m)});
  }
  return tree;
}

/// The mesh a result hands on as the next operand: its vertices and faces
/// (the curves' crease tags are not part of the solid).
inline Mesh_double operand_of(const Triangle_mesh<Point_3<double>>& m) {
  Mesh_double o;
  o.vertices = m.vertices;
  o.faces = m.faces;
  return o;
}

}  // namespace relgeo::test
