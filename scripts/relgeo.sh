#!/usr/bin/env bash
# relgeo's one entry point for machines: installs what is missing, builds, runs.
#
#   bash scripts/relgeo.sh experiment   # deps + Release build + `relgeo experiment` (the main job)
#   bash scripts/relgeo.sh test         # deps + Release build + all tests + sanitizer subset
#   bash scripts/relgeo.sh sanitize     # deps + ASan/UBSan build of the library's unit suites
#   bash scripts/relgeo.sh fuzz [SECONDS] [HARNESS...]
#                                       # deps + libFuzzer build + a campaign: SECONDS of CPU
#                                       # (default 3600) per harness, one after another, niced
#
# Debian 12. Missing apt packages are installed when run as root (or through
# sudo when it exists). Environment: RELGEO_BUILD_DIR (default build),
# RELGEO_RESULTS (default results), RELGEO_JOBS (default: number of cores),
# RELGEO_FUZZ_DIR (default .cache/fuzz: the campaigns' corpora, findings, logs).
set -euo pipefail

cd "$(dirname "$0")/.."
root=$(pwd)
build=${RELGEO_BUILD_DIR:-$root/build}
# ccache (when installed) hashes paths relative to the checkout, so clones in
# other folders (CI) reuse each other's objects.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
# The test suites' precompiled headers (RELGEO_PRECOMPILE_HEADERS): ccache
# caches their users only with these.
export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}
# Depend mode: on a miss, ccache takes the headers from the compiler's own
# dependency file (CMake passes -MD) instead of running the preprocessor
# first. On a fresh machine every compile is a miss, and that extra
# preprocessor run was 6% of the Release build's compile time.
export CCACHE_DEPEND=${CCACHE_DEPEND:-true}
jobs=${RELGEO_JOBS:-$(nproc)}

# What each package is for: README.md, section "Dependencies".
packages=(
  build-essential cmake pkg-config ccache
  python3             # scripts/api_rules.py (two tests of `test`)
  python3-dev python3-pybind11 python3-numpy python3-pytest   # the Python package relgeo (python/) and its tests
  python3-distributed   # relgeo.sweep on Dask (python/relgeo/sweep.py)
  python3-matplotlib    # examples/python/kernel_comparison.py's plot (and its test)
  libgmp-dev libmpfr-dev
  libcgal-dev libboost-dev libeigen3-dev libtbb-dev
  libgtest-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libstb-dev
  libopenmesh-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev
  chromium            # the browser test of the experiment report (tool_experiment_report_in_browser)
  clang libclang-rt-14-dev   # libFuzzer and the sanitizer runtimes (fuzz/; the sanitizer build of `test`)
)

log() { printf '[relgeo] %s\n' "$*" >&2; }

# Wall time of each phase of a command (install, build, ctest, ...), logged as
# it ends and summed up at the end: CI's log then says where its time went.
phase_started=$SECONDS
phase_summary=()
phase_done() {
  local took=$((SECONDS - phase_started))
  phase_summary+=("$1 $((took / 60))m$((took % 60))s")
  log "phase $1: ${took} s"
  phase_started=$SECONDS
}
phase_report() { log "phases: ${phase_summary[*]} (total $((SECONDS / 60))m$((SECONDS % 60))s)"; }

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
  # The Python package (when configured: python3-pybind11 and numpy found),
  # on the tool's facade objects just built: only its bindings compile.
  if [[ -f "$build/python/CMakeFiles/relgeo_python.dir/build.make" ]]; then
    cmake --build "$build" --target relgeo_python -j "$jobs"
    PYTHONPATH="$build/python" /usr/bin/python3 -c "import relgeo" && \
      log "Python: PYTHONPATH=$build/python /usr/bin/python3 -c 'import relgeo' (doc/python.md)"
  fi
}

# Runs "$1 ARG" for each further ARG, $jobs at a time (the machine's cores);
# fails when any run failed. Every run still runs to its end.
run_parallel() {
  local f=$1 running=0 failed=0 arg
  shift
  for arg in "$@"; do
    if ((running >= jobs)); then
      wait -n || failed=1
      running=$((running - 1))
    fi
    "$f" "$arg" &
    running=$((running + 1))
  done
  while ((running > 0)); do
    wait -n || failed=1
    running=$((running - 1))
  done
  return "$failed"
}

