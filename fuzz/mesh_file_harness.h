// fuzz/mesh_file_harness.h — the harness body the mesh-reader fuzzers share
// (one per format: mesh_off, mesh_obj, mesh_ply, mesh_stl), compiled once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace relgeo::fuzz {

/// Reads the bytes as a mesh file with `extension` (".off", ".obj", ".ply",
/// ".stl") through relgeo::read_mesh and checks the contract of
/// doc/reliability.md (harness mesh_*).
void check_mesh_file(const std::uint8_t* data, std::size_t size, std::string_view extension);

/// Reads the bytes as a tag side file and applies the tags to a fixed mesh
/// (harness mesh_tags).
void check_tag_file(const std::uint8_t* data, std::size_t size);

}  // namespace relgeo::fuzz
