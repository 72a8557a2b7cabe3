// relgeo/io/png.h — RGB images and their PNG encoding (stb_image_write).
// Needs libstb's stb_image_write.h on the include path: link relgeo::io.
//
// Header-only: stb's writer is compiled into every translation unit that
// includes this header as static functions (STB_IMAGE_WRITE_STATIC, no
// stdio). Do not include stb_image_write.h with its implementation in the
// same translation unit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/io/errors.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wcast-qual"
#endif
#ifndef INCLUDE_STB_IMAGE_WRITE_H
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#undef STB_IMAGE_WRITE_IMPLEMENTATION
#endif
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace relgeo::io {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

/// An RGB image, rows stored top to bottom.
struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;  ///< width * height, row-major

  /// A width x height image filled with `fill`. \throws Invalid_input for a
  /// size < 1 or above 2^15 per side.
  static Image filled(int width, int height, Rgb fill = {255, 255, 255}) {
    if (width < 1 || height < 1 || width > (1 << 15) || height > (1 << 15))
      throw Invalid_input("image size " + std::to_string(width) + " x " + std::to_string(height) +
                          ": each side must be in 1..32768");
    return {width, height, std::vector<Rgb>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill)};
  }
  Rgb& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
  const Rgb& at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};

/// The image as an 8-bit RGB PNG file's bytes.
/// \throws Invalid_input for an image whose size and pixel count disagree.
inline std::vector<unsigned char> encode_png(const Image& image) {
  static_assert(sizeof(Rgb) == 3, "Rgb must be three packed bytes");
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw Invalid_input("malformed image: " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                        " with " + std::to_string(image.pixels.size()) + " pixels");
  std::vector<unsigned char> bytes;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* p = static_cast<const unsigned char*>(data);
    out->insert(out->end(), p, p + size);
  };
  if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, image.pixels.data(), image.width * 3))
    throw Invalid_input("PNG encoding failed");
  return bytes;
}

/// Writes `image` as a PNG file. \throws Unwritable_file, Invalid_input.
inline void write_png(const std::string& path, const Image& image) {
  const std::vector<unsigned char> bytes = encode_png(image);
  std::ofstream f(path, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  f.close();
  if (!f) throw Unwritable_file("cannot write PNG file '" + path + "'");
}

}  // namespace relgeo::io
