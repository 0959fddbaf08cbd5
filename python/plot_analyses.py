#!/usr/bin/python3
"""Figures of the analyses beside the NFRC (docs/analyses.md), from their result folders.

    /usr/bin/python3 python/plot_analyses.py continue DIR [-o FIG.png]
        the first output's max against the parameter, stable solid, unstable dashed, LPs marked
    /usr/bin/python3 python/plot_analyses.py backbone DIR [--frc FRC_DIR ...] [-o FIG.png]
        omega against the modal amplitude (with the h1 of NFRCs overlaid) and the modal damping
        ratio against the amplitude
    /usr/bin/python3 python/plot_analyses.py period-doubled DIR --frc FRC_DIR [-o FIG.png]
        a period-doubled branch (switch at a PD) over its NFRC near the band: the output with the
        largest omega/2 harmonic, its max against omega, and that harmonic against omega
"""
import argparse
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, values = rows[0], np.array([[float(v) for v in r] for r in rows[1:] if r])
    return {name: values[:, i] for i, name in enumerate(header)}


def first_output(summary):
    outputs = summary.get("outputs", [])
    if not outputs:
        raise SystemExit("the result has no outputs to plot")
    return outputs[0]["name"]


def plot_segments(ax, x, y, stable, **style):
    """Stable runs solid, unstable dashed (stable = None: all solid)."""
    if stable is None:
        ax.plot(x, y, "-", **style)
        return
    start = 0
    for i in range(1, len(x) + 1):
        if i == len(x) or stable[i] != stable[start]:
            end = min(i + 1, len(x))
            ax.plot(x[start:end], y[start:end], "-" if stable[start] else "--", **style)
            start = i


def continue_figure(folder):
    summary = json.load(open(os.path.join(folder, "summary.json")))
    branch = read_columns(os.path.join(folder, "branch.csv"))
    name, param = first_output(summary), summary["options"]["continue"]["parameter"]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    plot_segments(ax, branch[param], branch["max_" + name], branch.get("stable"), color="C0")
    for sp in summary["special_points"]:
        ax.plot(sp[param], sp["max_" + name], "o" if sp["type"] == "LP" else "s", color="C3")
        ax.annotate(sp["type"], (sp[param], sp["max_" + name]), textcoords="offset points", xytext=(5, -12))
    ax.set_xlabel(param)
    ax.set_ylabel(f"max {name}")
    ax.set_title(f"continuation in {param} at omega = {summary['options']['continue']['omega']:g} (dashed: unstable)")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    return fig


def backbone_figure(folder, frc_folders):
    summary = json.load(open(os.path.join(folder, "summary.json")))
    branch = read_columns(os.path.join(folder, "branch.csv"))
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    left.plot(branch["omega"], branch["amplitude"], "k-", lw=2, label="backbone (EPMC)")
    for other in frc_folders:
        frc = read_columns(os.path.join(other, "branch.csv"))
        name = first_output(json.load(open(os.path.join(other, "summary.json"))))
        plot_segments(left, frc["omega"], frc["h1_" + name], frc.get("stable"), color="C0", lw=1)
    left.set_xlabel("omega (rad/s)")
    left.set_ylabel("modal amplitude a (NFRCs: first harmonic)")
    left.set_title(f"mode {summary['options']['backbone']['mode']}: backbone" + (" and NFRCs" if frc_folders else ""))
    left.grid(alpha=0.3)
    left.legend(loc="upper left")
    right.semilogx(branch["amplitude"], 100 * branch["damping_ratio"], "C3-")
    right.set_xlabel("modal amplitude a")
    right.set_ylabel("modal damping ratio (%)")
    right.set_title("amplitude-dependent damping")
    right.grid(alpha=0.3, which="both")
    fig.tight_layout()
    return fig


def period_doubled_figure(folder, frc_folders):
    summary = json.load(open(os.path.join(folder, "summary.json")))
    branch = read_columns(os.path.join(folder, "branch.csv"))
    names = [o["name"] for o in summary["outputs"]]
    name = max(names, key=lambda n: branch["h0.5_" + n].max())  # the most period-doubled output
    lo, hi = branch["omega"].min(), branch["omega"].max()
    margin = 0.6 * (hi - lo)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for other in frc_folders:
        frc = read_columns(os.path.join(other, "branch.csv"))
        near = (frc["omega"] > lo - margin) & (frc["omega"] < hi + margin) & (np.abs(frc["max_" + name] - branch["max_" + name].mean()) < 0.2)
        plot_segments(left, frc["omega"][near], frc["max_" + name][near], frc.get("stable")[near] if "stable" in frc else None,
                      color="C0", lw=1)
        right.plot(frc["omega"][near], 0 * frc["omega"][near], "C0-", lw=1, label="period T (NFRC)")
    plot_segments(left, branch["omega"], branch["max_" + name], branch.get("stable"), color="C3", lw=2)
    plot_segments(right, branch["omega"], branch["h0.5_" + name], branch.get("stable"), color="C3", lw=2)
    right.plot([], [], "C3-", lw=2, label="period 2T (switch at the PD)")
    left.set_xlabel("omega (rad/s)")
    left.set_ylabel(f"max {name} over the period")
    left.set_title("NFRC (blue, dashed: unstable) and period-doubled branch (red)", fontsize=10)
    right.set_xlabel("omega (rad/s)")
    right.set_ylabel(f"|harmonic omega/2| of {name}")
    right.set_title("the period-2T part of the motion", fontsize=10)
    right.legend(loc="upper right", fontsize=8)
    for ax in (left, right):
        ax.set_xlim(lo - margin, hi + margin)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("kind", choices=["continue", "backbone", "period-doubled"])
    parser.add_argument("result_dir")
    parser.add_argument("--frc", action="append", default=[], help="an NFRC folder to overlay (backbone, period-doubled)")
    parser.add_argument("-o", "--output", help="figure file (default RESULT_DIR/KIND.png)")
    args = parser.parse_args()
    if args.kind == "continue":
        figure = continue_figure(args.result_dir)
    elif args.kind == "backbone":
        figure = backbone_figure(args.result_dir, args.frc)
    else:
        figure = period_doubled_figure(args.result_dir, args.frc)
    out = args.output or os.path.join(args.result_dir, args.kind + ".png")
    figure.savefig(out, dpi=130)
    print(out)


if __name__ == "__main__":
    main()
