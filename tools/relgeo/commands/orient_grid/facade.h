// tools/relgeo/commands/orient_grid/facade.h — orientation grids under a
// kernel named at run time (instantiated in dispatch.cpp only).
#pragma once

#include <string_view>

#include "relgeo/analysis/orientation_grid.h"

namespace relgeo::tool {

/// relgeo::analysis::evaluate_orientation_grid under the named kernel.
/// \throws Usage_error for an unknown kernel.                [dispatch.cpp]
analysis::Orientation_grid_result evaluate_grid(std::string_view kernel,
                                                const analysis::Orientation_grid_triple& triple, int size);

}  // namespace relgeo::tool
