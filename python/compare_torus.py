#!/usr/bin/python3
"""A torus against time integrations at its omegas: each output's extremes, the second frequency,
and the lines at half of it (docs/analyses.md, "Rotor 67's band"). A thin wrapper of
hbtrack.torus_comparison.

    /usr/bin/python3 python/compare_torus.py TORUS_DIR SIM_DIR [SIM_DIR ...]

Prints a Markdown table: per simulation (a `simulate --record-periods` folder at an omega the
torus has a row at), each output's max and min against the torus row's, their relative
difference, the torus' omega2 and the simulation's (its strongest sideband), and the strongest
line at omega +- (j + 1/2) omega2 (a doubled modulation: the torus is not the attractor there).
Exit 2 with one line naming the folder when a folder or an omega does not fit.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack.results import read_result  # noqa: E402
from hbtrack.torus_comparison import torus_against_simulation  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("torus_dir")
    parser.add_argument("simulate_dirs", nargs="+")
    args = parser.parse_args()
    try:
        torus = read_result(args.torus_dir)
    except (OSError, ValueError) as error:
        print(f"compare_torus.py: {args.torus_dir}: {error}", file=sys.stderr)
        sys.exit(2)
    comparisons = []
    for folder in args.simulate_dirs:  # all read first: a bad folder prints no half table
        try:
            comparisons.append(torus_against_simulation(torus, read_result(folder)))
        except (OSError, ValueError, KeyError) as error:
            print(f"compare_torus.py: {folder}: {error}", file=sys.stderr)
            sys.exit(2)
    print("| omega (rad/s) | output | simulate | torus | difference | omega2: torus, simulate (rad/s) | lines at (j + 1/2) omega2 |")
    print("|---|---|---|---|---|---|---|")
    for c in comparisons:
        half = f"{c['half_lines'][0][1]:.3f} at {c['half_lines'][0][0] - c['omega']:+.2f}" if c["half_lines"] else "none"
        for i, e in enumerate(c["extremes"]):
            print(f"| {c['omega']:.3f} | {e['extreme']} {e['name']} | {e['simulated']:.5g} | {e['torus']:.5g} | {100 * e['difference']:+.2f} % | "
                  + (f"{c['omega2']:.2f}, {c['omega2_simulated']:.2f} | {half} |" if i == 0 else "| |"))

if __name__ == "__main__":
    main()
