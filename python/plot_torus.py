#!/usr/bin/python3
"""The quasi-periodic branch of `hbtrack torus` over its NFRC (docs/analyses.md).

    /usr/bin/python3 python/plot_torus.py NFRC_DIR TORUS_DIR [--simulate SIM_DIR ...] [--zoom LO:HI] -o FIG.png

One panel per output: the NFRC's max against omega (stable solid, unstable dashed), its NS points,
the torus branch's max over the torus (the outputs' largest value on the torus, at each omega of
the branch), and, per --simulate folder (a time integration with --record-periods), the largest
value of its recorded signals (after the transient) at its omega, or of its last period when it
found a periodic steady state.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # the hbtrack package next to this script
from hbtrack.results import read_result  # noqa: E402


def draw_nfrc(axes, nfrc, name):
    """The NFRC's max of `name`, stable solid and unstable dashed, as runs of rows."""
    omega, value = nfrc["branch"]["omega"], nfrc["branch"]["max_" + name]
    stable = nfrc["branch"].get("stable", np.ones_like(omega)) > 0.5
    start = 0
    for i in range(1, len(omega) + 1):
        if i == len(omega) or stable[i] != stable[start]:
            end = min(i + 1, len(omega))  # joined to the next run's first point
            axes.plot(omega[start:end], value[start:end], color="tab:blue", linestyle="-" if stable[start] else "--", linewidth=1.2,
                      label=None)
            start = i
    axes.plot([], [], color="tab:blue", label="NFRC, stable")
    axes.plot([], [], color="tab:blue", linestyle="--", label="NFRC, unstable")


def simulated_max(simulation, name):
    """The largest value of output `name`: of the last period when the integration found a
    periodic steady state (its record may hold the transient too), else of the recorded periods."""
    if simulation["summary"].get("converged"):
        return simulation["summary"]["max_" + name]
    return simulation["signals"][name].max()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("nfrc_dir")
    parser.add_argument("torus_dir")
    parser.add_argument("--simulate", action="append", default=[], help="a simulate folder inside the band (repeat)")
    parser.add_argument("--zoom", help="LO:HI, the omega interval drawn")
    parser.add_argument("-o", "--output", required=True, help="figure file (PNG)")
    args = parser.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    nfrc, torus = read_result(args.nfrc_dir), read_result(args.torus_dir)
    simulations = [read_result(d) for d in args.simulate]
    names = [o["name"] for o in torus["summary"]["outputs"]]
    figure, panels = plt.subplots(1, len(names), figsize=(5.2 * len(names), 4.2), squeeze=False)
    ns = [p for p in nfrc["special_points"] if p["type"] == "NS"]
    for axes, name in zip(panels[0], names):
        draw_nfrc(axes, nfrc, name)
        axes.plot([p["omega"] for p in ns], [p["max_" + name] for p in ns], "o", color="black", markerfacecolor="white", markersize=7,
                  label="NS points", zorder=4)
        axes.plot(torus["branch"]["omega"], torus["branch"]["max_" + name], color="tab:red", linewidth=1.8, label="torus: max over the torus")
        if simulations:
            axes.plot([s["summary"]["omega"] for s in simulations], [simulated_max(s, name) for s in simulations], "x", color="black",
                      markersize=8, markeredgewidth=1.6, label="simulate from rest: max", zorder=5)
        if args.zoom:
            low, high = (float(v) for v in args.zoom.split(":"))
            axes.set_xlim(low, high)
            shown = (nfrc["branch"]["omega"] >= low) & (nfrc["branch"]["omega"] <= high)
            top = max(nfrc["branch"]["max_" + name][shown].max(), torus["branch"]["max_" + name].max())
            axes.set_ylim(0, 1.1 * top)
        axes.set_xlabel("omega (rad/s)")
        axes.set_ylabel(f"max {name}")
        axes.grid(alpha=0.3)
        axes.legend(fontsize=8, loc="lower left")
    start = torus["summary"]["ns_point"]
    figure.suptitle(f"quasi-periodic branch from the NS point at omega = {start['omega']:.4f} (NS frequency {start['ns_frequency']:.4f})",
                    fontsize=10)
    figure.tight_layout()
    figure.savefig(args.output, dpi=130)


if __name__ == "__main__":
    main()
