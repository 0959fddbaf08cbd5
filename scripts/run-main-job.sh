#!/usr/bin/env bash
# The main job: builds hbtrack, then the study of the shipped blade (data/blade, reduced from the
# parametric blade by scripts/make-blade-rom.sh) with `hbtrack study`, and the same chain on the
# small examples (NFRCs, Duffing limit points tracked to their cusp, isolas search) with figures,
# into results/, and the isola of the nonlinear absorber example.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j "$(nproc)"
hbtrack=./build/hbtrack
mkdir -p results

# The blade study (the [study] section of its case): nominal NFRC with stability, every limit
# point tracked in amplitude, friction coefficient and clearance, validation NFRCs, isolas,
# a time-integration check, figures and results/blade_study/index.md.
$hbtrack modes examples/blade/nominal.toml --count 6 -o results/blade_modes
$hbtrack study examples/blade/nominal.toml --units m -o results/blade_study

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
echo "blade study: results/blade_study/index.md (figures in results/blade_study/figures/)"
echo "examples: results/*/nfrc.png, results/*tracking.png, results/nltva_isola.png"
