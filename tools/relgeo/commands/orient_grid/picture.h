// tools/relgeo/png_writer.h — PNG pictures of the tool (stb_image_write).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "relgeo/core/certified_sign.h"

namespace relgeo::tool {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

/// An RGB image, rows stored top to bottom.
struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;
  Rgb& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// Writes `image` as an 8-bit RGB PNG. Throws Usage_error when the file
/// cannot be written (bad --png / --output path).
void write_png(const std::string& path, const Image& image);

/// The legend of orientation-grid pictures, for help texts.
inline constexpr const char* orientation_grid_legend =
    "one cell per pixel, scaled up, row Y=0 at the bottom, X=0 at the left; colour = the "
    "kernel's answer: red = negative, yellow = zero, blue = positive, grey = uncertain; "
    "wrong answers (definite and different from the exact sign) in a dark shade of their "
    "colour (dark red, olive, dark blue)";

/// The picture of an orientation grid (answers and exact signs row-major, row
/// = Y, size x size cells), each cell drawn as scale x scale pixels, row Y=0
/// at the bottom. Colours: see orientation_grid_legend.
Image orientation_grid_image(std::span<const Certified_sign> answers,
                             std::span<const Certified_sign> exact, int size, int scale);

}  // namespace relgeo::tool
