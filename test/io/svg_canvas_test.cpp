// The SVG canvas: uniform scaling with y up, escaping, degenerate boxes,
// well-formed output.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "relgeo/io/svg_canvas.h"

namespace {

using relgeo::io::Svg_canvas;

TEST(SvgCanvas, MapsTheBoxUniformlyWithYUp) {
  Svg_canvas svg(200, 100);
  svg.fit(0, 0, 10, 10);  // square box in a 2:1 area: height decides the scale (10 per unit)
  const auto [x0, y0] = svg.map(0, 0);
  const auto [x1, y1] = svg.map(10, 10);
  EXPECT_DOUBLE_EQ(y0, 100);
  EXPECT_DOUBLE_EQ(y1, 0);
  EXPECT_DOUBLE_EQ(x1 - x0, 100);  // aspect kept
  EXPECT_DOUBLE_EQ((x0 + x1) / 2, 100);  // centred
}

TEST(SvgCanvas, DegenerateBoxesLandInTheMiddle) {
  Svg_canvas svg(100, 100);
  svg.fit(5, 5, 5, 5);  // one point
  const auto [x, y] = svg.map(5, 5);
  EXPECT_DOUBLE_EQ(x, 50);
  EXPECT_DOUBLE_EQ(y, 50);
  svg.fit(0, 1, 10, 1);  // a horizontal segment
  const auto [xa, ya] = svg.map(0, 1);
  const auto [xb, yb] = svg.map(10, 1);
  EXPECT_DOUBLE_EQ(ya, 50);
  EXPECT_DOUBLE_EQ(yb, 50);
  EXPECT_DOUBLE_EQ(xb - xa, 100);
}

TEST(SvgCanvas, EscapesTextAndWritesNumbersSafely) {
  EXPECT_EQ(relgeo::io::xml_escape("a<b & \"c\">\n"), "a&lt;b &amp; &quot;c&quot;&gt; ");
  EXPECT_EQ(relgeo::io::svg_number(1.5), "1.5");
  EXPECT_EQ(relgeo::io::svg_number(-0.0001), "0");
  EXPECT_EQ(relgeo::io::svg_number(2.0), "2");
  EXPECT_EQ(relgeo::io::svg_number(std::numeric_limits<double>::quiet_NaN()), "0");
  EXPECT_EQ(relgeo::io::svg_number(std::numeric_limits<double>::infinity()), "0");
}

TEST(SvgCanvas, DocumentIsComplete) {
  Svg_canvas svg(50, 40);
  const std::vector<relgeo::Point_2<double>> tri = {{0, 0}, {1, 0}, {0, 1}};
  svg.polygon(tri, true, "fill=\"none\"");
  svg.view_text(1, 2, "<title>", "");
  const std::string s = svg.str();
  EXPECT_NE(s.find("viewBox=\"0 0 50 40\""), std::string::npos);
  EXPECT_NE(s.find("<polygon points=\""), std::string::npos);
  EXPECT_NE(s.find("&lt;title&gt;</text>"), std::string::npos);
  EXPECT_EQ(s.substr(s.size() - 7), "</svg>\n");
  EXPECT_THROW(svg.write("/nonexistent/relgeo/x.svg"), relgeo::io::Unwritable_file);
}

}  // namespace
