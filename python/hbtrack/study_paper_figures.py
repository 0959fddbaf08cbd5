"""The paper's Fig. 12 from any `hbtrack study` folder: the nominal NFRC, the isolated branches the
study found at the nominal parameter values and the time integrations as dots, in the (omega,
||r(t)||_inf) plane of every output, zoomed on the resonance. The isola the time integration
started on, when it lies at another parameter value, is another system: it gets its own panel,
with the validation NFRC at its value. Every branch stable solid, unstable dashed, its limit
points (and NS, BP, PD) marked by type. What plot_study.py writes as figures/nfrc_isolas_simulation.
"""
import os

import numpy as np

from .branch_figures import ZOOM_FRACTION, _fit_y_to_window, _stability_legend, norm_of, resonance_window
from .output_descriptions import output_descriptions
from .figure_style import OMEGA_LABEL, SPECIAL_MARKERS, _plot_split, _stable_masks, length_label, marker_legend, plt
from .results import output_names, read_result

NORM_LABEL = r"$\Vert r(t) \Vert_\infty$"


def _panels(study_dir, summary, nominal, read):
    """[(title, nfrc folder, [isola folder])]: the nominal NFRC with its isolas at the nominal
    values, then, when the isola time integration started on an isola at another value of a
    parameter, that value's validation NFRC with that isola."""
    simulated = (summary.get("isola_simulation") or {}).get("folder")
    at_nominal, elsewhere = [], None
    for entry in summary.get("tracking", []):
        param = entry["parameter"]
        for v in entry.get("validations", []):
            nominal_here = np.isclose(v["value"], nominal.get(param, np.nan), rtol=1e-9, atol=0.0)
            for branch in v.get("isola_branches", []):
                if nominal_here:
                    at_nominal.append(branch["folder"])
                elif branch["folder"] == simulated:
                    elsewhere = (f"{param} = {v['value']:.4g}", v["folder"], [branch["folder"]])
    panels = [("nominal", "nfrc", at_nominal)]
    return panels + [elsewhere] if elsewhere else panels


def simulation_folder(summary):
    """The folder of the resonance's time integration the study compared.

    Parameters
    ----------
    summary : dict
        The study's summary.json.

    Returns
    -------
    str
        Relative to the study's folder: the fold search's start that held the orbit
        (``simulate/point_R``), or ``simulate`` for a study written before the search.

    Examples
    --------
    >>> simulation_folder({"simulation": {"folder": "simulate/point_115"}})
    'simulate/point_115'
    """
    return (summary.get("simulation") or {}).get("folder", "simulate")


def _simulated_points(study_dir, summary, names, read):
    """{"nominal" or "isola": (label, omega, {output: ||r||_inf})} of the resonance's and the
    isola's time integrations (steady or not: the study's page says whether they settled)."""
    points = {}
    for folder, key, label in ((simulation_folder(summary), "nominal", "time integration"),
                               ("simulate_isola", "isola", "time integration on the isola")):
        path = os.path.join(study_dir, folder)
        if os.path.exists(os.path.join(path, "summary.json")):
            s = read(path)["summary"]
            if all(f"max_{n}" in s for n in names):
                points[key] = (label, s["omega"], {n: float(norm_of(s, n)) for n in names})
    return points


def _draw_branch(ax, result, names, colours, label, descriptions):
    """||r||_inf of each output of a branch, its special points marked by type on each curve."""
    stable, unstable = _stable_masks(result["branch"])
    types = set()
    for name, colour in zip(names, colours):
        what = f", {descriptions[name]}" if len(names) > 1 else ""
        _plot_split(ax, result["branch"]["omega"], norm_of(result["branch"], name), stable, unstable, colour, label + what)
        for sp in result.get("special_points", []):
            if sp["type"] in SPECIAL_MARKERS and f"max_{name}" in sp:
                types.add(sp["type"])
                ax.plot(sp["omega"], float(norm_of(sp, name)), SPECIAL_MARKERS[sp["type"]][0], color=colour, mec="k", ms=5, ls="none",
                        zorder=5)
    return types


