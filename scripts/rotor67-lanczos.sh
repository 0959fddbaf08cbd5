#!/usr/bin/env bash
# What the Lanczos filter of the contact forces changes on rotor 67 (issue 35, item 3): the nominal
# NFRC with the case's filter (lanczos = 1: harmonic j's force multiplied by sinc(j / (H + 1)),
# 0.69 at j = 5 and 0.10 at j = 10) and without it (lanczos = 0), in both friction senses; then
# python/lanczos_filter_table.py: the special points side by side, ||r(t)||_inf stretch by stretch,
# and, given study folders, the full model's time integration (its fold search's start that held)
# next to both HBM solutions. Writes OUT/<sense>-{filtered,unfiltered}/ and OUT/table.md.
# About 2 minutes on one core.
# Usage: scripts/rotor67-lanczos.sh [OUT [GEOMETRY_STUDY REVERSED_STUDY]]
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/rotor67_lanczos}
hbtrack=${HBTRACK:-build/hbtrack}
mkdir -p "$out"
reversed=() unfiltered=()
for k in 0 1 2 3 4 5 6 7 8; do
  reversed+=(--set "elements[$k].engine_order=1")
  unfiltered+=(--set "elements[$k].lanczos=0")
done
for sense in geometry reversed; do
  sense_sets=()
  [ "$sense" = reversed ] && sense_sets=("${reversed[@]}")
  "$hbtrack" frc examples/rotor67/nominal.toml "${sense_sets[@]}" -o "$out/$sense-filtered" -q ||
    echo "rotor67-lanczos: $sense-filtered: exit $?" >&2
  "$hbtrack" frc examples/rotor67/nominal.toml "${sense_sets[@]}" "${unfiltered[@]}" -o "$out/$sense-unfiltered" -q ||
    echo "rotor67-lanczos: $sense-unfiltered: exit $?" >&2
done
# The time-integration comparison needs the studies' fold searches, whose starts are rows of the
# studies' own NFRCs: compare against those NFRCs (the same run as $out/<sense>-filtered).
geometry=("$out/geometry-filtered") reversed_nfrc=("$out/reversed-filtered")
if [ $# -ge 3 ]; then
  geometry=("$2/nfrc") reversed_nfrc=("$3/nfrc")
  geometry+=("$out/geometry-unfiltered" --simulate "$2/simulate")
  reversed_nfrc+=("$out/reversed-unfiltered" --simulate "$3/simulate")
else
  geometry+=("$out/geometry-unfiltered") reversed_nfrc+=("$out/reversed-unfiltered")
fi
/usr/bin/python3 python/lanczos_filter_table.py geometry "${geometry[@]}" reversed "${reversed_nfrc[@]}" > "$out/table.md"
cat "$out/table.md"
