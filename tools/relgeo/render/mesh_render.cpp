// tools/relgeo/render/mesh_render.cpp
#include "render/mesh_render.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace relgeo::tool {

namespace {

using io::Image;
using io::Rgb;

struct V3 {
  double x, y, z;
};

// Blue -> cyan -> green -> yellow -> red for t in [0, 1].
Rgb ramp(double t) {
  t = std::clamp(t, 0.0, 1.0);
  static const double stops[5][3] = {{40, 60, 200}, {40, 180, 220}, {60, 190, 80}, {240, 220, 50}, {220, 40, 40}};
  const double s = t * 4;
  const int i = std::min(3, int(s));
  const double f = s - i;
  Rgb c;
  c.r = std::uint8_t(stops[i][0] + f * (stops[i + 1][0] - stops[i][0]));
  c.g = std::uint8_t(stops[i][1] + f * (stops[i + 1][1] - stops[i][1]));
  c.b = std::uint8_t(stops[i][2] + f * (stops[i + 1][2] - stops[i][2]));
  return c;
}

}  // namespace

io::Image render_mesh(const Mesh_double& mesh, const Render_options& o, const Mesh_double* frame) {
  Image img{o.width, o.height, {}};
  img.pixels.assign(std::size_t(o.width) * o.height, Rgb{255, 255, 255});
  const double az = o.azimuth_deg * M_PI / 180, el = o.elevation_deg * M_PI / 180;
  // view: rotate about z by -az, then tilt by el; screen x right, y up, depth z towards the viewer
  const auto view = [&](const Point_3<double>& p) {
    const double x1 = std::cos(az) * p.x + std::sin(az) * p.y, y1 = -std::sin(az) * p.x + std::cos(az) * p.y;
    return V3{y1, std::cos(el) * p.z - std::sin(el) * x1, std::sin(el) * p.z + std::cos(el) * x1};
  };
  const Mesh_double& box = frame ? *frame : mesh;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const auto& p : box.vertices) {
    const V3 v = view(p);
    lo[0] = std::min(lo[0], v.x), hi[0] = std::max(hi[0], v.x), lo[1] = std::min(lo[1], v.y), hi[1] = std::max(hi[1], v.y);
  }
  if (!(hi[0] > lo[0]) || !(hi[1] > lo[1])) return img;
  const int bar = o.face_values.empty() ? 0 : 28;
  const double margin = 12, usable_h = o.height - 2 * margin - bar;
  const double scale = std::min((o.width - 2 * margin) / (hi[0] - lo[0]), usable_h / (hi[1] - lo[1]));
  const double cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2;
  std::vector<V3> s(mesh.vertices.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const V3 v = view(mesh.vertices[i]);
    s[i] = {o.width / 2.0 + (v.x - cx) * scale, margin + usable_h / 2 - (v.y - cy) * scale, v.z};
  }
  std::vector<double> depth(img.pixels.size(), -std::numeric_limits<double>::infinity());
  const V3 light{-0.3, 0.5, 0.8};
  const double ll = std::sqrt(light.x * light.x + light.y * light.y + light.z * light.z);
  const double vlo = std::log(std::max(o.value_min, 1e-300)), vhi = std::log(std::max(o.value_max, 1e-300));
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const V3 &a = s[mesh.faces[f][0]], &b = s[mesh.faces[f][1]], &c = s[mesh.faces[f][2]];
    // normal in view space (screen y points down: flip)
    const V3 pa = view(mesh.vertices[mesh.faces[f][0]]), pb = view(mesh.vertices[mesh.faces[f][1]]),
             pc = view(mesh.vertices[mesh.faces[f][2]]);
    const V3 e1{pb.x - pa.x, pb.y - pa.y, pb.z - pa.z}, e2{pc.x - pa.x, pc.y - pa.y, pc.z - pa.z};
    V3 n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
    const double nl = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(nl > 0)) continue;
    const double shade = 0.35 + 0.65 * std::abs(n.x * light.x + n.y * light.y + n.z * light.z) / (nl * ll);
    Rgb base{200, 200, 205};
    if (!o.face_groups.empty() && o.face_values.empty()) {
      static const Rgb groups[4] = {{205, 205, 210}, {130, 170, 225}, {230, 190, 120}, {160, 210, 150}};
      base = groups[std::size_t(o.face_groups[f]) % 4];
    }
    if (!o.face_values.empty()) {
      const double v = o.face_values[f];
      base = ramp(vhi > vlo ? (std::log(std::max(v, 1e-300)) - vlo) / (vhi - vlo) : 0.5);
    }
    const Rgb col{std::uint8_t(base.r * shade), std::uint8_t(base.g * shade), std::uint8_t(base.b * shade)};
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x})))), x1 = std::min(o.width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y})))), y1 = std::min(o.height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area == 0) continue;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
        const double w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
        const double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double z = w0 * a.z + w1 * b.z + w2 * c.z;
        const std::size_t i = std::size_t(y) * o.width + x;
        if (z > depth[i]) depth[i] = z, img.pixels[i] = col;
      }
  }
  if (o.wire) {
    const double zs = 1e-3 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
    for (const auto& f : mesh.faces)
      for (int k = 0; k < 3; ++k) {
        const V3 &a = s[f[k]], &b = s[f[(k + 1) % 3]];
        const int steps = std::max(1, int(std::ceil(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)))));
        for (int t = 0; t <= steps; ++t) {
          const double u = double(t) / steps;
          const int x = int(a.x + u * (b.x - a.x)), y = int(a.y + u * (b.y - a.y));
          if (x < 0 || y < 0 || x >= o.width || y >= o.height) continue;
          const std::size_t i = std::size_t(y) * o.width + x;
          if (a.z + u * (b.z - a.z) >= depth[i] - zs) img.pixels[i] = Rgb{30, 30, 40};
        }
      }
  }
  if (o.highlight_creases) {  // visible crease edges, red, two pixels wide
    const double zs = 2e-3 * std::max(hi[0] - lo[0], hi[1] - lo[1]);  // depth is in model units
    for (const Edge& e : mesh.tags.creases()) {
      const V3 &a = s[e.a], &b = s[e.b];
      const int steps = std::max(1, int(std::ceil(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)))));
      for (int t = 0; t <= steps; ++t) {
        const double u = double(t) / steps;
        const int x = int(a.x + u * (b.x - a.x)), y = int(a.y + u * (b.y - a.y));
        for (int dx = 0; dx < 2; ++dx)
          for (int dy = 0; dy < 2; ++dy) {
            const int px = x + dx, py = y + dy;
            if (px < 0 || py < 0 || px >= o.width || py >= o.height) continue;
            const std::size_t i = std::size_t(py) * o.width + px;
            if (a.z + u * (b.z - a.z) >= depth[i] - zs) img.pixels[i] = Rgb{210, 30, 30};
          }
      }
    }
  }
  if (bar) {  // colour bar: value_min (left) .. value_max (right), log scale
    for (int y = o.height - bar + 6; y < o.height - 8; ++y)
      for (int x = 20; x < o.width - 20; ++x) img.at(x, y) = ramp(double(x - 20) / (o.width - 41));
  }
  return img;
}

}  // namespace relgeo::tool
