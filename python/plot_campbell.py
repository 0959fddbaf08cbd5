#!/usr/bin/python3
"""Plots the Campbell diagram of `hbtrack modes CASE --speeds LO:HI:N -o DIR`: each mode's
frequency against the rotation speed, the engine-order lines and their crossings.
A thin wrapper of hbtrack.campbell_figures.campbell_figure.

    /usr/bin/python3 python/plot_campbell.py RESULT_DIR [-o FIGURE.png] [--engine-orders K] [--rpm] [--title TEXT]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack.campbell_figures import campbell_figure  # noqa: E402
from hbtrack.results import read_result  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result_dir")
    parser.add_argument("-o", "--output", help="figure file (default RESULT_DIR/campbell.png)")
    parser.add_argument("--engine-orders", type=int, default=8, help="engine-order lines drawn, 1 .. K (default 8)")
    parser.add_argument("--rpm", action="store_true", help="the speed axis in rpm (default rad/s)")
    parser.add_argument("--title", help="a title (default none)")
    args = parser.parse_args()
    result = read_result(args.result_dir)
    if result["kind"] != "campbell":
        sys.exit(f"plot_campbell: {args.result_dir} is a {result['kind']} result, not one of `hbtrack modes --speeds`")
    output = args.output or os.path.join(args.result_dir, "campbell.png")
    campbell_figure(result, engine_orders=args.engine_orders, title=args.title, speed_unit="rpm" if args.rpm else "rad/s", path=output)
    print(os.path.splitext(output)[0] + ".png")


if __name__ == "__main__":
    main()
