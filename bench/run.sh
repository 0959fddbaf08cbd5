#!/usr/bin/env bash
# Prints the README's performance tables (Markdown): the blade case (NFRC, stability, limit-point
# tracking) and the chain scaling case, with where the time goes. Builds Release with the
# benchmarks into build/ unless bench_blade and bench_chain are there already.
#
#   bash bench/run.sh [--quick] [--build-dir DIR]     --quick: a shorter run (about a minute)
#
# Not part of CI (minutes of wall time); run it on a machine as quiet as you can get, and read
# the ratio columns, which survive load on other cores better than the absolute times.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=""
build=build
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick="--quick" ;;
    --build-dir) build="$2"; shift ;;
    *) echo "usage: bash bench/run.sh [--quick] [--build-dir DIR]" >&2; exit 2 ;;
  esac
  shift
done
if [ ! -x "$build/bench/bench_blade" ] || [ ! -x "$build/bench/bench_chain" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHBTRACK_BUILD_BENCH=ON \
    -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
  cmake --build "$build" --target bench_blade bench_chain
fi
echo "### Blade (examples/blade/nominal.toml${quick:+, --quick: omega in [2000, 2150], 10 tracking points})"
echo
"$build/bench/bench_blade" $quick
echo
echo "### Chain of oscillators (n masses, H harmonics, N samples)"
echo
"$build/bench/bench_chain" $quick
echo
echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the end."
