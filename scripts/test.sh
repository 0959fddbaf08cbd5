#!/usr/bin/env bash
# Builds hbtrack with warnings on and runs the whole test suite (ctest). With --sanitize it
# also builds and runs the suite under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}

# /usr/bin/python3: the first python3 on PATH may lack numpy (the Python module and its tests).
# The benchmarks are built (so that CI sees them break) but not run: speed is measured on a quiet
# machine (bench/run.sh), never asserted by the suite.
bench=ON
# ccache when installed: a second build of unchanged sources takes seconds.
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Precompiled headers need these to be cached; paths relative to the clone, so that another
  # clone of the same sources hits the same entries.
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime CCACHE_BASEDIR="$PWD"
fi
# Unity builds: the suite builds from scratch twice below, and batches of files compile the
# shared Eigen, JSON, CLI11 and GoogleTest templates once per batch (docs/performance.md, CI).
unity=(-DHBTRACK_UNITY_BUILD=ON)
# The time of each phase on stderr ("test.sh: Release build 412 s"), for the CI's split.
started=$SECONDS
phase_done() {
  echo "test.sh: $1 $((SECONDS - started)) s" >&2
  started=$SECONDS
}
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 -DHBTRACK_BUILD_BENCH=$bench "${unity[@]}" "${launcher[@]}"
cmake --build build -j "$jobs"
phase_done "Release build"
ctest --test-dir build --output-on-failure -j "$jobs"
phase_done "Release suite"

if [ "${1:-}" = "--sanitize" ]; then
  # -O1 keeps Eigen fast enough under the sanitizers; benchmarks are not built, nor the Python
  # module (python cannot load an ASan-instrumented extension; its tests ran above). -g1 (line
  # tables: the sanitizers' stack traces still name file and line) compiles a quarter faster
  # than -g and writes a third of the object size (measured on harmonic_balance.cpp: 75 s
  # against 98 s, 14 against 43 MB).
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DHBTRACK_SANITIZE=ON -DHBTRACK_BUILD_BENCH=OFF -DHBTRACK_PYTHON=OFF "${unity[@]}" "${launcher[@]}"
  cmake --build build-sanitize -j "$jobs"
  phase_done "sanitizer build"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
  phase_done "sanitizer suite"
fi
