"""The branch figure of `hbtrack plot` (the NFRC: the paper's Fig. 3) and the Fourier coefficients
at one of its points (the paper's Fig. 5).

NFRC: per output the max and min over a period against omega (one axes per output), or with
norm=True the paper's form, ||r(t)||_inf = max(|max|, |min|) of every output in one axes. Stable
solid, unstable dashed; special points numbered per type in omega order over all the branches
drawn (LP1, LP2, ... NS1), marked by type on every curve through them (a legend entry per type),
each named once per axes, coincident ones merged ("LP2, NS1"), placed where they overlap no other
text (label_layout); branches overlaid are drawn widest first, so that one lying on another shows
as a thin line inside a wide pale one rather than hiding it; zoomed on the resonance unless zoom=None; outputs named by their descriptions
(output_descriptions). Lengths are drawn as the result holds them: units.scale_lengths converts.
"""
import re

import numpy as np
from matplotlib.lines import Line2D

from .label_layout import place_labels
from .output_descriptions import output_descriptions
from .figure_style import OMEGA_LABEL, SPECIAL_MARKERS, _plot_split, _stable_masks, length_label, marker_legend, plt, stability_legend
from .results import output_names
from .special_points import distinct_special_points, numbered_special_points

# Zoom: the window where the response exceeds this fraction of its peak, widened by this part of
# its width on each side; no zoom when that window already covers most of the branch.
ZOOM_FRACTION = 0.1
ZOOM_MARGIN = 0.25
ZOOM_USELESS = 0.7
NORM_LABEL = r"$\Vert r(t) \Vert_\infty$"


def norm_of(columns, name):
    """||x(t)||_inf = max(|max_NAME|, |min_NAME|) of a branch or special point.

    Parameters
    ----------
    columns : dict
        A branch ({column: array}) or a special point ({column: value}).
    name : str
        The output.

    Returns
    -------
    numpy.ndarray
        The norm at each point (0-d for a special point).

    Examples
    --------
    >>> float(norm_of({"max_x": 0.5, "min_x": -1.5}, "x"))
    1.5
    """
    return np.maximum(np.abs(np.asarray(columns[f"max_{name}"], float)), np.abs(np.asarray(columns[f"min_{name}"], float)))


def resonance_window(branches, names, fraction=ZOOM_FRACTION, margin=ZOOM_MARGIN):
    """The omega window of the resonance: where the response of any output on any branch exceeds
    `fraction` of its largest value, widened by `margin` of its width each side.

    Parameters
    ----------
    branches : sequence of dict
        Branches ({column: array}) drawn together.
    names : sequence of str
        The outputs drawn.
    fraction : float, optional
        Of the peak response.
    margin : float, optional
        Of the window's width, added each side.

    Returns
    -------
    (lo, hi) or None
        None when the window would show most of the branches anyway.

    Examples
    --------
    >>> resonance_window([nfrc["branch"]], ["x"])
    (1.02, 1.61)
    """
    omegas = np.concatenate([np.asarray(b["omega"], float) for b in branches])
    response = np.concatenate([np.max([norm_of(b, n) for n in names], axis=0) for b in branches])
    if not len(omegas) or not np.isfinite(response).any():
        return None
    loud = omegas[response >= fraction * np.nanmax(response)]
    full = omegas.max() - omegas.min()
    lo, hi = loud.min(), loud.max()
    width = max(hi - lo, 0.02 * full)
    lo, hi = max(lo - margin * width, omegas.min()), min(hi + margin * width, omegas.max())
    return None if full <= 0 or hi - lo >= ZOOM_USELESS * full else (lo, hi)


def _fit_y_to_window(ax, window):
    """matplotlib does not rescale y to the visible x: the limits of the data inside the window."""
    ax.set_xlim(*window)
    values = []
    for line in ax.get_lines():
        x, y = (np.asarray(v, float) for v in line.get_data())
        values.append(y[(x >= window[0]) & (x <= window[1]) & np.isfinite(y)])
    values = np.concatenate(values) if values else np.zeros(0)
    if len(values):
        pad = 0.06 * max(np.ptp(values), 1e-12 * max(abs(values).max(), 1e-300))
        ax.set_ylim(values.min() - pad, values.max() + pad)


def _stability_legend(ax, branches):
    """Legend entries for the line styles (figure_style.stability_legend), instead of a title
    saying so."""
    return stability_legend(branches)


