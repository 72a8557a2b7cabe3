// relgeo/io/svg_canvas.h — small SVG pictures of planar data: a canvas that
// maps a world box uniformly (aspect kept, y up) into a plot area of its
// viewBox, with primitives in world or viewBox coordinates. No dependency.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "relgeo/io/text_file.h"
#include "relgeo/io/xml_text.h"
#include "relgeo/kernel/point.h"

namespace relgeo::io {

/// A viewBox coordinate as text: 3 decimals, no trailing zeros, never "-0"
/// (non-finite values become 0: SVG has no infinity).
inline std::string svg_number(double v) {
  if (!std::isfinite(v)) v = 0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

class Svg_canvas {
 public:
  /// A width x height viewBox (also the picture's width and height).
  Svg_canvas(double width, double height) : width_(width), height_(height) { set_plot_area(0, 0, width, height); }

  /// The part of the viewBox that fit() maps the world box into.
  void set_plot_area(double left, double top, double right, double bottom) {
    left_ = left, top_ = top, right_ = right, bottom_ = bottom;
    fit(0, 0, 1, 1);
  }

  /// Scales [xmin, xmax] x [ymin, ymax] uniformly into the plot area, centred,
  /// y up. A box of one point or a segment is centred at a usable scale.
  void fit(double xmin, double ymin, double xmax, double ymax) {
    // long double: the box may span 1e-3 .. 1e12 or be a few ulps wide.
    const long double w = static_cast<long double>(xmax) - xmin, h = static_cast<long double>(ymax) - ymin;
    const long double pw = right_ - left_, ph = bottom_ - top_;
    long double s;
    if (w <= 0 && h <= 0) s = 1;
    else if (w <= 0) s = ph / h;
    else if (h <= 0) s = pw / w;
    else s = std::min(pw / w, ph / h);
    scale_ = static_cast<double>(s);
    const long double cx = (static_cast<long double>(xmin) + xmax) / 2, cy = (static_cast<long double>(ymin) + ymax) / 2;
    x_offset_ = static_cast<double>((left_ + right_) / 2.0L - s * cx);
    y_offset_ = static_cast<double>((top_ + bottom_) / 2.0L + s * cy);
  }

  /// World point -> viewBox point.
  std::pair<double, double> map(double x, double y) const {
    return {static_cast<double>(x_offset_ + static_cast<long double>(scale_) * x),
            static_cast<double>(y_offset_ - static_cast<long double>(scale_) * y)};
  }

  // World-coordinate primitives; `style` is SVG attribute text (`fill="none" stroke="blue"`).
  void polygon(std::span<const Point_2<double>> points, bool closed, std::string_view style) {
    if (points.empty()) return;
    body_ += closed && points.size() > 2 ? "<polygon points=\"" : "<polyline points=\"";
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto [vx, vy] = map(points[i].x, points[i].y);
      if (i) body_ += ' ';
      body_ += svg_number(vx) + "," + svg_number(vy);
    }
    body_ += '"';  // appended piecewise: GCC 12 warns (-Wrestrict) on "\"" + std::string&&
    body_ += attributes(style);
    body_ += "/>\n";
  }
  void circle(const Point_2<double>& p, double radius_px, std::string_view style) {
    const auto [vx, vy] = map(p.x, p.y);
    view_circle(vx, vy, radius_px, style);
  }
  void square(const Point_2<double>& p, double side_px, std::string_view style) {
    const auto [vx, vy] = map(p.x, p.y);
    view_square(vx, vy, side_px, style);
  }

  // ViewBox-coordinate primitives.
  void view_circle(double vx, double vy, double radius_px, std::string_view style) {
    body_ += "<circle cx=\"" + svg_number(vx) + "\" cy=\"" + svg_number(vy) + "\" r=\"" + svg_number(radius_px) + "\"" +
             attributes(style) + "/>\n";
  }
  void view_square(double vx, double vy, double side_px, std::string_view style) {
    body_ += "<rect x=\"" + svg_number(vx - side_px / 2) + "\" y=\"" + svg_number(vy - side_px / 2) + "\" width=\"" +
             svg_number(side_px) + "\" height=\"" + svg_number(side_px) + "\"" + attributes(style) + "/>\n";
  }
  void view_line(double x1, double y1, double x2, double y2, std::string_view style) {
    body_ += "<line x1=\"" + svg_number(x1) + "\" y1=\"" + svg_number(y1) + "\" x2=\"" + svg_number(x2) + "\" y2=\"" +
             svg_number(y2) + "\"" + attributes(style) + "/>\n";
  }
  void view_text(double vx, double vy, std::string_view text, std::string_view style) {
    body_ += "<text x=\"" + svg_number(vx) + "\" y=\"" + svg_number(vy) + "\"" + attributes(style) + ">" +
             xml_escape(text) + "</text>\n";
  }
  /// Verbatim SVG (must be well formed).
  void raw(std::string_view svg) { body_ += svg; }
  /// Opens / closes a group `<g style>` (one style shared by many elements).
  void begin_group(std::string_view style) {
    body_ += "<g";
    body_ += attributes(style);
    body_ += ">\n";
  }
  void end_group() { body_ += "</g>\n"; }

  /// The whole document (white background).
  std::string str() const {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + svg_number(width_) + " " + svg_number(height_) +
           "\" width=\"" + svg_number(width_) + "\" height=\"" + svg_number(height_) +
           "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body_ + "</svg>\n";
  }
  /// \throws Unwritable_file.
  void write(const std::string& path) const { write_text_file(path, str(), "SVG file"); }

 private:
  // Built by appending: GCC 12 warns (-Wrestrict, a false positive) on
  // " " + std::string&& once inlined into callers.
  static std::string attributes(std::string_view style) {
    std::string a;
    if (!style.empty()) a.append(1, ' ').append(style);
    return a;
  }

  double width_, height_;
  double left_ = 0, top_ = 0, right_ = 0, bottom_ = 0;
  double scale_ = 1, x_offset_ = 0, y_offset_ = 0;
  std::string body_;
};

}  // namespace relgeo::io
