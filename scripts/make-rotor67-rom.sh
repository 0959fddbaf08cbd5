#!/usr/bin/env bash
# Regenerates the shipped rotor 67 reduced model data/rotor67/ (39 dofs) from NASA's sections:
#   hbtrack make-blade --geometry data/rotor67/sections.csv -> hbtrack reduce (9 tip nodes x 3 +
#   12 fixed-interface modes), with the rotating blade's matrices about X (Kg1, Mspin, G) reduced
#   on the same basis and checked against the full model at the design speed, 1680 rad/s
# and prints the full model's first three frequencies against the paper's Table 2, the mesh
# convergence (every element count doubled), the root variants (hub section clamped; rim sectors
# of other depths) and the reduced model against the full one on the first six modes.
# Usage: bash scripts/make-rotor67-rom.sh [path/to/hbtrack]   (default: build/hbtrack)
set -euo pipefail
cd "$(dirname "$0")/.."
hbtrack=${1:-build/hbtrack}
[ -x "$hbtrack" ] || { echo "make-rotor67-rom: $hbtrack not found (build hbtrack first, or pass its path)" >&2; exit 1; }
hbtrack=$(realpath "$hbtrack")
sections=$(realpath data/rotor67/sections.csv)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The shipped model: the default rim (SectionBladeOptions), 16 x 2 x 13 airfoil elements.
"$hbtrack" make-blade --geometry "$sections" -o "$work/fe" --rotating -q
# Mesh convergence: every element count doubled.
"$hbtrack" make-blade --geometry "$sections" --refine 2 -o "$work/fe_refined" -q
# Root variants: the hub section clamped (no rim), and rims half and one and a half times as deep.
rim=$(/usr/bin/python3 -c "import json; print(json.load(open('$work/fe/summary.json'))['geometry']['rim_depth_m'])")
for depth in 0 "$(/usr/bin/python3 -c "print($rim * 0.5)")" "$(/usr/bin/python3 -c "print($rim * 1.5)")"; do
  "$hbtrack" make-blade --geometry "$sections" --rim-depth "$depth" -o "$work/fe_rim_$depth" -q
done
(cd "$work" && "$hbtrack" reduce --mass fe/M.mtx --stiffness fe/K.mtx --nodes fe/nodes.csv \
  --boundary-file fe/boundary.txt --modes 12 --axis x --rotating --check-speed 1680 -o rom -q)

mkdir -p data/rotor67
cp "$work/rom/M.mtx" "$work/rom/K.mtx" "$work/rom/Kg1.mtx" "$work/rom/Mspin.mtx" "$work/rom/G.mtx" "$work/rom/boundary_nodes.csv" \
  "$work/rom/summary.json" data/rotor67/
cp "$work/fe/summary.json" data/rotor67/full_model_summary.json

/usr/bin/python3 - "$work" "$rim" <<'PY'
import glob, json, os, sys
work, rim = sys.argv[1], float(sys.argv[2])
load = lambda p: json.load(open(os.path.join(work, p)))
fe, fine, rom = load("fe/summary.json"), load("fe_refined/summary.json"), load("rom/summary.json")
paper = fe["paper_frequencies"]
print(f"full FE model: {fe['dofs']} dofs ({fe['elements']['total']} hex20); refined: {fine['dofs']} dofs; "
      f"reduced: {rom['sizes']['reduced_dofs']} dofs; rotation sense {fe['geometry']['rotation_sense']:+d}")
print(f"{'mode':5} {'paper':>9} {'full FE':>9} {'vs paper':>9} {'refined':>9} {'change':>8}")
for r in range(3):
    f, g = fe["natural_frequencies"][r], fine["natural_frequencies"][r]
    print(f"{fe['mode_types'][r]:5} {paper[r]:9.2f} {f:9.2f} {100*(f/paper[r]-1):+8.2f}% {g:9.2f} {100*(f/g-1):+7.2f}%")
print("root variants (first three modes, rad/s):")
for path in sorted(glob.glob(os.path.join(work, "fe_rim_*", "summary.json")), key=lambda p: float(p.split("fe_rim_")[1].split("/")[0])):
    s = json.load(open(path))
    depth = s["geometry"]["rim_depth_m"]
    label = "hub section clamped" if depth == 0 else f"rim {1000*depth:.0f} mm"
    print(f"  {label:22}" + "".join(f" {t:>3} {w:9.2f}" for t, w in zip(s["mode_types"][:3], s["natural_frequencies"][:3])))
print(f"  {'rim %.0f mm (shipped)' % (1000*rim):22}" + "".join(f" {t:>3} {w:9.2f}" for t, w in zip(fe["mode_types"][:3], fe["natural_frequencies"][:3])))
print("reduced vs full, first six modes:")
for r, (w_full, err) in enumerate(zip(rom["full_model"]["natural_frequencies"], rom["full_model"]["relative_difference_of_reduced"])):
    print(f"  mode {r+1} ({fe['mode_types'][r]}): full {w_full:9.2f}  reduced {rom['natural_frequencies'][r]:9.2f}  {100*err:+.3f}%")
at = rom["rotation"]["check_at_speed"]
print(f"reduced vs full at {at['speed']:.0f} rad/s (K + W^2 (Kg1 - Mspin)), first six modes:")
for r, (w_full, err) in enumerate(zip(at["full_model_frequencies"], at["relative_difference_of_reduced"])):
    print(f"  mode {r+1}: full {w_full:9.2f}  reduced {at['reduced_frequencies'][r]:9.2f}  {100*err:+.3f}%")
PY
echo "data/rotor67/: M.mtx K.mtx Kg1.mtx Mspin.mtx G.mtx boundary_nodes.csv summary.json full_model_summary.json"
