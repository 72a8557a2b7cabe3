// tools/relgeo/plugins/occt/occt_join.h — what `join` needs of OpenCASCADE
// (STEP/IGES input, the occt method), in a plug-in loaded on first use.
//
// Why a plug-in: linked into the tool, OpenCASCADE's 19 libraries are loaded
// and relocated at the start of every command (35-40 ms of `relgeo --help`'s
// 49 ms) and of every `import relgeo`; only `join` uses them. The plug-in
// (librelgeo_occt_join.so, built with relgeo::occt) is opened with dlopen the
// first time a STEP/IGES file is read or the occt method runs.
//
// The plug-in is built by the same compiler from the same sources as the
// tool, so the C++ types below cross the boundary as they are; its one C
// symbol returns the table of functions.
#pragma once

#include <string>
#include <vector>

namespace relgeo {
template <class T>
struct Point_3;
template <class P>
struct Triangle_mesh;
struct Surface_model;
struct Join_result;
struct Occt_sewing_options;
}  // namespace relgeo

namespace relgeo::tool {

/// The plug-in's functions.
struct Occt_join_functions {
  /// read_cad_model (relgeo/surfaces/occt_io.h). \throws its errors.
  Surface_model (*read_cad_model)(const std::string& path);
  /// occt_sewing (relgeo/joining/occt_sewing.h) under the kernel named
  /// `kernel` (K::name() of one of the join command's kernels).
  /// \throws its errors; Usage_error for a kernel `join` does not run under.
  Join_result (*occt_sewing)(const std::string& kernel, const Surface_model& model,
                             const std::vector<Triangle_mesh<Point_3<double>>>& meshes,
                             const Occt_sewing_options& options);
};

/// The plug-in's C entry point (dlsym name "relgeo_occt_join_functions").
using Occt_join_entry = const Occt_join_functions* (*)();

/// The plug-in's functions, loaded on first use: from $RELGEO_OCCT_PLUGIN
/// when set (only from there), else from where the build put it, else from
/// where it is installed (loader.cpp).
/// \throws Invalid_input naming why (relgeo built without OpenCASCADE, the
/// plug-in not found or not loadable); what needs it says so first.
const Occt_join_functions& occt_join_functions(const std::string& what_needs_it);

}  // namespace relgeo::tool
