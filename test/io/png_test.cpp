// PNG: the encoded bytes decode (stb_image, an independent reader) to the
// same pixels; malformed images and unwritable paths are typed errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "relgeo/io/png.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace {

using relgeo::io::Image;
using relgeo::io::Rgb;

Image test_image() {
  Image img = Image::filled(7, 5);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.at(x, y) = Rgb{std::uint8_t(30 * x), std::uint8_t(50 * y), std::uint8_t(x * y)};
  return img;
}

TEST(Png, DecodesToTheSamePixels) {
  const Image img = test_image();
  const std::vector<unsigned char> bytes = relgeo::io::encode_png(img);
  ASSERT_GT(bytes.size(), 8u);
  EXPECT_EQ(bytes[1], 'P');
  int w = 0, h = 0, comp = 0;
  unsigned char* decoded = stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &comp, 3);
  ASSERT_NE(decoded, nullptr);
  EXPECT_EQ(w, 7);
  EXPECT_EQ(h, 5);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = decoded + 3 * (y * w + x);
      EXPECT_EQ((Rgb{p[0], p[1], p[2]}), img.at(x, y)) << x << "," << y;
    }
  stbi_image_free(decoded);
}

TEST(Png, WritesAFile) {
  const auto path = std::filesystem::temp_directory_path() / "relgeo_io_png_test.png";
  relgeo::io::write_png(path.string(), test_image());
  std::ifstream f(path, std::ios::binary);
  const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(f), {}};
  EXPECT_EQ(bytes, relgeo::io::encode_png(test_image()));
  std::filesystem::remove(path);
}

TEST(Png, BadImagesAndPathsAreTyped) {
  Image broken{3, 3, std::vector<Rgb>(8)};
  EXPECT_THROW(relgeo::io::encode_png(broken), relgeo::Invalid_input);
  EXPECT_THROW(Image::filled(0, 4), relgeo::Invalid_input);
  EXPECT_THROW(relgeo::io::write_png("/nonexistent/relgeo/x.png", test_image()), relgeo::io::Unwritable_file);
}

}  // namespace
