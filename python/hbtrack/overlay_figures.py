"""Several results drawn over each other in the NFRC's plane (max and min of each output against
omega): an NFRC with its backbone, the branches switched at its BP and PD points, isolas,
limit-point curves, a continuation at its fixed omega. What `hbtrack plot DIR DIR2 ...` and the
study's NFRC figure draw. Each result has its own colour and one legend entry naming its folder
and what it is; stable parts solid, unstable dashed; special points marked by type (a marker
per type in the legend rather than a text per point: a switched branch has dozens).
"""
import os

import numpy as np

from .figure_style import OMEGA_LABEL, _plot_split, _stable_masks, length_label, plt
from .results import output_names, tracking_curve
from .special_points import CurveExtremumType, SpecialPointType

# Marker of each special point type (LP, BP, PD, NS on branches; min, max of the parameter on
# limit-point curves), and its legend text.
SPECIAL_MARKERS = {SpecialPointType.LIMIT_POINT: ("o", "LP (fold)"), SpecialPointType.BRANCH_POINT: ("s", "BP (branch point)"),
                   SpecialPointType.PERIOD_DOUBLING: ("D", "PD (period doubling)"),
                   SpecialPointType.NEIMARK_SACKER: ("P", "NS (Neimark-Sacker)"),
                   CurveExtremumType.PARAMETER_MIN: ("v", "min of the tracked parameter"),
                   CurveExtremumType.PARAMETER_MAX: ("^", "max of the tracked parameter")}
# Results whose parameter values the legend does not give (they vary one, or have no forcing).
NO_PARAMETER_VALUE = ("continue", "track", "backbone")
# Results that live in the (omega, output) plane.
FREQUENCY_PLANE_KINDS = ("frc", "solve", "isola_branch", "isolas", "switch", "backbone", "continue", "track")


def describe(result):
    """The legend text of a result: its folder's name and what it is.

    Parameters
    ----------
    result : dict
        A result (read_result or the API); ``label`` wins when set.

    Returns
    -------
    str
        E.g. "bb: backbone of mode 1" or "switched: branch switched at the BP at omega = 1.082".

    Examples
    --------
    >>> describe({"kind": "backbone", "folder": "out/bb", "summary": {"options": {"backbone": {"mode": 1}}}})
    'bb: backbone of mode 1'
    """
    if result.get("label"):
        return result["label"]
    kind, options = result["kind"], result["summary"].get("options", {})
    if kind == "backbone":
        what = f"backbone of mode {options['backbone']['mode']}"
    elif kind == "switch":
        s = options["switch"]
        what = (f"period-doubled branch of the PD at ω = {s['omega']:.5g}" if s["type"] == SpecialPointType.PERIOD_DOUBLING
                else f"branch switched at the {s['type']} at ω = {s['omega']:.5g}")
    elif kind == "continue":
        c = options["continue"]
        what = f"{c['parameter']} from {c['range'][0]:g} to {c['range'][1]:g} at ω = {c['omega']:g}"
    elif kind == "track":
        t = options["tracking"]
        start = f"LP{t['lp']}" if t.get("lp_order") == "omega" else f"limit point {t.get('lp', '')}".rstrip()
        what = f"{start} tracked in {t['parameter']}"
    elif kind == "isola_branch":
        what = "isolated branch"
    elif kind == "isolas":
        what = "branches found by isolas"
    elif kind == "solve":
        what = "solve"
    else:
        what = "NFRC"
    folder = os.path.basename(os.path.normpath(result["folder"])) if result.get("folder") else ""
    return f"{folder}: {what}" if folder else what


def _branches(result):
    """The drawable branches of a result: an isolas result is its branches."""
    if result["kind"] == "isolas":
        return list(result["branches"].values())
    return [result]


