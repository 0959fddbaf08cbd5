"""The figure of a sweep folder (`hbtrack sweep`): the peak of the first output over the tasks,
read from the merged table DIR/sweep.csv. Two parameters on a full grid: a map with the value
written in each cell (and the first limit point's frequency beside it when the NFRCs fold);
one parameter: the peak of every output against it; other samples: a scatter of the first two
parameters coloured by the peak. Blank cells are tasks without a result ("no fold": a result
without a limit point); a "*" marks an NFRC that did not reach the end of its range. Outputs
are named by their descriptions (a task's summary.json)."""
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


def _grid_map(ax, x_values, y_values, x_name, y_name, z, label, length_unit, short=None, blank=None):
    """z (one per task, first parameter slowest) as a map over the categorical grid; very small
    or large values are shown in a power of ten that the label states (4 digits per cell); a
    task in `short` gets a "*" after its value (its NFRC did not reach the range's end), a
    task in `blank` without a value says so in its cell ("no fold")."""
    xs, ys = sorted(set(x_values)), sorted(set(y_values))
    image = np.full((len(ys), len(xs)), np.nan)
    starred, said = np.zeros(image.shape, bool), {}
    for k, (x, y, value) in enumerate(zip(x_values, y_values, z)):
        image[ys.index(y), xs.index(x)] = value
        starred[ys.index(y), xs.index(x)] = short is not None and bool(short[k])
        if blank is not None and not np.isfinite(value) and blank[k]:
            said[ys.index(y), xs.index(x)] = blank[k]
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
            ax.text(i, j, f"{value:.4g}" + ("*" if starred[j, i] else ""), ha="center", va="center", fontsize=6,
                    color="white" if value < middle else "black")
        elif (j, i) in said:
            ax.text(i, j, said[(j, i)], ha="center", va="center", fontsize=6, color="0.3")
    ax.set_xticks(range(len(xs)), [f"{v:g}" for v in xs], rotation=45, fontsize=7)
    ax.set_yticks(range(len(ys)), [f"{v:g}" for v in ys], fontsize=7)
    ax.set_xlabel(plots.parameter_label(x_name, length_unit))
    ax.set_ylabel(plots.parameter_label(y_name, length_unit))
    ax.figure.colorbar(mesh, ax=ax, label=label)


def _description(folder, name):
    """An output's description from a task's summary.json (output_descriptions), else its name."""
    from .output_descriptions import output_descriptions
    tasks = os.path.join(folder, "tasks")
    for task in sorted(os.listdir(tasks)) if os.path.isdir(tasks) else []:
        try:
            with open(os.path.join(tasks, task, "summary.json")) as f:
                summary = json.load(f)
        except (OSError, ValueError):
            continue
        return output_descriptions({"summary": summary, "branch": {f"max_{name}": []}}).get(name, name)
    return name


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
    what = _description(folder, first)
    peak_label = plots.length_label(f"peak of {what}", length_unit)
    # An NFRC that left the frequency range (left_range: its branch ran out below the start):
    # its peak and folds are those of the part computed, which its cell must say
    short = [status not in ("reached_end", "") for status in columns.get("status", [""] * len(peak))]
    values = {name: _numbers(columns[name]) for name in names}
    full_grid = len(names) == 2 and len(set(zip(values[names[0]], values[names[1]]))) == len(peak) == \
        len(set(values[names[0]])) * len(set(values[names[1]]))
    if full_grid:
        fold = _numbers(columns["lp1_omega"]) if "lp1_omega" in columns else np.array([])
        panels = 2 if np.isfinite(fold).any() else 1
        fig, axes = plots.plt.subplots(1, panels, figsize=(6.5 * panels, 5), squeeze=False)
        _grid_map(axes[0, 0], values[names[0]], values[names[1]], names[0], names[1], peak, peak_label, length_unit, short)
        axes[0, 0].set_title(f"peak of max {what} over each NFRC")
        if panels == 2:
            # lp1 is the fold of lowest omega (sweep.csv lists them in omega order); the colour bar says so, as
            # `hbtrack plot` drops titles
            no_fold = ["no fold" if np.isfinite(p) else "" for p in peak]
            _grid_map(axes[0, 1], values[names[0]], values[names[1]], names[0], names[1], fold,
                      r"$\omega$ of LP1, the lowest fold [rad/s]", length_unit, short, no_fold)
            axes[0, 1].set_title("the lowest limit point (LP1)")
        if any(short):
            fig.text(0.01, 0.01, f"* {sum(short)} of {len(short)} NFRCs left the frequency range (their status): the peak and "
                     "folds of the part computed", fontsize=8)
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
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    return fig
