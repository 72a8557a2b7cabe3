// Point files and number text: correctly rounded reading, exact round trip,
// and a typed error for every kind of bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <unistd.h>

#include "relgeo/io/number_text.h"
#include "relgeo/io/point_file.h"

namespace {

using relgeo::Non_finite_input;
using relgeo::Point_2;
using relgeo::Unreadable_file;
using relgeo::io::Parse_error;

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("relgeo_io_test_" + std::to_string(::getpid()) + "_" + name);
}

TEST(NumberText, RoundsToNearest) {
  // 0.1 is not a double: the nearest one, as the compiler rounds the literal.
  EXPECT_EQ(relgeo::io::parse_double("0.1", "t"), 0.1);
  // A halfway case between 1 and its successor rounds to even (1).
  EXPECT_EQ(relgeo::io::parse_double("1.00000000000000011102230246251565404236316680908203125", "t"), 1.0);
  // Just above halfway rounds up.
  EXPECT_EQ(relgeo::io::parse_double("1.00000000000000011102230246251565404236316680908203126", "t"),
            std::nextafter(1.0, 2.0));
  EXPECT_EQ(relgeo::io::parse_double("  +2.5\t", "t"), 2.5);
  // Below the smallest subnormal: a signed zero, not an error.
  const double z = relgeo::io::parse_double("-1e-400", "t");
  EXPECT_EQ(z, 0.0);
  EXPECT_TRUE(std::signbit(z));
  EXPECT_EQ(relgeo::io::parse_double("4.9406564584124654e-324", "t"), std::numeric_limits<double>::denorm_min());
}

TEST(NumberText, RefusesWhatIsNotOneFiniteNumber) {
  for (const char* bad : {"", "  ", "abc", "1,5", "1 2", "2x", "+-1", "--1", "0x10", "1e"})
    EXPECT_THROW(relgeo::io::parse_double(bad, "t"), Parse_error) << '"' << bad << '"';
  for (const char* bad : {"nan", "NaN", "inf", "-infinity", "1e999", "-1e400"})
    EXPECT_THROW(relgeo::io::parse_double(bad, "t"), Non_finite_input) << bad;
}

TEST(NumberText, Format17RoundTrips) {
  for (double v : {0.1, 1.0 / 3, 24.000000000000053, -7.3000000000000194, 1e-310, 1.7976931348623157e308})
    EXPECT_EQ(relgeo::io::parse_double(relgeo::io::format_17(v), "t"), v);
}

TEST(PointFile, ParsesBlanksCommasCommentsAndCrlf) {
  const auto pts = relgeo::io::parse_points_2("# header\n1 2\r\n\n 3.5 ,\t-4 # comment\n\t5\t6", "mem");
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_EQ(pts[0].x, 1);
  EXPECT_EQ(pts[1].x, 3.5);
  EXPECT_EQ(pts[1].y, -4);
  EXPECT_EQ(pts[2].y, 6);
  EXPECT_TRUE(relgeo::io::parse_points_2("# only comments\n\n", "mem").empty());
}

TEST(PointFile, WrongCountsAndGarbageNameTheLine) {
  struct Case { const char* text; std::size_t line; };
  for (const Case& c : {Case{"1 2\n3\n", 2}, Case{"1 2 3\n", 1}, Case{"1 2\n\n# c\n1,2,3\n", 4},
                        Case{"x y\n", 1}, Case{"1 2\n3 4z\n", 2}, Case{"1,\n", 1}, Case{", 2\n", 1}}) {
    try {
      relgeo::io::parse_points_2(c.text, "pts.txt");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const Parse_error& e) {
      EXPECT_EQ(e.source(), "pts.txt");
      EXPECT_EQ(e.line(), c.line) << c.text;
      EXPECT_NE(std::string(e.what()).find("pts.txt line " + std::to_string(c.line) + ":"), std::string::npos);
      EXPECT_EQ(e.code(), relgeo::Error_code::unreadable_file);
    }
  }
}

TEST(PointFile, NonFiniteNumbersAreTyped) {
  EXPECT_THROW(relgeo::io::parse_points_2("1 2\nnan 3\n", "p"), Non_finite_input);
  EXPECT_THROW(relgeo::io::parse_points_2("1 inf\n", "p"), Non_finite_input);
  EXPECT_THROW(relgeo::io::parse_points_2("1e309 0\n", "p"), Non_finite_input);
}

TEST(PointFile, WritesWhatItReadsBackExactly) {
  const std::vector<Point_2<double>> pts = {{0.50000000000001621, 0.50000000000001243}, {1e-300, -3.25}, {0.1, 0.2}};
  const auto path = temp_file("roundtrip.txt");
  relgeo::io::write_points_2(path.string(), pts, "two lines\nof header");
  const auto back = relgeo::io::read_points_2(path.string());
  std::filesystem::remove(path);
  ASSERT_EQ(back.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(back[i].x, pts[i].x);
    EXPECT_EQ(back[i].y, pts[i].y);
  }
  EXPECT_EQ(relgeo::io::format_points_2(pts, "h").substr(0, 4), "# h\n");
}

TEST(PointFile, ReadsStreams) {
  std::istringstream in("1 2\n3 4\n");
  EXPECT_EQ(relgeo::io::read_points_2(in).size(), 2u);
}

TEST(PointFile, UnreadableFilesAreTyped) {
  EXPECT_THROW(relgeo::io::read_points_2("/nonexistent/relgeo/points.txt"), Unreadable_file);
  EXPECT_THROW(relgeo::io::read_points_2(std::filesystem::temp_directory_path().string()), Unreadable_file);
  EXPECT_THROW(relgeo::io::read_points_2(std::string()), Unreadable_file);
  try {
    relgeo::io::read_points_2("/nonexistent/relgeo/points.txt");
  } catch (const Unreadable_file& e) {
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos);
  }
}

TEST(PointFile, UnwritableFilesAreTyped) {
  const std::vector<Point_2<double>> pts = {{1, 2}};
  EXPECT_THROW(relgeo::io::write_points_2("/nonexistent/relgeo/out.txt", pts), relgeo::io::Unwritable_file);
}

}  // namespace
