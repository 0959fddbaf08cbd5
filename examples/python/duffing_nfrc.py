#!/usr/bin/python3
"""The README's Duffing NFRC (docs/figures/duffing_nfrc.png) from Python, with its limit points
tracked in the amplitude (docs/figures/duffing_amplitude_tracking.png):

    PYTHONPATH=build/python /usr/bin/python3 examples/python/duffing_nfrc.py [OUT_DIR]

writes OUT_DIR (default out/python)/duffing_nfrc.{png,pdf} and duffing_tracking.{png,pdf}.
"""
import os
import sys

import hbtrack
from hbtrack import plots

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join("out", "python")
case = hbtrack.load_case(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "duffing.toml"))
nfrc = hbtrack.frc(case)
for point in nfrc["special_points"]:
    print(f"{point['type']} at omega = {point['omega']:.6f} rad/s, max x = {point['max_x']:.4f}")
tracks = [hbtrack.track(case, nfrc, lp=lp, param="amplitude", range=(0.1, 2.0)) for lp in (1, 2)]
print(*plots.save_figure(plots.nfrc_figure(nfrc), os.path.join(out, "duffing_nfrc")))
print(*plots.save_figure(plots.tracking_plane_figure(tracks, validations=[nfrc]), os.path.join(out, "duffing_tracking")))
