"""Several results drawn over each other in the NFRC's plane (max and min of each output against
omega): an NFRC with its backbone, the branches switched at its BP and PD points, isolas,
limit-point curves. What `hbtrack plot DIR DIR2 ...` and the study's NFRC figure draw. Each
result has its own colour and one legend entry saying what it is (never its folder's name: a
reader of the figure has no folders); stable parts solid, unstable dashed; special points marked
by type (a marker per type in the legend rather than a text per point: a switched branch has
dozens). A continuation at a fixed omega is a vertical segment in that plane: it gets its own
axes against its parameter. A branch switched at a symmetry-breaking BP holds two mirror images
(x1 and x2 swapped); drawn together, every output's envelope is the same: the first is drawn,
and the legend says so.
"""
import os

import numpy as np

from .figure_style import SPECIAL_MARKERS, OMEGA_LABEL, _plot_split, _stable_masks, length_label, plt, stability_legend
from .results import output_names, tracking_curve
from .special_points import CurveExtremumType, SpecialPointType

# Results whose parameter values the legend does not give (they vary one, or have no forcing).
NO_PARAMETER_VALUE = ("continue", "track", "backbone")
# Results that live in the (omega, output) plane.
FREQUENCY_PLANE_KINDS = ("frc", "solve", "isola_branch", "isolas", "switch", "backbone", "track")


def describe(result):
    """The legend text of a result: its folder's name and what it is.

    Parameters
    ----------
    result : dict
        A result (read_result or the API); ``label`` wins when set.

    Returns
    -------
    str
        E.g. "backbone of mode 1" or "branch switched at the BP at ω = 1.082".

    Examples
    --------
    >>> describe({"kind": "backbone", "folder": "out/bb", "summary": {"options": {"backbone": {"mode": 1}}}})
    'backbone of mode 1'
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
        what = f"continuation in {c['parameter']} at ω = {c['omega']:g}"
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
    return what


def _parameters_text(results):
    """The named parameters in which results differ, "speed = 1680" each ("" for one that has
    none of them, as a case without a speed at all); None when that does not tell them apart."""
    values = [r["summary"].get("options", {}).get("parameters", {}) for r in results]
    differing = sorted({k for v in values for k in v if any(w.get(k) != v.get(k) for w in values)})
    texts = [", ".join(f"{k} = {v[k]:.6g}" for k in differing if k in v) for v in values]
    return texts if differing and len(set(texts)) == len(texts) else None


def _harmonics_text(result):
    listed = result["summary"].get("options", {}).get("harmonic_balance", {}).get("harmonics")
    return f"H = {listed}" if isinstance(listed, int) else f"harmonics {', '.join(map(str, listed))}" if listed else None


def legend_labels(results):
    """The legend texts of results drawn together: describe's, told apart where two would read
    the same, by the harmonics balanced, else by a number ("NFRC", "NFRC, branch 2").

    Parameters
    ----------
    results : sequence of dict
        The results, in drawing order.

    Returns
    -------
    list of str
        One text per result, no two equal.

    Examples
    --------
    >>> legend_labels([read_result("out/duffing"), read_result("out/duffing_odd")])
    ['NFRC, H = 7', 'NFRC, harmonics 1, 3, 5, 7']
    """
    labels = [describe(r) for r in results]
    for text in set(labels):
        same = [i for i, t in enumerate(labels) if t == text]
        if len(same) < 2:
            continue
        harmonics = [_harmonics_text(results[i]) for i in same]
        parameters = _parameters_text([results[i] for i in same])
        if None not in harmonics and len(set(harmonics)) == len(same):
            for i, h in zip(same, harmonics):
                labels[i] = f"{text}, {h}"
        elif parameters:
            for i, p in zip(same, parameters):
                labels[i] = f"{text}, {p}" if p else text
        else:
            for k, i in enumerate(same[1:], start=2):
                labels[i] = f"{text}, branch {k}"
    return labels


def _distance(branch, rows_a, rows_b, a, b):
    """The 95th percentile of the distance from the rows_b points (omega, max b) to the nearest
    rows_a point (omega, max a), in units of the branch's ranges."""
    omega = np.asarray(branch["omega"], float)
    scale = np.array([np.ptp(omega) or 1.0, np.ptp(branch[f"max_{a}"]) or 1.0])
    one = np.column_stack([omega[rows_a], np.asarray(branch[f"max_{a}"], float)[rows_a]]) / scale
    two = np.column_stack([omega[rows_b], np.asarray(branch[f"max_{b}"], float)[rows_b]]) / scale
    return np.quantile(np.min(np.hypot(*(two[:, None, :] - one[None, :, :]).transpose(2, 0, 1)), axis=1), 0.95)


