"""The paper's Fig. 12 from any `hbtrack study` folder: the nominal NFRC, the isolated branches the
study found at the nominal parameter values (and the one its isola time integration started on,
wherever it lies), and the time integrations as dots, in the (omega, ||r(t)||_inf) plane of every
output, zoomed on the resonance. What plot_study.py writes as figures/nfrc_isolas_simulation.
"""
import os

import numpy as np

from .branch_figures import ZOOM_FRACTION, _fit_y_to_window, _legend, _stability_legend, norm_of, resonance_window
from .output_descriptions import output_descriptions
from .figure_style import OMEGA_LABEL, _plot_split, _stable_masks, length_label, plt
from .results import output_names, read_result

NORM_LABEL = r"$\Vert r(t) \Vert_\infty$"


def _isolas_to_draw(study_dir, summary, nominal, read):
    """[(label, result)] of the isolated branches at the nominal value of their parameter, and
    the one simulate_isola/ started on."""
    simulated = (summary.get("isola_simulation") or {}).get("folder")
    found = []
    for entry in summary.get("tracking", []):
        param = entry["parameter"]
        for v in entry.get("validations", []):
            at_nominal = np.isclose(v["value"], nominal.get(param, np.nan), rtol=1e-9, atol=0.0)
            for branch in v.get("isola_branches", []):
                if at_nominal or branch["folder"] == simulated:
                    label = "isolated branch" + ("" if at_nominal else f", {param} = {v['value']:.4g}")
                    found.append((label, read(os.path.join(study_dir, branch["folder"]))))
    return found


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
    """[(label, omega, {output: ||r||_inf})] of the resonance's and the isola's time integrations
    (steady or not: the study's page says whether they settled)."""
    points = []
    for folder, label in ((simulation_folder(summary), "time integration"), ("simulate_isola", "time integration on the isola")):
        path = os.path.join(study_dir, folder)
        if os.path.exists(os.path.join(path, "summary.json")):
            s = read(path)["summary"]
            if all(f"max_{n}" in s for n in names):
                points.append((label, s["omega"], {n: float(norm_of(s, n)) for n in names}))
    return points


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
    isolas = _isolas_to_draw(study_dir, summary, nominal, read)
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for i, name in enumerate(names):
        what = f", {descriptions[name]}" if len(names) > 1 else ""
        stable, unstable = _stable_masks(nfrc["branch"])
        _plot_split(ax, nfrc["branch"]["omega"], norm_of(nfrc["branch"], name), stable, unstable, f"C{i}", "NFRC" + what)
        for j, (label, isola) in enumerate(isolas):
            stable, unstable = _stable_masks(isola["branch"])
            _plot_split(ax, isola["branch"]["omega"], norm_of(isola["branch"], name), stable, unstable,
                        f"C{len(names) + i + j * len(names)}", label + what)
    for k, (label, omega, values) in enumerate(_simulated_points(study_dir, summary, names, read)):
        ax.plot([omega] * len(names), [values[n] for n in names], "o" if k == 0 else "s", color="k", ms=5, ls="none",
                zorder=6, label=label)
    ax.set_xlabel(OMEGA_LABEL)
    ax.set_ylabel(length_label(NORM_LABEL if len(names) > 1 else f"{NORM_LABEL} of {descriptions[names[0]]}", length_unit))
    ax.grid(alpha=0.3)
    branches = [nfrc["branch"]] + [isola["branch"] for _, isola in isolas]
    _legend(ax, _stability_legend(ax, branches))
    window = resonance_window(branches, names) if zoom else None
    if window:
        _fit_y_to_window(ax, window)
    fig.tight_layout()
    return fig
