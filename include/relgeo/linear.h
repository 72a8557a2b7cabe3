// relgeo/linear.h — umbrella header of the linear-equation area (thesis
// Sec. 3.2): Gaussian elimination variants in any scalar, Eigen's LU as peers,
// exact rational solutions, backward/forward errors and condition numbers.
// Needs Eigen 3.3+ on the include path (CMake: Eigen3::Eigen). (The thesis'
// example and Hilbert systems are fixtures, not library:
// fixtures/relgeo_fixtures/linear/test_problems.h.)
#pragma once

#include "relgeo/linear/backward_error.h"
#include "relgeo/linear/exact_solution.h"
#include "relgeo/linear/gaussian_elimination.h"
#include "relgeo/linear/scalar_traits.h"
#include "relgeo/linear/solvers.h"
