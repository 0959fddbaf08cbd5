"""Figures of hbtrack results (matplotlib): each function takes result dicts, from the API or
from hbtrack.results.read_result, and returns a matplotlib Figure; save_figure writes it as PNG
and PDF. Frequencies are in rad/s; lengths in the model's own unit (the case's matrices decide
it: metres for the blade), which the labels say unless a unit is given.
"""
import numpy as np

from .branch_figures import nfrc_figure as _branch_nfrc_figure
from .figure_style import (  # noqa: F401 (the names plots has always offered)
    MODEL_LENGTH,
    OMEGA_LABEL,
    PARAMETER_UNITS,
    _plot_split,
    _stable_masks,
    length_label,
    parameter_label,
    plt,
    save_figure,
    stability_legend,
    zoom_small_curves,
)
from .output_descriptions import output_descriptions
from .results import output_names, tracking_curve
from .special_points import CurveExtremumType, SpecialPointType, limit_points_on_curve, tracked_limit_point_label
from .view_angle import least_hidden_view


def nfrc_figure(result, outputs=None, others=(), length_unit=None, title=None, zoom=0.1, norm=False, descriptions=None):
    """The NFRC: max and min over a period against omega, or ||r(t)||_inf (branch_figures.nfrc_figure,
    where it is drawn; kept here, where the API has always had it).

    Parameters
    ----------
    result : dict
        A branch result (frc, solve, isola branch), from the API or hbtrack.read_result.
    outputs : list of str, optional
        The outputs drawn (default all).
    others : sequence of dict, optional
        More branch results of the same case overlaid (e.g. isolas).
    length_unit : str, optional
        The unit of the result's lengths, for the labels (units.scale_lengths converts).
    title : str, optional
        The figure's title (default none).
    zoom : float or None, optional
        Zoom on where the response exceeds this fraction of its peak; None: the whole branch.
    norm : bool, optional
        One axes of max(|max|, |min|) of every output (the paper's Fig. 3).
    descriptions : dict, optional
        {output: text} naming the outputs.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = nfrc_figure(hbtrack.frc(case), length_unit="m")
    """
    return _branch_nfrc_figure(result, outputs, others, length_unit, title, zoom, norm, descriptions)


def _response(columns, name, norm):
    """max_NAME, or with norm ||x(t)||_inf = max(|max_NAME|, |min_NAME|) (the paper's Figs 6 and 11)."""
    if not norm:
        return np.asarray(columns[f"max_{name}"], float)
    return np.maximum(np.abs(np.asarray(columns[f"max_{name}"], float)), np.abs(np.asarray(columns[f"min_{name}"], float)))


def _response_label(result, name, norm):
    """The axis label of an output's response, the output by its description ("leading-edge tip,
    radial", not the CSV stem "le", which mathtext set as an italic product)."""
    what = output_descriptions(result).get(name, name)
    return rf"$\Vert r(t) \Vert_\infty$ of {what}" if norm else f"max of {what} over a period"


def _tracking_parameter(track):
    return track["summary"]["options"]["tracking"]["parameter"]


def _extrema(track):
    return [sp for sp in track.get("special_points", [])
            if sp["type"] in (CurveExtremumType.PARAMETER_MIN, CurveExtremumType.PARAMETER_MAX)]


def _tracked_type(track):
    """LP, NS or PD (a SpecialPointType): what a track result follows (written since NS/PD
    tracking; LP before)."""
    return SpecialPointType(track["summary"]["options"]["tracking"].get("point", SpecialPointType.LIMIT_POINT))


def _resonance_ends(track):
    """The ends of an NS curve where its frequency reaches 0 (1:1) or w/2 (1:2)."""
    return [sp for sp in track.get("special_points", [])
            if sp["type"] in (CurveExtremumType.RESONANCE_1_1, CurveExtremumType.RESONANCE_1_2)]


