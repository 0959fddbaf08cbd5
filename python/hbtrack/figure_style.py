"""What every hbtrack figure shares: the matplotlib set-up (files, no display), axis labels with
units, stable segments solid and unstable dashed, and save_figure. The figure modules (plots,
branch_figures, overlay_figures, analysis_figures, study_paper_figures) import it; it imports
none of them.
"""
import os

import matplotlib

if "MPLBACKEND" not in os.environ:
    matplotlib.use("Agg")  # figures go to files; no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

OMEGA_LABEL = r"$\omega$ [rad/s]"
MODEL_LENGTH = "model length unit"
# Units of the usual tracking parameters; any other named parameter is in the case's units.
PARAMETER_UNITS = {"amplitude": "-, scales the case's forcing", "mu": "-", "clearance": MODEL_LENGTH}


def length_label(what, unit=None):
    """An axis label with a length unit.

    Parameters
    ----------
    what : str
        The quantity.
    unit : str, optional
        Its unit (default: "model length unit").

    Returns
    -------
    str
        "what [unit]".

    Examples
    --------
    >>> length_label("max x", "m")
    'max x [m]'
    """
    return f"{what} [{unit or MODEL_LENGTH}]"


def parameter_label(name, length_unit=None):
    """An axis label for a named parameter, with its unit.

    Parameters
    ----------
    name : str
        The parameter ("amplitude", "mu", "clearance", ...).
    length_unit : str, optional
        The model's length unit, for length parameters.

    Returns
    -------
    str
        "name [unit]".

    Examples
    --------
    >>> parameter_label("clearance", "m")
    'clearance [m]'
    """
    unit = PARAMETER_UNITS.get(name, "case units")
    if unit == MODEL_LENGTH and length_unit:
        unit = length_unit
    return f"{name} [{unit}]"


def save_figure(fig, path):
    """Writes a figure as PNG and PDF.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : str
        PATH without extension; its folder is created.

    Returns
    -------
    list of str
        [PATH.png, PATH.pdf].

    Examples
    --------
    >>> save_figure(nfrc_figure(nfrc), "out/nfrc")
    ['out/nfrc.png', 'out/nfrc.pdf']
    """
    folder = os.path.dirname(path)
    if folder:
        os.makedirs(folder, exist_ok=True)
    files = [f"{path}.png", f"{path}.pdf"]
    fig.savefig(files[0], dpi=150)
    fig.savefig(files[1])
    plt.close(fig)
    return files


def _stable_masks(branch):
    """(stable, unstable) point masks; every point stable when stability was not computed."""
    stable = branch.get("stable")
    if stable is None:
        return np.ones(len(branch["omega"]), bool), np.zeros(len(branch["omega"]), bool)
    return stable == 1, stable == 0


def _plot_split(ax, x, y, stable, unstable, colour, label):
    """Stable segments solid, unstable dashed; a segment joining a stable and an unstable point
    is drawn dashed so that the curve stays connected."""
    if len(x) == 1:
        ax.plot(x, y, "o", color=colour, label=label)
        return
    solid = np.where(stable, y, np.nan)
    dashed = np.where(unstable | np.roll(unstable, 1) | np.roll(unstable, -1), y, np.nan)
    ax.plot(x, solid, "-", color=colour, lw=1.3, label=label)
    if unstable.any():
        ax.plot(x, dashed, "--", color=colour, lw=1.3)
