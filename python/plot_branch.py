#!/usr/bin/python3
"""Plots the branch of an hbtrack result folder: for each output dof, the extremes (max and min
over a period) against omega, stable solid, unstable dashed, with the special points marked.
A thin wrapper of hbtrack.plots.nfrc_figure (`hbtrack plot DIR` makes all the figures).

    /usr/bin/python3 python/plot_branch.py RESULT_DIR [--also OTHER_DIR ...] [-o FIGURE.png]

--also overlays other branches of the same case (e.g. the isolas hbtrack isolas found). A
backbone, switch, continue or track folder among them draws the figure of `hbtrack plot DIR
DIR2 ...` instead (hbtrack.overlay_figures: one legend entry per folder); a continue folder alone,
its figure against the parameter.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack import plots  # noqa: E402
from hbtrack.analysis_figures import continuation_figure  # noqa: E402
from hbtrack.overlay_figures import overlay_figure  # noqa: E402
from hbtrack.results import read_result  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result_dir")
    parser.add_argument("-o", "--output", help="figure file (default RESULT_DIR/nfrc.png)")
    parser.add_argument("--units", default="", help="displacement unit for the axis label")
    parser.add_argument("--also", action="append", default=[], help="another result folder to overlay")
    args = parser.parse_args()

    main_result = read_result(args.result_dir)
    others = [read_result(folder) for folder in args.also]
    if main_result["kind"] == "continue" and not others:
        figure = continuation_figure(main_result, length_unit=args.units or None)
    elif any(r["kind"] not in ("frc", "solve", "isola_branch") for r in [main_result, *others]):
        figure = overlay_figure([main_result, *others], length_unit=args.units or None)
    else:
        for folder, other in zip(args.also, others):
            other["label"] = os.path.basename(os.path.normpath(folder))
        figure = plots.nfrc_figure(main_result, others=others, length_unit=args.units or None)
    out = args.output or os.path.join(args.result_dir, "nfrc.png")
    figure.savefig(out, dpi=130)
    print(out)


if __name__ == "__main__":
    main()
