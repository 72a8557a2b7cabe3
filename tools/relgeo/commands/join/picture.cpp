// tools/relgeo/commands/join/picture.cpp
#include "commands/join/picture.h"

#include <algorithm>
#include <cmath>

namespace relgeo::tool {

namespace {

constexpr const char* face_fills[] = {"#9ecae1", "#fdd0a2", "#c7e9c0", "#dadaeb"};

}  // namespace

std::size_t flipped_in_picture(const std::vector<Join_face_picture>& faces) {
  std::size_t n = 0;
  for (const auto& f : faces) n += static_cast<std::size_t>(std::count(f.flipped.begin(), f.flipped.end(), true));
  return n;
}

io::Svg_canvas join_picture(const std::vector<Join_face_picture>& faces, const std::string& title, const double* window) {
  const double panel = 360, gap = 16, top = 44;
  const double width = std::max<double>(1, static_cast<double>(faces.size())) * (panel + gap) + gap;
  io::Svg_canvas c(width, panel + top + 30);
  c.view_text(gap, 24, title, "font-size=\"16\"");
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Join_face_picture& p = faces[f];
    const double left = gap + static_cast<double>(f) * (panel + gap);
    c.set_plot_area(left, top, left + panel, top + panel);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (const auto& loop : p.domain)
      for (const auto& q : loop) lo[0] = std::min(lo[0], q.x), lo[1] = std::min(lo[1], q.y), hi[0] = std::max(hi[0], q.x), hi[1] = std::max(hi[1], q.y);
    if (window) lo[0] = window[0], lo[1] = window[1], hi[0] = window[2], hi[1] = window[3];
    if (!(hi[0] >= lo[0] && hi[1] >= lo[1])) continue;
    c.fit(lo[0], lo[1], hi[0], hi[1]);
    const auto inside = [&](const Point_2<double>& q) {
      return !window || (q.x >= lo[0] && q.x <= hi[0] && q.y >= lo[1] && q.y <= hi[1]);
    };
    const std::string fill = face_fills[f % std::size(face_fills)];
    const std::string clip = "join-panel-" + std::to_string(f);
    c.raw("<clipPath id=\"" + clip + "\"><rect x=\"" + io::svg_number(left) + "\" y=\"" + io::svg_number(top) +
          "\" width=\"" + io::svg_number(panel) + "\" height=\"" + io::svg_number(panel) + "\"/></clipPath>\n");
    c.begin_group("clip-path=\"url(#" + clip + ")\"");
    c.begin_group("stroke=\"#333\" stroke-width=\"0.4\"");
    std::size_t flipped = 0;
    for (std::size_t t = 0; t < p.triangles.size(); ++t) {
      const Point_2<double> tri[3] = {p.uv[p.triangles[t][0]], p.uv[p.triangles[t][1]], p.uv[p.triangles[t][2]]};
      flipped += p.flipped[t];
      if (!inside(tri[0]) && !inside(tri[1]) && !inside(tri[2])) continue;
      c.polygon(tri, true, p.flipped[t] ? "fill=\"#d7191c\"" : "fill=\"" + fill + "\"");
    }
    c.end_group();
    for (const auto& loop : p.domain) c.polygon(loop, true, "fill=\"none\" stroke=\"black\" stroke-width=\"1.2\"");
    c.end_group();
    c.view_text(left, top + panel + 20,
                "face " + std::to_string(f) + ": " + std::to_string(p.triangles.size()) + " triangles, " +
                    std::to_string(flipped) + " flipped" +
                    (p.unprojected ? ", " + std::to_string(p.unprojected) + " not projected" : ""),
                "font-size=\"13\"" + std::string(flipped ? " fill=\"#d7191c\"" : ""));
  }
  return c;
}

}  // namespace relgeo::tool
