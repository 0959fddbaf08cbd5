#!/usr/bin/python3
"""Plots limit-point tracking curves of hbtrack track result folders in the (omega, parameter)
plane, with the located extrema of the parameter (min: a pair of limit points is born, max: a
pair disappears) marked.

    /usr/bin/python3 python/plot_tracking.py TRACK_DIR [TRACK_DIR ...] -o FIGURE.png
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_curve(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    tracking = summary.get("options", {}).get("tracking")
    if not tracking:
        sys.exit(f"{folder}/summary.json: not a track result (options.tracking missing)")
    name = tracking["parameter"]
    with open(os.path.join(folder, "branch.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{folder}/branch.csv: no data rows")
    # Leg 1 runs from the start towards the range's low end, leg 2 towards the high end: the
    # curve in order is leg 1 reversed, then leg 2.
    leg1 = [r for r in rows if r["leg"] == "1"][::-1]
    leg2 = [r for r in rows if r["leg"] == "2"]
    ordered = leg1 + leg2
    omega = [float(r["omega"]) for r in ordered]
    gamma = [float(r[name]) for r in ordered]
    return name, omega, gamma, summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("-o", "--output", required=True, help="figure file")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    names = set()
    for i, folder in enumerate(args.folders):
        name, omega, gamma, summary = read_curve(folder)
        names.add(name)
        lp = summary["options"]["tracking"]["lp"]
        ax.plot(omega, gamma, color=f"C{i}", lw=1.3, label=f"LP {lp} of {os.path.basename(os.path.normpath(folder))}")
        ax.plot([summary["start"]["omega"]], [summary["start"][name]], "o", color=f"C{i}", ms=5)
        for sp in summary.get("special_points", []):
            marker = "v" if sp["type"] == "min" else "^"
            ax.plot([sp["omega"]], [sp[name]], marker, color="k", ms=7)
            ax.annotate(f"{sp['type']} ({sp['omega']:.6g}, {sp[name]:.4g})", (sp["omega"], sp[name]),
                        textcoords="offset points", xytext=(6, 4), fontsize=8)
    if len(names) != 1:
        sys.exit("the folders track different parameters: " + ", ".join(sorted(names)))
    ax.set_xlabel("omega [rad/s]")
    ax.set_ylabel(names.pop())
    ax.set_title(args.title or "limit-point tracking (o: start, v: min, ^: max)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(args.output)


if __name__ == "__main__":
    main()
