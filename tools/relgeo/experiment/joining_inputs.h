// tools/relgeo/experiment/joining_inputs.h — the inputs of the experiment's
// joining section, made by the fixtures (relgeo_fixtures/joining/
// test_models.h) and written as files, so that the section runs exactly what
// `relgeo join` runs and a reader can repeat any row with the command.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace relgeo::tool {

/// One case on disk: the surface model (JSON) and one mesh (OFF) per face.
struct Joining_input {
  std::string name;     ///< "folding", "two-faces-curve", ...
  std::string summary;  ///< one line: what it is, which thesis case
  std::string surface;
  std::vector<std::string> meshes;
};

/// Writes every case under `dir` (created): NAME.json, NAME_0.off, ...
std::vector<Joining_input> write_joining_inputs(const std::filesystem::path& dir);

}  // namespace relgeo::tool
