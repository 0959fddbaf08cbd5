"""Figures of the analyses beside the NFRC (docs/analyses.md) in their own coordinates: a
backbone's frequency and modal damping ratio against its modal amplitude, a continuation's
outputs against its parameter, a period-doubled branch's omega/2 harmonic against omega. (In the
NFRC's plane, over an NFRC: hbtrack.overlay_figures.)
"""
import numpy as np

from .overlay_figures import SPECIAL_MARKERS, _draw, describe, draw_overlay
from .figure_style import OMEGA_LABEL, _stable_masks, length_label, parameter_label, plt, stability_legend
from .results import output_names


def backbone_figure(result, length_unit=None):
    """A nonlinear mode: omega and the modal damping ratio against the modal amplitude a.

    Both against log a (an EPMC range spans decades, a friction joint's stick-slip lies in one).

    Parameters
    ----------
    result : dict
        A backbone result (``hbtrack backbone`` folder or :func:`hbtrack.backbone`).
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = backbone_figure(read_result("out/bb"))
    """
    branch, summary = result["branch"], result["summary"]
    mode = summary["options"]["backbone"]["mode"]
    unit = f"{length_unit or 'model length unit'} x sqrt(mass unit)"
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.6))
    left.semilogx(branch["amplitude"], branch["omega"], "k-", lw=1.8, label=describe(result))
    types = set()
    for sp in result.get("special_points", []):
        if sp.get("type") in SPECIAL_MARKERS and "amplitude" in sp:
            types.add(sp["type"])
            left.plot(sp["amplitude"], sp["omega"], SPECIAL_MARKERS[sp["type"]][0], color="w", mec="k", ms=5)
    for t in sorted(types, key=list(SPECIAL_MARKERS).index):
        left.plot([], [], SPECIAL_MARKERS[t][0], color="w", mec="k", ms=5, label=SPECIAL_MARKERS[t][1])
    linear = summary.get("linear_mode", {})
    if "omega" in linear:  # of M and K alone: a stuck friction joint stiffens the start above it
        left.axhline(linear["omega"], color="0.5", lw=0.8, ls=":",
                     label=f"linear mode {mode} of M, K (no elements): ω = {linear['omega']:.5g}")
    left.set_xlabel(f"modal amplitude a [{unit}]")
    left.set_ylabel(OMEGA_LABEL)
    left.set_title(f"mode {mode}: frequency against amplitude", fontsize=10)
    right.semilogx(branch["amplitude"], 100 * branch["damping_ratio"], "C3-", lw=1.5)
    right.set_xlabel(f"modal amplitude a [{unit}]")
    right.set_ylabel("modal damping ratio [%]")
    right.set_title(f"mode {mode}: modal damping ratio", fontsize=10)
    for ax in (left, right):
        ax.grid(alpha=0.3, which="both")
    # Below the panels: a backbone crosses any corner of its axes (rising, or falling with friction).
    fig.legend(*left.get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    return fig


def continuation_figure(results, outputs=None, length_unit=None):
    """Continuations at fixed omega: max and min of each output against the parameter.

    Stable parts solid, unstable dashed, special points (LP: folds in the parameter, BP, PD, NS)
    marked; several results of the same parameter overlaid.

    Parameters
    ----------
    results : dict or sequence of dict
        Continue results (``hbtrack continue`` folders or :func:`hbtrack.continuation`).
    outputs : list of str, optional
        The outputs drawn (default all).
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = continuation_figure(read_result("out/cont"))
    """
    results = [results] if isinstance(results, dict) else list(results)
    params = {r["summary"]["options"]["continue"]["parameter"] for r in results}
    if len(params) != 1:
        raise ValueError(f"continuation_figure: the results continue different parameters ({', '.join(sorted(params))})")
    param = params.pop()
    names = outputs or output_names(results[0])
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 3.6 * len(names)), squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        types = set()
        for number, result in enumerate(results):
            branch, colour = result["branch"], f"C{number}"
            stable, unstable = _stable_masks(branch)
            label = describe(result)
            for key in (f"max_{name}", f"min_{name}"):
                _draw(ax, branch[param], branch[key], stable, unstable, colour, label, {})
                label = None
                for sp in result.get("special_points", []):
                    if sp.get("type") in SPECIAL_MARKERS and key in sp:
                        types.add(sp["type"])
                        ax.plot(sp[param], sp[key], SPECIAL_MARKERS[sp["type"]][0], color=colour, mec="k", mew=0.7, ms=5, zorder=5)
        for t in sorted(types, key=list(SPECIAL_MARKERS).index):
            ax.plot([], [], SPECIAL_MARKERS[t][0], color="w", mec="k", ms=5, label=SPECIAL_MARKERS[t][1])
        for handle in stability_legend([r["branch"] for r in results]):  # the styles named, not a title's sentence
            ax.plot([], [], handle.get_linestyle(), color="0.3", lw=1.3, label=handle.get_label())
        ax.set_xlabel(parameter_label(param, length_unit))
        ax.set_ylabel(length_label(f"max and min of {name}", length_unit))
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="best")
    omegas = {r["summary"]["options"]["continue"]["omega"] for r in results}
    at = f"ω = {omegas.pop():g}" if len(omegas) == 1 else "fixed ω"
    axes[0, 0].set_title(f"continuation in {param} at {at}", fontsize=10)
    fig.tight_layout()
    return fig


