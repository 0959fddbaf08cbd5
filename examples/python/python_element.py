#!/usr/bin/python3
"""An element written in Python (docs/elements.md, "Elements written in Python"): the Duffing
example's cubic spring as a numpy callable, its NFRC against the built-in element's.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/python_element.py
"""
import os

import numpy as np

import hbtrack

CASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "duffing.toml")


def cubic(x, v):
    """x, v: (N, k) samples of the element's dofs over one period. Returns the forces (N, k) and
    d f_i / d x_j as (N, k, k); without the second, central differences stand in for it."""
    return 0.1 * x**3, (0.3 * x**2)[:, :, None]


builtin = hbtrack.frc(hbtrack.load_case(CASE))
case = hbtrack.load_case(CASE, set={"elements[0].cubic_stiffness": 0.0})
hbtrack.add_python_element(case, ["x"], cubic)
python = hbtrack.frc(case)
gap = np.abs(python["states"] - builtin["states"]).max() / np.abs(builtin["states"]).max()
print(f"{len(python['branch']['omega'])} points, {python['summary']['stop_reason']}; "
      f"largest difference from the built-in cubic_spring's branch {gap:.1e}")
