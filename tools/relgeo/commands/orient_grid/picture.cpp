// tools/relgeo/commands/orient_grid/picture.cpp
#include "commands/orient_grid/picture.h"

#include "cli/text.h"

namespace relgeo::tool {

namespace {
io::Rgb colour_of(Certified_sign answer, bool wrong) {
  switch (answer) {
    case Certified_sign::negative: return wrong ? io::Rgb{110, 0, 0} : io::Rgb{230, 40, 40};
    case Certified_sign::zero: return wrong ? io::Rgb{120, 110, 0} : io::Rgb{250, 220, 40};
    case Certified_sign::positive: return wrong ? io::Rgb{0, 0, 110} : io::Rgb{50, 90, 230};
    case Certified_sign::uncertain: return io::Rgb{160, 160, 160};
  }
  return io::Rgb{255, 255, 255};
}
}  // namespace

io::Image orientation_grid_image(std::span<const Certified_sign> answers, std::span<const Certified_sign> exact,
                                 int size, int scale) {
  const std::size_t cells = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
  if (size < 1 || scale < 1 || answers.size() != cells || exact.size() != cells)
    throw Usage_error("internal: orientation grid picture of inconsistent size");
  io::Image img = io::Image::filled(size * scale, size * scale);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x);
      const Certified_sign a = answers[i];
      const io::Rgb c = colour_of(a, is_certain(a) && a != exact[i]);
      const int top = (size - 1 - y) * scale;  // row Y=0 at the bottom
      for (int dy = 0; dy < scale; ++dy)
        for (int dx = 0; dx < scale; ++dx) img.at(x * scale + dx, top + dy) = c;
    }
  return img;
}

}  // namespace relgeo::tool
