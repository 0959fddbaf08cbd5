#!/usr/bin/env bash
# The main job: builds hbtrack, then the paper's study of NASA rotor 67 (data/rotor67, built from
# NASA's sections by scripts/make-rotor67-rom.sh) with `hbtrack study`, side by side with the
# paper's numbers; the study of the small parametric blade (data/blade); and the small examples
# (NFRCs, Duffing limit points tracked to their cusp, isolas search) with figures, into results/.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j "$(nproc)"
hbtrack=./build/hbtrack
mkdir -p results

# Rotor 67 (the [study] section of its case): nominal NFRC with stability, every limit point
# tracked in amplitude, friction coefficient and clearance, validation NFRCs (the paper's values
# and next to every extremum), isolas, time integration, the events at H = 15 and N = 2048,
# figures and results/rotor67_study/index.md; then the same NFRC with the friction sense reversed
# and the page against the paper, results/rotor67_study/paper_comparison.md.
$hbtrack modes examples/rotor67/nominal.toml --count 6 -o results/rotor67_modes
# A study whose own checks fail (a validation NFRC that leaves the range, a limit point on no
# tracking curve) exits 1 and says so first on its page: the main job goes on to show it.
$hbtrack study examples/rotor67/nominal.toml --units m -o results/rotor67_study || echo "rotor 67 study: exit $? (see results/rotor67_study/index.md)"
reversed=()
for k in 0 1 2 3 4 5 6 7 8; do reversed+=(--set "elements[$k].engine_order=1"); done
$hbtrack frc examples/rotor67/nominal.toml "${reversed[@]}" -o results/rotor67_reversed_nfrc
/usr/bin/python3 python/compare_with_paper.py results/rotor67_study --paper data/rotor67/paper_values.json \
  --model data/rotor67/summary.json --reversed results/rotor67_reversed_nfrc
# The reversed sense tracked in the amplitude, for the paper's Tables 3-4 (no convergence check).
$hbtrack study examples/rotor67/nominal.toml --only amplitude "${reversed[@]}" --set study.convergence.harmonics=0 --units m \
  -o results/rotor67_reversed_study || echo "rotor 67 reversed-sense study: exit $?"
/usr/bin/python3 python/compare_with_paper.py results/rotor67_reversed_study --paper data/rotor67/paper_values.json \
  --model data/rotor67/summary.json --label 'friction sense reversed'

# The parametric blade: the same study on a small, fast model.
$hbtrack modes examples/blade/nominal.toml --count 6 -o results/blade_modes
$hbtrack study examples/blade/nominal.toml --units m -o results/blade_study || echo "blade study: exit $? (see results/blade_study/index.md)"

# The small examples.
for example in duffing two_dof_contact coupled_duffing chain_contact nltva; do
  $hbtrack frc "examples/$example.toml" -o "results/$example"
  $hbtrack plot "results/$example"
done
for lp in 1 2; do
  $hbtrack track examples/duffing.toml --from results/duffing --lp $lp --param amplitude --range 0.1:2 -o "results/duffing_track_lp$lp"
done
/usr/bin/python3 python/plot_tracking.py results/duffing_track_lp1 results/duffing_track_lp2 -o results/duffing_tracking.png
$hbtrack isolas examples/duffing.toml --from results/duffing_track_lp1 --from results/duffing_track_lp2 --at 1.5 -o results/duffing_isolas
# The absorber's isola: born and merging on the tracking curve, computed at A = 0.15.
$hbtrack track examples/nltva.toml --from results/nltva --lp 1 --param amplitude --range 0.01:0.4 -o results/nltva_track
/usr/bin/python3 python/plot_tracking.py results/nltva_track -o results/nltva_tracking.png
$hbtrack frc examples/nltva.toml --set amplitude=0.15 -o results/nltva_A0.15
$hbtrack isolas examples/nltva.toml --from results/nltva_track --at 0.15 -o results/nltva_isolas
/usr/bin/python3 python/plot_branch.py results/nltva_A0.15 --also results/nltva_isolas/isola_1 -o results/nltva_isola.png
for folder in results/duffing_track_lp1 results/duffing_track_lp2 results/duffing_isolas results/nltva_track results/nltva_isolas; do
  $hbtrack plot "$folder"
done
echo "rotor 67 study: results/rotor67_study/index.md and paper_comparison.md (figures in results/rotor67_study/figures/)"
echo "blade study: results/blade_study/index.md (figures in results/blade_study/figures/)"
echo "examples: results/*/nfrc.png, results/*tracking.png, results/nltva_isola.png"
