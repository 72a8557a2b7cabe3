// Joining two triangle-mesh patches to the trimmed faces of a NURBS surface
// model with relgeo::join_meshes (the Whitney joiner, thesis Ch. 4), and a
// patch that lies off its face refused with Projection_error. The model and
// the patches are made here through the public API. Built by
// examples/client with relgeo::cgal (Ruppert's refinement of the external
// regions: CGAL Mesh_2) and relgeo::eigen.
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <relgeo/joining/joiner.h>
#include <relgeo/joining/joining_errors.h>
#include <relgeo/surfaces/nurbs_surface.h>
#include <relgeo/surfaces/surface_model.h>

namespace {

using Mesh = relgeo::Triangle_mesh<relgeo::Point_3<double>>;

// A straight trim curve from a to b on model edge `edge`; `reversed`: the
// loop runs from b to a (the edge's direction is a -> b).
relgeo::Trim_curve segment(relgeo::Point_2<double> a, relgeo::Point_2<double> b, int edge, bool reversed = false) {
  return {std::vector<relgeo::Point_2<double>>{a, b}, reversed, edge};
}

// A bicubic Bezier bump over [0,1]^2 spanning [0,2] x [0,1] in x, y, cut
// along u = 1/2 into two faces that share model edge 0 (without its 3D
// curve: the joiner builds the seam from the two patches). Edges 1-6 are
// free.
relgeo::Surface_model two_face_model() {
  std::vector<relgeo::Point_3<double>> control;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) control.push_back({2 * i / 3.0, j / 3.0, (i % 3 && j % 3) ? 0.3 : 0.0});
  const std::vector<double> bezier{0, 0, 0, 0, 1, 1, 1, 1};
  const relgeo::Nurbs_surface<double> surface(3, 3, bezier, bezier, 4, 4, std::move(control));
  relgeo::Trim_loop left, right;
  left.curves = {segment({0, 0}, {0.5, 0}, 1), segment({0.5, 0}, {0.5, 1}, 0), segment({0.5, 1}, {0, 1}, 2),
                 segment({0, 1}, {0, 0}, 3)};
  right.curves = {segment({0.5, 0}, {1, 0}, 4), segment({1, 0}, {1, 1}, 5), segment({1, 1}, {0.5, 1}, 6),
                  segment({0.5, 0}, {0.5, 1}, 0, true)};
  relgeo::Surface_model model;
  model.edges.resize(7);
  model.faces.emplace_back(surface, left);
  model.faces.emplace_back(surface, right);
  return model;
}

// A mesh patch of the face over [u0, u1] x [0, 1]: a grid of nu x nv cells,
// counter-clockwise in (u,v) (the surface's normal points outward), each
// vertex lifted off the surface along its normal by up to `noise` (as a
// tessellation with its own error would be). The two patches get different
// grids, so they do not match along the shared edge.
Mesh grid_patch(const relgeo::Trimmed_surface& face, double u0, double u1, int nu, int nv, double noise) {
  Mesh m;
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j) {
      const double u = u0 + (u1 - u0) * i / nu, v = double(j) / nv;
      const auto d = face.surface().derivatives(u, v, 1);
      const auto n = relgeo::unit_normal(d);
      const double h = noise * std::sin(37 * u + 23 * v);
      m.vertices.push_back({d.point.x + h * n[0], d.point.y + h * n[1], d.point.z + h * n[2]});
    }
  const auto at = [nv](int i, int j) { return relgeo::Index(i * (nv + 1) + j); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

}  // namespace

int main() {
  const relgeo::Surface_model model = two_face_model();
  const std::vector<Mesh> meshes{grid_patch(model.faces[0], 0, 0.5, 10, 20, 1e-3),
                                 grid_patch(model.faces[1], 0.5, 1, 7, 14, 1e-3)};
  // The kernel of the certified checks defaults to Filtered_exact_kernel.
  const relgeo::Join_result r = relgeo::join_meshes(model, meshes);
  const relgeo::Join_report& report = r.report;
  std::printf("joined %zu patches: %zu vertices, %zu triangles, %s seams, %zu flipped triangles (kernel %s)\n",
              meshes.size(), report.vertices, report.triangles, report.watertight_seams ? "watertight" : "OPEN",
              report.flipped_triangles, report.kernel.c_str());
  for (std::size_t f = 0; f < report.faces.size(); ++f) {
    const relgeo::Join_face_report& face = report.faces[f];
    std::printf("  face %zu: absolute error %.3g -> %.3g (boundary max %.3g), normal-vector error %.3g -> %.3g (L %.3g)\n",
                f, face.before.absolute, face.after.absolute, face.boundary_max_abs_height, face.before.normal_vector,
                face.after.normal_vector, face.lipschitz_constant);
  }
  // What the joiner guarantees (doc/joining.md): |a| <= max |e| on the
  // boundary, slope <= L, no flipped triangle (certified in (u,v)), one
  // conforming mesh with watertight seams. The bounds are the boundary's:
  // here the seam is the median of the two patches' boundary chains, whose
  // chords stray a little further from the curved surface than the noise.
  if (!(report.guarantees_hold && report.flipped_triangles == 0 && report.conforming && report.watertight_seams))
    return 1;

  // A bad input is refused with a typed error: a patch moved away from its
  // face (its vertices project beyond the face's domain).
  std::vector<Mesh> off = meshes;
  for (auto& p : off[0].vertices) p.x += 5;
  try {
    (void)relgeo::join_meshes(model, off);
  } catch (const relgeo::Projection_error& e) {
    std::printf("patch off its face refused: %s\n", e.what());
    return e.failure() == relgeo::Projection_failure::outside_domain ? 0 : 1;
  }
  std::printf("a patch off its face was not refused\n");
  return 1;
}
