// benchmark/joining/joining_figures.cpp — the pictures of doc/joining.md:
//   folding.png       the folding configuration (thesis Figs. 4.7-4.9): the
//                     input near the seam, naive midpoint sewing (flipped
//                     triangles in red, certified), the Whitney joiner;
//   three_faces.png   the Whitney result of the three-face model (case 2),
//                     shaded, one colour per face;
//   scaling_mesh.png, scaling_sigma.png
//                     time against n and sigma, from the CSV that
//                     relgeo_joining_benchmark --relgeo_csv=FILE writes.
// Usage: relgeo_joining_figures OUTPUT_DIR [BENCHMARK_CSV]
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wcast-qual"
#endif
#include <stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "figure_canvas.h"
#include "relgeo/io/png.h"
#include "relgeo/joining/joiner.h"
#include "relgeo/joining/naive_sewing.h"
#include "relgeo/kernel.h"
#include "relgeo_fixtures/joining/test_models.h"

namespace relgeo_figures {

void Canvas::text(double x, double y, const std::string& s, Color c, int scale) {
  std::vector<char> buffer(60000);
  const int quads = stb_easy_font_print(0, 0, const_cast<char*>(s.c_str()), nullptr, buffer.data(), static_cast<int>(buffer.size()));
  const float* v = reinterpret_cast<const float*>(buffer.data());
  for (int q = 0; q < quads; ++q) {
    const float* p = v + q * 16;  // 4 vertices of (x, y, z, colour)
    const double qx0 = x + scale * p[0], qy0 = y + scale * p[1], qx1 = x + scale * p[8], qy1 = y + scale * p[9];
    for (int py = static_cast<int>(qy0); py < static_cast<int>(qy1); ++py)
      for (int px = static_cast<int>(qx0); px < static_cast<int>(qx1); ++px) pixel(px, py, c);
  }
}

void write_png(const std::string& path, const Canvas& c) {
  relgeo::io::Image image = relgeo::io::Image::filled(c.width(), c.height());
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = {c.pixels()[3 * i], c.pixels()[3 * i + 1], c.pixels()[3 * i + 2]};
  relgeo::io::write_png(path, image);
}

}  // namespace relgeo_figures

