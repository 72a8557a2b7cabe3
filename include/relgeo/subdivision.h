// relgeo/subdivision.h — umbrella header of the subdivision area: Loop
// refinement with creases and corners, weights and their number hook, masks
// (refinement, limit position, tangents) and limit meshes.
#pragma once

#include "relgeo/subdivision/loop_masks.h"
#include "relgeo/subdivision/loop_subdivision.h"
#include "relgeo/subdivision/loop_weights.h"
#include "relgeo/subdivision/number_traits.h"