def _legend(ax, extra):
    """Above the axes, outside them: inside, 'best' still covers a peak or a labelled point."""
    handles, labels = ax.get_legend_handles_labels()
    labels += [h.get_label() for h in extra]
    # One row when short (each entry's handle and spacing take about 7 characters' width: six
    # entries of 60 characters in all ran past the axes); else two columns, each half the axes'
    # width: about 38 characters at this size beside the handle, so a longer label takes one
    # column (it ran into its neighbour).
    one_row = sum(len(t) for t in labels) + 7 * len(labels) <= 95
    columns = len(labels) if one_row else min(len(labels), 2 if max(map(len, labels)) <= 38 else 1)
    ax.legend(handles + extra, labels, fontsize=8, loc="lower left", bbox_to_anchor=(0, 1.01, 1, 0.1), ncol=columns,
              mode="expand" if columns > 1 else None, borderaxespad=0, frameon=False, handlelength=2.4)


def nfrc_figure(result, outputs=None, others=(), length_unit=None, title=None, zoom=ZOOM_FRACTION, norm=False,
                descriptions=None):
    """The NFRC: max and min over a period against omega, or ||r(t)||_inf.

    Parameters
    ----------
    result : dict
        A branch result (frc, solve, isola branch, switch), API or read_result.
    outputs : list of str, optional
        The outputs drawn (default all).
    others : sequence of dict, optional
        More branch results of the same case overlaid (e.g. isolas; "label" names them).
    length_unit : str, optional
        The unit of the lengths as the result holds them (units.scale_lengths), for the labels.
    title : str, optional
        The figure's title (default none: the legend says what is solid and dashed).
    zoom : float or None, optional
        Zoom on the omega window where the response exceeds this fraction of its peak; None: the
        whole branch.
    norm : bool, optional
        True: one axes, ||r(t)||_inf = max(|max|, |min|) of each output (the paper's Fig. 3).
    descriptions : dict, optional
        {output: text}; default output_descriptions(result).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = nfrc_figure(hbtrack.frc(case), length_unit="m")
    >>> fig = nfrc_figure(scale_lengths(r67, 1e3), length_unit="mm", norm=True)
    """
    names = outputs or output_names(result)
    if not names:
        raise ValueError("nfrc_figure: the result records no outputs")
    descriptions = {**output_descriptions(result), **(descriptions or {})}
    results = [result, *others]
    branches = [r["branch"] for r in results]
    panels = [names] if norm else [[name] for name in names]
    fig, axes = plt.subplots(len(panels), 1, figsize=(6.5, 4.2 if norm else 3.2 * len(panels)), squeeze=False)
    labels = {}  # axes: [(omega, value, text)]
    # Numbered over all the branches drawn, so that every label is unique without naming its branch.
    numbered = numbered_special_points(distinct_special_points([sp for r in results for sp in r.get("special_points", [])]))
    types = {sp["type"] for _, sp in numbered if sp["type"] in SPECIAL_MARKERS}
    unknown_everywhere = all(r["branch"].get("stable") is None for r in results)
    for ax, panel in zip(axes[:, 0], panels):
        for number, r in enumerate(results):
            stable, unstable = _stable_masks(r["branch"])
            if unknown_everywhere:  # solid, the legend saying none is known (dotted wide lines were unreadable)
                stable = np.ones_like(stable)
            tag = r.get("label", "" if number == 0 else f"branch {number + 1}")
            width = 1.3 + 2.2 * (len(results) - 1 - number)  # the first widest: a branch on another stays visible
            if norm:
                curves = [(descriptions[n] + (f" ({tag})" if tag else ""), norm_of(r["branch"], n)) for n in panel]
            elif len(results) == 1:
                curves = [("max over a period", r["branch"][f"max_{panel[0]}"]), ("min over a period", r["branch"][f"min_{panel[0]}"])]
            else:  # a colour per branch: its max is the upper curve, its min the lower
                curves = [(tag, r["branch"][f"max_{panel[0]}"]), (None, r["branch"][f"min_{panel[0]}"])]
            for side, (what, values) in enumerate(curves):
                colour = f"C{number}" if not norm and len(results) > 1 else f"C{len(curves) * number + side}"
                _plot_split(ax, r["branch"]["omega"], values, stable, unstable, colour, what,
                            lw=width, alpha=1.0 if number == len(results) - 1 else 0.55)
        for text, sp in numbered:
            values = [float(norm_of(sp, n)) if norm else sp.get(key) for n in panel
                      for key in ((n,) if norm else (f"max_{n}", f"min_{n}"))]
            values = [v for v in values if v is not None]
            if values and sp["type"] in SPECIAL_MARKERS:
                ax.plot([sp["omega"]] * len(values), values, SPECIAL_MARKERS[sp["type"]][0], color="k", mfc="w", mew=1.0, ms=5,
                        ls="none", zorder=5)
                labels.setdefault(ax, []).append((sp["omega"], max(values), text))
        ax.set_xlabel(OMEGA_LABEL)
        # One colour per branch when overlaid: the label says both curves are its; on two lines, as
        # a description beside "max and min of" ran past a panel's height.
        what = descriptions[panel[0]] if len(results) == 1 else f"max and min of\n{descriptions[panel[0]]}"
        ax.set_ylabel(length_label(NORM_LABEL if norm else what, length_unit))
        ax.grid(alpha=0.3)
        styles = [Line2D([], [], color="0.3", lw=1.3, label="stability not computed")] if unknown_everywhere else _stability_legend(ax, branches)
        _legend(ax, styles + marker_legend(types))
        window = resonance_window(branches, panel) if zoom else None
        if window:
            _fit_y_to_window(ax, window)
    if title:
        fig.suptitle(title, fontsize=10)  # the axes' top holds the legend
    fig.tight_layout()
    for ax, items in labels.items():
        place_labels(ax, items)
    return fig


