// Fuzz harness: the feature-tag side file (relgeo::read_feature_tags) on
// arbitrary text, and the tags applied to a mesh (contract in
// mesh_file_harness.cpp).
#include "mesh_file_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  relgeo::fuzz::check_tag_file(data, size);
  return 0;
}
