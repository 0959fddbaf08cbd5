#!/usr/bin/python3
"""Plots limit-point tracking curves of hbtrack track result folders in the (omega, parameter)
plane, with the located extrema of the parameter (min: a pair of limit points is born, max: a
pair disappears) marked. A thin wrapper of hbtrack.plots.tracking_plane_figure.

    /usr/bin/python3 python/plot_tracking.py TRACK_DIR [TRACK_DIR ...] -o FIGURE.png
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack import plots  # noqa: E402
from hbtrack.results import read_result  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("-o", "--output", required=True, help="figure file")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    tracks = [read_result(folder) for folder in args.folders]
    if any(t["kind"] != "track" for t in tracks):
        sys.exit("not a track result: " + ", ".join(t["folder"] for t in tracks if t["kind"] != "track"))
    if len({t["summary"]["options"]["tracking"]["parameter"] for t in tracks}) != 1:
        sys.exit("the folders track different parameters")
    figure = plots.tracking_plane_figure(tracks)
    if args.title:
        figure.get_axes()[0].set_title(args.title)
    figure.savefig(args.output, dpi=120)
    print(args.output)


if __name__ == "__main__":
    main()
