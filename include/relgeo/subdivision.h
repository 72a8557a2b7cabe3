// relgeo/subdivision.h — umbrella header of the subdivision area: Loop
// refinement with creases and corners, weights and their number hook, masks
// (refinement, limit position, tangents), limit meshes, exact limit-surface
// evaluation (box splines, local subdivision) and error bounds.
#pragma once

#include "relgeo/subdivision/box_spline.h"
#include "relgeo/subdivision/error_bounds.h"
#include "relgeo/subdivision/limit_evaluation.h"
#include "relgeo/subdivision/loop_features.h"
#include "relgeo/subdivision/loop_masks.h"
#include "relgeo/subdivision/loop_patch_kind.h"
#include "relgeo/subdivision/loop_subdivision.h"
#include "relgeo/subdivision/loop_weights.h"
#include "relgeo/subdivision/number_traits.h"
#include "relgeo/subdivision/stencil.h"