def nfrc_isolas_simulation_figure(study_dir, outputs=None, length_unit=None, read=read_result, zoom=ZOOM_FRACTION):
    """The nominal NFRC, its isolated branches and the time integrations (the paper's Fig. 12).

    Parameters
    ----------
    study_dir : str
        An `hbtrack study` folder.
    outputs : list of str, optional
        The outputs drawn (default all).
    length_unit : str, optional
        The unit of the lengths as `read` returns them, for the labels.
    read : callable, optional
        Reads a result folder (study_figures passes one that converts lengths).
    zoom : float or None, optional
        As branch_figures.nfrc_figure's.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = nfrc_isolas_simulation_figure("out/r67-study", length_unit="m")
    """
    import json
    with open(os.path.join(study_dir, "summary.json")) as f:
        summary = json.load(f)
    nfrc = read(os.path.join(study_dir, "nfrc"))
    names = outputs or output_names(nfrc)
    descriptions = output_descriptions(nfrc)
    nominal = nfrc["summary"].get("options", {}).get("parameters", {})
    panels = _panels(study_dir, summary, nominal, read)
    simulated = _simulated_points(study_dir, summary, names, read)
    fig, axes = plt.subplots(1, len(panels), figsize=(6.5 if len(panels) == 1 else 11, 4.4), squeeze=False)
    types, drawn = set(), []
    for index, (ax, (title, nfrc_folder, isola_folders)) in enumerate(zip(axes[0], panels)):
        base = nfrc if index == 0 else read(os.path.join(study_dir, nfrc_folder))
        types |= _draw_branch(ax, base, names, [f"C{i}" for i in range(len(names))], "NFRC", descriptions)
        branches = [base["branch"]]
        for j, folder in enumerate(isola_folders):
            isola = read(os.path.join(study_dir, folder))
            branches.append(isola["branch"])
            types |= _draw_branch(ax, isola, names, [f"C{len(names) * (j + 1) + i}" for i in range(len(names))],
                                  "isolated branch" + (f" {j + 1}" if len(isola_folders) > 1 else ""), descriptions)
        # The resonance's integration on the nominal panel; the isola's on its isola's panel
        shown = ("nominal", "isola") if len(panels) == 1 else ("nominal",) if index == 0 else ("isola",)
        for key, marker in (("nominal", "o"), ("isola", "s")):
            if key in simulated and key in shown:
                label, omega, values = simulated[key]
                ax.plot([omega] * len(names), [values[n] for n in names], marker, color="k", ms=5, ls="none", zorder=6, label=label)
        ax.set_xlabel(OMEGA_LABEL)
        ax.set_ylabel(length_label(NORM_LABEL if len(names) > 1 else f"{NORM_LABEL} of {descriptions[names[0]]}", length_unit))
        ax.grid(alpha=0.3)
        if len(panels) > 1:
            ax.set_title(title, fontsize=9, loc="left")  # the panel's parameter value: kept without titles
        drawn += branches
        window = resonance_window(branches, names) if zoom else None
        if window:
            _fit_y_to_window(ax, window)
    # One legend below the panels: the curves' colours, the styles and the marker types
    entries = {}
    for ax in axes[0]:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            entries.setdefault(label, handle)
    extra = _stability_legend(axes[0, 0], drawn) + marker_legend(types)
    handles = list(entries.values()) + extra
    labels = list(entries) + [h.get_label() for h in extra]
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=7.5, frameon=False)
    rows = (len(labels) + 2) // 3
    fig.set_size_inches(fig.get_size_inches()[0], 4.4 + 0.2 * rows)
    fig.tight_layout(rect=(0, (0.2 * rows + 0.15) / (4.4 + 0.2 * rows), 1, 1))
    return fig
