// relgeo/analysis.h — umbrella header of the analysis area: input workloads,
// tallies of answers against exact signs, orientation grids.
#pragma once

#include "relgeo/analysis/orientation_grid.h"
#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/analysis/sign_tally.h"
