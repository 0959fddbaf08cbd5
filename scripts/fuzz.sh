#!/usr/bin/env bash
# Fuzzes the input readers with libFuzzer (clang) under AddressSanitizer + UBSan.
#   bash scripts/fuzz.sh [TARGET|all] [SECONDS]
# TARGET: case_file, matrix_market, mat_file, calculix, sections (default all, one after the other);
# SECONDS per target (default 600). JOBS=N sets the build's parallelism (default 2).
#
# Needs clang and libFuzzer, from Debian (bookworm): `apt-get install clang libclang-rt-14-dev`
# (clang-14 and its compiler-rt runtimes, libclang_rt.fuzzer and the sanitizers). These are for
# fuzzing only: CI does not fuzz, so scripts/install-deps.sh does not install them.
#
# Builds build-fuzz/ (git-ignored). Each run starts from the corpus kept in the repo,
# fuzz/corpus/TARGET, plus the hand-made seeds in fuzz/seeds/TARGET, and writes what it finds
# into build-fuzz/corpus/TARGET (the repo's folders are only read); a crashing input goes to
# build-fuzz/findings/TARGET/ and the script exits non-zero. KEEP=1: after a clean run, the
# kept corpus and the run's are minimized together into fuzz/corpus/TARGET, a greedy smallest
# set of inputs with every coverage feature of the two (libFuzzer's -set_cover_merge=1; plain
# -merge=1 keeps about half as many files again); commit it.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:-all}
seconds=${2:-600}
targets=(case_file matrix_market mat_file calculix sections)
[ "$target" = all ] || targets=("$target")

cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DHBTRACK_FUZZ=ON -DHBTRACK_BUILD_TESTS=OFF -DHBTRACK_BUILD_BENCH=OFF >/dev/null
for t in "${targets[@]}"; do
  cmake --build build-fuzz -j "${JOBS:-2}" --target "fuzz_$t"
done
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/findings/$t"
  inputs=("fuzz/seeds/$t")
  [ -d "fuzz/corpus/$t" ] && inputs=("fuzz/corpus/$t" "${inputs[@]}")
  # max_len 4096: the seeds are small and short inputs keep the executions fast; rss 2 GB: a
  # reader that sizes an allocation from a header it did not check is a finding.
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ASAN_OPTIONS=detect_leaks=1 \
    "build-fuzz/fuzz/fuzz_$t" -max_total_time="$seconds" -max_len=4096 -rss_limit_mb=2048 -timeout=30 -print_final_stats=1 \
    -artifact_prefix="build-fuzz/findings/$t/" "build-fuzz/corpus/$t" "${inputs[@]}"
  if [ "${KEEP:-0}" = 1 ]; then
    rm -rf "build-fuzz/kept/$t" && mkdir -p "build-fuzz/kept/$t"
    sources=("build-fuzz/corpus/$t")
    [ -d "fuzz/corpus/$t" ] && sources=("fuzz/corpus/$t" "${sources[@]}")
    "build-fuzz/fuzz/fuzz_$t" -set_cover_merge=1 -max_len=4096 -timeout=30 "build-fuzz/kept/$t" "${sources[@]}"
    rm -rf "fuzz/corpus/$t" && mkdir -p fuzz/corpus && mv "build-fuzz/kept/$t" "fuzz/corpus/$t"
  fi
done
