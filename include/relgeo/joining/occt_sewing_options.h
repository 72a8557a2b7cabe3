// relgeo/joining/occt_sewing_options.h — the options of occt_sewing
// (occt_sewing.h), in a header of their own that needs no OpenCASCADE: code
// that passes them on to a plug-in (the tool's `join`) does not include it.
#pragma once

namespace relgeo {

/// Options of occt_sewing (lengths relative to the model's size: the
/// diagonal of the input meshes' bounding box).
struct Occt_sewing_options {
  double sewing_tolerance = 1e-3;   ///< BRepBuilderAPI_Sewing's tolerance [1e-3]
  double linear_deflection = 2e-4;  ///< BRepMesh's chordal deflection [2e-4]
  double angular_deflection = 0.3;  ///< radians [0.3]
};

}  // namespace relgeo
