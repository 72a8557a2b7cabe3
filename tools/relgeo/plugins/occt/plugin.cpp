// tools/relgeo/plugins/occt/plugin.cpp — the OpenCASCADE plug-in of `join`
// (librelgeo_occt_join.so, occt_join.h): read_cad_model and occt_sewing
// under the join command's kernels (commands/join/join_kernels.h).
#include <string>
#include <vector>

#include "commands/join/join_kernels.h"
#include "kernels/dispatch.h"
#include "plugins/occt/occt_join.h"
#include "relgeo/core/errors.h"
#include "relgeo/joining/occt_sewing.h"
#include "relgeo/kernel.h"
#include "relgeo/surfaces/occt_io.h"

namespace relgeo::tool {
namespace {

Surface_model read_cad(const std::string& path) { return read_cad_model(path); }

Join_result sew(const std::string& kernel, const Surface_model& model,
                const std::vector<Triangle_mesh<Point_3<double>>>& meshes, const Occt_sewing_options& options) {
  return with_kernel<Join_kernels>(kernel, [&]<class K>(const K& k) { return occt_sewing(model, meshes, k, options); });
}

constexpr Occt_join_functions functions{&read_cad, &sew};

}  // namespace
}  // namespace relgeo::tool

extern "C" __attribute__((visibility("default"))) const relgeo::tool::Occt_join_functions*
relgeo_occt_join_functions() {
  return &relgeo::tool::functions;
}
