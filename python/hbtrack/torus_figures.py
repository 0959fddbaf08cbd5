"""The quasi-periodic branch of ``hbtrack torus`` over its NFRC: one panel per output, the NFRC's
max against omega (stable solid, unstable dashed) with its NS points, the largest value on the
torus along the branch, and time integrations' maxima (``hbtrack plot`` of a torus folder,
python/plot_torus.py, docs/analyses.md)."""
import numpy as np

from .figure_style import SPECIAL_MARKERS
from .plots import OMEGA_LABEL, length_label, plt
from .special_points import SpecialPointType


def simulated_max(simulation, name):
    """The largest value of output `name` in a time integration.

    Of its last period when it found a periodic steady state (its record may hold the transient
    too), else of its recorded periods (a quasi-periodic motion, after the transient).

    Parameters
    ----------
    simulation : dict
        A simulate result (``hbtrack simulate`` folder or :func:`hbtrack.simulate`).
    name : str
        An output's name.

    Returns
    -------
    float

    Examples
    --------
    >>> simulated_max(read_result("out/sim_1.14"), "x1")
    """
    return simulated_extreme(simulation, name, "max")


def simulated_extreme(simulation, name, extreme):
    """The largest (``extreme="max"``) or least (``"min"``) value of output `name` in a time integration.

    As :func:`simulated_max`: of its last period when it found a periodic steady state, else of
    its recorded periods.

    Parameters
    ----------
    simulation : dict
        A simulate result (``hbtrack simulate`` folder or :func:`hbtrack.simulate`).
    name : str
        An output's name.
    extreme : {"max", "min"}
        Which extreme.

    Returns
    -------
    float

    Examples
    --------
    >>> simulated_extreme(read_result("out/sim_1.14"), "x1", "min")
    """
    if simulation["summary"].get("converged"):
        return simulation["summary"][f"{extreme}_{name}"]
    signal = simulation["signals"][name]
    return float(np.max(signal) if extreme == "max" else np.min(signal))


def _draw_nfrc(axes, nfrc, name, extreme="max"):
    """The NFRC's `extreme` ("max" or "min") of `name`, stable solid and unstable dashed, as runs of rows."""
    column = f"{extreme}_{name}"
    omega, value = nfrc["branch"]["omega"], nfrc["branch"][column]
    stable = nfrc["branch"].get("stable", np.ones_like(omega)) > 0.5
    start = 0
    for i in range(1, len(omega) + 1):
        if i == len(omega) or stable[i] != stable[start]:
            end = min(i + 1, len(omega))  # joined to the next run's first point
            axes.plot(omega[start:end], value[start:end], color="tab:blue", linestyle="-" if stable[start] else "--", linewidth=1.2)
            start = i
    axes.plot([], [], color="tab:blue", label="NFRC, stable")
    axes.plot([], [], color="tab:blue", linestyle="--", label="NFRC, unstable")
    ns = [p for p in nfrc.get("special_points", []) if p["type"] == SpecialPointType.NEIMARK_SACKER]
    axes.plot([p["omega"] for p in ns], [p[column] for p in ns], SPECIAL_MARKERS["NS"][0], color="black", markerfacecolor="white",
              markersize=8, label=SPECIAL_MARKERS["NS"][1], zorder=4, ls="none")
    # Its folds too: the stability changes the dashes show are the NS points and these
    lps = [p for p in nfrc.get("special_points", []) if p["type"] == SpecialPointType.LIMIT_POINT]
    if lps:
        axes.plot([p["omega"] for p in lps], [p[column] for p in lps], SPECIAL_MARKERS["LP"][0], color="black",
                  markerfacecolor="white", markersize=6, label=SPECIAL_MARKERS["LP"][1], zorder=4, ls="none")


def torus_figure(torus, nfrc=None, simulations=(), zoom=None, length_unit=None, extreme="max"):
    """The torus branch's largest (or least) value of each output against omega, over its NFRC.

    Parameters
    ----------
    torus : dict
        A torus result (``hbtrack torus`` folder or :func:`hbtrack.torus`).
    nfrc : dict, optional
        The frc result it started from, drawn under it with its NS points.
    simulations : list of dict, optional
        Time integrations (``hbtrack simulate`` with ``--record-periods``) marked at their omega.
    zoom : tuple of float, optional
        (LO, HI): the omega interval drawn (default: the torus' with a margin).
    length_unit : str, optional
        The model's length unit for the labels.
    extreme : {"max", "min"}, optional
        Which extreme of each output is drawn (``"min"`` for a motion bounded above, as a tip
        stopped by its casing).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = torus_figure(read_result("out/nltva_torus"), nfrc=read_result("out/nltva"), zoom=(1.0, 1.35))
    """
    names = [o["name"] for o in torus["summary"]["outputs"]]
    figure, panels = plt.subplots(1, len(names), figsize=(5.2 * len(names), 4.2), squeeze=False)
    omega = torus["branch"]["omega"]
    if zoom is None:
        margin = 0.5 * (omega.max() - omega.min())
        zoom = (omega.min() - margin, omega.max() + margin)
    if extreme not in ("max", "min"):
        raise ValueError(f"extreme must be 'max' or 'min', not {extreme!r}")
    sign = 1.0 if extreme == "max" else -1.0
    for axes, name in zip(panels[0], names):
        column = f"{extreme}_{name}"
        top = (sign * torus["branch"][column]).max()
        if nfrc is not None:
            _draw_nfrc(axes, nfrc, name, extreme)
            shown = (nfrc["branch"]["omega"] >= zoom[0]) & (nfrc["branch"]["omega"] <= zoom[1])
            if shown.any():
                top = max(top, (sign * nfrc["branch"][column][shown]).max())
        axes.plot(omega, torus["branch"][column], color="tab:red", linewidth=1.8, label=f"torus: {extreme} over the torus")
        if simulations:
            axes.plot([s["summary"]["omega"] for s in simulations], [simulated_extreme(s, name, extreme) for s in simulations], "x",
                      color="black", markersize=8, markeredgewidth=1.6, label=f"time integration: {extreme}", zorder=5)
        axes.set_xlim(*zoom)
        axes.set_ylim(*sorted((0.0, 1.1 * sign * top)))
        axes.set_xlabel(OMEGA_LABEL)
        axes.set_ylabel(length_label(f"{extreme} {name}", length_unit))
        axes.grid(alpha=0.3)
        # Below the maxima the plot is empty; around the minima matplotlib finds the emptiest corner.
        axes.legend(fontsize=8, loc="lower left" if extreme == "max" else "best")
    # A run stopped before its end has no ns_point in its summary yet: its row 0 is that point.
    start = torus["summary"].get("ns_point") or {"omega": omega[0], "ns_frequency": torus["branch"]["omega2"][0]}
    figure.suptitle(f"quasi-periodic branch from the NS point at ω = {start['omega']:.4f} (NS frequency {start['ns_frequency']:.4f})",
                    fontsize=10)
    figure.tight_layout()
    return figure
