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


def zoom_small_curves(ax, curves, fraction=0.08, size=0.3):
    """An inset zoom on each curve too small to be seen among the axes' markers: one whose
    extent is under `fraction` of both axis spans (rotor 67's closed limit-point curve in mu, 35
    rad/s by 0.005, hidden under its own extrema's markers). Small curves whose boxes overlap
    share an inset. Every line of the axes is drawn again in the inset, placed in the corner that
    covers the fewest of their points.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes, with its limits final.
    curves : sequence of (x, y)
        The curves to check, in data coordinates.
    fraction : float, optional
        A curve narrower and lower than this share of the axis spans is zoomed.
    size : float, optional
        The inset's width and height, in axes fractions.

    Returns
    -------
    list of matplotlib.axes.Axes
        The insets made (at most two).

    Examples
    --------
    >>> insets = zoom_small_curves(ax, [(omega, mu)])
    """
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    small = [(np.asarray(x, float), np.asarray(y, float)) for x, y in curves if len(x) > 1
             and np.ptp(x) < fraction * (x1 - x0) and np.ptp(y) < fraction * (y1 - y0)]
    groups = []  # small curves whose boxes overlap share one inset
    for x, y in small:
        for g, (gx, gy) in enumerate(groups):
            if x.min() <= gx.max() and gx.min() <= x.max() and y.min() <= gy.max() and gy.min() <= y.max():
                groups[g] = (np.concatenate([gx, x]), np.concatenate([gy, y]))
                break
        else:
            groups.append((x, y))
    small = groups[:2]
    if not small:
        return []
    points = []  # every drawn point in axes fractions, to choose the emptiest corner
    for line in ax.get_lines():
        x, y = np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)
        points.append(np.c_[(x - x0) / (x1 - x0), (y - y0) / (y1 - y0)])
    points = np.concatenate(points) if points else np.empty((0, 2))
    # Inset from the axes' edges by its own tick labels' room (left, bottom), which must not sit on the axes' own
    corners = {(0.1, 0.1), (0.98 - size, 0.1), (0.1, 0.97 - size), (0.98 - size, 0.97 - size)}
    insets = []
    for x, y in small:
        def covered(corner):
            # the inset's rectangle, grown by a margin, and the zoomed curve kept out from under it
            cx, cy = corner
            inside = ((points[:, 0] > cx - 0.1) & (points[:, 0] < cx + size + 0.02)
                      & (points[:, 1] > cy - 0.1) & (points[:, 1] < cy + size + 0.02))
            own = (cx - 0.05 < (x.mean() - x0) / (x1 - x0) < cx + size + 0.05) and (cy - 0.05 < (y.mean() - y0) / (y1 - y0) < cy + size + 0.05)
            return inside.sum() + (10 ** 9 if own else 0)
        corner = min(sorted(corners), key=covered)
        corners.discard(corner)
        inset = ax.inset_axes([corner[0], corner[1], size, size])
        for line in ax.get_lines():
            inset.plot(line.get_xdata(), line.get_ydata(), ls=line.get_linestyle(), lw=line.get_linewidth(), color=line.get_color(),
                       marker=line.get_marker(), ms=line.get_markersize() * 0.8, mfc=line.get_markerfacecolor(),
                       mec=line.get_markeredgecolor(), zorder=line.get_zorder())
        pad_x, pad_y = 0.15 * max(np.ptp(x), 1e-12), 0.15 * max(np.ptp(y), 1e-12)
        inset.set_xlim(x.min() - pad_x, x.max() + pad_x)
        inset.set_ylim(y.min() - pad_y, y.max() + pad_y)
        inset.tick_params(labelsize=6)
        inset.grid(alpha=0.3)
        ax.indicate_inset_zoom(inset, edgecolor="0.4")
        insets.append(inset)
    return insets
