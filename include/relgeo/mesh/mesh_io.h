// relgeo/mesh/mesh_io.h — reading and writing triangle meshes (OFF, OBJ, PLY,
// STL through CGAL's polygon-soup IO) and feature tags (a side file).
//
// Needs CGAL (link relgeo::cgal). Its IO headers are parsed only in the
// header-only use: a client that links relgeo::compiled calls the reader and
// writer compiled there (internal/cgal_soup_io.h).
//
// Tag file format (".tags" by convention, next to the mesh file): text, one
// entry per line, '#' starts a comment, indices 0-based into the mesh's
// vertices as read:
//     # relgeo feature tags
//     crease 0 1
//     corner 5
// Mesh formats have no standard field for crease edges, hence the side file;
// it works with every format and survives tools that rewrite the mesh file
// without reordering its vertices.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/io/text_file.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/internal/cgal_soup_io.h"
#include "relgeo/mesh/internal/off_reader.h"
#include "relgeo/mesh/internal/off_writer.h"
#include "relgeo/mesh/internal/ply_check.h"
#include "relgeo/mesh/polygon_soup.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

namespace internal {

/// The extension of a file name in lower case (as CGAL's IO dispatches).
inline std::string lower_case_extension(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  std::string e = dot == std::string::npos ? std::string() : path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

/// A binary STL (one that does not start with "solid") must hold the 84-byte
/// header and the 50 bytes of each triangle its header announces: CGAL's
/// reader takes a shorter file for an empty mesh.
inline void check_binary_stl_size(std::string_view text, const std::string& path) {
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start != std::string_view::npos && text.substr(start, 5) == "solid") return;  // ASCII (or CGAL's fallback)
  if (text.size() < 84)
    throw Unreadable_file("binary STL file '" + path + "' has " + std::to_string(text.size()) +
                          " bytes, fewer than its 84-byte header");
  std::uint32_t n = 0;
  for (int i = 3; i >= 0; --i) n = (n << 8) | static_cast<unsigned char>(text[80 + static_cast<std::size_t>(i)]);
  if (n > (text.size() - 84) / 50)
    throw Unreadable_file("binary STL file '" + path + "' announces " + std::to_string(n) + " triangles but holds " +
                          std::to_string((text.size() - 84) / 50));
}

}  // namespace internal

/// Options of read_mesh.
struct Read_options {
  /// Split polygons with more than three corners into fans (else an error).
  bool triangulate_polygons = false;
  /// Also read tags from this file (empty: none).
  std::string tags_path{};
};

/// Options of write_mesh.
struct Write_options {
  /// Significant digits of ASCII coordinates (17: doubles round-trip
  /// exactly; OFF then writes each as the shortest such decimal).
  int precision = 17;
  /// Binary PLY/STL (ignored for OFF and OBJ).
  bool binary = false;
  /// Also write the tags to this file (empty: none).
  std::string tags_path{};
};

/// Reads feature tags. \throws Unreadable_file (missing file, unknown keyword,
/// bad index: the message names the line).
inline Feature_tags read_feature_tags(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Unreadable_file("cannot open tag file '" + path + "'");
  Feature_tags tags;
  std::vector<Edge> creases;
  std::vector<Index> corners;
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    if (const auto c = line.find('#'); c != std::string::npos) line.erase(c);
    std::istringstream s(line);
    std::string key;
    if (!(s >> key)) continue;
    const auto bad = [&] {
      return Unreadable_file("tag file '" + path + "', line " + std::to_string(no) + ": cannot parse '" + line + "'");
    };
    long long a = -1, b = -1;
    std::string rest;
    if (key == "crease") {
      if (!(s >> a >> b) || (s >> rest) || a < 0 || b < 0 || a == b || a >= invalid_index || b >= invalid_index)
        throw bad();
      creases.push_back(Edge::of(static_cast<Index>(a), static_cast<Index>(b)));
    } else if (key == "corner") {
      if (!(s >> a) || (s >> rest) || a < 0 || a >= invalid_index) throw bad();
      corners.push_back(static_cast<Index>(a));
    } else {
      throw bad();
    }
  }
  tags.set_creases(std::move(creases));
  tags.set_corners(std::move(corners));
  return tags;
}

/// Writes feature tags (format in the file comment). \throws Unreadable_file
/// when the file cannot be written.
inline void write_feature_tags(const std::string& path, const Feature_tags& tags) {
  std::ofstream out(path);
  if (!out) throw Unreadable_file("cannot write tag file '" + path + "'");
  out << "# relgeo feature tags: 'crease a b', 'corner v' (0-based vertex indices)\n";
  for (const Edge& e : tags.creases()) out << "crease " << e.a << ' ' << e.b << '\n';
  for (Index v : tags.corners()) out << "corner " << v << '\n';
  if (!out) throw Unreadable_file("cannot write tag file '" + path + "'");
}