# Two stretches of a branch are the same curve when every point of one lies within this fraction
# of the branch's ranges of the other (their continuation steps differ, so points do not match).
_SAME_CURVE = 0.04


def distinct_part(result):
    """The part of a switched branch that is drawn: its first leg when the second retraces it, and
    at a symmetry-breaking BP only the first of its two mirror images.

    `switch` at a BP follows the branch both ways from it; on a closed branch both legs go round
    the same loop (every special point twice), and the loop is the asymmetric motion and its
    mirror image (two outputs swapped) joined at the BPs: drawn whole, each output's envelope is
    the other's and the symmetry breaking cannot be seen.

    Parameters
    ----------
    result : dict
        Any result.

    Returns
    -------
    (dict, tuple of str or None)
        The result cut to its distinct part (itself when nothing repeats) and the two outputs the
        omitted mirror image swaps (None when none was omitted).

    Examples
    --------
    >>> part, swapped = distinct_part(read_result("out/switched"))
    >>> swapped
    ('x1', 'x2')
    """
    summary = result.get("summary", {})
    legs, options = summary.get("legs", []), summary.get("options", {}).get("switch", {})
    if result.get("kind") != "switch" or options.get("type") != SpecialPointType.BRANCH_POINT:
        return result, None
    branch, names = result["branch"], output_names(result)
    count = len(branch["omega"])
    end = count
    if len(legs) == 2 and 2 < legs[0]["points"] < count - 2:
        first = legs[0]["points"]
        if all(_distance(branch, slice(0, first), slice(first, count), n, n) < _SAME_CURVE for n in names):
            end = first  # the second leg went round the same loop
    swapped = None
    inner = sorted(sp["index"] for sp in result.get("special_points", [])
                   if sp["type"] == SpecialPointType.BRANCH_POINT and 2 < sp.get("index", 0) < end - 2)
    if inner:
        k = inner[0]
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                if (_distance(branch, slice(0, k + 1), slice(k, end), a, b) < _SAME_CURVE
                        and _distance(branch, slice(0, k + 1), slice(k, end), b, a) < _SAME_CURVE
                        and _distance(branch, slice(0, k + 1), slice(k, end), a, a) > 2 * _SAME_CURVE):
                    swapped, end = (a, b), k + 1
                    break
            if swapped:
                break
    if end == count:
        return result, None
    cut = dict(result, branch={key: np.asarray(v)[:end] for key, v in branch.items()},
               special_points=[sp for sp in result.get("special_points", []) if sp.get("index", 0) < end])
    return cut, swapped


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
        return omega, branch[f"max_{name}"], branch[f"min_{name}"], np.ones(len(omega), bool), unstable, {"lw": 2.2, "alpha": 0.85}
    return omega, branch[f"max_{name}"], branch[f"min_{name}"], stable, unstable, {}


