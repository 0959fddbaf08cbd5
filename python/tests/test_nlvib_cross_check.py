"""NLvib's own points of its three-oscillator example in hbtrack's equations
(tests/data/nlvib/three_oscillators/README.md, docs/elements.md).

Where both Jenkins sliders slip, or one sticks centred on 0 (NLvib's rest position, hbtrack's
midrange), hbtrack's residual at NLvib's points is at NLvib's own convergence level (its fsolve in
Octave: at most 4.6e-5 of the unit force there). Where a slider sticks off-centre the two tools
close the free slider position differently, and hbtrack's residual must then be exactly the
constant force 2 k (z_NLvib - z_midrange) w in the mean rows (a0 rows: twice the mean), every other
row again at NLvib's level.
"""
import importlib.util
import os

import numpy as np
import pytest

import hbtrack

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
_spec = importlib.util.spec_from_file_location(
    "nlvib_cross_check", os.path.join(ROOT, "scripts", "reference", "nlvib_cross_check.py"))
xcheck = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(xcheck)

# NLvib's points are converged to its fsolve's tolerance, not to hbtrack's 1e-9: the stored
# nlvib_residual column (NLvib's own max|R|) is at most 4.6e-5; twice that leaves room for the
# penalty spring's sample-mean quadrature (1.7e-6 at most in the other direction).
NLVIB_LEVEL = 1e-4


@pytest.fixture(scope="module")
def classified():
    points = xcheck.read_points()
    assert np.max(points["nlvib_residual"]) <= 0.5 * NLVIB_LEVEL
    return xcheck.classify(points, hbtrack.load_case(xcheck.CASE))


def test_nlvib_points_solve_hbtrack_equations_where_the_sliders_slip_or_stick_centred(classified):
    agreeing = [r for r in classified if not r["stuck"] or np.abs(r["mean_force"]).max() <= 1e-6]
    assert len(agreeing) == 97  # 77 slipping, 20 centred (the stored run: docs/elements.md)
    assert max(r["relative"] for r in agreeing) <= NLVIB_LEVEL


def test_off_centre_sticking_differs_by_the_slider_offset_force_in_the_mean_only(classified):
    offset = [r for r in classified if r["stuck"] and np.abs(r["mean_force"]).max() > 1e-6]
    assert len(offset) == 9
    assert all(r["stuck"] == [2] for r in offset)  # the x2 - x1 slider, between 1.574 and 1.635
    for r in offset:
        mean_rows = r["residual"][: len(xcheck.DOFS)]
        # hbtrack's residual is f_hbtrack - f_NLvib = k (z_NLvib - z_mid) w, a constant: a0 row 2x.
        np.testing.assert_allclose(mean_rows, r["mean_force"], rtol=0, atol=NLVIB_LEVEL)
        assert np.abs(r["residual"][len(xcheck.DOFS):]).max() <= NLVIB_LEVEL
    # Not a rounding: up to 0.12 of the force, 1000x NLvib's level.
    assert max(np.abs(r["mean_force"]).max() for r in offset) > 0.1


def test_nlvib_slider_slips_once_from_rest():
    # d = 0.2 + 0.01 cos: k d = 4 > F at the first sample after rest, so the slider jumps to
    # d - F / k; from there the motion's range (0.02 < 2 F / k) is too small to move it back, but
    # the next visit of the maximum pushes it once more: it ends at max d - F / k, the force
    # k (d - z) between 0.6 and 1 where hbtrack's midrange gives -0.2 to 0.2.
    tau = 2 * np.pi * np.arange(64) / 64
    d = 0.2 + 0.01 * np.cos(tau)
    assert xcheck.nlvib_slider(d) == pytest.approx(d.max() - 0.05, abs=1e-15)
    # Centred and small: never slips, stays at rest.
    assert xcheck.nlvib_slider(0.01 * np.cos(tau)) == 0.0
