// tools/relgeo/png_writer.cpp — the one translation unit that compiles
// stb_image_write's implementation.
#include "png_writer.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wcast-qual"
#endif
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "tool_common.h"

namespace relgeo::tool {

void write_png(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
    throw Usage_error("internal: malformed image for '" + path + "'");
  const int ok = stbi_write_png(path.c_str(), image.width, image.height, 3, image.pixels.data(),
                                image.width * 3);
  if (!ok) throw Usage_error("cannot write PNG file '" + path + "'");
}

namespace {
Rgb colour_of(Certified_sign answer, bool wrong) {
  switch (answer) {
    case Certified_sign::negative: return wrong ? Rgb{110, 0, 0} : Rgb{230, 40, 40};
    case Certified_sign::zero: return wrong ? Rgb{120, 110, 0} : Rgb{250, 220, 40};
    case Certified_sign::positive: return wrong ? Rgb{0, 0, 110} : Rgb{50, 90, 230};
    case Certified_sign::uncertain: return Rgb{160, 160, 160};
  }
  return Rgb{255, 255, 255};
}
}  // namespace

Image orientation_grid_image(std::span<const Certified_sign> answers,
                             std::span<const Certified_sign> exact, int size, int scale) {
  const std::size_t cells = static_cast<std::size_t>(size) * size;
  if (size < 1 || scale < 1 || answers.size() != cells || exact.size() != cells)
    throw Usage_error("internal: orientation grid picture of inconsistent size");
  Image img{size * scale, size * scale, {}};
  img.pixels.resize(static_cast<std::size_t>(img.width) * img.height);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * size + x;
      const Certified_sign a = answers[i];
      const bool wrong = is_certain(a) && a != exact[i];
      const Rgb c = colour_of(a, wrong);
      const int top = (size - 1 - y) * scale;  // row Y=0 at the bottom
      for (int dy = 0; dy < scale; ++dy)
        for (int dx = 0; dx < scale; ++dx) img.at(x * scale + dx, top + dy) = c;
    }
  return img;
}

}  // namespace relgeo::tool