/// \brief Reads a triangle mesh from an OFF, OBJ, PLY or STL file (by
/// extension), with double coordinates. OFF is read by relgeo's own reader
/// (internal/off_reader.h: errors name the line); OBJ, PLY and STL by
/// CGAL::IO::read_polygon_soup, PLY after a structural check of its counts
/// (internal/ply_check.h) and binary STL after a check of its size: CGAL's
/// readers trust the counts in a file (doc/reliability.md).
///
/// \throws Unreadable_file when the file is missing, empty, of an unknown
/// format or cannot be parsed (also when a count in it exceeds what the file
/// holds); Non_finite_input for NaN or infinite coordinates;
/// Invalid_input / Invalid_mesh for polygons that are not triangles (unless
/// triangulated) or bad indices. The mesh itself is not checked (check_mesh).
inline Triangle_mesh<Point_3<double>> read_mesh(const std::string& path, const Read_options& options = {}) {
  std::string text;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Unreadable_file("cannot open mesh file '" + path + "'");
    text = io::read_text_stream(in, "mesh file '" + path + "'");
  }
  if (text.find_first_not_of(" \t\r\n\v\f") == std::string::npos)
    throw Unreadable_file("mesh file '" + path + "' is empty");
  const std::string extension = internal::lower_case_extension(path);
  const Soup_options soup_options{.triangulate_polygons = options.triangulate_polygons};
  // Before the faces' indices are checked (a file with both defects names its coordinates).
  const auto require_finite = [&](const std::vector<Point_3<double>>& points) {
    for (std::size_t v = 0; v < points.size(); ++v)
      if (!std::isfinite(points[v].x) || !std::isfinite(points[v].y) || !std::isfinite(points[v].z))
        throw Non_finite_input("mesh file '" + path + "': vertex " + std::to_string(v) +
                               " has a NaN or infinite coordinate");
  };
  Triangle_mesh<Point_3<double>> m;
  if (extension == "off") {
    internal::Off_soup soup = internal::read_off_soup(text, path);
    require_finite(soup.points);  // the reader's are finite; x / w of 4OFF may not be
    m = from_polygon_soup(std::move(soup.points), soup.polygons(), soup_options);
  } else {
    std::vector<Point_3<double>> points;
    std::vector<std::vector<std::size_t>> polys;
    if (extension == "ply") internal::check_ply_structure(text, path);
    if (extension == "stl") internal::check_binary_stl_size(text, path);
    bool ok = false;
    try {
      ok = internal::read_cgal_polygon_soup(path, points, polys);
    } catch (const std::exception& e) {
      throw Unreadable_file("cannot parse mesh file '" + path + "': " + e.what());
    }
    if (!ok) throw Unreadable_file("cannot parse mesh file '" + path + "' (OFF, OBJ, PLY or STL expected)");
    require_finite(points);
    m = from_polygon_soup(std::move(points), polys, soup_options);
  }
  if (!options.tags_path.empty()) m.tags = read_feature_tags(options.tags_path);
  return m;
}

/// \brief Writes a triangle mesh (format by extension: .off, .obj, .ply, .stl):
/// OFF by relgeo's writer (internal/off_writer.h), the others through
/// CGAL::IO::write_polygon_soup. Coordinates are converted to double
/// (exact types are rounded; intervals give their midpoints).
/// \throws Unreadable_file when writing fails.
template <class P>
void write_mesh(const std::string& path, const Triangle_mesh<P>& m, const Write_options& options = {}) {
  using A = internal::Point_access<P>;
  if (internal::lower_case_extension(path) == "off") {
    const auto xyz = [&](std::size_t v) {
      const P& p = m.vertices[v];
      return std::array<double, 3>{internal::coordinate_to_double(A::x(p)), internal::coordinate_to_double(A::y(p)),
                                   internal::coordinate_to_double(A::z(p))};
    };
    const std::string text = internal::off_text(m.vertices.size(), m.faces, xyz, options.precision);
    std::ofstream out(path, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw Unreadable_file("cannot write mesh file '" + path + "'");
    if (!options.tags_path.empty()) write_feature_tags(options.tags_path, m.tags);
    return;
  }
  std::vector<Point_3<double>> pts;
  pts.reserve(m.vertices.size());
  for (const P& p : m.vertices)
    pts.push_back({internal::coordinate_to_double(A::x(p)), internal::coordinate_to_double(A::y(p)),
                   internal::coordinate_to_double(A::z(p))});
  const auto polys = to_polygon_soup(m);
  bool ok = false;
  try {
    ok = internal::write_cgal_polygon_soup(path, pts, polys, options.precision, options.binary);
  } catch (const std::exception& e) {
    throw Unreadable_file("cannot write mesh file '" + path + "': " + e.what());
  }
  if (!ok) throw Unreadable_file("cannot write mesh file '" + path + "' (.off, .obj, .ply or .stl expected)");
  if (!options.tags_path.empty()) write_feature_tags(options.tags_path, m.tags);
}

}  // namespace relgeo
