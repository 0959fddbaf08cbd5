"""The figure of a sweep folder (`hbtrack sweep`): the peak of the first output over the tasks,
read from the merged table DIR/sweep.csv. Two parameters on a full grid: a map with the value
written in each cell (and the first limit point's frequency beside it when the NFRCs fold);
one parameter: the peak of every output against it; other samples: a scatter of the first two
parameters coloured by the peak. Blank cells are tasks without a result."""
import csv
import json
import os

import numpy as np

from . import plots


def read_sweep(folder):
    """A sweep folder's merged table.

    Parameters
    ----------
    folder : str
        A sweep folder (sweep.csv, sweep.json).

    Returns
    -------
    names : list of str
        The swept parameters.
    columns : dict
        {column: list of str} of sweep.csv.

    Examples
    --------
    >>> names, columns = read_sweep("out/sweep")
    """
    with open(os.path.join(folder, "sweep.json")) as f:
        names = json.load(f)["parameters"]
    with open(os.path.join(folder, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    columns = {key: [row[key] for row in rows] for key in (rows[0] if rows else {})}
    return names, columns


def _numbers(cells):
    return np.array([float(c) if c not in ("", None) else np.nan for c in cells])


def _grid_map(ax, x_values, y_values, x_name, y_name, z, label, length_unit):
    """z (one per task, first parameter slowest) as a map over the categorical grid; very small
    or large values are shown in a power of ten that the label states (4 digits per cell)."""
    xs, ys = sorted(set(x_values)), sorted(set(y_values))
    image = np.full((len(ys), len(xs)), np.nan)
    for x, y, value in zip(x_values, y_values, z):
        image[ys.index(y), xs.index(x)] = value
    largest = np.nanmax(np.abs(image)) if np.isfinite(image).any() else 0.0
    exponent = int(np.floor(np.log10(largest))) if largest > 0 else 0
    if exponent < -2 or exponent > 4:
        image = image / 10.0 ** exponent
        label = label.replace("[", f"[1e{exponent} ", 1)
    mesh = ax.imshow(image, origin="lower", aspect="auto", cmap="viridis")
    finite = image[np.isfinite(image)]
    middle = (finite.min() + finite.max()) / 2 if finite.size else 0.0
    for (j, i), value in np.ndenumerate(image):
        if np.isfinite(value):
            ax.text(i, j, f"{value:.4g}", ha="center", va="center", fontsize=6, color="white" if value < middle else "black")
    ax.set_xticks(range(len(xs)), [f"{v:g}" for v in xs], rotation=45, fontsize=7)
    ax.set_yticks(range(len(ys)), [f"{v:g}" for v in ys], fontsize=7)
    ax.set_xlabel(plots.parameter_label(x_name, length_unit))
    ax.set_ylabel(plots.parameter_label(y_name, length_unit))
    ax.figure.colorbar(mesh, ax=ax, label=label)


def sweep_figure(folder, length_unit=None):
    """The peak of the outputs over a sweep's tasks.

    Parameters
    ----------
    folder : str
        A sweep folder.
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> save_figure(sweep_figure("out/sweep"), "out/sweep/sweep_peaks")
    """
    names, columns = read_sweep(folder)
    outputs = [key[len("peak_max_"):] for key in columns if key.startswith("peak_max_")]
    if not outputs:
        raise ValueError(f"{folder}/sweep.csv: no peak_max_ column (the case records no output)")
    first = outputs[0]
    peak = _numbers(columns[f"peak_max_{first}"])
    peak_label = plots.length_label(f"peak of max {first}", length_unit)
    values = {name: _numbers(columns[name]) for name in names}
    full_grid = len(names) == 2 and len(set(zip(values[names[0]], values[names[1]]))) == len(peak) == \
        len(set(values[names[0]])) * len(set(values[names[1]]))
    if full_grid:
        fold = _numbers(columns["lp1_omega"]) if "lp1_omega" in columns else np.array([])
        panels = 2 if np.isfinite(fold).any() else 1
        fig, axes = plots.plt.subplots(1, panels, figsize=(6.5 * panels, 5), squeeze=False)
        _grid_map(axes[0, 0], values[names[0]], values[names[1]], names[0], names[1], peak, peak_label, length_unit)
        axes[0, 0].set_title(f"peak of max {first} over each NFRC")
        if panels == 2:
            _grid_map(axes[0, 1], values[names[0]], values[names[1]], names[0], names[1], fold, plots.OMEGA_LABEL, length_unit)
            axes[0, 1].set_title("first limit point (the resonance fold)")
    elif len(names) == 1:
        fig, ax = plots.plt.subplots(figsize=(6.5, 4.5))
        for name in outputs:
            ax.plot(values[names[0]], _numbers(columns[f"peak_max_{name}"]), "o-", label=f"max {name}")
        ax.set_xlabel(plots.parameter_label(names[0], length_unit))
        ax.set_ylabel(plots.length_label("peak over the NFRC", length_unit))
        ax.legend()
    else:
        fig, ax = plots.plt.subplots(figsize=(6.5, 5))
        x, y = values[names[0]], values[names[1]] if len(names) > 1 else peak
        dots = ax.scatter(x, y, c=peak, cmap="viridis")
        fig.colorbar(dots, ax=ax, label=peak_label)
        ax.set_xlabel(plots.parameter_label(names[0], length_unit))
        ax.set_ylabel(plots.parameter_label(names[1], length_unit) if len(names) > 1 else peak_label)
    fig.suptitle(f"sweep: {os.path.basename(os.path.normpath(folder))}, {len(peak)} tasks")
    fig.tight_layout()
    return fig
