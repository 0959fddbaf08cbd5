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
# Units of the usual tracking parameters; any other named parameter is in the case's units. An axis
# label is a name and a unit: what the amplitude scales is the caption's to say.
PARAMETER_UNITS = {"amplitude": "-", "mu": "-", "clearance": MODEL_LENGTH}
# Marker of each special point type (LP, BP, PD, NS on branches; min, max of the parameter on
# tracking curves; GR, grazing, in the exact-shooting references of tests/data/shooting) and its
# legend text: every figure marks a type the same way, and a legend entry per type names the
# markers (no unexplained dot).
SPECIAL_MARKERS = {"LP": ("o", "LP (fold)"), "BP": ("s", "BP (branch point)"), "PD": ("D", "PD (period doubling)"),
                   "NS": ("P", "NS (Neimark-Sacker)"), "min": ("v", "min of the tracked parameter"),
                   "max": ("^", "max of the tracked parameter"), "GR": ("x", "GR (grazing: a contact starts or ends)")}


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


def marker_legend(types, colour="w"):
    """Legend handles, one per special point type drawn, in SPECIAL_MARKERS' order.

    Parameters
    ----------
    types : iterable of str
        The types drawn ("LP", "NS", ...); others are ignored.
    colour : str, optional
        The markers' face colour in the legend.

    Returns
    -------
    list of matplotlib.lines.Line2D
        Handles labelled "LP (fold)", ...

    Examples
    --------
    >>> [h.get_label() for h in marker_legend({"NS", "LP"})]
    ['LP (fold)', 'NS (Neimark-Sacker)']
    """
    from matplotlib.lines import Line2D
    types = set(types)
    return [Line2D([], [], marker=marker, color=colour, mec="k", ls="none", ms=5, label=text)
            for kind, (marker, text) in SPECIAL_MARKERS.items() if kind in types]


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
    """(stable, unstable) point masks; both False where stability was not computed (a study's
    validation NFRCs, DLFT), which _plot_split draws dotted: solid would claim stability."""
    stable = branch.get("stable")
    if stable is None:
        return np.zeros(len(branch["omega"]), bool), np.zeros(len(branch["omega"]), bool)
    stable = np.asarray(stable)
    return stable == 1, stable == 0


def stability_legend(branches):
    """Legend handles for the line styles the branches are drawn with: "stable" (solid) and
    "unstable" (dashed) when any point is unstable, "stability not computed" (dotted) when a
    branch has none.

    Parameters
    ----------
    branches : sequence of dict
        The branches drawn ({column: array}).

    Returns
    -------
    list of matplotlib.lines.Line2D

    Examples
    --------
    >>> [h.get_label() for h in stability_legend([{"omega": [1.0, 2.0], "stable": [1, 0]}])]
    ['stable', 'unstable']
    """
    from matplotlib.lines import Line2D
    masks = [_stable_masks(b) for b in branches]
    handles = []
    if any(u.any() for _, u in masks):
        handles += [Line2D([], [], color="0.3", ls="-", lw=1.3, label="stable"), Line2D([], [], color="0.3", ls="--", lw=1.3, label="unstable")]
    if any((~s & ~u).any() for s, u in masks):
        handles.append(Line2D([], [], color="0.3", ls=":", lw=1.5, label="stability not computed"))
    return handles


def _plot_split(ax, x, y, stable, unstable, colour, label, lw=1.3, alpha=1.0):
    """Stable segments solid, unstable dashed, points of unknown stability dotted; a segment
    joining a stable and an unstable point is drawn dashed so that the curve stays connected."""
    if len(x) == 1:
        ax.plot(x, y, "o", color=colour, label=label)
        return
    unknown = ~stable & ~unstable
    if unknown.all():
        ax.plot(x, y, ":", color=colour, lw=lw + 0.2, alpha=alpha, label=label)
        return
    solid = np.where(stable, y, np.nan)
    dashed = np.where(unstable | np.roll(unstable, 1) | np.roll(unstable, -1), y, np.nan)
    ax.plot(x, solid, "-", color=colour, lw=lw, alpha=alpha, label=label)
    if unstable.any():
        ax.plot(x, dashed, "--", color=colour, lw=lw, alpha=alpha)
    if unknown.any():
        ax.plot(x, np.where(unknown | np.roll(unknown, 1) | np.roll(unknown, -1), y, np.nan), ":", color=colour, lw=lw + 0.2, alpha=alpha)
