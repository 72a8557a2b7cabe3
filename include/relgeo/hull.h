// relgeo/hull.h — umbrella header of the planar convex-hull area.
#pragma once

#include "relgeo/hull/graham_fortune.h"
#include "relgeo/hull/graham_incremental.h"
#include "relgeo/hull/hull_result.h"
#include "relgeo/hull/monotone_chain.h"
