// The union of two overlapping cubes with relgeo::boolean (the default
// kernel: filtered exact predicates on implicit points), and an open operand
// refused with Invalid_operand. Built twice by
// examples/client: linked with relgeo::compiled (the Boolean engine comes
// compiled) and header-only (the engine is compiled here).
#include <cstdio>

#if defined(RELGEO_COMPILED) && RELGEO_COMPILED
#include <relgeo/boolean/compiled.h>  // the declaration: the engine is in relgeo::compiled
#else
#include <relgeo/boolean.h>  // header-only: the engine is compiled here
#endif
#include <relgeo/mesh/shapes.h>

int main() {
  const relgeo::Mesh_double a = relgeo::cube(0, 0, 0, 2), b = relgeo::cube(1, 1, 1, 2);
  const auto r = relgeo::boolean(a, b, relgeo::Boolean_operation::union_of);
  if (!r.ok()) {
    std::printf("boolean failed: %s\n", r.failure.c_str());
    return 1;
  }
  // 8 + 8 - 1: the union's volume, certified by the exact volume's bounds.
  const auto& v = r.validation.volume;
  std::printf("union of two cubes: %zu faces, %s, volume in [%.17g, %.17g]\n", r.mesh.faces.size(),
              r.validation.is_valid_solid() ? "a valid solid" : "NOT a valid solid", v.lower, v.upper);
  if (!(v.computed && v.lower <= 15 && 15 <= v.upper && r.validation.is_valid_solid())) return 1;

  // A bad operand is refused with a typed error naming the defect: here a
  // cube with one face missing (an open mesh).
  relgeo::Mesh_double open = b;
  open.faces.pop_back();
  try {
    (void)relgeo::boolean(a, open, relgeo::Boolean_operation::union_of);
  } catch (const relgeo::Invalid_operand& e) {
    std::printf("open operand refused: %s\n", e.what());
    return e.operand() == "B" ? 0 : 1;
  }
  std::printf("an open operand was not refused\n");
  return 1;
}