# The library's own unit suites under AddressSanitizer and UBSan: those
# marked SANITIZED in test/ (relgeo_add_test), built by the target
# relgeo_sanitized_suites, listed in sanitized_suites.txt of the build.
run_sanitized_tests() {
  local dir=$build-asan
  command -v clang++ >/dev/null || { log "error: clang++ not found (package clang)"; exit 2; }
  # clang (as for the fuzzers): with UBSan's checks it compiles these suites
  # in about 60% of GCC's time, and the environment soundness suites then run
  # under a second compiler. A folder configured for another compiler is
  # configured afresh.
  if [[ -f $dir/CMakeCache.txt ]] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++$' "$dir/CMakeCache.txt"; then
    rm -rf "$dir/CMakeCache.txt" "$dir/CMakeFiles"
  fi
  # -O1 and line tables only: the sanitizers' usual setting, and half the
  # compile time of -O2 -g on the Boolean suites.
  configure "$dir" -DCMAKE_CXX_COMPILER=clang++ -DRELGEO_SANITIZE=ON -DRELGEO_BUILD_BENCHMARKS=OFF \
    -DRELGEO_BUILD_TOOLS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG"
  cmake --build "$dir" -j "$jobs" --target relgeo_sanitized_suites
  local suites=()
  mapfile -t suites <"$dir/sanitized_suites.txt"
  ((${#suites[@]} > 0)) || { log "error: no sanitized suite is configured"; exit 1; }
  # $jobs suites at a time, each log kept until it is done; a twentieth of the
  # soundness inputs: the sanitizers check memory and UB, the full-size run
  # checks the figures.
  local logs failed=0
  logs=$(mktemp -d)
  run_one_sanitized() {
    local bin=$1 out=$logs/${1##*/}.log
    if RELGEO_TEST_SCALE=0.05 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
         "$bin" --gtest_brief=1 >"$out" 2>&1; then
      log "sanitized: ${bin##*/}: $(grep -oE 'PASSED  \] [0-9]+ tests?' "$out" | tail -n 1 | grep -oE '[0-9]+ tests?') passed"
    else
      log "sanitized: ${bin##*/} FAILED; log:"
      local report='Failure$|runtime error|ERROR: AddressSanitizer|ERROR: LeakSanitizer|\[  FAILED  \]'
      if grep -q -E "$report" "$out"; then grep -E -A 12 "$report" "$out" | head -n 100 >&2; else tail -n 60 "$out" >&2; fi
      return 1
    fi
  }
  run_parallel run_one_sanitized "${suites[@]}" || failed=1
  rm -rf "$logs"
  ((failed == 0)) || { log "sanitized tests failed"; exit 1; }
  log "sanitized tests passed: ${#suites[@]} suites"
}

# ---- fuzzing (fuzz/, doc/reliability.md) -------------------------------------
fuzz_build=${RELGEO_FUZZ_BUILD_DIR:-$build-fuzz}
fuzz_work=${RELGEO_FUZZ_DIR:-$root/.cache/fuzz}
# Per input: 10 s (a hang is a finding), 2 GB of memory, no single allocation
# over 1 GB (a reader must not trust a count in a header).
# -timeout: a hang, not a slow input (the exact-kernel seeds of loop_limit take
# seconds under the sanitizers on a loaded machine)
fuzz_limits=(-timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=1024)

build_fuzzers() {
  command -v clang++ >/dev/null || { log "error: clang++ not found (package clang)"; exit 2; }
  # -O1 and line tables only, as OSS-Fuzz builds: stack traces keep file and
  # line, and the Boolean's harness compiles in three quarters of the time of
  # -O2 with full debug information (the flags before).
  configure "$fuzz_build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
    -DRELGEO_BUILD_FUZZERS=ON -DRELGEO_BUILD_TESTS=OFF -DRELGEO_BUILD_BENCHMARKS=OFF -DRELGEO_BUILD_TOOLS=OFF
  cmake --build "$fuzz_build" -j "$jobs" --target relgeo_fuzzers
}

# The harnesses: one seed folder fuzz/corpus/NAME per executable relgeo_fuzz_NAME.
fuzz_harnesses() {
  local d
  for d in "$root"/fuzz/corpus/*/; do
    d=${d%/}; d=${d##*/}
    if [[ -x $fuzz_build/fuzz/relgeo_fuzz_$d ]]; then echo "$d"; fi
  done
}

# The corpus replay (CTest: every seed and kept finding once, no mutation),
# then a short run of every harness from its seeds (a copy: the seeds stay as
# they are): about 60 s of fuzzing in all, $jobs harnesses at a time. Any
# crash, hang or sanitizer report fails.
# Harnesses to leave out of the smoke (a known finding whose fix is not
# merged yet would be found again within seconds); empty: every harness runs.
fuzz_smoke_skip=()

run_fuzz_smoke() {
  build_fuzzers
  (cd "$fuzz_build" && ctest --output-on-failure -j "$jobs" -L fuzz) || { log "fuzz corpus replay failed"; exit 1; }
  local all=() harnesses=() tmp failed=0 h
  mapfile -t all < <(fuzz_harnesses)
  ((${#all[@]} > 0)) || { log "error: no fuzz harness built"; exit 1; }
  for h in "${all[@]}"; do
    if [[ " ${fuzz_smoke_skip[*]} " == *" $h "* ]]; then log "fuzz smoke: $h skipped (fuzz_smoke_skip)"; else harnesses+=("$h"); fi
  done
  # About 60 s of fuzzing in all, $jobs harnesses at a time.
  local each=$(( (60 + ${#all[@]} - 1) / ${#all[@]} ))
  tmp=$(mktemp -d)
  fuzz_one() {
    local h=$1
    mkdir -p "$tmp/$h"
    cp "$root/fuzz/corpus/$h"/* "$tmp/$h/"
    # A fixed seed: the smoke explores the same way in every run (CI stays
    # reproducible); campaigns (fuzz) draw their seeds.
    if TMPDIR=$tmp "$fuzz_build/fuzz/relgeo_fuzz_$h" "${fuzz_limits[@]}" -seed=1 -max_total_time="$each" \
         -artifact_prefix="$tmp/$h-" "$tmp/$h" >"$tmp/$h.log" 2>&1; then
      log "fuzz smoke: $h ($each s): $(grep -o 'Done [0-9]* runs' "$tmp/$h.log" | tail -n 1)"
    else
      log "fuzz smoke: $h FAILED; log:"
      grep -E -A 30 'relgeo fuzz|ERROR|SUMMARY' "$tmp/$h.log" | head -n 60 >&2 || tail -n 40 "$tmp/$h.log" >&2
      return 1
    fi
  }
  run_parallel fuzz_one "${harnesses[@]}" || failed=1
  rm -rf "$tmp"
  ((failed == 0)) || { log "fuzz smoke failed"; exit 1; }
  log "fuzz smoke passed: ${#harnesses[@]} harnesses"
}

# A campaign: SECONDS of CPU time per harness (default 3600; user + system of
# the fuzzer and its fork-mode jobs, so a busy machine lengthens the wall time
# instead of shortening the campaign; a wall-time cap of 4 x SECONDS stops a
# starved one), one harness after another, niced, in libFuzzer's fork mode so
# that a finding is saved and the campaign goes on. Corpora grow in
# $fuzz_work/corpus/NAME (seeded from fuzz/corpus/NAME), findings land in
# $fuzz_work/findings/NAME-*, logs in $fuzz_work/logs; the summary gives the
# CPU time each harness used. RELGEO_FUZZ_BUILD_DIR lets a campaign run on its
# own build while the smoke rebuilds the default one.
run_fuzz_campaign() {
  local seconds=${1:-3600}; shift || true
  [[ $seconds =~ ^[0-9]+$ ]] || { log "error: fuzz SECONDS must be a number, got '$seconds'"; exit 2; }
  build_fuzzers
  # nice alone does not yield to other sessions' work when the kernel groups
  # tasks by session (sched_autogroup): lower the session's group too, so a
  # campaign started with setsid or from another terminal runs in the
  # machine's idle time.
  echo 19 >/proc/self/autogroup 2>/dev/null || true
  local harnesses=("$@")
  ((${#harnesses[@]} > 0)) || mapfile -t harnesses < <(fuzz_harnesses)
  mkdir -p "$fuzz_work/corpus" "$fuzz_work/findings" "$fuzz_work/logs" "$fuzz_work/tmp"
  for h in "${harnesses[@]}"; do
    local bin=$fuzz_build/fuzz/relgeo_fuzz_$h corpus=$fuzz_work/corpus/$h
    [[ -x $bin ]] || { log "error: no harness '$h' (have: $(fuzz_harnesses | tr '\n' ' '))"; exit 2; }
    mkdir -p "$corpus"
    cp -n "$root/fuzz/corpus/$h"/* "$corpus/" 2>/dev/null || true
    log "fuzz: $h for $seconds CPU s (log: $fuzz_work/logs/$h.log)"
    rm -f "$fuzz_work/logs/$h.cpu-used"
    TMPDIR=$fuzz_work/tmp /usr/bin/time -f '%U %S %e' -o "$fuzz_work/logs/$h.cpu" \
      nice -n 10 "$bin" "${fuzz_limits[@]}" -max_total_time=$((4 * seconds)) -fork=1 \
        -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
        -artifact_prefix="$fuzz_work/findings/$h-" "$corpus" >"$fuzz_work/logs/$h.log" 2>&1 &
    local runner=$!
    stop_at_cpu_seconds "$runner" "$seconds" "$fuzz_work/logs/$h.cpu-used"
    wait "$runner" || true
    local cpu wall findings
    cpu=$(cat "$fuzz_work/logs/$h.cpu-used" 2>/dev/null || echo "under 10")
    # The last line: the interrupted fuzzer's exit status comes before.
    wall=$(tail -n 1 "$fuzz_work/logs/$h.cpu" | awk '{printf "%.0f", $3}')
    findings=$(find "$fuzz_work/findings" -name "$h-*" | wc -l)
    log "fuzz: $h: ${cpu} CPU s in ${wall} s of wall time, $(grep -o 'exec/s:\? [0-9]*' "$fuzz_work/logs/$h.log" | tail -n 1)," \
        "corpus $(find "$corpus" -type f | wc -l) inputs, findings so far: $findings"
  done
  log "findings (if any) are in $fuzz_work/findings; reproduce one with $fuzz_build/fuzz/relgeo_fuzz_NAME FILE"
}

# The pids of process $1 and of all its descendants.
process_tree() {
  local child
  echo "$1"
  for child in $(pgrep -P "$1"); do process_tree "$child"; done
}

# Interrupts the fuzzer run by /usr/bin/time (pid $1) once it and its jobs
# have used $2 CPU seconds, and writes the CPU seconds used to file $3: summed
# over the fuzzer's process tree, each process's utime + stime + cutime +
# cstime (/proc/PID/stat fields 14-17; a reaped job's time is in its parent's
# cutime, a live one's in its own). This is the campaign's figure:
# /usr/bin/time misses the last job, which the fuzzer does not reap when
# interrupted.
stop_at_cpu_seconds() {
  local timer=$1 budget=$2 out=$3 ticks fuzzer used=0 tree
  ticks=$(getconf CLK_TCK)
  while kill -0 "$timer" 2>/dev/null; do
    sleep 10
    fuzzer=$(pgrep -P "$timer" | head -n 1) || continue
    tree=$(process_tree "$fuzzer")
    used=$(for p in $tree; do cat "/proc/$p/stat" 2>/dev/null || true; done |
             awk '{sub(/^.*\) /, ""); t += $12 + $13 + $14 + $15} END {printf "%d", t}')
    echo $((used / ticks)) >"$out"
    if ((used >= budget * ticks)); then
      # SIGTERM: libFuzzer's fork mode waits for its jobs in system(), which
      # ignores SIGINT.
      kill -TERM $tree 2>/dev/null || true
      break
    fi
  done
}

run_tests() {
  configure "$build"
  cmake --build "$build" -j "$jobs"
  phase_done build
  (cd "$build" && ctest --output-on-failure -j "$jobs")
  phase_done ctest
  run_sanitized_tests
  phase_done sanitizers
  run_fuzz_smoke
  phase_done "fuzz-smoke"
  phase_report
}

case "${1:-}" in
  experiment) install_missing; run_experiment ;;
  test) install_missing; phase_done install; run_tests ;;
  sanitize) install_missing; run_sanitized_tests ;;
  fuzz-smoke) install_missing; run_fuzz_smoke ;;
  fuzz) shift; install_missing; run_fuzz_campaign "$@" ;;
  *) echo "usage: bash scripts/relgeo.sh experiment|test|sanitize|fuzz-smoke|fuzz [SECONDS] [HARNESS...]" >&2; exit 2 ;;
esac
