#!/usr/bin/python3
"""NLvib's and hbtrack's points of the three-oscillator example, each in the other's equations.

NLvib's points (scripts/reference/nlvib_three_oscillators.m, stored in
tests/data/nlvib/three_oscillators/) are put into hbtrack's harmonic balance with
`hbtrack.residual`; hbtrack's points go the other way through the Octave script. Where a Jenkins
slider sticks for the whole period the periodic problem leaves its position free (docs/elements.md):
NLvib's slider slips once from rest at the period's first samples, hbtrack's sits at the midrange,
and the two residuals then differ by exactly the constant force k (z_NLvib - z_midrange) in the
mean. This script classifies every point and reports that.

    nlvib_cross_check.py hbtrack-points RESULT_DIR OUT.csv   hbtrack's points in NLvib's layout
    nlvib_cross_check.py report [NLVIB_POINTS] [--hbtrack RESULT_DIR --in-nlvib FILE]
"""
import argparse
import csv
import os
import sys

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASE = os.path.join(ROOT, "examples", "three_oscillators_jenkins.toml")
POINTS = os.path.join(ROOT, "tests", "data", "nlvib", "three_oscillators", "nlvib_points.csv")
DOFS = ("x1", "x2", "x3")
HARMONICS, SAMPLES = 7, 1024
JENKINS_STIFFNESS, JENKINS_LIMIT = 20.0, 1.0
# Jenkins elements' displacements d = w . x (x1; x2 - x1), as the case file and NLvib define them.
JENKINS_DIRECTIONS = (np.array([1.0, 0.0, 0.0]), np.array([-1.0, 1.0, 0.0]))


def column_names():
    names = [f"{d}_h0" for d in DOFS]
    for h in range(1, HARMONICS + 1):
        names += [f"{d}_c{h}" for d in DOFS] + [f"{d}_s{h}" for d in DOFS]
    return names


def read_points(path=POINTS):
    """{column: array} of a points file (omega, x1_h0, ..., x3_s7[, nlvib_residual])."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def dof_samples(points, i):
    """3 x N displacements of point i at NLvib's and hbtrack's instants tau_j = 2 pi j / N."""
    tau = 2 * np.pi * np.arange(SAMPLES) / SAMPLES
    x = np.empty((len(DOFS), SAMPLES))
    for k, d in enumerate(DOFS):
        x[k] = points[f"{d}_h0"][i]
        for h in range(1, HARMONICS + 1):
            x[k] += points[f"{d}_c{h}"][i] * np.cos(h * tau) + points[f"{d}_s{h}"][i] * np.sin(h * tau)
    return x


def nlvib_slider(d, stiffness=JENKINS_STIFFNESS, limit=JENKINS_LIMIT):
    """NLvib's slider position after its two passes from rest (slider at 0) over the samples d."""
    z = 0.0
    for value in np.concatenate([d, d])[1:]:
        force = stiffness * (value - z)
        if abs(force) >= limit:
            z = value - np.sign(force) * limit / stiffness
    return z


def state_row(points, i):
    """hbtrack's state row [omega, a0 (twice the mean), a1, b1, ...] of point i."""
    x = np.array([points[c][i] for c in column_names()])
    x[: len(DOFS)] *= 2.0
    return np.concatenate([[points["omega"][i]], x])


def classify(points, case):
    """Per point: omega, hbtrack's relative residual, the sticking elements and the force
    2 k (z_NLvib - z_midrange) each puts into the mean rows (hbtrack's a0 rows: twice the mean)."""
    import hbtrack

    out = []
    for i in range(len(points["omega"])):
        x = dof_samples(points, i)
        stuck, mean_force = [], np.zeros(len(DOFS))
        for e, w in enumerate(JENKINS_DIRECTIONS):
            d = w @ x
            if np.ptp(d) <= 2 * JENKINS_LIMIT / JENKINS_STIFFNESS:
                stuck.append(e + 1)
                mean_force += 2 * JENKINS_STIFFNESS * (nlvib_slider(d) - 0.5 * (d.max() + d.min())) * w
        r = hbtrack.residual(case, state_row(points, i))
        out.append({"omega": points["omega"][i], "relative": r["relative"], "residual": r["residual"],
                    "stuck": stuck, "mean_force": mean_force})
    return out


def report(args):
    import hbtrack

    case = hbtrack.load_case(CASE)
    points = read_points(args.points)
    rows = classify(points, case)
    own = points.get("nlvib_residual")
    print(f"NLvib's {len(rows)} points in hbtrack's equations (max|r| / force unit):")
    slipping = [r for r in rows if not r["stuck"]]
    centred = [r for r in rows if r["stuck"] and np.abs(r["mean_force"]).max() <= 1e-6]
    offset = [r for r in rows if r["stuck"] and np.abs(r["mean_force"]).max() > 1e-6]
    for name, group in (("both sliders slip", slipping), ("a slider sticks, centred on NLvib's 0", centred)):
        if group:
            print(f"  {name}: {len(group)} points, largest {max(r['relative'] for r in group):.2e}")
    if own is not None:
        print(f"  NLvib's own residual at its points: largest {own.max():.2e}")
    print(f"  a slider sticks off-centre: {len(offset)} points")
    for r in offset:
        rest = np.abs(r["residual"][len(DOFS):]).max()
        print(f"    omega {r['omega']:.5f}  elements {r['stuck']}  mean rows {np.round(r['residual'][:3], 5)}"
              f"  2k(z_NLvib - z_mid) w {np.round(r['mean_force'], 5)}  other rows {rest:.1e}")
    if args.in_nlvib:
        theirs = read_points(args.in_nlvib)
        mine = hbtrack.read_result(args.hbtrack)["dof_states"]
        pts = {c: mine[c] for c in ["omega"] + column_names()}
        kinds = np.array([0 if not c["stuck"] else 1 if np.abs(c["mean_force"]).max() <= 1e-6 else 2
                          for c in classify(pts, case)])
        r = theirs["nlvib_residual"]
        print(f"hbtrack's {len(r)} points in NLvib's equations (max|R|, the force is 1):")
        for kind, name in enumerate(("both sliders slip", "a slider sticks, centred", "a slider sticks off-centre")):
            if np.any(kinds == kind):
                group = r[kinds == kind]
                print(f"  {name}: {group.size} points, {group.min():.1e} to {group.max():.1e}")


def hbtrack_points(args):
    import hbtrack

    states = hbtrack.read_result(args.result)["dof_states"]
    names = ["omega"] + column_names()
    np.savetxt(args.out, np.column_stack([states[c] for c in names]), delimiter=",", fmt="%.17g",
               header=",".join(names), comments="")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("hbtrack-points", help="hbtrack's points in NLvib's layout, for the Octave script")
    p.add_argument("result")
    p.add_argument("out")
    p.set_defaults(run=hbtrack_points)
    p = sub.add_parser("report", help="each tool's points in the other's equations")
    p.add_argument("points", nargs="?", default=POINTS)
    p.add_argument("--hbtrack", help="hbtrack's frc folder of the example")
    p.add_argument("--in-nlvib", help="the Octave script's hbtrack_in_nlvib.csv for those points")
    p.set_defaults(run=report)
    args = parser.parse_args(argv)
    args.run(args)


if __name__ == "__main__":
    sys.exit(main())
