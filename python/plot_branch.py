#!/usr/bin/python3
"""Plots the branch of an hbtrack result folder: for each output dof, the extremes (max and min
over a period) against omega, with the special points of summary.json marked.

    /usr/bin/python3 python/plot_branch.py RESULT_DIR [--also OTHER_DIR ...] [-o FIGURE.png]

--also overlays other branches of the same case (e.g. the isolas hbtrack isolas found).
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_branch(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no data rows")
    return {key: [float(r[key]) for r in rows] for key in rows[0]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result_dir")
    parser.add_argument("-o", "--output", help="figure file (default RESULT_DIR/nfrc.png)")
    parser.add_argument("--units", default="", help="displacement unit for the axis label")
    parser.add_argument("--also", action="append", default=[], help="another result folder to overlay")
    args = parser.parse_args()

    branch = read_branch(os.path.join(args.result_dir, "branch.csv"))
    with open(os.path.join(args.result_dir, "summary.json")) as f:
        summary = json.load(f)
    names = [o["name"] for o in summary.get("outputs", [])]
    if not names:
        sys.exit(f"{args.result_dir}: the case records no outputs")

    fig, axes = plt.subplots(len(names), 1, figsize=(6.5, 3.2 * len(names)), squeeze=False)
    unit = f" [{args.units}]" if args.units else ""
    folders = [args.result_dir] + args.also
    for ax, name in zip(axes[:, 0], names):
        for number, folder in enumerate(folders):
            if number == 0:
                data, info, colours, tag = branch, summary, ("C0", "C1"), ""
            else:
                data = read_branch(os.path.join(folder, "branch.csv"))
                with open(os.path.join(folder, "summary.json")) as f:
                    info = json.load(f)
                colours, tag = (f"C{2 * number}", f"C{2 * number + 1}"), f" ({os.path.basename(os.path.normpath(folder))})"
            stable = data.get("stable")
            for key, colour in ((f"max_{name}", colours[0]), (f"min_{name}", colours[1])):
                if stable is None:
                    ax.plot(data["omega"], data[key], color=colour, lw=1.2, label=key + tag)
                else:  # stable solid, unstable dashed
                    for flag, style in ((1.0, "-"), (0.0, "--")):
                        ys = [y if s == flag else float("nan") for y, s in zip(data[key], stable)]
                        ax.plot(data["omega"], ys, style, color=colour, lw=1.2, label=key + tag if flag else None)
            for sp in info.get("special_points", []):
                for key in (f"max_{name}", f"min_{name}"):
                    if key in sp:
                        ax.plot(sp["omega"], sp[key], "o", color="k", ms=4)
                        ax.annotate(sp["type"], (sp["omega"], sp[key]), textcoords="offset points", xytext=(4, 4), fontsize=8)
        ax.set_xlabel(r"$\omega$ [rad/s]")
        ax.set_ylabel(f"{name}{unit}")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    out = args.output or os.path.join(args.result_dir, "nfrc.png")
    fig.savefig(out, dpi=130)
    print(out)


if __name__ == "__main__":
    main()
