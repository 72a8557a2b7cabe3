// Calls of relgeo's algorithms with a type that is not a kernel. This file
// must NOT compile: check_wrong_kernel.cmake compiles it and requires each
// call's error to name the concept the algorithm states (issue 29: a clear
// compile error for a wrong kernel, as CGAL documents the traits each
// function needs).
#include <array>
#include <vector>

#include "relgeo/boolean/mesh_boolean.h"
#include "relgeo/hull/monotone_chain.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/subdivision/loop_subdivision.h"

struct Not_a_kernel {};

int main() {
  const relgeo::Triangle_mesh<relgeo::Point_3<double>> mesh;
  (void)relgeo::boolean(mesh, mesh, relgeo::Boolean_operation::union_of, Not_a_kernel{}, {});
  (void)relgeo::monotone_chain(std::vector<relgeo::Point_2<double>>{}, Not_a_kernel{});
  (void)relgeo::find_self_intersections(mesh, Not_a_kernel{}, relgeo::Self_intersection_options{});
  (void)relgeo::check_solid<Not_a_kernel>(mesh);
  (void)relgeo::Loop_subdivider<Not_a_kernel>{};
}
