// relgeo/kernel.h — umbrella header of the kernel area: the concepts and every
// kernel model that needs no CGAL (include relgeo/kernel/cgal_kernel.h for the
// CGAL adapters).
#pragma once

#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/interval_kernel.h"
#include "relgeo/kernel/kernel_for_number.h"
#include "relgeo/kernel/mpfr_kernel.h"
#include "relgeo/kernel/naive_kernel.h"
#include "relgeo/kernel/point.h"