def _curve_name(track, i, nfrc_special_points):
    """"LP2 tracked" as the NFRC figure numbers its limit points (omega order) when the NFRC's
    special points are given; else by track's --lp, "limit point 1 tracked"; "NS point 1
    tracked" for an NS (PD) curve; a result's own "label" (the study names the curves it started
    from a validation NFRC by that NFRC's folder and limit point) before any of these."""
    if track.get("label"):
        return track["label"]
    options = track["summary"]["options"]["tracking"]
    if _tracked_type(track) != SpecialPointType.LIMIT_POINT:
        key = _tracked_type(track).lower()
        return f"{_tracked_type(track)} point {options.get(key, i + 1)} tracked"
    lp = options.get("lp", i + 1)
    if nfrc_special_points:
        start = tracked_limit_point_label(nfrc_special_points, options)
        # Every limit point of the NFRC on the curve, as the study tracks a curve once
        labels = [start] + [label for label, _ in _nfrc_points_on(track, nfrc_special_points) if label != start]
        if len(labels) > 1:
            return f"{', '.join(sorted(labels, key=lambda t: int(t[2:]) if t[2:].isdigit() else 0))} tracked (one curve)"
        return f"{start} tracked"
    return f"limit point {lp} tracked"


def _nfrc_points_on(track, nfrc_special_points):
    """The NFRC's limit points on a limit-point curve tracked from it (special_points.limit_points_on_curve),
    at its start's parameter value; none for a curve started from another NFRC (a "label")."""
    if not nfrc_special_points or track.get("label") or _tracked_type(track) != SpecialPointType.LIMIT_POINT:
        return []
    param = _tracking_parameter(track)
    value = (track["summary"].get("start") or {}).get(param, track["summary"]["options"].get("parameters", {}).get(param))
    if value is None:
        return []
    curve = tracking_curve(track)
    return limit_points_on_curve(nfrc_special_points, np.asarray(curve["omega"], float), np.asarray(curve[param], float), value)


def tracking_3d_figure(tracks, output=None, validations=(), length_unit=None, isolas=(), norm=False, nfrc_special_points=None):
    """Limit-point curves in (omega, parameter, max of an output).

    Extrema of the parameter marked (v: min, a pair of limit points is born; ^: max, a pair
    disappears). Seen from the azimuth where the tracking curves and isolas hide each other
    least (view_angle.least_hidden_view: no one view suits every parameter).

    Parameters
    ----------
    tracks : dict or sequence of dict
        Track results.
    output : str, optional
        The output drawn (default the first).
    validations : sequence of dict, optional
        NFRC results overlaid at their own parameter value.
    length_unit : str, optional
        The model's length unit for the labels.
    isolas : sequence of dict, optional
        Isolated branches, drawn in their own colour at their parameter value (the paper's Fig. 6).
    norm : bool, optional
        The vertical axis ||x(t)||_inf = max(|max|, |min|) rather than max.
    nfrc_special_points : sequence of dict, optional
        The special points of the NFRC the tracks started from: the curves are named by its
        limit points' labels (LP1, LP2 in omega order, as its figure has them).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = tracking_3d_figure([lp1, lp2])
    """
    tracks = [tracks] if isinstance(tracks, dict) else list(tracks)
    name = output or output_names(tracks[0])[0]
    param = _tracking_parameter(tracks[0])
    fig = plt.figure(figsize=(7, 5.5))
    ax = fig.add_subplot(projection="3d")
    drawn = []  # the tracking curves and isolas, which the view must keep apart (view_angle.py)
    marked = False
    for i, track in enumerate(tracks):
        curve = tracking_curve(track)
        drawn.append((curve["omega"], curve[param], _response(curve, name, norm)))
        ax.plot(*drawn[-1], color=f"C{i}", lw=1.4, label=_curve_name(track, i, nfrc_special_points))
        for sp in _extrema(track):
            ax.scatter([sp["omega"]], [sp[param]], [_response(sp, name, norm)], marker="v" if sp["type"] == CurveExtremumType.PARAMETER_MIN else "^", color="k", s=30)
        value = (track["summary"].get("start") or {}).get(param)
        for _, sp in _nfrc_points_on(track, nfrc_special_points):
            if f"max_{name}" in sp:
                ax.scatter([sp["omega"]], [value], [_response(sp, name, norm)], marker="o", color=f"C{i}", edgecolor="k", s=25, zorder=6,
                           label="the NFRC's LPs on the curves" if not marked else None)
                marked = True
    unknown = all(nfrc["branch"].get("stable") is None for nfrc in validations)
    for j, nfrc in enumerate(validations):
        value = nfrc["summary"]["options"]["parameters"][param]
        branch = nfrc["branch"]
        ax.plot(branch["omega"], np.full(len(branch["omega"]), value), _response(branch, name, norm), color="0.4", lw=0.9,
                ls=":", label=("NFRCs at fixed values" + (" (stability not computed)" if unknown else "")) if j == 0 else None)
    for j, isola in enumerate(isolas):
        value = isola["summary"]["options"]["parameters"][param]
        branch = isola["branch"]
        drawn.append((branch["omega"], np.full(len(branch["omega"]), value), _response(branch, name, norm)))
        ax.plot(*drawn[-1], color="k", lw=1.1, label="isolated branches" if j == 0 else None)
    ax.view_init(*least_hidden_view(drawn, [ax.get_xlim3d(), ax.get_ylim3d(), ax.get_zlim3d()]))
    ax.set_xlabel(OMEGA_LABEL)
    ax.set_ylabel(parameter_label(param, length_unit))
    ax.set_zlabel(length_label(_response_label(tracks[0], name, norm), length_unit))
    ax.set_title("limit-point tracking (v: min, ^: max of the parameter)", fontsize=10)
    # Beside the box: inside it, a study's legend covered the omega axis and its label
    fig.set_size_inches(9.5, 5.5)
    fig.subplots_adjust(left=0.0, right=0.68)
    # Long names (a study's curve from another NFRC) wrapped: one line ran past the figure's edge
    import textwrap
    handles, labels = ax.get_legend_handles_labels()
    # at the figure's right edge: beside the box, a long z label (an output's description) ran under it
    fig.legend(handles, [textwrap.fill(t, 44, subsequent_indent="  ") for t in labels], fontsize=8, loc="upper right",
               bbox_to_anchor=(0.99, 0.9), borderaxespad=0)
    return fig


