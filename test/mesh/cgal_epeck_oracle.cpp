// The CGAL-over-Epeck oracle of solid_validation_cgal_test (see the header).
#include "mesh/cgal_epeck_oracle.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <functional>
#include <iterator>
#include <sstream>
#include <utility>

#include "relgeo/mesh/cgal_conversion.h"
#include "relgeo/mesh/mesh_errors.h"

namespace relgeo_test {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using SM = CGAL::Surface_mesh<CGAL::Epeck::Point_3>;

std::vector<relgeo::Face_pair> self_intersecting_pairs(const SM& sm) {
  std::vector<std::pair<SM::Face_index, SM::Face_index>> pairs;
  PMP::self_intersections(sm, std::back_inserter(pairs));
  std::vector<relgeo::Face_pair> out;
  for (const auto& [f, g] : pairs)
    if (f != g)  // (f, f): a degenerate face
      out.push_back({std::min<relgeo::Index>(f.idx(), g.idx()), std::max<relgeo::Index>(f.idx(), g.idx())});
  std::sort(out.begin(), out.end());
  return out;
}

bool bounds_outward_volume(const SM& sm) {
  SM copy = sm;  // the face-to-volume map is a property of the mesh
  auto volume = copy.add_property_map<SM::Face_index, std::size_t>("f:volume", 0).first;
  std::vector<bool> outward;
  std::vector<std::size_t> level;
  std::vector<PMP::Volume_error_code> errors;
  PMP::volume_connected_components(copy, volume,
                                   CGAL::parameters::do_orientation_tests(true)
                                       .is_cc_outward_oriented(std::ref(outward))
                                       .nesting_levels(std::ref(level))
                                       .error_codes(std::ref(errors)));
  bool ok = !outward.empty() && outward.size() == level.size();
  for (PMP::Volume_error_code e : errors) ok = ok && e == PMP::VALID_VOLUME;
  for (std::size_t c = 0; ok && c < outward.size(); ++c) ok = outward[c] == (level[c] % 2 == 0);
  return ok;
}

}  // namespace

Cgal_solid_verdict cgal_epeck_verdict(const relgeo::Triangle_mesh<relgeo::Point_3<double>>& m, bool pairs_only) {
  Cgal_solid_verdict v;
  SM sm;
  try {
    sm = relgeo::to_surface_mesh<CGAL::Epeck::Point_3>(m);
  } catch (const relgeo::Invalid_mesh&) {
    return v;
  }
  v.representable = true;
  v.pairs = self_intersecting_pairs(sm);
  if (pairs_only) return v;
  v.closed = CGAL::is_closed(sm);
  v.self_intersects = PMP::does_self_intersect(sm);
  if (!v.closed) return v;
  std::ostringstream s;
  s << CGAL::exact(PMP::volume(sm));
  v.volume = s.str();
  // The orientation tests assume a manifold without isolated vertices
  // (volume_connected_components crashes on prim.off, which has some).
  if (v.self_intersects) return v;
  std::vector<SM::Halfedge_index> pinched;
  PMP::non_manifold_vertices(sm, std::back_inserter(pinched));
  if (!pinched.empty()) return v;
  for (SM::Vertex_index x : sm.vertices())
    if (sm.is_isolated(x)) return v;
  v.outward_oriented = PMP::is_outward_oriented(sm);
  v.bounds_outward_volume = bounds_outward_volume(sm);
  return v;
}

}  // namespace relgeo_test
