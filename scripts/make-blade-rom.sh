#!/usr/bin/env bash
# Regenerates the shipped reduced blade data/blade/ (39 dofs) from the parametric blade:
#   hbtrack make-blade -> hbtrack reduce (9 tip nodes x 3 + 12 fixed-interface modes), with the
#   rotating blade's matrices about X (Kg1, Mspin, G) reduced on the same basis
# and prints the full model's first three frequencies against the paper's, the reduced model's,
# and the mesh convergence (shipped mesh vs every element count doubled).
# Usage: bash scripts/make-blade-rom.sh [path/to/hbtrack]   (default: build/hbtrack)
set -euo pipefail
cd "$(dirname "$0")/.."
hbtrack=${1:-build/hbtrack}
[ -x "$hbtrack" ] || { echo "make-blade-rom: $hbtrack not found (build hbtrack first, or pass its path)" >&2; exit 1; }
hbtrack=$(realpath "$hbtrack")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$hbtrack" make-blade -o "$work/fe" --rotating -q
"$hbtrack" make-blade -o "$work/fe_refined" --refine 2 -q
# Relative paths, so that the shipped summary.json names no temporary folder.
(cd "$work" && "$hbtrack" reduce --mass fe/M.mtx --stiffness fe/K.mtx --nodes fe/nodes.csv \
  --boundary-file fe/boundary.txt --modes 12 --rotating -o rom -q)

mkdir -p data/blade
cp "$work/rom/M.mtx" "$work/rom/K.mtx" "$work/rom/Kg1.mtx" "$work/rom/Mspin.mtx" "$work/rom/G.mtx" "$work/rom/boundary_nodes.csv" \
  "$work/rom/summary.json" data/blade/
# The full model's summary, with its mode names (1B, 2B, 1T), which `hbtrack modes` shows.
cp "$work/fe/summary.json" data/blade/full_model_summary.json

/usr/bin/python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
fe = json.load(open(f"{work}/fe/summary.json"))
fine = json.load(open(f"{work}/fe_refined/summary.json"))
rom = json.load(open(f"{work}/rom/summary.json"))
paper = fe["paper_frequencies"]
print(f"full FE model: {fe['dofs']} dofs; refined: {fine['dofs']} dofs; reduced: {rom['sizes']['reduced_dofs']} dofs")
print(f"{'mode':5} {'paper':>9} {'full FE':>9} {'vs paper':>9} {'refined':>9} {'change':>8} {'reduced':>9} {'vs full':>8}")
for r in range(3):
    f, g, q = fe["natural_frequencies"][r], fine["natural_frequencies"][r], rom["natural_frequencies"][r]
    label = f"{fe['mode_types'][r]}/{fine['mode_types'][r]}"
    print(f"{label:5} {paper[r]:9.2f} {f:9.2f} {100*(f/paper[r]-1):+8.2f}% {g:9.2f} {100*(f/g-1):+7.2f}% {q:9.2f} {100*(q/f-1):+7.3f}%")
PY
echo "data/blade/: M.mtx K.mtx Kg1.mtx Mspin.mtx G.mtx boundary_nodes.csv summary.json full_model_summary.json"
