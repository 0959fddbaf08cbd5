#!/usr/bin/env bash
# Issue 34's NFRC targets, measured in one run on one core: the blade and rotor 67 (both friction
# senses) with stability sampled (the default), with Hill at every point, and without stability;
# NLvib's two-dof contact example (at NLvib's settings, H = 21, N = 1024) and the 8-mass contact
# chain with their defaults (Hill cross-checked by shooting at every point) and without stability.
# Prints a Markdown table from each run's summary.json (points, corrector iterations, dense LUs
# per point, Hill evaluations, wall time, Hill's time and its ratio to the continuation's).
#
#   bash bench/nfrc_targets.sh [HBTRACK [CASE...]]   (default build/hbtrack, every case below)
#
# Not part of CI. Run it with nothing else on the machine (a build on the other core inflates
# the times 3-10x) and say what else was running.
set -euo pipefail
cd "$(dirname "$0")/.."
hbtrack=$(realpath "${1:-build/hbtrack}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
reversed=()
for k in 0 1 2 3 4 5 6 7 8; do reversed+=(--set "elements[$k].engine_order=1"); done
run() {  # run NAME CASE [ARGS...]
  local name=$1 case=$2
  shift 2
  OPENBLAS_NUM_THREADS=1 taskset -c 1 "$hbtrack" frc "$case" -o "$work/$name" -q "$@" 2> /dev/null || true
}
echo "| case | stability | points | iterations | LUs / point | Floquet at | wall [s] | stability [s] | stability / continuation |"
echo "|---|---|---|---|---|---|---|---|---|"
cases=(blade rotor67 rotor67_reversed nlvib_two_dof_contact chain_contact)
[ $# -gt 1 ] && cases=("${@:2}")
for c in "${cases[@]}"; do
  case_file=examples/${c%_reversed}/nominal.toml
  modes=(sampled every none)
  [ -f "examples/$c.toml" ] && case_file=examples/$c.toml modes=(sampled none)  # small: every point anyway
  extra=()
  [ "$c" = rotor67_reversed ] && extra=("${reversed[@]}")
  run "$c-sampled" "$case_file" "${extra[@]}"
  [ "${#modes[@]}" = 3 ] && run "$c-every" "$case_file" "${extra[@]}" --set stability.every_point=true
  run "$c-none" "$case_file" "${extra[@]}" --set 'stability.method="none"'
  for mode in "${modes[@]}"; do
    /usr/bin/python3 - "$work/$c-$mode/summary.json" "$c" "$mode" << 'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timings"]
hill = s.get("stability_methods", {}).get("points", {})
evaluated = sum(v for k, v in hill.items() if k != "bracketed")
continuation = t["wall_s"] - t["stability_s"]
ratio = f"{t['stability_s'] / continuation:.2f}" if t["stability_s"] > 0 else "-"
print(f"| {sys.argv[2]} | {sys.argv[3]} | {s['points']} | {s['newton_iterations']} | {s['factorizations'] / s['points']:.2f} | "
      f"{evaluated if hill else '-'} | {t['wall_s']:.2f} | {t['stability_s']:.2f} | {ratio} |")
PY
  done
done
