#!/usr/bin/env bash
# Rotor 67's nominal NFRC with harmonics chosen as the run goes (harmonic_balance.adaptive,
# docs/analyses.md) against the fixed H = 15, N = 2048 of the study's convergence step: the limit
# points side by side, the unknowns per point and the times, as a Markdown table; and the figure
# docs/figures/rotor67_adaptive_harmonics.png (the NFRC, and H along omega).
#
#   bash scripts/rotor67-adaptive-harmonics.sh HBTRACK OUT_DIR [FIGURE]
#
# HBTRACK: the tool (build/hbtrack). Both runs use one BLAS thread, one after the other; not part
# of CI (about 15 minutes on 2 cores); say what else was running when quoting the times.
set -euo pipefail
cd "$(dirname "$0")/.."
hbtrack=$(realpath "$1")
out=$2
figure=${3:-}
case=examples/rotor67/nominal.toml
adaptive="{min = 3, max = 15, add_above = 1e-4, drop_below = 1e-6}"
mkdir -p "$out"
export OPENBLAS_NUM_THREADS=1
if [ ! -f "$out/fixed/summary.json" ]; then
  /usr/bin/time -f "%U %S %e" -o "$out/fixed.time" "$hbtrack" frc "$case" -q -o "$out/fixed" \
    --set harmonic_balance.harmonics=15 --set harmonic_balance.samples=2048
fi
if [ ! -f "$out/adaptive/summary.json" ]; then
  /usr/bin/time -f "%U %S %e" -o "$out/adaptive.time" "$hbtrack" frc "$case" -q -o "$out/adaptive" \
    --set harmonic_balance.harmonics=3 --set harmonic_balance.samples=2048 --set "harmonic_balance.adaptive=$adaptive"
fi
/usr/bin/python3 - "$out" "$figure" << 'EOF'
import json
import sys

import numpy as np

out, figure = sys.argv[1], sys.argv[2]
runs = {name: json.load(open(f"{out}/{name}/summary.json")) for name in ("fixed", "adaptive")}
times = {name: [float(t) for t in open(f"{out}/{name}.time").read().split()[-3:]] for name in runs}
lps = {name: [p for p in s["special_points"] if p["type"] == "LP"] for name, s in runs.items()}
print("| LP | fixed H = 15 (rad/s) | adaptive (rad/s) | H there | relative difference |")
print("|---|---|---|---|---|")
for i, (f, a) in enumerate(zip(lps["fixed"], lps["adaptive"])):
    print(f"| {i + 1} | {f['omega']:.6f} | {a['omega']:.6f} | {a.get('harmonics', '')} | {abs(a['omega'] - f['omega']) / f['omega']:.2e} |")
if len(lps["fixed"]) != len(lps["adaptive"]):
    print(f"\nLP counts differ: fixed {len(lps['fixed'])}, adaptive {len(lps['adaptive'])}")
branch = np.genfromtxt(f"{out}/adaptive/branch.csv", delimiter=",", names=True)
h = branch["harmonics"]
q = len(runs["adaptive"]["options"]["harmonic_balance"]["retained_dofs"])
unknowns = q * (2 * h + 1)
fixed_unknowns = runs["fixed"]["options"]["harmonic_balance"]["unknowns"]
print()
print("| run | points | unknowns per point min / max / mean | H min / max / mean | changes of H | CPU user + sys (s) | wall (s) |")
print("|---|---|---|---|---|---|---|")
for name, s in runs.items():
    cpu = times[name][0] + times[name][1]
    if name == "fixed":
        per_point, hs, changes = f"{fixed_unknowns} / {fixed_unknowns} / {fixed_unknowns}", "15 / 15 / 15", 0
    else:
        per_point = f"{unknowns.min():.0f} / {unknowns.max():.0f} / {unknowns.mean():.0f}"
        hs, changes = f"{h.min():.0f} / {h.max():.0f} / {h.mean():.1f}", s["adaptive_harmonics"]["changes"]
    print(f"| {name} | {s['points']} | {per_point} | {hs} | {changes} | {cpu:.0f} | {times[name][2]:.0f} |")
if figure:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fixed = np.genfromtxt(f"{out}/fixed/branch.csv", delimiter=",", names=True)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), gridspec_kw={"height_ratios": [2, 1]})
    top.plot(fixed["omega"], -1e3 * fixed["min_le"], color="0.7", lw=4, label="fixed H = 15")
    # The adaptive branch: solid where stable, dashed where not (Hill's method at each point's H).
    stable = branch["stable"] > 0.5
    for flag, style, name in ((True, "-", "adaptive H, stable"), (False, "--", "adaptive H, unstable")):
        y = np.where(stable == flag, -1e3 * branch["min_le"], np.nan)
        top.plot(branch["omega"], y, style, color="C0", lw=1.2, label=name)
    marks = {"LP": ("o", "C3"), "NS": ("x", "C2")}
    for kind, (marker, color) in marks.items():
        points = [p for p in runs["adaptive"]["special_points"] if p["type"] == kind]
        top.plot([p["omega"] for p in points], [-1e3 * p["min_le"] for p in points], marker, mfc="none", color=color, ls="none",
                 label=f"{kind} ({len(points)})")
    top.set_ylabel("leading-edge tip, radial,\ninward extreme (mm)")
    top.legend(loc="upper right", fontsize=8)
    top.set_title("Rotor 67, nominal NFRC: harmonics chosen as the run goes")
    bottom.plot(branch["omega"], h, color="C0", lw=1.2)
    bottom.set_ylabel("H at the point")
    bottom.set_xlabel("omega (rad/s)")
    bottom.set_ylim(0, 16)
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figure, dpi=120)
EOF
