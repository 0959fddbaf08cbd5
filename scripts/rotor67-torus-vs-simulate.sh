#!/usr/bin/env bash
# Rotor 67's quasi-periodic response against time integration (docs/analyses.md, "Rotor 67's
# band"): the NFRC without the Lanczos filter (a torus takes none) at H = 10 and H = 20, the torus
# from NS 1 at H1 = 10 and 20 (H2 = 3, N = 256 x 16) ending on each simulated omega, `simulate`
# there from the unstable contact branch (1600 periods, the last 400 recorded), and the table of
# python/compare_torus.py (extremes, omega2, lines at half of omega2).
#
#   bash scripts/rotor67-torus-vs-simulate.sh HBTRACK OUT_DIR [geometry|reversed]
#
# HBTRACK: the tool (build/hbtrack). Runs are skipped when their folder holds a summary.json, so
# a stopped script resumes. The range's low end is the page's (the continuation's steps are
# scaled by the range). Not part of CI: about 2 hours on 2 cores (a torus at H1 = 20 has 7749
# unknowns, a dense LU of that order per Newton step, 3.1 GB).
set -euo pipefail
cd "$(dirname "$0")/.."
hbtrack=$(realpath "$1")
out=$2
sense=${3:-geometry}
case=examples/rotor67/nominal.toml
flags=()
for k in 0 1 2 3 4 5 6 7 8; do
  flags+=(--set "elements[$k].lanczos=0")
  if [ "$sense" = reversed ]; then flags+=(--set "elements[$k].engine_order=1"); fi
done
case "$sense" in
  # OMEGA:POINT: where to simulate (H1 = 10 torus rows; for the reversed sense NFRC points) and
  # the H = 10 NFRC's point of the band simulate starts from (an unstable periodic orbit near it).
  geometry) runs=(2094.501684496404:269 2097.2551453724691:274 2099.673992158529:276 2119.9514021707846:284) lo=2080 ;;
  reversed) runs=(2410.6047112544134:50 2412.454000134486:51) lo=2400 ;;
  *) echo "rotor67-torus-vs-simulate.sh: sense: must be geometry or reversed, got $sense" >&2; exit 2 ;;
esac
mkdir -p "$out"
export OPENBLAS_NUM_THREADS=1
run() {  # run FOLDER ARGS...: hbtrack ARGS -o FOLDER unless FOLDER holds a result
  local folder=$1
  shift
  [ -f "$folder/summary.json" ] || "$hbtrack" "$@" "${flags[@]}" -q -o "$folder" || [ -f "$folder/summary.json" ]
}
for h in 10 20; do
  run "$out/nfrc_h$h" frc "$case" --set harmonic_balance.harmonics=$h
done
for run_at in "${runs[@]}"; do
  omega=${run_at%%:*}
  point=${run_at##*:}
  # simulate exits 1 on a quasi-periodic record (no periodic steady state): run() accepts it.
  run "$out/sim_$omega" simulate "$case" --from "$out/nfrc_h10" --point "$point" --omega "$omega" \
    --element-steps 32 --max-periods 1600 --record-periods 400
  for h in 10 20; do
    run "$out/torus_h${h}_$omega" torus "$case" --set harmonic_balance.harmonics=$h --from "$out/nfrc_h$h" --ns 1 \
      --range "$lo:$omega" --harmonics "$h,3" --samples 256,16
  done
done
for h in 10 20; do
  echo "H1 = $h:"
  for run_at in "${runs[@]}"; do
    omega=${run_at%%:*}
    /usr/bin/python3 python/compare_torus.py "$out/torus_h${h}_$omega" "$out/sim_$omega"; done
done
