// tools/relgeo/svg_writer.h — small SVG pictures of planar data: a canvas that
// maps a world box uniformly (aspect kept, y up) into a plot area of the
// viewBox, with primitives in world or viewBox coordinates.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "relgeo/kernel/point.h"

namespace relgeo::tool {

/// Text with &, <, >, " escaped for XML.
std::string xml_escape(std::string_view s);

class Svg_canvas {
 public:
  /// A width x height viewBox; the world box [xmin, xmax] x [ymin, ymax] is
  /// scaled uniformly into the plot area [left, right] x [top, bottom]
  /// (viewBox units), centred, y pointing up. A degenerate box (one point or
  /// a line) is widened so that its content lands in the middle.
  Svg_canvas(double width, double height);
  void set_plot_area(double left, double top, double right, double bottom);
  void fit(double xmin, double ymin, double xmax, double ymax);

  /// World point -> viewBox point.
  std::pair<double, double> map(double x, double y) const;

  // World-coordinate primitives; `style` is the SVG attribute text
  // (e.g. `fill="none" stroke="blue"`).
  void polygon(std::span<const Point_2<double>> points, bool closed, std::string_view style);
  void circle(const Point_2<double>& p, double radius_px, std::string_view style);
  void square(const Point_2<double>& p, double side_px, std::string_view style);
  // ViewBox-coordinate primitives.
  void view_circle(double vx, double vy, double radius_px, std::string_view style);
  void view_square(double vx, double vy, double side_px, std::string_view style);
  void view_line(double x1, double y1, double x2, double y2, std::string_view style);
  void view_text(double vx, double vy, std::string_view text, std::string_view style);
  /// Verbatim SVG (must be well formed).
  void raw(std::string_view svg);
  /// Opens/closes a group `<g style>` (e.g. to share a style between many points).
  void begin_group(std::string_view style);
  void end_group();

  std::string str() const;
  /// \throws Usage_error when the file cannot be written.
  void write(const std::string& path) const;

 private:
  double width_, height_;
  double left_ = 0, top_ = 0, right_ = 0, bottom_ = 0;
  double scale_ = 1, x_offset_ = 0, y_offset_ = 0;
  std::string body_;
};

/// A coordinate of the viewBox as text (3 decimals, no trailing zeros).
std::string svg_number(double v);

}  // namespace relgeo::tool
