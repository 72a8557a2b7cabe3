// tools/relgeo/commands/join/picture.h — the (u,v) picture of a joined mesh:
// one panel per face, its triangles of the result over the face's trim
// loops, flipped (or degenerate, undecided) triangles in red.
#pragma once

#include <string>
#include <vector>

#include "commands/join/facade.h"
#include "relgeo/io/svg_canvas.h"

namespace relgeo::tool {

/// The panels side by side under `title`; `window` (optional, u0 v0 u1 v1)
/// restricts every panel to a part of the domain (a seam in detail).
io::Svg_canvas join_picture(const std::vector<Join_face_picture>& faces, const std::string& title,
                            const double* window = nullptr);

/// Triangles marked flipped in `faces`.
std::size_t flipped_in_picture(const std::vector<Join_face_picture>& faces);

}  // namespace relgeo::tool