def _curves(result, name):
    """(omega, max, min, stable, unstable, style) of one result in the (omega, output) plane."""
    kind = result["kind"]
    if kind == "track":
        curve = tracking_curve(result)
        n = len(curve["omega"])
        return curve["omega"], curve[f"max_{name}"], curve[f"min_{name}"], np.ones(n, bool), np.zeros(n, bool), {"ls": ":", "lw": 1.4}
    branch = result["branch"]
    omega = branch["omega"]
    stable, unstable = _stable_masks(branch)
    if kind == "backbone":  # no stability: the EPMC motion is not a motion of the forced system
        return omega, branch[f"max_{name}"], branch[f"min_{name}"], stable, unstable, {"lw": 2.2, "alpha": 0.85}
    return omega, branch[f"max_{name}"], branch[f"min_{name}"], stable, unstable, {}


def _draw(ax, x, y, stable, unstable, colour, label, style):
    if style.get("ls") == ":" or not unstable.any():
        ax.plot(x, y, style.get("ls", "-"), color=colour, lw=style.get("lw", 1.3), alpha=style.get("alpha", 1.0), label=label)
    else:
        _plot_split(ax, x, y, stable, unstable, colour, label)


def _varying_parameters(results):
    """The named parameters whose values differ between the results (NFRCs at several forcing
    levels): the legend gives each result's value. A continuation and a limit-point curve vary
    their own parameter; a backbone has no forcing."""
    values = {}
    for result in results:
        if result["kind"] in NO_PARAMETER_VALUE:
            continue
        for name, value in result["summary"].get("options", {}).get("parameters", {}).items():
            values.setdefault(name, set()).add(value)
    return sorted(name for name, seen in values.items() if len(seen) > 1)


def _window(results):
    """The omega range of the results that are responses (not backbones): the figure's x range."""
    spans = [(np.min(r["branch"]["omega"]), np.max(r["branch"]["omega"]))
             for result in results for r in _branches(result)
             if r["kind"] not in ("backbone", "track", "continue") and len(r["branch"]["omega"])]
    if not spans:
        return None
    return min(s[0] for s in spans), max(s[1] for s in spans)


def _fit_y(ax, window):
    """Y limits from the data drawn inside the x window (matplotlib scales to all of it)."""
    lo, hi = np.inf, -np.inf
    for line in ax.get_lines():
        x, y = (np.asarray(v, dtype=float) for v in line.get_data())
        inside = (x >= window[0]) & (x <= window[1]) & np.isfinite(y)
        if inside.any():
            lo, hi = min(lo, y[inside].min()), max(hi, y[inside].max())
    if np.isfinite(lo) and hi > lo:
        margin = 0.05 * (hi - lo)
        ax.set_ylim(lo - margin, hi + margin)


