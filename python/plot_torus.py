#!/usr/bin/python3
"""The quasi-periodic branch of `hbtrack torus` over its NFRC (docs/analyses.md). A thin wrapper
of hbtrack.torus_figures (`hbtrack plot TORUS_DIR` draws the same without the time integrations).

    /usr/bin/python3 python/plot_torus.py NFRC_DIR TORUS_DIR [--simulate SIM_DIR ...] [--zoom LO:HI] -o FIG.png

One panel per output: the NFRC's max against omega (stable solid, unstable dashed), its NS points,
the largest value on the torus along the branch, and, per --simulate folder (a time integration
with --record-periods), its largest value after the transient (of its last period when it found
a periodic steady state) at its omega.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack.results import read_result  # noqa: E402
from hbtrack.torus_figures import torus_figure  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("nfrc_dir")
    parser.add_argument("torus_dir")
    parser.add_argument("--simulate", action="append", default=[], help="a simulate folder inside the band (repeat)")
    parser.add_argument("--zoom", help="LO:HI, the omega interval drawn")
    parser.add_argument("--units", default=None, help="the model's length unit for the labels")
    parser.add_argument("--extreme", choices=("max", "min"), default="max", help="which extreme of each output is drawn")
    parser.add_argument("-o", "--output", required=True, help="figure file (PNG)")
    args = parser.parse_args()
    zoom = tuple(float(v) for v in args.zoom.split(":")) if args.zoom else None
    figure = torus_figure(read_result(args.torus_dir), nfrc=read_result(args.nfrc_dir), simulations=[read_result(d) for d in args.simulate],
                          zoom=zoom, length_unit=args.units, extreme=args.extreme)
    figure.savefig(args.output, dpi=130)


if __name__ == "__main__":
    main()
