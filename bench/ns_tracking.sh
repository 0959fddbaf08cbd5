#!/usr/bin/env bash
# The cost of a point of Neimark-Sacker tracking on rotor 67 (the Hill pencil of order 820 and
# its bordered LU): NS 1 of the nominal NFRC tracked in the forcing amplitude for 6 steps a leg
# (11 points), each HBTRACK given in turn, twice, on one core. Prints CPU (user) and wall seconds
# per run; compare binaries within one run of this script.
#
#   bash bench/ns_tracking.sh NFRC_DIR HBTRACK [HBTRACK ...]
#
# NFRC_DIR: `hbtrack frc examples/rotor67/nominal.toml -o DIR`. Not part of CI; run it with
# nothing else on the machine and say what else was running.
set -euo pipefail
cd "$(dirname "$0")/.."
nfrc=$(realpath "$1")
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| binary | user [s] | wall [s] | points |"
echo "|---|---|---|---|"
for round in 1 2; do
  for hbtrack in "$@"; do
    out="$work/run"
    rm -rf "$out"
    OPENBLAS_NUM_THREADS=1 taskset -c 1 /usr/bin/time -f "%U %e" -o "$work/time" "$hbtrack" track examples/rotor67/nominal.toml \
      --from "$nfrc" --ns 1 --param amplitude --range 130:160 --set continuation.max_points=6 -o "$out" -q 2> /dev/null || true
    times=$(tail -1 "$work/time")
    points=$(/usr/bin/python3 -c "import json; print(json.load(open('$out/summary.json'))['points'])")
    echo "| $hbtrack (round $round) | ${times% *} | ${times#* } | $points |"
  done
done
