#!/usr/bin/python3
"""Plots the branch of an hbtrack result folder: for each output dof, the extremes (max and min
over a period) against omega, stable solid, unstable dashed, with the special points marked.
A thin wrapper of hbtrack.branch_figures.nfrc_figure (`hbtrack plot DIR` makes all the figures).

    /usr/bin/python3 python/plot_branch.py RESULT_DIR [--also OTHER_DIR ...] [-o FIGURE.png]
        [--units mm] [--norm] [--no-zoom] [--title TEXT] [--label NAME=TEXT]

--also overlays other branches of the same case (e.g. the isolas hbtrack isolas found). A
backbone, switch, continue or track folder among them draws the figure of `hbtrack plot DIR
DIR2 ...` instead (hbtrack.overlay_figures: one legend entry per folder); a continue folder alone,
its figure against the parameter.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack import branch_figures  # noqa: E402
from hbtrack.analysis_figures import continuation_figure  # noqa: E402
from hbtrack.overlay_figures import overlay_figure  # noqa: E402
from hbtrack.output_descriptions import parse_labels  # noqa: E402
from hbtrack.results import read_result  # noqa: E402
from hbtrack.units import length_factor, scale_lengths  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result_dir")
    parser.add_argument("-o", "--output", help="figure file (default RESULT_DIR/nfrc.png)")
    parser.add_argument("--units", default="", help="length unit of the figure: m, cm, mm, um, nm, in convert from --model-units; "
                                                    "any other text only labels")
    parser.add_argument("--model-units", default="m", help="the unit of the model's lengths (default m)")
    parser.add_argument("--also", action="append", default=[], help="another result folder to overlay")
    parser.add_argument("--norm", action="store_true", help="||r(t)||_inf = max(|max|, |min|) of every output in one axes")
    parser.add_argument("--no-zoom", action="store_true", help="the whole branch, not zoomed on the resonance")
    parser.add_argument("--title", help="a title (default none)")
    parser.add_argument("--label", action="append", default=[], metavar="NAME=TEXT", help="describe output NAME")
    args = parser.parse_args()

    factor = length_factor(args.units, args.model_units)
    main_result = scale_lengths(read_result(args.result_dir), factor)
    others = [scale_lengths(read_result(folder), factor) for folder in args.also]
    if main_result["kind"] == "continue" and not others:
        figure = continuation_figure(main_result, length_unit=args.units or None)
    elif any(r["kind"] not in ("frc", "solve", "isola_branch") for r in [main_result, *others]):
        figure = overlay_figure([main_result, *others], length_unit=args.units or None)
    else:
        for folder, other in zip(args.also, others):
            other["label"] = os.path.basename(os.path.normpath(folder))
        if others:  # the main branch named as the others are, by its folder
            main_result.setdefault("label", os.path.basename(os.path.normpath(args.result_dir)))
        figure = branch_figures.nfrc_figure(main_result, others=others, length_unit=args.units or None, title=args.title,
                                            zoom=None if args.no_zoom else branch_figures.ZOOM_FRACTION, norm=args.norm,
                                            descriptions=parse_labels(args.label))
    out = args.output or os.path.join(args.result_dir, "nfrc.png")
    figure.savefig(out, dpi=130)
    print(out)


if __name__ == "__main__":
    main()
