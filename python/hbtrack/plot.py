"""The figures of a result folder of any verb, as PNG and PDF (what `hbtrack plot DIR` runs):

    /usr/bin/python3 -m hbtrack.plot DIR [DIR2 ...] [-o OUT]      (PYTHONPATH=python or build/python)

frc, solve, isola branches: nfrc and the harmonics at the largest response; track: the curve in
3D and projected on (omega, parameter), with the NFRC it started from overlaid when its folder
is there; isolas: the branches found overlaid, the tracking curves with the value; simulate:
time signals against the HBM orbit and the harmonic amplitudes of both; sweep: the peak over
the grid of parameter values (sweep_figures.py); backbone: omega and the modal damping ratio
against the modal amplitude; continue: the outputs against the parameter; switch: the branch,
over the NFRC it was switched from when that folder is there, and at a PD its omega/2 harmonic.

Several folders: one figure, `overlay`, of all of them on the NFRC's axes (an NFRC, its
backbone and its switched branches; overlay_figures.py), or `continuation` when all are
continuations; written to OUT, default the first folder.
"""
import argparse
import os
import sys

import numpy as np

from . import analysis_figures, plots
from .overlay_figures import describe, overlay_figure
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


def _harmonics_at_the_largest(result, length_unit):
    names = output_names(result)
    if not len(result.get("states", [])) or not names:
        return {}
    point = int(np.argmax(result["branch"][f"max_{names[0]}"]))
    omega = result["branch"]["omega"][point]
    return {"harmonics": plots.harmonics_figure(
        plots.state_harmonics(result, point),
        f"HBM harmonics at point {point} (omega = {omega:.6g} rad/s, largest max_{names[0]})", length_unit)}


def _switched_figures(result, length_unit):
    """A branch switched at a BP over the NFRC it left (when that folder is found), zoomed on it
    when it spans a small part of the NFRC; at a PD the period-doubled branch zoomed on its band
    with the period-2T part of its motion (a band is a few of the NFRC's steps wide)."""
    options = result["summary"]["options"]["switch"]
    origin = _related(result["folder"], options.get("from", "")) if result.get("folder") else None
    origin = origin if origin and origin["kind"] == "frc" else None
    if options.get("type") == "PD":
        return {"period_doubled": analysis_figures.period_doubled_figure(result, origin, length_unit)}
    if not origin or not len(result["branch"]["omega"]):
        return {}
    lo, hi = np.min(result["branch"]["omega"]), np.max(result["branch"]["omega"])
    span = np.ptp(origin["branch"]["omega"])
    window = (lo - 0.3 * (hi - lo) - 0.01 * span, hi + 0.3 * (hi - lo) + 0.01 * span) if hi - lo < 0.2 * span else None
    return {"switched": overlay_figure([origin, result], length_unit=length_unit, window=window,
                                       title="over the NFRC it was switched from (solid: stable, dashed: unstable)")}


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
    if kind in ("frc", "solve", "isola_branch", "switch"):
        title = f"{describe(result)}\n(solid: stable, dashed: unstable)" if kind == "switch" else None
        figures = {"nfrc": plots.nfrc_figure(result, length_unit=length_unit, title=title)}
        figures.update(_harmonics_at_the_largest(result, length_unit))
        if kind == "switch":
            figures.update(_switched_figures(result, length_unit))
        return figures
    if kind == "backbone":
        return {"backbone": analysis_figures.backbone_figure(result, length_unit),
                "backbone_outputs": overlay_figure([result], length_unit=length_unit,
                                                   title=f"backbone of mode {result['summary']['options']['backbone']['mode']}: "
                                                         "max and min of the outputs over a period")}
    if kind == "continue":
        figures = {"continuation": analysis_figures.continuation_figure(result, length_unit=length_unit)}
        figures.update(_harmonics_at_the_largest(result, length_unit))
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


def overlay_figures(results, length_unit=None):
    """The figure of several results drawn over each other.

    Parameters
    ----------
    results : sequence of dict
        Results (read_result or the API) of one case.
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    dict
        {"continuation": figure} when every result is a continuation (against the parameter),
        else {"overlay": figure} on the NFRC's axes (max and min against omega).

    Examples
    --------
    >>> figures = overlay_figures([read_result("out/duffing"), read_result("out/bb")])
    """
    if all(r["kind"] == "continue" for r in results):
        return {"continuation": analysis_figures.continuation_figure(results, length_unit=length_unit)}
    return {"overlay": overlay_figure(results, length_unit=length_unit)}


def make_figures(folder, out=None, length_unit=None):
    """Writes the figures of a result folder as PNG and PDF.

    Parameters
    ----------
    folder : str or list of str
        A result folder of any verb, or several to draw over each other (overlay_figures).
    out : str, optional
        Where to write them (default: the (first) folder itself).
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    list of str
        The files written.

    Examples
    --------
    >>> make_figures("out/duffing")
    >>> make_figures(["out/duffing", "out/bb", "out/switched"], "out/figures")   # out/figures/overlay.png
    """
    folders = [folder] if isinstance(folder, str) else list(folder)
    out = out or folders[0]
    if len(folders) == 1:
        figures = figures_for(read_result(folders[0]), length_unit)
    else:
        figures = overlay_figures([read_result(f) for f in folders], length_unit)
    files = []
    for stem, figure in figures.items():
        files += plots.save_figure(figure, os.path.join(out, stem))
    return files


def main(argv=None):
    """`hbtrack plot DIR [DIR2 ...] [-o OUT] [--units U]`.

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
    parser.add_argument("folders", nargs="+", help="result folder; several: drawn over each other")
    parser.add_argument("-o", "--output", help="folder for the figures (default: the (first) result folder)")
    parser.add_argument("--units", help="the model's length unit for the labels (e.g. m)")
    args = parser.parse_args(argv)
    try:
        files = make_figures(args.folders, args.output, args.units)
    except (ValueError, OSError, KeyError) as error:
        print(f"hbtrack plot: {error}", file=sys.stderr)
        return 2
    for f in files:
        print(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
