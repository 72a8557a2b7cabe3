// tools/relgeo/plugins/occt/loader.cpp — finds and opens the OpenCASCADE
// plug-in of `join` once (occt_join.h).
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include "plugins/occt/occt_join.h"
#include "relgeo/core/errors.h"

namespace relgeo::tool {
namespace {

// The environment's when set (only that: a setting that does not load is an
// error, not skipped); else the build's, the one installed beside this
// executable (its prefix: an install to another prefix than the configured
// one), the one installed to the configured prefix.
[[maybe_unused]] std::vector<std::string> plugin_paths() {
  std::vector<std::string> paths;
  if (const char* env = std::getenv("RELGEO_OCCT_PLUGIN"); env && *env) return {env};
#ifdef RELGEO_OCCT_PLUGIN_BUILD_PATH
  paths.emplace_back(RELGEO_OCCT_PLUGIN_BUILD_PATH);
#endif
#ifdef RELGEO_OCCT_PLUGIN_INSTALL_PATH
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);  // <prefix>/bin/relgeo
  if (!ec) paths.push_back((exe.parent_path().parent_path() / RELGEO_OCCT_PLUGIN_INSTALL_RELATIVE).string());
  paths.emplace_back(RELGEO_OCCT_PLUGIN_INSTALL_PATH);
#endif
  return paths;
}

struct Loaded {
  const Occt_join_functions* functions = nullptr;
  std::string failure;
};

Loaded load() {
#if !defined(RELGEO_OCCT_PLUGIN_BUILD_PATH)
  return {nullptr, "relgeo was built without OpenCASCADE (relgeo::occt)"};
#else
  std::string tried;
  for (const std::string& path : plugin_paths()) {
    // RTLD_LOCAL: OpenCASCADE's symbols stay the plug-in's. Never closed.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* e = dlerror();
      tried += (tried.empty() ? "" : "; ") + std::string(e ? e : path.c_str());
      continue;
    }
    const auto entry = reinterpret_cast<Occt_join_entry>(dlsym(handle, "relgeo_occt_join_functions"));
    if (!entry) {
      tried += (tried.empty() ? "" : "; ") + path + ": no relgeo_occt_join_functions";
      continue;
    }
    return {entry(), {}};
  }
  return {nullptr, "the OpenCASCADE plug-in librelgeo_occt_join.so cannot be loaded (" + tried +
                       "); RELGEO_OCCT_PLUGIN names its path"};
#endif
}

}  // namespace

const Occt_join_functions& occt_join_functions(const std::string& what_needs_it) {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.functions) throw Invalid_input(what_needs_it + " needs OpenCASCADE: " + loaded.failure);
  return *loaded.functions;
}

}  // namespace relgeo::tool
