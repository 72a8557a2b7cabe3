// tools/relgeo/commands/hull/picture.cpp — the SVG picture of a computed hull.
#include "commands/hull/picture.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cli/text.h"
#include "relgeo/error/convex_polygon.h"
#include "relgeo/io/svg_canvas.h"

namespace relgeo::tool {


void write_hull_svg(const std::string& path, std::span<const Point_2<double>> points,
                    const Hull_evaluation& e, const std::string& title) {
  constexpr double size = 600;
  constexpr std::size_t max_drawn = 100000;
  io::Svg_canvas svg(size, size);
  svg.set_plot_area(20, 52, size - 20, size - 100);
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (const auto& p : points) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  }
  if (points.empty()) xmin = ymin = 0, xmax = ymax = 1;
  svg.fit(xmin, ymin, xmax, ymax);

  const std::vector<Point_2<double>> exact = exact_hull(points);
  std::vector<Point_2<double>> computed;
  for (std::size_t i : e.run.indices) computed.push_back(points[i]);

  // exact hull: wide, light green, dashed; computed hull: blue
  svg.polygon(exact, true,
              "fill=\"#e8f5e9\" stroke=\"#2e7d32\" stroke-width=\"5\" stroke-opacity=\"0.45\" "
              "stroke-dasharray=\"10,6\" stroke-linejoin=\"round\"");
  svg.polygon(computed, true,
              "fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.6\" stroke-linejoin=\"round\"");
  if (points.size() <= max_drawn) {
    svg.begin_group("fill=\"#424242\"");
    for (const auto& p : points) svg.circle(p, 1.6, "");
    svg.end_group();
  }
  for (const auto& p : computed) svg.circle(p, 2.6, "fill=\"#1565c0\"");
  // computed hull vertices that are not vertices of the exact hull
  auto less = [](const Point_2<double>& a, const Point_2<double>& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  };
  std::vector<Point_2<double>> exact_sorted = exact;
  std::sort(exact_sorted.begin(), exact_sorted.end(), less);
  std::size_t not_vertices = 0;
  for (const auto& p : computed)
    if (!std::binary_search(exact_sorted.begin(), exact_sorted.end(), p, less)) {
      svg.square(p, 9, "fill=\"none\" stroke=\"#ef6c00\" stroke-width=\"2\"");
      ++not_vertices;
    }
  // lost points: input points outside the computed hull
  for (std::size_t i : e.backward.moved_points)
    svg.circle(points[i], 7, "fill=\"none\" stroke=\"#d50000\" stroke-width=\"2.2\"");

  // title
  svg.view_text(20, 22, title, "font-size=\"15\" font-weight=\"bold\"");
  const bool hull_inf = std::isinf(e.backward.value);
  svg.view_text(20, 40,
                std::to_string(points.size()) + " points, |hull| = " + std::to_string(computed.size()) +
                    ", exact |hull| = " + std::to_string(exact.size()) + ", E = " +
                    measure_text(e.error.value) + ", backward error = " +
                    measure_text(e.backward.value) +
                    (e.run.status == Hull_status::ok ? "" : ", FAILED: " + e.run.failure),
                "font-size=\"11.5\" fill=\"#333\"");
  // legend (rows at the bottom)
  const double y1 = size - 76, y2 = size - 56, y3 = size - 36, y4 = size - 12;
  svg.view_circle(28, y1, 1.6, "fill=\"#424242\"");
  svg.view_text(38, y1 + 4, points.size() <= max_drawn ? "input point" : "input points (too many: not drawn)",
                "font-size=\"12\"");
  svg.view_line(250, y1, 280, y1, "stroke=\"#1565c0\" stroke-width=\"1.6\"");
  svg.view_circle(265, y1, 2.6, "fill=\"#1565c0\"");
  svg.view_text(288, y1 + 4, "computed hull", "font-size=\"12\"");
  svg.view_line(420, y1, 450, y1,
                "stroke=\"#2e7d32\" stroke-width=\"5\" stroke-opacity=\"0.45\" stroke-dasharray=\"10,6\"");
  svg.view_text(458, y1 + 4, "exact hull", "font-size=\"12\"");
  svg.view_circle(28, y2, 7, "fill=\"none\" stroke=\"#d50000\" stroke-width=\"2.2\"");
  svg.view_text(42, y2 + 4,
                "lost point: input point outside the computed hull (" +
                    (hull_inf ? std::string("n/a: hull not convex")
                              : std::to_string(e.backward.moved_points.size())) + ")",
                "font-size=\"12\"");
  svg.view_square(28, y3, 9, "fill=\"none\" stroke=\"#ef6c00\" stroke-width=\"2\"");
  svg.view_text(42, y3 + 4,
                "computed hull vertex that is not a vertex of the exact hull (" +
                    std::to_string(not_vertices) + ")",
                "font-size=\"12\"");
  svg.view_text(20, y4, "y up; x in [" + format_g(xmin, 6) + ", " + format_g(xmax, 6) + "], y in [" +
                            format_g(ymin, 6) + ", " + format_g(ymax, 6) + "]; marks not to scale",
                "font-size=\"10.5\" fill=\"#555\"");
  svg.write(path);
}

}  // namespace relgeo::tool
