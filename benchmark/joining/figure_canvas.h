// benchmark/joining/figure_canvas.h — a small RGB canvas for the joining
// figures: lines, filled triangles with a depth buffer, text (stb_easy_font),
// written as PNG through relgeo/io/png.h (joining_figures.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace relgeo_figures {

using Color = std::array<std::uint8_t, 3>;

class Canvas {
 public:
  Canvas(int width, int height, Color background = {255, 255, 255})
      : w_(width), h_(height), rgb_(static_cast<std::size_t>(width) * height * 3),
        depth_(static_cast<std::size_t>(width) * height, std::numeric_limits<double>::infinity()) {
    for (int i = 0; i < w_ * h_; ++i) std::copy(background.begin(), background.end(), rgb_.begin() + 3 * i);
  }
  int width() const { return w_; }
  int height() const { return h_; }
  const std::vector<std::uint8_t>& pixels() const { return rgb_; }

  /// Drawing is limited to [x0, x1) x [y0, y1) until reset_clip().
  void set_clip(int x0, int y0, int x1, int y1) { cx0_ = x0, cy0_ = y0, cx1_ = x1, cy1_ = y1; }
  void reset_clip() { cx0_ = cy0_ = 0, cx1_ = w_, cy1_ = h_; }

  void pixel(int x, int y, Color c, double alpha = 1) {
    if (x < std::max(0, cx0_) || y < std::max(0, cy0_) || x >= std::min(w_, cx1_) || y >= std::min(h_, cy1_)) return;
    std::uint8_t* p = &rgb_[3 * (static_cast<std::size_t>(y) * w_ + x)];
    for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::lround(alpha * c[k] + (1 - alpha) * p[k]));
  }
  /// A line in pixel coordinates, `thick` pixels wide.
  void line(double x0, double y0, double x1, double y1, Color c, double thick = 1) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    const int steps = std::max(1, static_cast<int>(len * 2));
    const int r = static_cast<int>(std::floor(thick / 2));
    for (int s = 0; s <= steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0))), y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
      for (int dx = -r; dx <= r; ++dx)
        for (int dy = -r; dy <= r; ++dy) pixel(x + dx, y + dy, c);
    }
  }
  /// A filled triangle (pixel coordinates, depth z per corner; nearer = smaller).
  void triangle(const std::array<double, 3>& x, const std::array<double, 3>& y, const std::array<double, 3>& z, Color c,
                double alpha = 1) {
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({x[0], x[1], x[2]}))));
    const int x1 = std::min(w_ - 1, static_cast<int>(std::ceil(std::max({x[0], x[1], x[2]}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({y[0], y[1], y[2]}))));
    const int y1 = std::min(h_ - 1, static_cast<int>(std::ceil(std::max({y[0], y[1], y[2]}))));
    const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (area == 0) return;
    for (int py = y0; py <= y1; ++py)
      for (int px = x0; px <= x1; ++px) {
        const double cx = px + 0.5, cy = py + 0.5;
        const double a = ((x[1] - cx) * (y[2] - cy) - (x[2] - cx) * (y[1] - cy)) / area;
        const double b = ((x[2] - cx) * (y[0] - cy) - (x[0] - cx) * (y[2] - cy)) / area;
        const double g = 1 - a - b;
        if (a < 0 || b < 0 || g < 0) continue;
        const double depth = a * z[0] + b * z[1] + g * z[2];
        double& d = depth_[static_cast<std::size_t>(py) * w_ + px];
        if (depth > d) continue;
        d = depth;
        pixel(px, py, c, alpha);
      }
  }
  /// Text at (x, y) (top left), `scale` pixels per font unit.
  void text(double x, double y, const std::string& s, Color c, int scale = 2);

 private:
  int w_, h_;
  int cx0_ = 0, cy0_ = 0, cx1_ = 1 << 30, cy1_ = 1 << 30;
  std::vector<std::uint8_t> rgb_;
  std::vector<double> depth_;
};

/// Writes the canvas as PNG. \throws relgeo::io::Unwritable_file.
void write_png(const std::string& path, const Canvas& c);

}  // namespace relgeo_figures
