"""The figures of a result folder of any verb, as PNG and PDF (what `hbtrack plot DIR` runs):

    /usr/bin/python3 -m hbtrack.plot DIR [-o OUT]      (PYTHONPATH=python or build/python)

frc, solve, isola branches: nfrc and the harmonics at the largest response; track: the curve in
3D and projected on (omega, parameter), with the NFRC it started from overlaid when its folder
is there; isolas: the branches found overlaid, the tracking curves with the value; simulate:
time signals against the HBM orbit and the harmonic amplitudes of both; sweep: the peak over
the grid of parameter values (sweep_figures.py).
"""
import argparse
import os
import sys

import numpy as np

from . import plots
from .results import output_names, read_result
from .sweep_figures import sweep_figure


def _folder_label(result):
    return os.path.basename(os.path.normpath(result["folder"]))


def _related(folder, path):
    """A folder a summary names (relative to where the verb ran): tried as given, then next to DIR."""
    for candidate in (path, os.path.join(os.path.dirname(os.path.normpath(folder)), os.path.basename(os.path.normpath(path)))):
        if candidate and os.path.exists(os.path.join(candidate, "summary.json")):
            return read_result(candidate)
    return None


def figures_for(result, length_unit=None):
    """The figures of a result, whatever verb produced it.

    Parameters
    ----------
    result : dict
        A result dict with "kind" (from read_result or the API).
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    dict
        {file stem: matplotlib.figure.Figure}.

    Examples
    --------
    >>> figures = figures_for(read_result("out/duffing"))
    """
    kind = result["kind"]
    if kind in ("frc", "solve", "isola_branch"):
        figures = {"nfrc": plots.nfrc_figure(result, length_unit=length_unit)}
        names = output_names(result)
        if len(result.get("states", [])) and names:
            point = int(np.argmax(result["branch"][f"max_{names[0]}"]))
            omega = result["branch"]["omega"][point]
            figures["harmonics"] = plots.harmonics_figure(
                plots.state_harmonics(result, point),
                f"HBM harmonics at point {point} (omega = {omega:.6g} rad/s, largest max_{names[0]})", length_unit)
        return figures
    if kind == "track":
        origin = _related(result.get("folder", ""), result["summary"]["options"]["tracking"].get("from", ""))
        validations = [origin] if origin and origin["kind"] == "frc" else []
        return {"tracking_3d": plots.tracking_3d_figure(result, validations=validations, length_unit=length_unit),
                "tracking": plots.tracking_plane_figure(result, validations=validations, length_unit=length_unit)}
    if kind == "isolas":
        options = result["summary"]["options"]["isolas"]
        branches = list(result["branches"].values())
        for name, branch in result["branches"].items():
            branch["label"] = name
        figures = {}
        if branches:
            figures["isolas"] = plots.nfrc_figure(branches[0], others=branches[1:], length_unit=length_unit,
                                                  title=f"branches at {options['parameter']} = {options['at']:g}")
        tracks = [t for t in (_related(result["folder"], f) for f in options.get("from", [])) if t and t["kind"] == "track"]
        if tracks:
            figures["tracking"] = plots.tracking_plane_figure(tracks, length_unit=length_unit, at=options["at"])
        return figures
    if kind == "sweep":
        return {"sweep_peaks": sweep_figure(result["folder"], length_unit=length_unit)}
    if kind == "simulate":
        figures = {"signals": plots.time_signals_figure(result, length_unit=length_unit)}
        summary = result["summary"]
        for name in output_names(result):
            series = {"time integration": summary[f"harmonics_{name}"]}
            if f"harmonics_{name}" in summary.get("start", {}):
                series["HBM"] = summary["start"][f"harmonics_{name}"]
            figures[f"harmonics_{name}"] = plots.harmonics_figure(series, f"harmonics of {name}, last period", length_unit)
        return figures
    raise ValueError(f"{result.get('folder', 'result')}: no figures for a '{kind}' result")


def make_figures(folder, out=None, length_unit=None):
    """Writes the figures of a result folder as PNG and PDF.

    Parameters
    ----------
    folder : str
        A result folder of any verb.
    out : str, optional
        Where to write them (default: the folder itself).
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    list of str
        The files written.

    Examples
    --------
    >>> make_figures("out/duffing")
    """
    result = read_result(folder)
    out = out or folder
    files = []
    for stem, figure in figures_for(result, length_unit).items():
        files += plots.save_figure(figure, os.path.join(out, stem))
    return files


def main(argv=None):
    """`hbtrack plot DIR [-o OUT] [--units U]`.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default sys.argv[1:]).

    Returns
    -------
    int
        The exit code: 0 on success, 2 for a folder that is not a result.

    Examples
    --------
    >>> main(["out/duffing"])
    """
    parser = argparse.ArgumentParser(prog="hbtrack plot", description=__doc__.splitlines()[0])
    parser.add_argument("folder", help="result folder")
    parser.add_argument("-o", "--output", help="folder for the figures (default: the result folder)")
    parser.add_argument("--units", help="the model's length unit for the labels (e.g. m)")
    args = parser.parse_args(argv)
    try:
        files = make_figures(args.folder, args.output, args.units)
    except (ValueError, OSError, KeyError) as error:
        print(f"hbtrack plot: {error}", file=sys.stderr)
        return 2
    for f in files:
        print(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
