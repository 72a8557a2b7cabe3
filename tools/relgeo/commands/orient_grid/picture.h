// tools/relgeo/commands/orient_grid/picture.h — the PNG picture of an
// orientation grid (also the experiment's kernels section).
#pragma once

#include <span>

#include "relgeo/core/certified_sign.h"
#include "relgeo/io/png.h"

namespace relgeo::tool {

/// The legend of orientation-grid pictures, for help texts and the report.
inline constexpr const char* orientation_grid_legend =
    "one cell per pixel, scaled up, row Y=0 at the bottom, X=0 at the left; colour = the "
    "kernel's answer: red = negative, yellow = zero, blue = positive, grey = uncertain; "
    "wrong answers (definite and different from the exact sign) in a dark shade of their "
    "colour (dark red, olive, dark blue)";

/// The picture of an orientation grid (answers and exact signs row-major, row
/// = Y, size x size cells), each cell scale x scale pixels, row Y=0 at the
/// bottom. Colours: orientation_grid_legend.
io::Image orientation_grid_image(std::span<const Certified_sign> answers, std::span<const Certified_sign> exact,
                                 int size, int scale);

}  // namespace relgeo::tool
