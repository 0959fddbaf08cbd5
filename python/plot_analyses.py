#!/usr/bin/python3
"""Figures of the analyses beside the NFRC (docs/analyses.md), from their result folders.

    /usr/bin/python3 python/plot_analyses.py continue DIR [-o FIG.png]
        the first output's max against the parameter, stable solid, unstable dashed, LPs marked
    /usr/bin/python3 python/plot_analyses.py backbone DIR [--frc FRC_DIR ...] [-o FIG.png]
        omega against the modal amplitude (with the h1 of NFRCs overlaid) and the modal damping
        ratio against the amplitude
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("kind", choices=["continue", "backbone"])
    parser.add_argument("result_dir")
    parser.add_argument("--frc", action="append", default=[], help="an NFRC folder to overlay on a backbone")
    parser.add_argument("-o", "--output", help="figure file (default RESULT_DIR/KIND.png)")
    args = parser.parse_args()
    figure = continue_figure(args.result_dir) if args.kind == "continue" else backbone_figure(args.result_dir, args.frc)
    out = args.output or os.path.join(args.result_dir, args.kind + ".png")
    figure.savefig(out, dpi=130)
    print(out)


if __name__ == "__main__":
    main()
