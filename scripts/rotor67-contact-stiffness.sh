#!/usr/bin/env bash
# Rotor 67's NFRC as the contact stiffness goes towards the rigid limit (issue 35, item 1): k = 1e8
# (the case's), 1e9 and 1e10 N/m, in both friction senses and nearly without friction (mu = 1e-4),
# with the law's width in force units kept at the case's 400 N: its force at a gap g away from the
# casing, about width^2 / (4 k |g|), then vanishes as k grows (a width scaled with k, the rounding
# kept at +-4 um, makes that tail grow as k: 1 N at the clearance at 1e8, 1000 N at 1e11, which
# pushed the blade off-resonance and is no rigid limit). Then k = 1e10 at H = 15 (2048 samples)
# for the truncation of the sharper law. From
# omega = 1000 rad/s, not the case's 1600: at k >= 1e9 the geometry sense's branch bends below
# 1600. Writes OUT/<sense>-k<k>[-h15]/ and OUT/table.md (python/contact_stiffness_table.py).
# About 15 minutes on one core. Usage: scripts/rotor67-contact-stiffness.sh [OUT]
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/rotor67_contact_stiffness}
hbtrack=${HBTRACK:-build/hbtrack}
mkdir -p "$out"
reversed=()
for k in 0 1 2 3 4 5 6 7 8; do reversed+=(--set "elements[$k].engine_order=1"); done
run() {  # sense stiffness folder [extra --set ...]
  local sense=$1 k=$2 folder=$3
  shift 3
  local sense_sets=()
  [ "$sense" = reversed ] && sense_sets=("${reversed[@]}")
  [ "$sense" = frictionless ] && sense_sets=(--set mu=1e-4)  # the case's [study] needs mu in its range
  "$hbtrack" frc examples/rotor67/nominal.toml --set "contact_stiffness=$k" "${sense_sets[@]}" \
    --set continuation.omega_start=1000 "$@" \
    -o "$out/$folder" -q || echo "rotor67-contact-stiffness: $folder: exit $?" >&2
}
for sense in geometry reversed frictionless; do
  for k in 1e8 1e9 1e10; do run "$sense" "$k" "$sense-k$k"; done
  run "$sense" 1e10 "$sense-k1e10-h15" --set harmonic_balance.harmonics=15 --set harmonic_balance.samples=2048
done
/usr/bin/python3 python/contact_stiffness_table.py "$out" > "$out/table.md"
cat "$out/table.md"