def draw_overlay(ax, results, name, length_unit=None, window=None, legend=True):
    """Draws results over each other on one axes: max and min of one output against omega.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    results : sequence of dict
        As for :func:`overlay_figure`.
    name : str
        The output drawn.
    length_unit : str, optional
        The model's length unit for the labels.
    window : tuple of float, optional
        (lo, hi) omega range shown, y fitted to what lies in it (default: all).
    legend : bool, optional
        A legend inside the axes (default); False leaves it to the caller.

    Returns
    -------
    matplotlib.axes.Axes
        `ax`.

    Examples
    --------
    >>> draw_overlay(ax, [nfrc, switched], "x2", window=(0.75, 0.78))
    """
    types = set()
    varying = _varying_parameters(results)
    for number, result in enumerate(results):
        colour = f"C{number}"
        values = {} if result["kind"] in NO_PARAMETER_VALUE else result["summary"].get("options", {}).get("parameters", {})
        label = ", ".join([describe(result)] + [f"{p} = {values[p]:g}" for p in varying if p in values])
        for k, branch in enumerate(_branches(result)):
            omega, high, low, stable, unstable, style = _curves(branch, name)
            if branch["kind"] == "continue":  # a fixed omega: the branch is a vertical segment
                omega = np.full(len(high), branch["summary"]["options"]["continue"]["omega"])
            _draw(ax, omega, high, stable, unstable, colour, label if k == 0 else None, style)
            _draw(ax, omega, low, stable, unstable, colour, None, style)
            for sp in branch.get("special_points", []):
                if sp.get("type") not in SPECIAL_MARKERS:
                    continue
                for key in (f"max_{name}", f"min_{name}"):
                    if key in sp:
                        types.add(sp["type"])
                        ax.plot(sp["omega"], sp[key], SPECIAL_MARKERS[sp["type"]][0], color=colour, mec="k", mew=0.7, ms=5, zorder=5)
    for t in sorted(types, key=list(SPECIAL_MARKERS).index):
        ax.plot([], [], SPECIAL_MARKERS[t][0], color="w", mec="k", ms=5, label=SPECIAL_MARKERS[t][1])
    if window:
        margin = 0.02 * (window[1] - window[0])
        ax.set_xlim(window[0] - margin, window[1] + margin)
        _fit_y(ax, ax.get_xlim())
    ax.set_xlabel(OMEGA_LABEL)
    ax.set_ylabel(length_label(f"max and min of {name}", length_unit))
    ax.grid(alpha=0.3)
    if legend:
        ax.legend(fontsize=7.5, loc="best", framealpha=0.85)
    return ax


def overlay_figure(results, outputs=None, length_unit=None, title=None, window=None):
    """Results of the same case overlaid on the NFRC's axes: max and min of each output against omega.

    Parameters
    ----------
    results : sequence of dict
        Results of kinds frc, solve, isolas, isola_branch, switch, backbone, continue (drawn at
        its fixed omega) or track (its limit points' max and min, dotted).
    outputs : list of str, optional
        The outputs drawn (default: those every result records).
    length_unit : str, optional
        The model's length unit for the labels.
    title : str, optional
        The figure's title.
    window : tuple of float, optional
        (lo, hi) omega range shown (default: the responses' range, a backbone clipped to it).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = overlay_figure([read_result("out/duffing"), read_result("out/bb"), read_result("out/switched")])
    """
    results = list(results)
    for result in results:
        if result["kind"] not in FREQUENCY_PLANE_KINDS:
            raise ValueError(f"{result.get('folder', 'a result')}: a '{result['kind']}' result has no branch in the (omega, output) plane")
    names = outputs or [n for n in output_names(results[0]) if all(n in output_names(b) for r in results for b in _branches(r))]
    if not names:
        raise ValueError("overlay_figure: the results record no common output (results of different cases?)")
    fig, axes = plt.subplots(len(names), 1, figsize=(7.5, 3.4 * len(names) + 0.5), squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        draw_overlay(ax, results, name, length_unit, window or _window(results), legend=False)
    axes[0, 0].set_title(title or "solid: stable, dashed: unstable", fontsize=10)
    # One legend for all panels, below them: inside an axes it hides curves (a switched
    # branch's fold sits where "best" puts it), and every panel has the same entries. The
    # results (long names) in one column on the left, the marker types on the right; the
    # figure grows by the legend's height.
    entries = {}
    for ax in axes[:, 0]:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            entries.setdefault(label, handle)
    marker_labels = {text for _, text in SPECIAL_MARKERS.values()}
    curves = [(h, l) for l, h in entries.items() if l not in marker_labels]
    markers = [(h, l) for l, h in entries.items() if l in marker_labels]
    rows = max(len(curves), len(markers))
    width, height = fig.get_size_inches()
    legend_height = 0.19 * rows + 0.2
    fig.set_size_inches(width, height + legend_height)
    top = legend_height / (height + legend_height)
    for group, corner, x in ((curves, "upper left", 0.01), (markers, "upper right", 0.99)):
        if group:
            fig.legend(*zip(*group), loc=corner, bbox_to_anchor=(x, top), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, top, 1, 1))
    return fig