def _harmonic_columns(branch, name):
    """[(K as text, column)] of the hK_NAME magnitudes, in increasing K (0.5 steps on a
    period-doubled branch)."""
    found = [(m.group(1), c) for c in branch for m in [re.match(rf"^h(\d+(?:\.\d+)?)_{re.escape(name)}$", c)] if m]
    return sorted(found, key=lambda kc: float(kc[0]))


def chosen_point(result, point=None):
    """The branch row the Fourier figure shows, and what it is.

    Parameters
    ----------
    result : dict
        A branch result.
    point : int or str, optional
        A row of branch.csv (0-based), or "LPk" (the k-th special point of that type in omega
        order, as the NFRC figure numbers them). Default: LP1, else the largest response.

    Returns
    -------
    (int, str)
        The row and its description ("LP1", "point 37").

    Examples
    --------
    >>> chosen_point(nfrc, "LP3")
    (512, 'LP3')
    """
    branch = result["branch"]
    count = len(branch["omega"])
    numbered = dict(numbered_special_points(result.get("special_points", [])))
    if point is None:
        point = "LP1" if "LP1" in numbered else None
    if point is None:
        names = output_names(result)
        return int(np.argmax(np.max([norm_of(branch, n) for n in names], axis=0))), "largest response"
    if isinstance(point, str) and not point.lstrip("-").isdigit():
        if point not in numbered:
            raise ValueError(f"--point {point}: the branch has {', '.join(numbered) or 'no special points'}")
        return min(int(numbered[point]["index"]), count - 1), point
    row = int(point)
    if not -count <= row < count:
        raise ValueError(f"--point {row}: the branch has {count} points (0 to {count - 1})")
    return row % count, f"point {row % count}"


def fourier_figure(result, point=None, outputs=None, length_unit=None, title=None, descriptions=None, where=None):
    """The magnitudes of the harmonics of each output at one point (the paper's Fig. 5).

    Bars h_K = sqrt(a_K^2 + b_K^2) (h_0 = |a_0/2|) from branch.csv's hK_NAME columns, one panel
    per output side by side.

    Parameters
    ----------
    result : dict
        A branch result whose branch has hK_ columns.
    point : int or str, optional
        See chosen_point (default LP1, else the largest response).
    outputs : list of str, optional
        Default all.
    length_unit : str, optional
        The unit of the lengths as the result holds them, for the labels.
    title : str, optional
        A title; "auto" says which point and omega.
    descriptions : dict, optional
        {output: text}; default output_descriptions(result).
    where : str, optional
        What the point is, said on each panel with its omega (default: chosen_point's "LP1",
        "point 37").

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = fourier_figure(read_result("out/r67"), "LP3", length_unit="mm")
    """
    names = outputs or output_names(result)
    branch = result["branch"]
    row, what = chosen_point(result, point)
    descriptions = {**output_descriptions(result), **(descriptions or {})}
    fig, axes = plt.subplots(1, len(names), figsize=(3.4 * len(names) + 0.6, 3.3), squeeze=False)
    for ax, name in zip(axes[0], names):
        columns = _harmonic_columns(branch, name)
        if not columns:
            raise ValueError(f"{result.get('folder', 'result')}: no hK_{name} columns (written since the harmonics' columns exist)")
        orders = [k for k, _ in columns]
        ax.bar(range(len(columns)), [abs(float(branch[c][row])) for _, c in columns], 0.7, color="C0")
        ax.set_xticks(range(len(columns)))
        ax.set_xticklabels(orders, fontsize=8 if len(columns) <= 12 else 6)
        ax.set_xlabel(r"harmonic $K$ (frequency $K\omega$) [-]")
        ax.set_ylabel(length_label(r"magnitude $h_K$", length_unit))
        # A panel's name and its point, not a title: publication figures (no titles) keep it
        ax.set_title(f"{descriptions[name]}\nat {where or what}, ω = {branch['omega'][row]:.5g} rad/s", fontsize=9, loc="left")
        ax.grid(alpha=0.3, axis="y")
    if title:
        fig.suptitle(f"harmonics at {what} (ω = {branch['omega'][row]:.6g} rad/s)" if title == "auto" else title, fontsize=10)
    fig.tight_layout()
    return fig