def _draw(ax, x, y, stable, unstable, colour, label, style):
    if style.get("ls") == ":" or stable.all():
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
    for number, (result, text) in enumerate(zip(results, legend_labels(results))):
        colour = f"C{number}"
        values = {} if result["kind"] in NO_PARAMETER_VALUE else result["summary"].get("options", {}).get("parameters", {})
        result, swapped = distinct_part(result)
        label = ", ".join([text] + [f"{p} = {values[p]:g}" for p in varying if p in values])
        if swapped:
            label += f" (one half; its mirror swaps {swapped[0]}, {swapped[1]})"
        for k, branch in enumerate(_branches(result)):
            omega, high, low, stable, unstable, style = _curves(branch, name)
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
    """Results of the same case overlaid on the NFRC's axes: max and min of each output against omega;
    continuations at a fixed omega beside them, against their parameter.

    Parameters
    ----------
    results : sequence of dict
        Results of kinds frc, solve, isolas, isola_branch, switch, backbone, continue (beside,
        against its parameter) or track (its limit points' max and min, dotted).
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
        if result["kind"] not in FREQUENCY_PLANE_KINDS + ("continue",):
            raise ValueError(f"{result.get('folder', 'a result')}: a '{result['kind']}' result has no branch in the (omega, output) plane")
    names = outputs or [n for n in output_names(results[0]) if all(n in output_names(b) for r in results for b in _branches(r))]
    if not names:
        raise ValueError("overlay_figure: the results record no common output (results of different cases?)")
    plane = [r for r in results if r["kind"] != "continue"]
    continued = [r for r in results if r["kind"] == "continue"]
    columns = (1 if plane else 0) + (1 if continued else 0)
    fig, axes = plt.subplots(len(names), columns, figsize=(7.5 if columns == 1 else 11, 3.4 * len(names) + 0.5), squeeze=False)
    for row, name in enumerate(names):
        if plane:
            draw_overlay(axes[row, 0], plane, name, length_unit, window or _window(plane), legend=False)
        if continued:
            _draw_continuations(axes[row, -1], continued, plane, name, length_unit, first_colour=len(plane))
    if title:
        axes[0, 0].set_title(title, fontsize=10)
    # One legend for all panels, below them: inside an axes it hides curves (a switched
    # branch's fold sits where "best" puts it), and every panel has the same entries. The
    # results (long names) in one column on the left, the marker types on the right; the
    # figure grows by the legend's height.
    entries = {}
    for ax in axes.flat:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            entries.setdefault(label, handle)
    marker_labels = {text for _, text in SPECIAL_MARKERS.values()}
    curves = [(h, l) for l, h in entries.items() if l not in marker_labels]
    markers = [(h, l) for l, h in entries.items() if l in marker_labels]
    styles = stability_legend([b["branch"] for r in results if r["kind"] not in ("backbone", "track") for b in _branches(r)])
    markers = [(h, h.get_label()) for h in styles] + markers
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


def _draw_continuations(ax, continued, plane, name, length_unit, first_colour):
    """Continuations at a fixed omega against their parameter, beside the frequency plane: the
    fixed omega drawn there as a dotted line, and here the plane's NFRC's value of the parameter,
    the one point both show."""
    from .figure_style import parameter_label
    param = continued[0]["summary"]["options"]["continue"]["parameter"]
    types = set()
    for number, (result, label) in enumerate(zip(continued, legend_labels(continued))):
        colour, branch = f"C{first_colour + number}", result["branch"]
        stable, unstable = _stable_masks(branch)
        for key in (f"max_{name}", f"min_{name}"):
            _draw(ax, branch[param], branch[key], stable, unstable, colour, label if key.startswith("max") else None, {})
            for sp in result.get("special_points", []):
                if sp.get("type") in SPECIAL_MARKERS and key in sp and param in sp:
                    types.add(sp["type"])
                    ax.plot(sp[param], sp[key], SPECIAL_MARKERS[sp["type"]][0], color=colour, mec="k", mew=0.7, ms=5, zorder=5)
        omega = result["summary"]["options"]["continue"]["omega"]
        if plane:  # where this continuation cuts the frequency plane
            plane_ax = ax.figure.axes[list(ax.figure.axes).index(ax) - 1]
            plane_ax.axvline(omega, color=colour, lw=0.8, ls=":", label=f"ω = {omega:g}, where the continuation runs")
    for t in sorted(types, key=list(SPECIAL_MARKERS).index):
        ax.plot([], [], SPECIAL_MARKERS[t][0], color="w", mec="k", ms=5, label=SPECIAL_MARKERS[t][1])
    values = {r["summary"].get("options", {}).get("parameters", {}).get(param) for r in plane if r["kind"] not in NO_PARAMETER_VALUE}
    for value in sorted(v for v in values if v is not None):
        ax.axvline(value, color="0.5", lw=0.8, ls=":", label=f"{param} = {value:g}, the NFRC's")
    ax.set_xlabel(parameter_label(param, length_unit))
    ax.set_ylabel(length_label(f"max and min of {name}", length_unit))
    ax.grid(alpha=0.3)