# More extrema than this and their coordinates are left to the tables (a study's index.md): two
# dozen labels on leaders crossed each other and hid the curves (rotor 67 in mu).
MAX_COORDINATE_LABELS = 6


def tracking_plane_figure(tracks, validations=(), length_unit=None, at=None, nfrc_special_points=None):
    """Limit-point (and NS, PD) curves projected on (omega, parameter).

    Start (o) and extrema (v min, ^ max) marked, their coordinates written when there are at
    most MAX_COORDINATE_LABELS of them, an NS curve's ends on a fold (s: NS
    frequency 0) marked; the special points of the tracked types (LP, NS, PD) of the
    `validations` NFRCs (x) at their parameter value, which the curves must pass through.

    Parameters
    ----------
    tracks : dict or sequence of dict
        Track results.
    validations : sequence of dict, optional
        NFRC results computed at fixed parameter values.
    length_unit : str, optional
        The model's length unit for the labels.
    at : float, optional
        A parameter value drawn as a line (isolas).
    nfrc_special_points : sequence of dict, optional
        As tracking_3d_figure's: the curves named LPk as the NFRC figure numbers them.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = tracking_plane_figure(lp1, at=0.15)
    """
    tracks = [tracks] if isinstance(tracks, dict) else list(tracks)
    param = _tracking_parameter(tracks[0])
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    coordinates = []  # texts at the extrema, placed once the layout is final
    kinds = set()
    tracked = sorted({_tracked_type(t) for t in tracks})
    for i, track in enumerate(tracks):
        curve = tracking_curve(track)
        ax.plot(curve["omega"], curve[param], color=f"C{i}", lw=1.3, label=_curve_name(track, i, nfrc_special_points))
        start = track["summary"].get("start")
        if start:
            ax.plot([start["omega"]], [start[param]], "o", color=f"C{i}", ms=5, zorder=6)
            kinds.add("start")
            for _, sp in _nfrc_points_on(track, nfrc_special_points):  # the NFRC's other folds on the curve
                if abs(sp["omega"] - start["omega"]) > 1e-9 * abs(start["omega"]):
                    ax.plot([sp["omega"]], [start[param]], "o", color=f"C{i}", ms=5, mfc="w", zorder=6)
                    kinds.add("also")
        for sp in _extrema(track):
            ax.plot([sp["omega"]], [sp[param]], "v" if sp["type"] == CurveExtremumType.PARAMETER_MIN else "^", color="k", ms=7, zorder=5)
            coordinates.append((sp["omega"], sp[param], f"({sp['omega']:.6g}, {sp[param]:.4g})"))
            kinds.add(sp["type"])
        for sp in _resonance_ends(track):
            ax.plot([sp["omega"]], [sp[param]], "s", color="k", mfc="none", ms=7, zorder=5)
            kinds.add("resonance")
    for j, nfrc in enumerate(validations):
        value = nfrc["summary"]["options"]["parameters"][param]
        points = [sp["omega"] for sp in nfrc.get("special_points", []) if sp["type"] in tracked]
        ax.plot(points, [value] * len(points), "x", color="k", ms=8, label=f"{'/'.join(tracked)}s of NFRCs" if j == 0 else None)
    if at is not None:
        ax.axhline(at, color="0.5", lw=0.8, ls=":", label=f"{param} = {at:g}")
    ax.set_xlabel(OMEGA_LABEL)
    ax.set_ylabel(parameter_label(param, length_unit))
    ax.set_title("limit-point tracking" if tracked == [SpecialPointType.LIMIT_POINT] else f"{', '.join(tracked)} tracking", fontsize=10)
    ax.grid(alpha=0.3)
    # The paper's Fig. 7: a minimum of the parameter along a curve is where a pair of limit points
    # is born (an isola appears, or a fold on the main branch), a maximum where a pair vanishes
    # (an isola merges).
    from matplotlib.lines import Line2D
    born, merged = CurveExtremumType.PARAMETER_MIN, CurveExtremumType.PARAMETER_MAX
    meaning = {born: ("v", f"min of {param}: a pair of limit points born"), merged: ("^", f"max of {param}: a pair merges")}
    if tracked != [SpecialPointType.LIMIT_POINT]:  # on an NS (PD) curve a pair of NS (PD) points, the edges of an unstable band
        points = "limit (NS, PD) points" if SpecialPointType.LIMIT_POINT in tracked else f"{'/'.join(tracked)} points: an unstable band"
        meaning = {born: ("v", f"min of {param}: a pair of {points} born"), merged: ("^", f"max of {param}: a pair merges")}
    meaning["resonance"] = ("s", "NS curve ends on a fold (NS frequency 0)")
    meaning["start"] = ("o", "start: the NFRC's point tracked")
    meaning["also"] = ("o", "the NFRC's other LPs on the curve")
    extra = [Line2D([], [], marker=meaning[k][0], color="0.4" if k in ("start", "also") else "k", ls="none",
                    mfc="none" if k == "resonance" else ("w" if k == "also" else None),
                    ms=5 if k in ("start", "also") else 7, label=meaning[k][1])
             for k in ("start", "also", born, merged, "resonance") if k in kinds]
    handles, labels = ax.get_legend_handles_labels()
    # Below the axes: "best" inside moves when the labels are added and covered curves and labels
    entries = len(handles) + len(extra)
    import textwrap  # long names (a study's curve from another NFRC) wrapped: they ran past the figure's edges
    ax.legend(handles + extra, [textwrap.fill(t, 46, subsequent_indent="  ") for t in labels + [h.get_label() for h in extra]],
              fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)
    fig.set_size_inches(6.5, 4.2 + 0.17 * ((entries + 1) // 2))
    fig.tight_layout()
    if len(coordinates) <= MAX_COORDINATE_LABELS:
        from .label_layout import place_labels
        place_labels(ax, coordinates)
    zoom_small_curves(ax, [(c["omega"], c[param]) for c in map(tracking_curve, tracks)])
    return fig


def validation_figure(tracks, nfrcs, output=None, length_unit=None, norm=False):
    """Tracking curves in (omega, max of an output) with separately computed NFRCs.

    Each NFRC's folds must lie on a tracking curve.

    Parameters
    ----------
    tracks : dict or sequence of dict
        Track results.
    nfrcs : sequence of dict
        NFRC results overlaid.
    output : str, optional
        The output drawn (default the first).
    length_unit : str, optional
        The model's length unit for the labels.
    norm : bool, optional
        ||x(t)||_inf = max(|max|, |min|) rather than max (the paper's Fig. 11).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = validation_figure(lp1, [nfrc_low, nfrc_high])
    """
    tracks = [tracks] if isinstance(tracks, dict) else list(tracks)
    name = output or output_names(tracks[0])[0]
    param = _tracking_parameter(tracks[0])
    fig, ax = plt.subplots(figsize=(7.2, 4.4))
    for i, track in enumerate(tracks):
        curve = tracking_curve(track)
        ax.plot(curve["omega"], _response(curve, name, norm), color="k", lw=1.6, label="limit points tracked" if i == 0 else None)
    # A colour per parameter value on a colour bar, not a legend entry per NFRC: with a study's two
    # dozen values the colour cycle repeats and two NFRCs read as one; an isolated branch takes
    # its NFRC's colour, drawn thicker.
    from matplotlib import cm, colors
    values = [nfrc["summary"]["options"]["parameters"][param] for nfrc in nfrcs]
    scale = colors.Normalize(min(values), max(values) if max(values) > min(values) else min(values) + 1) if values else None
    kinds, folds = set(), []
    for nfrc, value in zip(nfrcs, values):
        stable, unstable = _stable_masks(nfrc["branch"])
        isola = nfrc.get("kind") == "isola_branch"
        kinds.add("isola" if isola else "nfrc")
        _plot_split(ax, nfrc["branch"]["omega"], _response(nfrc["branch"], name, norm), stable, unstable, cm.viridis(scale(value)), None,
                    lw=2.2 if isola else 1.1)
        folds += [(sp["omega"], float(_response(sp, name, norm))) for sp in nfrc.get("special_points", [])
                  if sp["type"] == SpecialPointType.LIMIT_POINT and f"max_{name}" in sp]
    if folds:
        ax.plot(*zip(*folds), "o", color="w", mec="k", ms=5, ls="none", zorder=5, label="LP (fold) of an NFRC")
    from matplotlib.lines import Line2D
    extra = [Line2D([], [], color="0.5", lw=1.1, label=f"NFRC at a fixed {param} (colour)")] if "nfrc" in kinds else []
    extra += [Line2D([], [], color="0.5", lw=2.2, label="isolated branch at that value")] if "isola" in kinds else []
    extra += [h for h in stability_legend([n["branch"] for n in nfrcs]) if h.get_label() != "stable"]
    # The folds are what is checked: show the frequencies the tracking curves span, not the
    # NFRCs' whole range where the resonance would be a spike.
    omegas = np.concatenate([np.asarray(tracking_curve(t)["omega"]) for t in tracks])
    span = max(omegas.max() - omegas.min(), 1e-3 * abs(omegas.max()))
    ax.set_xlim(omegas.min() - 0.25 * span, omegas.max() + 0.25 * span)
    ax.set_xlabel(OMEGA_LABEL)
    ax.set_ylabel(length_label(_response_label(tracks[0], name, norm), length_unit))
    ax.set_title("tracking curves and NFRCs (folds on the curves)", fontsize=10)
    ax.grid(alpha=0.3)
    if scale is not None:
        bar = fig.colorbar(cm.ScalarMappable(norm=scale, cmap=cm.viridis), ax=ax, pad=0.02)
        bar.set_label(parameter_label(param, length_unit))
        bar.ax.plot([0.5] * len(values), values, "_", color="w", ms=10)  # the values computed
    handles, labels = ax.get_legend_handles_labels()
    ax.legend(handles + extra, labels + [h.get_label() for h in extra], fontsize=7.5, loc="upper center",
              bbox_to_anchor=(0.5, -0.15), ncol=3, frameon=False)
    fig.tight_layout()
    return fig


def harmonic_signal(harmonics, omega, time):
    """The time signal of Fourier coefficients.

    x(t) = a0/2 + sum a_j cos(j omega t) + b_j sin(j omega t).

    Parameters
    ----------
    harmonics : array_like
        [a0, a1, b1, ..., aH, bH].
    omega : float
        The fundamental frequency (rad/s).
    time : array_like
        Instants (s).

    Returns
    -------
    numpy.ndarray
        x at each instant.

    Examples
    --------
    >>> harmonic_signal([0.0, 1.0, 0.0], 1.0, [0.0])
    array([1.])
    """
    h = np.asarray(harmonics, dtype=float)
    time = np.asarray(time, dtype=float)  # a list of instants too
    x = np.full(time.shape, 0.5 * h[0])
    for j in range(1, (len(h) - 1) // 2 + 1):
        x += h[2 * j - 1] * np.cos(j * omega * time) + h[2 * j] * np.sin(j * omega * time)
    return x


def harmonic_amplitudes(harmonics):
    """Magnitudes of Fourier coefficients.

    Parameters
    ----------
    harmonics : array_like
        [a0, a1, b1, ..., aH, bH].

    Returns
    -------
    numpy.ndarray
        H + 1 values: |a0/2|, then hypot(a_j, b_j) for j = 1..H.

    Examples
    --------
    >>> harmonic_amplitudes([2.0, 3.0, 4.0])
    array([1., 5.])
    """
    h = np.asarray(harmonics)
    return np.concatenate([[abs(0.5 * h[0])], np.hypot(h[1::2], h[2::2])])


def time_signals_figure(simulation, outputs=None, length_unit=None, descriptions=None):
    """Simulated displacement of each output over the recorded periods.

    With the HBM orbit the simulation started from (when it started from one) for comparison.

    Parameters
    ----------
    simulation : dict
        A simulate result.
    outputs : list of str, optional
        The outputs drawn (default all).
    length_unit : str, optional
        The model's length unit for the labels.
    descriptions : dict, optional
        {output: text} naming the outputs (default: their names).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = time_signals_figure(hbtrack.simulate(case, omega=1.0))
    """
    names = outputs or output_names(simulation)
    signals, summary = simulation["signals"], simulation["summary"]
    omega = summary["omega"]
    start = summary.get("start", {})
    fig, axes = plt.subplots(len(names), 1, figsize=(6.5, 2.8 * len(names)), squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        t = signals["time"]
        ax.plot(t, signals[name], color="C0", lw=1.3, label="time integration")
        if f"harmonics_{name}" in start:
            ax.plot(t, harmonic_signal(start[f"harmonics_{name}"], omega, t), "--", color="C1", lw=1.3, label="HBM")
        ax.set_xlabel("t [s]")
        ax.set_ylabel(length_label((descriptions or {}).get(name, name), length_unit))
        ax.grid(alpha=0.3)
    # Above the first panel, not inside: inside it covered a flank of the signals (rotor 67)
    axes[0, 0].legend(fontsize=8, loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=2, frameon=False, borderaxespad=0.2)
    axes[0, 0].set_title(f"steady state at ω = {omega:.6g} rad/s", fontsize=10, loc="right")
    fig.tight_layout()
    return fig


def harmonics_figure(series, title, length_unit=None):
    """Bar chart of harmonic amplitudes, log scale.

    Parameters
    ----------
    series : dict
        {label: [a0, a1, b1, ..., aH, bH]}.
    title : str
        The figure's title.
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = harmonics_figure(hbtrack.output_harmonics(case, nfrc["states"][20]), "point 20")
    """
    fig, ax = plt.subplots(figsize=(6.5, 3.6))
    width = 0.8 / max(len(series), 1)
    for i, (label, harmonics) in enumerate(series.items()):
        amplitudes = harmonic_amplitudes(harmonics)
        orders = np.arange(len(amplitudes))
        ax.bar(orders + (i - (len(series) - 1) / 2) * width, amplitudes, width, label=label, color=f"C{i}")
    ax.set_xticks(np.arange(max(len(harmonic_amplitudes(h)) for h in series.values())))
    ax.set_yscale("log", nonpositive="clip")  # bars start at 0: clipped to the axis, not dropped
    ax.set_xlabel(r"harmonic $K$ (frequency $K\omega$) [-]")
    ax.set_ylabel(length_label("amplitude", length_unit))
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3, axis="y")
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def state_harmonics(result, point, largest=4):
    """Fourier coefficients of the retained dofs at one point of a result.

    The retained dofs are the condensed unknowns (the dofs the nonlinear elements act on, in model
    order); only the `largest` in first harmonic are returned (the blade retains 27).

    Parameters
    ----------
    result : dict
        A result with ``states``.
    point : int
        The row of its states.
    largest : int, optional
        How many dofs to return.

    Returns
    -------
    dict
        {label: [a0, a1, b1, ..., aH, bH]}.

    Examples
    --------
    >>> series = state_harmonics(nfrc, 20)
    """
    listed = result["summary"]["options"]["harmonic_balance"]["harmonics"]  # H, or the list balanced
    if isinstance(listed, int):
        listed = list(range(listed + 1))
    harmonics = listed[-1]
    row = np.asarray(result["states"][point])
    x = row[3:] if "leg" in result.get("branch", {}) else row[1:]  # after leg, omega, parameter or omega
    selected = x.reshape(sum(1 if k == 0 else 2 for k in listed), -1)  # harmonic-major: entry c * q + dof
    blocks = np.zeros((2 * harmonics + 1, selected.shape[1]))  # the dense layout 0..H, zeros where not balanced
    rows = [r for k in listed for r in ([0] if k == 0 else [2 * k - 1, 2 * k])]
    blocks[rows] = selected
    first = np.hypot(blocks[1], blocks[2]) if harmonics >= 1 else np.abs(blocks[0])
    keep = sorted(np.argsort(first)[::-1][:largest])
    names = result["summary"]["options"]["harmonic_balance"].get("retained_dofs")  # absent before the dof columns
    return {(names[k] if names else f"retained dof {k + 1}"): blocks[:, k] for k in keep}
