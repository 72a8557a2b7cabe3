// tools/relgeo/svg_writer.cpp
#include "svg_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "tool_common.h"

namespace relgeo::tool {

std::string xml_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
  return out;
}

std::string svg_number(double v) {
  if (!std::isfinite(v)) v = 0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

Svg_canvas::Svg_canvas(double width, double height) : width_(width), height_(height) {
  set_plot_area(0, 0, width, height);
}

void Svg_canvas::set_plot_area(double left, double top, double right, double bottom) {
  left_ = left, top_ = top, right_ = right, bottom_ = bottom;
  fit(0, 0, 1, 1);
}

void Svg_canvas::fit(double xmin, double ymin, double xmax, double ymax) {
  // Work in long double: the box may span 1e-3 .. 1e12 or be a few ulps wide.
  long double w = static_cast<long double>(xmax) - xmin, h = static_cast<long double>(ymax) - ymin;
  const long double pw = right_ - left_, ph = bottom_ - top_;
  long double s;
  if (w <= 0 && h <= 0) s = 1;  // one point: any scale, centred below
  else if (w <= 0) s = ph / h;
  else if (h <= 0) s = pw / w;
  else s = std::min(pw / w, ph / h);
  scale_ = static_cast<double>(s);
  // centre the box in the plot area
  const long double cx = (static_cast<long double>(xmin) + xmax) / 2,
                    cy = (static_cast<long double>(ymin) + ymax) / 2;
  x_offset_ = static_cast<double>((left_ + right_) / 2.0L - s * cx);
  y_offset_ = static_cast<double>((top_ + bottom_) / 2.0L + s * cy);
}

std::pair<double, double> Svg_canvas::map(double x, double y) const {
  return {static_cast<double>(x_offset_ + static_cast<long double>(scale_) * x),
          static_cast<double>(y_offset_ - static_cast<long double>(scale_) * y)};
}

void Svg_canvas::polygon(std::span<const Point_2<double>> points, bool closed,
                         std::string_view style) {
  if (points.empty()) return;
  body_ += closed && points.size() > 2 ? "<polygon points=\"" : "<polyline points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [vx, vy] = map(points[i].x, points[i].y);
    if (i) body_ += ' ';
    body_ += svg_number(vx) + "," + svg_number(vy);
  }
  body_ += "\" " + std::string(style) + "/>\n";
}

void Svg_canvas::circle(const Point_2<double>& p, double radius_px, std::string_view style) {
  const auto [vx, vy] = map(p.x, p.y);
  view_circle(vx, vy, radius_px, style);
}
void Svg_canvas::square(const Point_2<double>& p, double side_px, std::string_view style) {
  const auto [vx, vy] = map(p.x, p.y);
  view_square(vx, vy, side_px, style);
}
void Svg_canvas::view_circle(double vx, double vy, double radius_px, std::string_view style) {
  body_ += "<circle cx=\"" + svg_number(vx) + "\" cy=\"" + svg_number(vy) + "\" r=\"" +
           svg_number(radius_px) + "\"" + (style.empty() ? "" : " ") + std::string(style) + "/>\n";
}
void Svg_canvas::view_square(double vx, double vy, double side_px, std::string_view style) {
  body_ += "<rect x=\"" + svg_number(vx - side_px / 2) + "\" y=\"" + svg_number(vy - side_px / 2) +
           "\" width=\"" + svg_number(side_px) + "\" height=\"" + svg_number(side_px) + "\"" +
           (style.empty() ? "" : " ") + std::string(style) + "/>\n";
}
void Svg_canvas::view_line(double x1, double y1, double x2, double y2, std::string_view style) {
  body_ += "<line x1=\"" + svg_number(x1) + "\" y1=\"" + svg_number(y1) + "\" x2=\"" +
           svg_number(x2) + "\" y2=\"" + svg_number(y2) + "\" " + std::string(style) + "/>\n";
}
void Svg_canvas::view_text(double vx, double vy, std::string_view text, std::string_view style) {
  body_ += "<text x=\"" + svg_number(vx) + "\" y=\"" + svg_number(vy) + "\"" +
           (style.empty() ? "" : " ") + std::string(style) + ">" + xml_escape(text) + "</text>\n";
}
void Svg_canvas::raw(std::string_view svg) { body_ += svg; }
void Svg_canvas::begin_group(std::string_view style) { body_ += "<g " + std::string(style) + ">\n"; }
void Svg_canvas::end_group() { body_ += "</g>\n"; }

std::string Svg_canvas::str() const {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " +
         svg_number(width_) + " " + svg_number(height_) + "\" width=\"" + svg_number(width_) +
         "\" height=\"" + svg_number(height_) +
         "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" +
         body_ + "</svg>\n";
}

void Svg_canvas::write(const std::string& path) const {
  std::ofstream f(path, std::ios::binary);
  f << str();
  f.close();
  if (!f) throw Usage_error("cannot write SVG file '" + path + "'");
}

}  // namespace relgeo::tool
