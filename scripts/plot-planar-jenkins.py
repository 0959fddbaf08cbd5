"""The figure of docs/elements.md's elastic_dry_friction_2d section.

Left: the steady circular orbit of the slider in its plane. The imposed motion u = r (cos wt, sin wt)
(k r > F) drags the slider z round a circle of radius sqrt(r^2 - (F/k)^2); the force T = k (u - z),
of magnitude F, leads u by arccos(F / (k r)). The dots are the return mapping at N = 16 samples per
period, written out here as the element does it: half a sample behind the continuous slider.
Middle: the NFRC of examples/planar_jenkins.toml (hbtrack.frc, H = 7, N = 512) and time
integration from rest (hbtrack.simulate, Newmark, 512 steps per period) at a few frequencies.
Right, on the same scale, for contrast: the same oscillators with a 1D Jenkins element on each
axis (two uncoupled sliders). One system per axes, outputs by the case's descriptions, stability
styles and special points from figure_style (both branches are stable, without folds).

    PYTHONPATH=build/python /usr/bin/python3 scripts/plot-planar-jenkins.py -o docs/figures/planar_jenkins.png
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import hbtrack  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from hbtrack.figure_style import OMEGA_LABEL, SPECIAL_MARKERS, _plot_split, _stable_masks, length_label, marker_legend, stability_legend  # noqa: E402
from hbtrack.output_descriptions import output_descriptions  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
CASE = os.path.join(ROOT, "examples", "planar_jenkins.toml")


def sampled_orbit(r, k, limit, n, periods=40):
    """The slider after each sample of the radial return, stepped from rest: its last period."""
    z = np.zeros(2)
    out = []
    for _ in range(periods):
        out = []
        for t in range(n):
            u = r * np.array([np.cos(2 * np.pi * t / n), np.sin(2 * np.pi * t / n)])
            trial = k * (u - z)
            if np.linalg.norm(trial) > limit:
                trial *= limit / np.linalg.norm(trial)
                z = u - trial / k
            out.append(z.copy())
    return np.array(out)


def orbit_panel(ax):
    k, limit, r = 1.0, 0.5, 1.0  # s = F / (k r) = 0.5
    rho, alpha = np.sqrt(r**2 - (limit / k) ** 2), np.arccos(limit / (k * r))
    th = np.linspace(0, 2 * np.pi, 400)
    ax.plot(r * np.cos(th), r * np.sin(th), color="C0", label="imposed motion u, radius r")
    ax.plot(rho * np.cos(th), rho * np.sin(th), color="C1", label=r"slider z, radius $\sqrt{r^2 - (F/k)^2}$")
    theta = 0.35 * np.pi  # one instant
    u = r * np.array([np.cos(theta), np.sin(theta)])
    z = rho * np.array([np.cos(theta - np.arcsin(limit / (k * r))), np.sin(theta - np.arcsin(limit / (k * r)))])
    ax.plot([0, u[0]], [0, u[1]], color="C0", lw=0.8)
    ax.plot([0, z[0]], [0, z[1]], color="C1", lw=0.8)
    force = k * (u - z)
    ax.annotate("", xy=u + force, xytext=u, arrowprops=dict(arrowstyle="->", color="C3", lw=1.6))
    ax.text(*(u + 1.05 * force), r"T = k(u - z), |T| = F", color="C3", ha="left", va="bottom", fontsize=8)
    ax.text(0.12, 0.3, r"T leads u by $\arccos(F/kr)$ = %.0f$^\circ$" % np.degrees(alpha), fontsize=8)
    sampled = sampled_orbit(r, k, limit, 16)
    ax.plot(sampled[:, 0], sampled[:, 1], "o", ms=3.5, color="C2", label="slider, return mapping at N = 16 samples")
    ax.set_aspect("equal")
    ax.set_xlim(-1.3, 1.9)
    ax.set_ylim(-2.0, 1.6)  # room for the legend below the circles
    ax.set_xlabel("in-plane coordinate 1 / r [-]")
    ax.set_ylabel("in-plane coordinate 2 / r [-]")
    ax.set_title("Steady circular sliding, slip force F = 0.5 k r\n(k: the element's spring)", fontsize=9)
    ax.legend(fontsize=7, loc="lower left")


def nfrc_panels(planar_ax, separate_ax):
    """One system per axes: the planar slider (HBM and time integration), then the same oscillators
    with a 1D slider per axis. Outputs by their descriptions, stable solid, unstable dashed, and
    the special points (none: both branches are stable throughout, without folds) marked."""
    case = hbtrack.load_case(CASE)
    planar = hbtrack.frc(case)
    # Two 1D sliders, one per axis, with the same stiffness and slip force.
    uncoupled = hbtrack.case_from_arrays(
        M=np.eye(2), K=np.diag([1.0, 1.44]), dofs=["x", "y"], damping={"rayleigh": [0.0, 0.01]},
        forcing=[{"cos": [0.0866, 0.05]}],
        elements=[hbtrack.elements.elastic_dry_friction([d], stiffness=1.0, limit_force=0.06) for d in ("x", "y")],
        harmonic_balance={"harmonics": 7, "samples": 512},
        continuation={"omega_start": 0.6, "omega_end": 1.8, "step": 0.02})
    separate = hbtrack.frc(uncoupled)
    descriptions = output_descriptions(planar)
    colours = {"x": "C0", "y": "C1"}
    for ax, result in ((planar_ax, planar), (separate_ax, separate)):
        branch = result["branch"]
        stable, unstable = _stable_masks(branch)
        for name, colour in colours.items():
            _plot_split(ax, branch["omega"], branch[f"h1_{name}"], stable, unstable, colour, descriptions[name])
        types = {sp["type"] for sp in result["special_points"] if sp["type"] in SPECIAL_MARKERS}
        for sp in result["special_points"]:
            if sp["type"] in SPECIAL_MARKERS:
                for name in colours:
                    ax.plot(sp["omega"], sp[f"h1_{name}"], SPECIAL_MARKERS[sp["type"]][0], color="k", mfc="w", ms=5, zorder=5)
        styles = stability_legend([branch]) or [Line2D([], [], color="0.3", lw=1.3, label="stable at every point")]
        ax.set_yscale("log")
        ax.set_xlabel(OMEGA_LABEL)
        ax.grid(alpha=0.3, which="both")
        ax.extra_legend = styles + marker_legend(types) + \
            ([] if types else [Line2D([], [], ls="none", label="no fold or bifurcation")])
    for omega in (0.7, 0.9, 0.97, 1.0, 1.03, 1.1, 1.2, 1.3, 1.5, 1.7):
        run = hbtrack.simulate(case, omega, steps_per_period=512, max_periods=4000)
        summary = run["summary"]
        assert summary["converged"], omega
        for name, colour in colours.items():
            planar_ax.plot(omega, summary[f"h1_{name}"], "o", mfc="none", color=colour, ls="none",
                           label="time integration from rest" if (omega == 0.7 and name == "x") else None)
    planar_ax.set_ylabel(length_label("first-harmonic amplitude"))
    planar_ax.set_title("Planar slider (elastic_dry_friction_2d)", fontsize=9)
    separate_ax.set_title("The same oscillators, a 1D slider per axis", fontsize=9)
    for ax in (planar_ax, separate_ax):
        handles, _ = ax.get_legend_handles_labels()
        ax.legend(handles=handles + ax.extra_legend, fontsize=7, loc="upper right")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="planar_jenkins.png")
    args = parser.parse_args()
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(15, 4.8), gridspec_kw={"width_ratios": [1, 1.15, 1.15]})
    orbit_panel(left)
    middle.sharey(right)
    nfrc_panels(middle, right)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(args.output)


if __name__ == "__main__":
    main()
