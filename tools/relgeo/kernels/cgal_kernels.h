// tools/relgeo/kernels/cgal_kernels.h — completes the CGAL kernel types of
// kernels/list.h. Heavy (Epeck: ~11 s of compile time): include it only in
// the translation units that dispatch over every kernel (the dispatch*.cpp
// files and kernels/registry.cpp).
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
