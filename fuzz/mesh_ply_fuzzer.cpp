// Fuzz harness: relgeo::read_mesh on arbitrary .ply files (PLY, ASCII and binary, through CGAL's
// IO; contract in mesh_file_harness.cpp).
#include "mesh_file_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  relgeo::fuzz::check_mesh_file(data, size, ".ply");
  return 0;
}
