// relgeo/mesh/internal/cgal_soup_io.h — the two calls of read_mesh and
// write_mesh into CGAL's polygon-soup IO (OBJ, PLY, STL): the only code of
// mesh_io.h that needs CGAL's IO headers, which cost a translation unit
// about 4 s to parse and 8 s more to compile at -O3 (doc/mesh.md, "Files").
// A client that links relgeo::compiled (RELGEO_COMPILED_MESH_IO) sees their
// declarations only; src/compiled/mesh_io.cpp defines them once. In the
// header-only use they are inline here.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "relgeo/kernel/point.h"

#if defined(RELGEO_COMPILED_MESH_IO) && RELGEO_COMPILED_MESH_IO && !defined(RELGEO_DEFINE_CGAL_SOUP_IO)

namespace relgeo::internal {

/// CGAL::IO::read_polygon_soup of `path` (format by extension), its points
/// as doubles. False when CGAL's reader fails; its exceptions pass through.
bool read_cgal_polygon_soup(const std::string& path, std::vector<Point_3<double>>& points,
                            std::vector<std::vector<std::size_t>>& polygons);

/// CGAL::IO::write_polygon_soup to `path` (format by extension) with
/// `precision` significant digits, binary where the format has it and
/// `binary` is set. False when CGAL's writer fails.
bool write_cgal_polygon_soup(const std::string& path, const std::vector<Point_3<double>>& points,
                             const std::vector<std::vector<std::size_t>>& polygons, int precision, bool binary);

}  // namespace relgeo::internal

#else

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

// Empty where src/compiled/mesh_io.cpp makes the one definition.
#if defined(RELGEO_DEFINE_CGAL_SOUP_IO)
#define RELGEO_CGAL_SOUP_IO_INLINE
#else
#define RELGEO_CGAL_SOUP_IO_INLINE inline
#endif

namespace relgeo::internal {

RELGEO_CGAL_SOUP_IO_INLINE bool read_cgal_polygon_soup(const std::string& path, std::vector<Point_3<double>>& points,
                                                       std::vector<std::vector<std::size_t>>& polygons) {
  using CP = CGAL::Simple_cartesian<double>::Point_3;
  std::vector<CP> pts;
  if (!CGAL::IO::read_polygon_soup(path, pts, polygons)) return false;
  points.clear();
  points.reserve(pts.size());
  for (const CP& p : pts) points.push_back({p.x(), p.y(), p.z()});
  return true;
}

RELGEO_CGAL_SOUP_IO_INLINE bool write_cgal_polygon_soup(const std::string& path,
                                                        const std::vector<Point_3<double>>& points,
                                                        const std::vector<std::vector<std::size_t>>& polygons,
                                                        int precision, bool binary) {
  using CP = CGAL::Simple_cartesian<double>::Point_3;
  std::vector<CP> pts;
  pts.reserve(points.size());
  for (const Point_3<double>& p : points) pts.emplace_back(p.x, p.y, p.z);
  return CGAL::IO::write_polygon_soup(path, pts, polygons,
                                      CGAL::parameters::stream_precision(precision).use_binary_mode(binary));
}

}  // namespace relgeo::internal

#undef RELGEO_CGAL_SOUP_IO_INLINE

#endif
