#!/usr/bin/python3
"""The tasks of `hbtrack sweep` driven from Python: NFRCs of the Duffing example over a grid of
forcing amplitude and number of harmonics (the peak's convergence in H at each amplitude), side by
side in a thread pool. hbtrack's computations
release the GIL, so N threads keep N cores busy; any executor with the same map() interface
(a cluster client's, for instance) distributes the same function.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_threads.py [WORKERS]

prints one CSV row per task, as sweep.csv's first columns, and the wall time. Any parameter set
works the same way: `set` takes the named parameters and dotted case keys of `--set`.
"""
import itertools
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import hbtrack

CASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "duffing.toml")
GRID = list(itertools.product([0.6, 1.0, 1.4], [3, 5, 7]))  # (amplitude, harmonics)


def nfrc_task(values):
    """One task: the NFRC (with stability and special points) at these parameter values."""
    amplitude, harmonics = values
    case = hbtrack.load_case(CASE, set={"amplitude": amplitude, "harmonic_balance.harmonics": harmonics})
    nfrc = hbtrack.frc(case)
    lps = [p["omega"] for p in nfrc["special_points"] if p["type"] == "LP"]
    return amplitude, harmonics, nfrc["summary"]["stop_reason"], nfrc["branch"]["max_x"].max(), lps


def main():
    workers = int(sys.argv[1]) if len(sys.argv) > 1 else os.cpu_count()
    start = time.perf_counter()
    print("amplitude,harmonics,status,peak_max_x,lps,lp_omegas")
    with ThreadPoolExecutor(max_workers=workers) as pool:
        for amplitude, harmonics, status, peak, lps in pool.map(nfrc_task, GRID):  # results in grid order
            print(f"{amplitude:g},{harmonics},{status},{peak:.10g},{len(lps)},{' '.join(f'{w:.6f}' for w in lps)}")
    print(f"{len(GRID)} NFRCs on {workers} threads in {time.perf_counter() - start:.2f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
