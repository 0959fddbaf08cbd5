#!/usr/bin/python3
"""Figures of the analyses beside the NFRC (docs/analyses.md), from their result folders. A thin
wrapper of hbtrack.analysis_figures and hbtrack.overlay_figures (`hbtrack plot DIR [DIR2 ...]`
makes the same figures and more).

    /usr/bin/python3 python/plot_analyses.py continue DIR [-o FIG.png]
        the outputs' max and min against the parameter, stable solid, unstable dashed, LPs marked
    /usr/bin/python3 python/plot_analyses.py backbone DIR [--frc FRC_DIR ...] [-o FIG.png]
        without --frc: omega and the modal damping ratio against the modal amplitude; with it:
        the backbone over the NFRCs (max and min of the outputs against omega)
    /usr/bin/python3 python/plot_analyses.py period-doubled DIR --frc FRC_DIR [-o FIG.png]
        a period-doubled branch (switch at a PD) over its NFRC, zoomed on the band, and its
        omega/2 harmonic against omega
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack import analysis_figures  # noqa: E402
from hbtrack.overlay_figures import overlay_figure  # noqa: E402
from hbtrack.results import read_result  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("kind", choices=["continue", "backbone", "period-doubled"])
    parser.add_argument("result_dir")
    parser.add_argument("--frc", action="append", default=[], help="an NFRC folder to overlay (backbone, period-doubled)")
    parser.add_argument("--units", default=None, help="the model's length unit for the labels")
    parser.add_argument("-o", "--output", help="figure file (default RESULT_DIR/KIND.png)")
    args = parser.parse_args()
    result = read_result(args.result_dir)
    nfrcs = [read_result(f) for f in args.frc]
    if args.kind == "continue":
        figure = analysis_figures.continuation_figure(result, length_unit=args.units)
    elif args.kind == "backbone" and nfrcs:
        figure = overlay_figure([*nfrcs, result], length_unit=args.units,
                                title="backbone over the NFRCs")
    elif args.kind == "backbone":
        figure = analysis_figures.backbone_figure(result, length_unit=args.units)
    else:
        figure = analysis_figures.period_doubled_figure(result, nfrcs[0] if nfrcs else None, length_unit=args.units)
    out = args.output or os.path.join(args.result_dir, args.kind + ".png")
    figure.savefig(out, dpi=130)
    print(out)


if __name__ == "__main__":
    main()
