// relgeo/error.h — umbrella header of the error-measure area.
#pragma once

#include "relgeo/error/convex_polygon.h"
#include "relgeo/error/hull_backward_error.h"
#include "relgeo/error/hull_error.h"
