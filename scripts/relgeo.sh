#!/usr/bin/env bash
# relgeo's one entry point for machines: installs what is missing, builds, runs.
#
#   bash scripts/relgeo.sh experiment   # deps + Release build + `relgeo experiment` (the main job)
#   bash scripts/relgeo.sh test         # deps + Release build + all tests + sanitizer subset
#   bash scripts/relgeo.sh sanitize     # deps + ASan/UBSan build of the library's unit suites
#
# Debian 12. Missing apt packages are installed when run as root (or through
# sudo when it exists). Environment: RELGEO_BUILD_DIR (default build),
# RELGEO_RESULTS (default results), RELGEO_JOBS (default: number of cores).
set -euo pipefail

cd "$(dirname "$0")/.."
root=$(pwd)
build=${RELGEO_BUILD_DIR:-$root/build}
# ccache (when installed) hashes paths relative to the checkout, so clones in
# other folders (CI) reuse each other's objects.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
jobs=${RELGEO_JOBS:-$(nproc)}

# What each package is for: README.md, section "Dependencies".
packages=(
  build-essential cmake pkg-config ccache
  libgmp-dev libmpfr-dev
  libcgal-dev libboost-dev libeigen3-dev libtbb-dev
  libgtest-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libstb-dev
  libopenmesh-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev
  chromium            # the browser test of the experiment report (tool_experiment_report_in_browser)
)

log() { printf '[relgeo] %s\n' "$*" >&2; }

install_missing() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]} == 0)); then
    log "all dependencies present"
    return
  fi
  log "installing: ${missing[*]}"
  local sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    if command -v sudo >/dev/null; then sudo=(sudo); else
      log "error: missing packages (${missing[*]}) and not root: run as root"; exit 2
    fi
  fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# CGAL's data set of real meshes (tests, benchmarks) is in libcgal-demo, whose
# GUI dependencies we do not want: unpack the package itself into .cache/.
cgal_data_archive() {
  local system=/usr/share/doc/libcgal-dev/data.tar.gz
  local cache=$root/.cache/cgal-demo
  local unpacked=$cache/usr/share/doc/libcgal-dev/data.tar.gz
  if [[ -f $system ]]; then echo "$system"; return; fi
  if [[ ! -f $unpacked ]]; then
    mkdir -p "$cache"
    (cd "$cache" && { apt-get download libcgal-demo >/dev/null 2>&1 ||
                      { apt-get update -qq >/dev/null 2>&1 || true; apt-get download libcgal-demo >/dev/null; }; } &&
     dpkg -x libcgal-demo_*.deb . && rm -f libcgal-demo_*.deb) >&2 ||
      log "warning: could not fetch CGAL's data set (libcgal-demo); its tests will be skipped"
  fi
  echo "$unpacked"
}

configure() {  # $1 build dir, rest: extra cmake args
  local dir=$1; shift
  cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release \
    -DRELGEO_CGAL_DATA_ARCHIVE="$(cgal_data_archive)" "$@" >/dev/null
}

run_experiment() {
  configure "$build"
  cmake --build "$build" --target relgeo_tool -j "$jobs"
  local out=${RELGEO_RESULTS:-$root/results}
  "$build/tools/relgeo/relgeo" experiment --output "$out"
  log "results in $out"
}

# The library's own unit suites under AddressSanitizer and UBSan. The peer
# suites (CGAL, OpenMesh, Eigen LU) and file IO exercise other libraries' code
# at a high compile cost; the Release run covers them.
sanitized_suites=(
  relgeo_core_tests relgeo_kernel_tests relgeo_kernel_soundness_tests relgeo_kernel_cgal_tests
  relgeo_kernel_environment_tests
  relgeo_hull_error_tests relgeo_hull_kernel_tests relgeo_hull_property_tests
  relgeo_linear_tests relgeo_curves_tests relgeo_extrusion_tests
  relgeo_mesh_tests relgeo_mesh_solid_tests relgeo_subdivision_tests relgeo_subdivision_limit_tests
  relgeo_subdivision_bounds_tests
)

run_sanitized_tests() {
  local dir=$build-asan
  configure "$dir" -DRELGEO_SANITIZE=ON -DRELGEO_BUILD_BENCHMARKS=OFF -DRELGEO_BUILD_TOOLS=OFF \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo
  local available targets=()
  available=$(cmake --build "$dir" --target help)
  for t in "${sanitized_suites[@]}"; do
    [[ $available == *"... $t"$'\n'* || $available == *"... $t" ]] && targets+=("$t")
  done
  ((${#targets[@]} > 0)) || { log "error: no sanitized suite is configured"; exit 1; }
  cmake --build "$dir" -j "$jobs" --target "${targets[@]}"
  # A twentieth of the soundness inputs: the sanitizers check memory and UB, the
  # full-size run checks the figures.
  local failed=0
  for t in "${targets[@]}"; do
    local bin
    bin=$(find "$dir/test" -name "$t" -type f -perm -u+x | head -n 1)
    log "sanitized: $t"
    RELGEO_TEST_SCALE=0.05 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      "$bin" --gtest_brief=1 || failed=1
  done
  ((failed == 0)) || { log "sanitized tests failed"; exit 1; }
  log "sanitized tests passed: ${#targets[@]} suites"
}

run_tests() {
  configure "$build"
  cmake --build "$build" -j "$jobs"
  (cd "$build" && ctest --output-on-failure -j "$jobs")
  run_sanitized_tests
}

case "${1:-}" in
  experiment) install_missing; run_experiment ;;
  test) install_missing; run_tests ;;
  sanitize) install_missing; run_sanitized_tests ;;
  *) echo "usage: bash scripts/relgeo.sh experiment|test|sanitize" >&2; exit 2 ;;
esac