def period_doubled_figure(result, nfrc=None, length_unit=None):
    """A period-doubled branch (``hbtrack switch`` at a PD) across its band.

    Left: the max of the output with the largest omega/2 harmonic against omega, over the NFRC
    it was switched from (zoomed on the band); right: that omega/2 harmonic, the period-2T part
    of the motion, which the period-T branch does not have.

    Parameters
    ----------
    result : dict
        A switch result at a PD (its branch has h0.5_NAME columns).
    nfrc : dict, optional
        The NFRC it was switched from.
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = period_doubled_figure(read_result("out/two_dof_pd"), read_result("out/two_dof"))
    """
    branch = result["branch"]
    names = [n for n in output_names(result) if f"h0.5_{n}" in branch]
    if not names:
        raise ValueError(f"{result.get('folder', 'result')}: no h0.5_ columns (not a period-doubled branch)")
    name = max(names, key=lambda n: np.max(branch[f"h0.5_{n}"]))  # the most period-doubled output
    lo, hi = float(np.min(branch["omega"])), float(np.max(branch["omega"]))
    margin = max(0.6 * (hi - lo), 1e-4 * hi)
    window = (lo - margin, hi + margin)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 5.0))
    draw_overlay(left, [r for r in (nfrc, result) if r is not None], name, length_unit, window, legend=False)
    left.set_title("the branch over the NFRC it leaves (dashed: unstable)", fontsize=10)
    stable, unstable = _stable_masks(branch)
    colour = "C1" if nfrc is not None else "C0"  # the branch's colour on the left
    _draw(right, branch["omega"], branch[f"h0.5_{name}"], stable, unstable, colour, f"|harmonic ω/2| of {name}", {})
    right.axhline(0, color="0.4", lw=1, label="period-T branch: none")
    right.set_xlim(*window)
    right.set_ylabel(length_label(f"|harmonic ω/2| of {name}", length_unit))
    right.set_title("the period-2T part of the motion", fontsize=10)
    for ax in (left, right):
        ax.set_xlabel(OMEGA_LABEL)
        ax.grid(alpha=0.3)
    # Below the panels: the NFRC's other passes through the band fill the left one.
    handles, labels = left.get_legend_handles_labels()
    for handle, label in zip(*right.get_legend_handles_labels()):
        handles.append(handle)
        labels.append(label)
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.11, 1, 1))
    return fig
