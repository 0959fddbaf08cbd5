#!/usr/bin/env bash
# Builds hbtrack with warnings on and runs the whole test suite (ctest). With --sanitize it
# also builds and runs the suite under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}

# /usr/bin/python3: the first python3 on PATH may lack numpy (the Python module and its tests).
# CI (CI=true) runs no benchmark and skips building them: it has 30 minutes on 2 cores.
bench=ON
[ -n "${CI:-}" ] && bench=OFF
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 -DHBTRACK_BUILD_BENCH=$bench
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs"

if [ "${1:-}" = "--sanitize" ]; then
  # -O1 keeps Eigen fast enough under the sanitizers; benchmarks are not built, nor the Python
  # module (python cannot load an ASan-instrumented extension; its tests ran above).
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DHBTRACK_SANITIZE=ON -DHBTRACK_BUILD_BENCH=OFF -DHBTRACK_PYTHON=OFF
  cmake --build build-sanitize -j "$jobs"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
fi
