#!/usr/bin/env bash
# Craig-Bampton reduction (`hbtrack reduce`) against CalculiX's own frequency step on the same
# mesh: the parametric blade refined R times (dofs grow like R^3), written as a CalculiX deck by
# `make-blade --calculix`. For each R: ccx writes the matrices (matrix storage step), hbtrack
# reduces them onto the 9 tip nodes + 12 fixed-interface modes, and ccx solves the 12 lowest modes
# of the same deck (*FREQUENCY, its default solver). CPU time (user + system: the machine is
# shared, and both run on one thread: OMP_NUM_THREADS=1) and peak memory (GNU time) per run.
# Usage: bash bench/cb_vs_calculix.sh [BUILD_DIR] [R ...]   (default: build, R = 1 2 3)
set -euo pipefail
build=${1:-build}
shift || true
refinements=("$@")
[ ${#refinements[@]} -eq 0 ] && refinements=(1 2 3)
hbtrack=$(realpath "$build/hbtrack")
command -v ccx > /dev/null || { echo "cb_vs_calculix: ccx (calculix-ccx) is not installed" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 CCX_NPROC_STIFFNESS=1 CCX_NPROC_EQUATION_SOLVER=1
measure() {  # measure LOG COMMAND...: runs it, prints "cpu_s peak_MB" from GNU time
  /usr/bin/time -f "%U %S %M" -o "$1.time" "${@:2}" > "$1" 2>&1
  awk '{printf "%.2f %.0f", $1 + $2, $3 / 1024}' "$1.time"
}
echo "| R | dofs | ccx matrices, CPU [s] | reduce, CPU [s] | reduce peak [MB] | ccx frequency step (12 modes), CPU [s] | its peak [MB] | reduce / ccx frequency (CPU) |"
echo "|---|---|---|---|---|---|---|---|"
for r in "${refinements[@]}"; do
  dir="$work/R$r"
  "$hbtrack" make-blade --refine "$r" --calculix -q -o "$dir"
  dofs=$(/usr/bin/python3 -c "import json; print(json.load(open('$dir/summary.json'))['dofs'])")
  read -r matrices_s _ <<< "$(cd "$dir" && measure "$dir/ccx_matrices.log" ccx blade)"
  read -r reduce_s reduce_mb <<< "$(measure "$dir/reduce.log" "$hbtrack" reduce --calculix "$dir/blade" --boundary-file "$dir/boundary.txt" \
    --modes 12 --compare 0 -q -o "$dir/rom")"
  sed 's/^\*FREQUENCY, SOLVER=MATRIXSTORAGE$/*FREQUENCY\n12/' "$dir/blade.inp" > "$dir/modes.inp"
  read -r modes_s modes_mb <<< "$(cd "$dir" && measure "$dir/ccx_modes.log" ccx modes)"
  ratio=$(/usr/bin/python3 -c "print(f'{$reduce_s / $modes_s:.2f}' if $modes_s > 0 else 'nan')")
  echo "| $r | $dofs | $matrices_s | $reduce_s | $reduce_mb | $modes_s | $modes_mb | $ratio |"
done
