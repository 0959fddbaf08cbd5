#!/usr/bin/env bash
# The README's sweep figures ("Parameter sweeps (MPI)"): parallel efficiency of a 32-task blade
# sweep on 1 and 2 MPI processes, and the runner's overhead per task on 32 Duffing NFRCs that
# take milliseconds each. Prints a Markdown table. Needs a build with MPI (build/ or $BUILD).
#   bash scripts/bench-sweep.sh            (about 15 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
hbtrack=${BUILD:-build}/hbtrack
out=${OUT:-out/bench-sweep}
rm -rf "$out" && mkdir -p "$out"
# Root in containers: Open MPI refuses it unless told; no single-copy shared memory there.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none

# name, slots, then the command; prints wall time, the tasks' own time (sum of their
# summary.json wall_s) and the overhead per task: (slots x wall - tasks' time) / tasks.
run() {
  local name=$1 slots=$2
  shift 2
  local start end
  start=$(date +%s.%N)
  "$@" -q -o "$out/$name"
  end=$(date +%s.%N)
  /usr/bin/python3 - "$out/$name" "$name" "$slots" "$start" "$end" <<'PY'
import glob, json, sys
folder, name, slots, start, end = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
own = [json.load(open(f))["timings"]["wall_s"] for f in glob.glob(f"{folder}/tasks/*/summary.json")]
wall = end - start
print(f"| {name} | {len(own)} | {slots} | {wall:.2f} | {sum(own):.2f} | {1000 * (slots * wall - sum(own)) / len(own):.1f} |")
PY
}

blade=(sweep examples/blade/sweep.toml --param clearance --values 1e-4:4.5e-4:count=8 --param mu --values 0.02,0.1,0.18,0.26)
duffing=(sweep examples/duffing.toml --param amplitude --values 0.5:1.5:count=32)
echo "| run | tasks | processes | wall [s] | tasks' own time [s] | overhead per task [ms] |"
echo "|---|---|---|---|---|---|"
run blade_mpi1 1 mpirun -n 1 "$hbtrack" "${blade[@]}"
run blade_mpi2 2 mpirun -n 2 "$hbtrack" "${blade[@]}"
run duffing_jobs1 1 "$hbtrack" "${duffing[@]}" --jobs 1
run duffing_jobs2 2 "$hbtrack" "${duffing[@]}" --jobs 2
run duffing_mpi1 1 mpirun -n 1 "$hbtrack" "${duffing[@]}"
run duffing_mpi2 2 mpirun -n 2 "$hbtrack" "${duffing[@]}"
cmp -s "$out/blade_mpi1/sweep.csv" "$out/blade_mpi2/sweep.csv" && echo "blade: the same sweep.csv on 1 and 2 processes"
