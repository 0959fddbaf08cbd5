#!/usr/bin/python3
"""Plots limit-point (NS, PD) tracking curves of hbtrack track result folders in the (omega,
parameter) plane, with the located extrema of the parameter (min: a pair of limit points is born,
max: a pair disappears) marked, and the special points of NFRCs at other parameter values
(--validate). A thin wrapper of hbtrack.plots.tracking_plane_figure.

    /usr/bin/python3 python/plot_tracking.py TRACK_DIR [TRACK_DIR ...] [--validate FRC_DIR ...] [--units m] -o FIGURE.png
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack import plots  # noqa: E402
from hbtrack.label_layout import place_labels  # noqa: E402
from hbtrack.results import read_result  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("-o", "--output", required=True, help="figure file")
    parser.add_argument("--title", default="")
    parser.add_argument("--units", help="the model's length unit (e.g. m), for a length parameter's axis label")
    parser.add_argument("--zoom", help="OMEGA_LO:OMEGA_HI:PARAM_LO:PARAM_HI, the window drawn (legend moved below it)")
    parser.add_argument("--validate", action="append", default=[],
                        help="an frc folder at another parameter value: its points of the tracked types marked (repeat)")
    args = parser.parse_args()

    tracks = [read_result(folder) for folder in args.folders]
    if any(t["kind"] != "track" for t in tracks):
        sys.exit("not a track result: " + ", ".join(t["folder"] for t in tracks if t["kind"] != "track"))
    if len({t["summary"]["options"]["tracking"]["parameter"] for t in tracks}) != 1:
        sys.exit("the folders track different parameters")
    figure = plots.tracking_plane_figure(tracks, validations=[read_result(folder) for folder in args.validate],
                                         length_unit=args.units)
    if args.zoom:
        axes = figure.get_axes()[0]
        lo, hi, param_lo, param_hi = (float(v) for v in args.zoom.split(":"))
        axes.set_xlim(lo, hi)
        axes.set_ylim(param_lo, param_hi)
        legend = axes.get_legend()
        handles = getattr(legend, "legend_handles", None) or legend.legendHandles
        axes.legend(handles, [t.get_text() for t in legend.get_texts()], loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=7)
        figure.set_size_inches(6.5, 5.6)
        figure.subplots_adjust(bottom=0.3)
        # The labels were placed for the old limits: placed again for the new ones
        texts = [(t.xy[0], t.xy[1], t.get_text()) for t in list(axes.texts)]
        for t in list(axes.texts):
            t.remove()
        place_labels(axes, texts)
    if args.title:
        figure.get_axes()[0].set_title(args.title)
    figure.savefig(args.output, dpi=120)
    print(args.output)


if __name__ == "__main__":
    main()
