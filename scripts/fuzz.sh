#!/usr/bin/env bash
# Fuzzes the input readers with libFuzzer (clang) under AddressSanitizer + UBSan.
#   bash scripts/fuzz.sh [TARGET|all] [SECONDS]
# TARGET: case_file, matrix_market, mat_file, calculix (default all, one after the other);
# SECONDS per target (default 600). Builds build-fuzz/ (git-ignored); the growing corpus is
# kept in build-fuzz/corpus/TARGET, seeded from fuzz/seeds/TARGET; a crashing input is written
# to build-fuzz/findings/TARGET/ and the script exits non-zero.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:-all}
seconds=${2:-600}
targets=(case_file matrix_market mat_file calculix)
[ "$target" = all ] || targets=("$target")

cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DHBTRACK_FUZZ=ON -DHBTRACK_BUILD_TESTS=OFF -DHBTRACK_BUILD_BENCH=OFF >/dev/null
for t in "${targets[@]}"; do
  cmake --build build-fuzz -j "${JOBS:-2}" --target "fuzz_$t"
done
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/findings/$t"
  # max_len 4096: the seeds are small and short inputs keep the executions fast; rss 2 GB: a
  # reader that sizes an allocation from a header it did not check is a finding.
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ASAN_OPTIONS=detect_leaks=1 \
    "build-fuzz/fuzz/fuzz_$t" -max_total_time="$seconds" -max_len=4096 -rss_limit_mb=2048 -timeout=30 -print_final_stats=1 \
    -artifact_prefix="build-fuzz/findings/$t/" "build-fuzz/corpus/$t" "fuzz/seeds/$t"
done
