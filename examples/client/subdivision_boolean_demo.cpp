// The union of two overlapping Loop subdivision solids with
// relgeo::subdivision_boolean (the default kernel: filtered exact
// predicates), and an open control mesh refused with Invalid_operand.
// Built by examples/client with relgeo::eigen (the fitting's least squares)
// and, when the package has it, relgeo::compiled (the polyhedral Boolean's
// engine comes compiled).
#include <cstdio>

#include <relgeo/boolean/subdivision_boolean.h>
#include <relgeo/mesh/shapes.h>

int main() {
  // Two control meshes: 80-face icospheres, the second turned and moved so
  // that their limit surfaces cross.
  const relgeo::Mesh_double a = relgeo::icosphere(1);
  const relgeo::Mesh_double b = relgeo::rigidly_moved(relgeo::icosphere(1), 0.3, 0.2, {0.7, 0.2, 0.1});
  const unsigned level = 1;  // the limit meshes the polyhedral Boolean works on
  const auto r = relgeo::subdivision_boolean(a, b, relgeo::Boolean_operation::union_of, level);
  if (!r.ok()) {
    std::printf("subdivision Boolean failed: %s\n", r.failure.c_str());
    return 1;
  }
  std::printf("union of two Loop spheres at level %u: a control mesh of %zu faces, %zu curve edges as creases\n",
              r.level, r.control.faces.size(), r.counts.curve_edges);
  std::printf("  polyhedral result: %zu faces, %s\n", r.polyhedral.mesh.faces.size(),
              r.polyhedral.validation.is_valid_solid() ? "a valid solid" : "NOT a valid solid");
  std::printf("  limit surface to polyhedral result: %.3g (sampled Hausdorff distance)\n",
              r.distance_to_polyhedral.hausdorff());
  std::printf("  validation of the result: %s; %s\n", r.validation.summary().c_str(),
              r.validation.has_no_defect() ? "no check failed" : "a check FAILED");
  // What an exact kernel promises (doc/boolean.md): the polyhedral result is
  // a valid solid, the curves exist, and no check of the subdivision solid
  // fails (pieces around irregular vertices may stay undecided, never wrong).
  if (!(r.polyhedral.validation.is_valid_solid() && r.counts.curve_edges > 0 && r.validation.has_no_defect()))
    return 1;

  // A bad operand is refused with a typed error naming it: here the second
  // control mesh with one face missing (an open mesh has no Loop solid).
  relgeo::Mesh_double open = b;
  open.faces.pop_back();
  try {
    (void)relgeo::subdivision_boolean(a, open, relgeo::Boolean_operation::union_of, level);
  } catch (const relgeo::Invalid_operand& e) {
    std::printf("open control mesh refused: %s\n", e.what());
    return e.operand() == "B" ? 0 : 1;
  }
  std::printf("an open control mesh was not refused\n");
  return 1;
}
