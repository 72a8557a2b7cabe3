// The CGAL subjects of relgeo_boolean_benchmark: corefine_and_compute_union /
// intersection / difference on Surface_mesh, with Epick and with Epeck, on
// the same operands (converted before timing); and relgeo's Boolean under
// CGAL's Epeck (Cgal_kernel<Epeck>: relgeo's algorithm in CGAL's arithmetic,
// against CGAL's algorithm in the same arithmetic).
#include <memory>
#include <utility>

#include "boolean_benchmark.h"
#include "relgeo/boolean.h"
#include "relgeo/kernel/cgal_kernel.h"
#include "relgeo/mesh/cgal_conversion.h"
#include "relgeo_fixtures/peers/cgal_corefinement.h"

namespace relgeo_bench {
namespace {

// The Surface_mesh operands are built before the timed run (corefinement
// changes them, so each run gets its own).
template <class K>
Timed_run corefine(const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
  auto operands = std::make_shared<std::pair<CGAL::Surface_mesh<typename K::Point_3>, CGAL::Surface_mesh<typename K::Point_3>>>(
      relgeo::to_surface_mesh<typename K::Point_3>(a), relgeo::to_surface_mesh<typename K::Point_3>(b));
  return [operands, op]() -> Inspect {
    auto& [sa, sb] = *operands;
    auto out = std::make_shared<CGAL::Surface_mesh<typename K::Point_3>>();
    const bool ok = relgeo::peers::cgal_corefine_and_compute(sa, sb, op, *out);
    return [out, ok] {
      Run_outcome r;
      r.faces = out->number_of_faces();
      r.valid = ok && CGAL::is_closed(*out) && out->is_valid();
      return r;
    };
  };
}

Timed_run relgeo_on_epeck(const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
  return [&a, &b, op]() -> Inspect {
    auto r = std::make_shared<relgeo::Boolean_result<relgeo::Cgal_kernel<CGAL::Epeck>>>(
        relgeo::boolean(a, b, op, relgeo::Cgal_kernel<CGAL::Epeck>{}, {.validate_output = false}));
    return [r] {
      return Run_outcome{r->mesh.faces.size(), r->ok() && closed_oriented_manifold(r->mesh), volume(r->mesh), r->time};
    };
  };
}

}  // namespace

std::vector<Subject> cgal_subjects() {
  return {{"CGAL::corefine Epick", corefine<CGAL::Epick>, false, ""},
          {"CGAL::corefine Epeck", corefine<CGAL::Epeck>, true, ""},
          {"relgeo on CGAL::Epeck", relgeo_on_epeck, true, "CGAL::corefine Epeck"}};
}

}  // namespace relgeo_bench