namespace {

using namespace relgeo;
using namespace relgeo_figures;

constexpr Color face_colors[] = {{158, 202, 225}, {253, 208, 162}, {199, 233, 192}};
constexpr Color red{215, 25, 28}, dark{60, 60, 60};

// One panel of the folding figure: the planar meshes' xy in a window.
void draw_planar(Canvas& c, int x0, int width, const std::vector<Triangle_mesh<Point_3<double>>>& meshes,
                 const std::string& title, std::size_t* flipped) {
  const double wx0 = 0.93, wx1 = 1.05, wy0 = 0.0, wy1 = 0.3;
  const double s = std::min(width / (wx1 - wx0), (c.height() - 40) / (wy1 - wy0));
  const auto X = [&](double x) { return x0 + (x - wx0) * s; };
  const auto Y = [&](double y) { return c.height() - 10 - (y - wy0) * s; };
  const auto orient = Filtered_exact_kernel{}.orientation_2_object();
  const auto pt = Filtered_exact_kernel{}.construct_point_2_object();
  *flipped = 0;
  c.set_clip(x0, 0, x0 + width, c.height());
  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (const Triangle& t : meshes[m].faces) {
      const auto& a = meshes[m].vertices[t[0]];
      const auto& b = meshes[m].vertices[t[1]];
      const auto& d = meshes[m].vertices[t[2]];
      const bool flip = orient(pt(a.x, a.y), pt(b.x, b.y), pt(d.x, d.y)) == Certified_sign::negative;
      *flipped += flip;
      c.triangle({X(a.x), X(b.x), X(d.x)}, {Y(a.y), Y(b.y), Y(d.y)}, {flip ? -1.0 : 0.0, flip ? -1.0 : 0.0, flip ? -1.0 : 0.0},
                 flip ? red : face_colors[m % 3]);
    }
  for (const auto& mesh : meshes)
    for (const Triangle& t : mesh.faces)
      for (int i = 0; i < 3; ++i) {
        const auto& a = mesh.vertices[t[i]];
        const auto& b = mesh.vertices[t[(i + 1) % 3]];
        c.line(X(a.x), Y(a.y), X(b.x), Y(b.y), dark);
      }
  c.text(x0 + 8, 6, title, {0, 0, 0}, 2);
  c.reset_clip();
}

// The meshes of a result, split by face (for colouring).
std::vector<Triangle_mesh<Point_3<double>>> by_face(const Join_result& r, std::size_t faces) {
  std::vector<Triangle_mesh<Point_3<double>>> out(faces);
  for (auto& m : out) m.vertices = r.mesh.vertices;
  for (std::size_t i = 0; i < r.mesh.faces.size(); ++i) out[r.face_of_triangle[i]].faces.push_back(r.mesh.faces[i]);
  return out;
}

void folding_figure(const std::string& dir) {
  const Joining_case c = folding_case();
  const Join_result naive = naive_sewing(c.model, c.meshes), whitney = join_meshes(c.model, c.meshes);
  Canvas canvas(3 * 330, 760);
  std::size_t f0 = 0, f1 = 0, f2 = 0;
  draw_planar(canvas, 0, 320, c.meshes, "input", &f0);
  draw_planar(canvas, 330, 320, by_face(naive, 2), "naive midpoint sewing", &f1);
  draw_planar(canvas, 660, 320, by_face(whitney, 2), "Whitney joiner", &f2);
  write_png(dir + "/folding.png", canvas);
  std::cout << "folding.png: flipped triangles (certified) input " << f0 << ", naive " << f1 << ", whitney " << f2 << "\n";
}

void three_faces_figure(const std::string& dir) {
  const Joining_case c = make_joining_case("three faces, case 2", three_face_model(false));
  const Join_result r = join_meshes(c.model, c.meshes);
  Canvas canvas(900, 640);
  // Orthographic view from (1, -1.4, 1.6), z exaggerated twice.
  double d[3] = {1, -1.4, 1.6};
  const double dl = std::hypot(d[0], d[1], d[2]);
  for (double& x : d) x /= dl;
  const double right[3] = {-d[1] / std::hypot(d[0], d[1]), d[0] / std::hypot(d[0], d[1]), 0};
  const double up[3] = {right[1] * d[2] - right[2] * d[1], right[2] * d[0] - right[0] * d[2], right[0] * d[1] - right[1] * d[0]};
  const auto view = [&](const Point_3<double>& p) {
    const double q[3] = {p.x - 0.75, p.y - 0.5, 2 * p.z};
    return std::array<double, 3>{q[0] * right[0] + q[1] * right[1], q[0] * up[0] + q[1] * up[1] + q[2] * up[2],
                                 -(q[0] * d[0] + q[1] * d[1] + q[2] * d[2])};
  };
  const double s = 400;
  const auto X = [&](double x) { return 450 + s * x; };
  const auto Y = [&](double y) { return 300 - s * y; };
  const double light[3] = {0.3, -0.5, 0.8};
  for (std::size_t i = 0; i < r.mesh.faces.size(); ++i) {
    const Triangle& t = r.mesh.faces[i];
    const auto& a = r.mesh.vertices[t[0]];
    const auto& b = r.mesh.vertices[t[1]];
    const auto& e = r.mesh.vertices[t[2]];
    const double u[3] = {b.x - a.x, b.y - a.y, 2 * (b.z - a.z)}, v[3] = {e.x - a.x, e.y - a.y, 2 * (e.z - a.z)};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double nl = std::hypot(n[0], n[1], n[2]);
    const double lambert = std::abs(n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / nl / std::hypot(light[0], light[1], light[2]);
    const Color base = face_colors[r.face_of_triangle[i] % 3];
    const double k = 0.35 + 0.65 * lambert;
    const Color shaded{static_cast<std::uint8_t>(base[0] * k), static_cast<std::uint8_t>(base[1] * k),
                       static_cast<std::uint8_t>(base[2] * k)};
    const auto pa = view(a), pb = view(b), pe = view(e);
    canvas.triangle({X(pa[0]), X(pb[0]), X(pe[0])}, {Y(pa[1]), Y(pb[1]), Y(pe[1])}, {pa[2], pb[2], pe[2]}, shaded);
  }
  canvas.text(10, 10, "Whitney joiner: three faces, case 2 (" + std::to_string(r.report.triangles) + " triangles)",
              {0, 0, 0}, 2);
  write_png(dir + "/three_faces.png", canvas);
  std::cout << "three_faces.png: " << r.report.triangles << " triangles, watertight seams "
            << r.report.watertight_seams << "\n";
}

struct Csv_row {
  std::string method, series;
  double n, sigma, seconds;
};

// A log-log plot of seconds against x (n or sigma) per method.
void plot(const std::string& path, const std::vector<Csv_row>& rows, const std::string& series, bool by_sigma,
          const std::string& title) {
  Canvas c(720, 480);
  const double L = 80, R = 700, T = 40, B = 420;
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (const auto& r : rows)
    if (r.series == series) {
      const double x = by_sigma ? r.sigma : r.n;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, r.seconds), y1 = std::max(y1, r.seconds);
    }
  if (x1 == 0) return;
  const double lx0 = std::floor(std::log10(x0)), lx1 = std::ceil(std::log10(x1));
  const double ly0 = std::floor(std::log10(y0)), ly1 = std::ceil(std::log10(y1));
  const auto X = [&](double x) { return L + (std::log10(x) - lx0) / (lx1 - lx0) * (R - L); };
  const auto Y = [&](double y) { return B - (std::log10(y) - ly0) / (ly1 - ly0) * (B - T); };
  c.line(L, B, R, B, dark, 2), c.line(L, B, L, T, dark, 2);
  for (double e = lx0; e <= lx1; ++e) {
    c.line(X(std::pow(10, e)), B, X(std::pow(10, e)), B + 6, dark, 2);
    c.text(X(std::pow(10, e)) - 12, B + 10, "1e" + std::to_string(static_cast<int>(e)), dark, 2);
  }
  for (double e = ly0; e <= ly1; ++e) {
    c.line(L - 6, Y(std::pow(10, e)), L, Y(std::pow(10, e)), dark, 2);
    c.text(8, Y(std::pow(10, e)) - 6, "1e" + std::to_string(static_cast<int>(e)) + " s", dark, 2);
  }
  c.text(L, 10, title, {0, 0, 0}, 2);
  c.text(R - 120, B + 30, by_sigma ? "sigma" : "n (vertices)", dark, 2);
  const std::map<std::string, Color> colors = {{"whitney", {33, 102, 172}}, {"naive", {230, 97, 1}}, {"occt", {26, 152, 80}}};
  int legend = 0;
  for (const auto& [method, color] : colors) {
    std::vector<std::pair<double, double>> pts;
    for (const auto& r : rows)
      if (r.series == series && r.method == method) pts.push_back({by_sigma ? r.sigma : r.n, r.seconds});
    if (pts.empty()) continue;
    std::sort(pts.begin(), pts.end());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double px = X(pts[i].first), py = Y(pts[i].second);
      for (int dx = -4; dx <= 4; ++dx)
        for (int dy = -4; dy <= 4; ++dy) c.pixel(static_cast<int>(px) + dx, static_cast<int>(py) + dy, color);
      if (i) c.line(X(pts[i - 1].first), Y(pts[i - 1].second), px, py, color, 2);
    }
    c.text(L + 20, T + 10 + 22 * legend++, method, color, 2);
  }
  write_png(path, c);
}

void scaling_figures(const std::string& dir, const std::string& csv) {
  std::ifstream in(csv);
  if (!in) {
    std::cerr << "no benchmark CSV '" << csv << "': scaling figures skipped\n";
    return;
  }
  std::vector<Csv_row> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string f[8];
    for (auto& x : f) std::getline(s, x, ',');
    rows.push_back({f[0], f[1], std::stod(f[3]), std::stod(f[4]), std::stod(f[5])});
  }
  plot(dir + "/scaling_mesh.png", rows, "mesh", false, "joining time (CPU) against mesh size n");
  plot(dir + "/scaling_sigma.png", rows, "sigma", true, "Whitney joining time (CPU) against boundary samples, n = 8192");
  std::cout << "scaling_mesh.png, scaling_sigma.png from " << csv << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: relgeo_joining_figures OUTPUT_DIR [BENCHMARK_CSV]\n";
    return 2;
  }
  const std::string dir = argv[1];
  std::filesystem::create_directories(dir);
  folding_figure(dir);
  three_faces_figure(dir);
  if (argc > 2) scaling_figures(dir, argv[2]);
  return 0;
}
