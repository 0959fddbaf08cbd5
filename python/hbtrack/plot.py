"""The figures of a result folder of any verb, as PNG and PDF (what `hbtrack plot DIR` runs):

    /usr/bin/python3 -m hbtrack.plot DIR [DIR2 ...] [-o OUT]      (PYTHONPATH=python or build/python)

frc, solve, isola branches: nfrc (max and min, or with --norm ||r(t)||_inf, zoomed on the
resonance unless --no-zoom, special points numbered LP1, LP2, ... in omega order), fourier (the
magnitudes h_K of each output at --point, default LP1: the paper's Fig. 5) and the harmonics of
the retained dofs at the largest response; track: the curve in
3D and projected on (omega, parameter), with the NFRC it started from overlaid when its folder
is there; isolas: the branches found overlaid, the tracking curves with the value; simulate:
time signals against the HBM orbit and the harmonic amplitudes of both; sweep: the peak over
the grid of parameter values (sweep_figures.py); backbone: omega and the modal damping ratio
against the modal amplitude; continue: the outputs against the parameter; switch: the branch,
over the NFRC it was switched from when that folder is there, and at a PD its omega/2 harmonic.

Several folders: one figure, `overlay`, of all of them on the NFRC's axes (an NFRC, its
backbone and its switched branches; overlay_figures.py), or `continuation` when all are
continuations; written to OUT, default the first folder.

--units mm multiplies the lengths by 1000 (the model in metres, or as --model-units says); a unit
that is not a length unit only labels. Titles only with --titles. Outputs are named by their
descriptions (output_descriptions: --label NAME=TEXT, or the case file's comment).
"""
import argparse
import os
import sys

import numpy as np

from . import analysis_figures, branch_figures, plots
from .output_descriptions import output_descriptions, parse_labels
from .overlay_figures import describe, overlay_figure
from .results import output_names, read_result
from .special_points import SpecialPointType
from .sweep_figures import sweep_figure
from .torus_figures import torus_figure
from .units import length_factor, scale_lengths


def _folder_label(result):
    return os.path.basename(os.path.normpath(result["folder"]))


def _related(folder, path, factor=1.0):
    """A folder a summary names (relative to where the verb ran): tried as given, then next to
    DIR; its lengths scaled as the figure's."""
    for candidate in (path, os.path.join(os.path.dirname(os.path.normpath(folder)), os.path.basename(os.path.normpath(path)))):
        if candidate and os.path.exists(os.path.join(candidate, "summary.json")):
            return scale_lengths(read_result(candidate), factor)
    return None


def isola_label(name):
    """What a branch folder of `isolas` is, for a legend: "isola_2" is "isolated branch 2",
    "open_1" "main branch (from crossing 1)".

    Parameters
    ----------
    name : str
        The folder's name in the isolas result.

    Returns
    -------
    str
        The legend text.

    Examples
    --------
    >>> isola_label("isola_1")
    'isolated branch 1'
    """
    kind, _, number = name.rpartition("_")
    if not number.isdigit():
        return name
    # open_K: the branch through crossing K reached the range: the main branch, found again
    # from each such crossing (so two of them are one branch: the legend says why it repeats)
    return {"isola": f"isolated branch {number}", "open": f"main branch (from crossing {number})"}.get(kind, name)


def _harmonics_at_the_largest(result, length_unit, labels=None):
    """The outputs' harmonics (by their descriptions) at the largest response, the point said on
    each panel (the retained dofs' harmonics named internal dofs no reader knows)."""
    names = output_names(result)
    if not names or not len(result["branch"]["omega"]) or not any(c.startswith("h0_") for c in result["branch"]):
        return {}
    row = int(np.argmax(np.max([branch_figures.norm_of(result["branch"], n) for n in names], axis=0)))
    return {"harmonics": branch_figures.fourier_figure(result, row, length_unit=length_unit, descriptions=labels,
                                                       where="largest response")}


def _switched_figures(result, length_unit, factor):
    """A branch switched at a BP over the NFRC it left (when that folder is found), zoomed on it
    when it spans a small part of the NFRC; at a PD the period-doubled branch zoomed on its band
    with the period-2T part of its motion (a band is a few of the NFRC's steps wide)."""
    options = result["summary"]["options"]["switch"]
    origin = _related(result["folder"], options.get("from", ""), factor) if result.get("folder") else None
    origin = origin if origin and origin["kind"] == "frc" else None
    if options.get("type") == SpecialPointType.PERIOD_DOUBLING:
        return {"period_doubled": analysis_figures.period_doubled_figure(result, origin, length_unit)}
    if not origin or not len(result["branch"]["omega"]):
        return {}
    lo, hi = np.min(result["branch"]["omega"]), np.max(result["branch"]["omega"])
    span = np.ptp(origin["branch"]["omega"])
    window = (lo - 0.3 * (hi - lo) - 0.01 * span, hi + 0.3 * (hi - lo) + 0.01 * span) if hi - lo < 0.2 * span else None
    return {"switched": overlay_figure([origin, result], length_unit=length_unit, window=window,
                                       title="over the NFRC it was switched from")}


def _branch_figures(result, length_unit, options):  # options: figures_for's keywords
    """nfrc (max/min or ||r||_inf, zoomed) and fourier (the paper's Fig. 5) of a branch result."""
    titles, kind = options.get("titles"), result["kind"]
    title = (f"{describe(result)}" if kind == "switch" else "NFRC") if titles else None
    figures = {"nfrc": branch_figures.nfrc_figure(result, length_unit=length_unit, title=title, zoom=options.get("zoom", 0.1),
                                                  norm=options.get("norm", False), descriptions=options.get("labels"))}
    if any(c.startswith("h0_") for c in result["branch"]) and len(result["branch"]["omega"]):
        figures["fourier"] = branch_figures.fourier_figure(result, options.get("point"), length_unit=length_unit,
                                                           title="auto" if titles else None, descriptions=options.get("labels"))
    return figures


def _without_titles(figures):
    """Publication figures: the caption says what a title would (hbtrack plot --titles keeps them)."""
    for figure in figures.values():
        for ax in figure.get_axes():
            ax.set_title("")
        if getattr(figure, "_suptitle", None) is not None:
            figure._suptitle.set_text("")
    return figures


def figures_for(result, length_unit=None, model_unit=None, norm=False, zoom=0.1, point=None, titles=True, labels=None):
    """The figures of a result, whatever verb produced it.

    Parameters
    ----------
    result : dict
        A result dict with "kind" (from read_result or the API).
    length_unit : str, optional
        The unit of the lengths in the figures: with model_unit, what they are converted to
        (units.length_factor), else only the labels' unit.
    model_unit : str, optional
        The unit of the model's lengths (e.g. "m"); None: the lengths are drawn as they are.
    norm : bool, optional
        The NFRC as ||r(t)||_inf = max(|max|, |min|) of every output in one axes (the paper's Fig. 3).
    zoom : float or None, optional
        The NFRC zoomed where the response exceeds this fraction of its peak; None: not zoomed.
    point : int or str, optional
        The Fourier figure's point: a row of branch.csv or "LPk" (default LP1).
    titles : bool, optional
        Titles on the figures (`hbtrack plot` drops them unless --titles).
    labels : dict, optional
        {output: description} naming the outputs (output_descriptions).

    Returns
    -------
    dict
        {file stem: matplotlib.figure.Figure}.

    Examples
    --------
    >>> figures = figures_for(read_result("out/duffing"))
    >>> figures = figures_for(read_result("out/r67"), "mm", "m", norm=True, point="LP3")
    """
    factor = length_factor(length_unit, model_unit) if model_unit else 1.0
    result = scale_lengths(result, factor)
    options = {"norm": norm, "zoom": zoom, "point": point, "titles": titles, "labels": labels}
    kind = result["kind"]
    if kind in ("frc", "solve", "isola_branch", "switch"):
        figures = _branch_figures(result, length_unit, options)
        figures.update(_harmonics_at_the_largest(result, length_unit, labels))
        if kind == "switch":
            figures.update(_switched_figures(result, length_unit, factor))
        return figures
    if kind == "backbone":
        return {"backbone": analysis_figures.backbone_figure(result, length_unit),
                "backbone_outputs": overlay_figure([result], length_unit=length_unit,
                                                   title=f"backbone of mode {result['summary']['options']['backbone']['mode']}: "
                                                         "max and min of the outputs over a period")}
    if kind == "continue":
        figures = {"continuation": analysis_figures.continuation_figure(result, length_unit=length_unit)}
        figures.update(_harmonics_at_the_largest(result, length_unit, labels))
        return figures
    if kind == "track":
        origin = _related(result.get("folder", ""), result["summary"]["options"]["tracking"].get("from", ""), factor)
        validations = [origin] if origin and origin["kind"] == "frc" else []
        return {"tracking_3d": plots.tracking_3d_figure(result, validations=validations, length_unit=length_unit),
                "tracking": plots.tracking_plane_figure(result, validations=validations, length_unit=length_unit)}
    if kind == "isolas":
        isolas = result["summary"]["options"]["isolas"]
        branches = list(result["branches"].values())
        for name, branch in result["branches"].items():
            branch["label"] = isola_label(name)
        figures = {}
        if branches:
            figures["isolas"] = branch_figures.nfrc_figure(
                branches[0], others=branches[1:], length_unit=length_unit, zoom=options.get("zoom", 0.1), norm=options.get("norm", False),
                title=f"branches at {isolas['parameter']} = {isolas['at']:g}" if options["titles"] else None,
                descriptions=options.get("labels"))
        tracks = [t for t in (_related(result["folder"], f, factor) for f in isolas.get("from", [])) if t and t["kind"] == "track"]
        if tracks:
            figures["tracking"] = plots.tracking_plane_figure(tracks, length_unit=length_unit, at=isolas["at"])
        return figures
    if kind == "torus":
        origin = _related(result.get("folder", ""), result["summary"]["options"]["torus"].get("from", ""), factor)
        return {"torus": torus_figure(result, nfrc=origin if origin and origin["kind"] == "frc" else None, length_unit=length_unit)}
    if kind == "sweep":
        return {"sweep_peaks": sweep_figure(result["folder"], length_unit=length_unit)}
    if kind == "simulate" and "fold_search" in result["summary"]:
        # `simulate --near-lp`: the figures of the start that held the orbit, else of the last one
        search = result["summary"]["fold_search"]
        run = search.get("held") or (search["runs"][-1] if search.get("runs") else None)
        started = run and _related(result.get("folder", ""), os.path.join(result.get("folder", ""), run["folder"]), factor)
        if not started:
            raise ValueError(f"{result.get('folder', 'result')}: the fold search has no integration to draw")
        return figures_for(started, length_unit, titles=titles, labels=labels)
    if kind == "simulate":
        described = {**output_descriptions(result), **(labels or {})}
        figures = {"signals": plots.time_signals_figure(result, length_unit=length_unit, descriptions=described)}
        summary = result["summary"]
        for name in output_names(result):
            series = {"time integration": summary[f"harmonics_{name}"]}
            if f"harmonics_{name}" in summary.get("start", {}):
                series["HBM"] = summary["start"][f"harmonics_{name}"]
            figures[f"harmonics_{name}"] = plots.harmonics_figure(series, f"harmonics of {described[name]}, last period", length_unit)
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


def make_figures(folder, out=None, length_unit=None, model_unit="m", titles=False, norm=False, zoom=0.1, point=None, labels=None):
    """Writes the figures of a result folder as PNG and PDF.

    Parameters
    ----------
    folder : str or list of str
        A result folder of any verb, or several to draw over each other (overlay_figures).
    out : str, optional
        Where to write them (default: the (first) folder itself).
    length_unit : str, optional
        The unit of the lengths in the figures (mm: the model's lengths times 1000 when it is in
        metres); one that units.LENGTH_UNITS does not know only labels.
    model_unit : str, optional
        The unit of the model's lengths (default m).
    titles : bool, optional
        Titles on the figures (default none, for publication).
    norm, zoom, point, labels : optional
        As figures_for's.

    Returns
    -------
    list of str
        The files written.

    Examples
    --------
    >>> make_figures("out/duffing")
    >>> make_figures("out/r67", length_unit="mm", norm=True, point="LP3")
    >>> make_figures(["out/duffing", "out/bb", "out/switched"], "out/figures")   # out/figures/overlay.png
    """
    folders = [folder] if isinstance(folder, str) else list(folder)
    out = out or folders[0]
    if len(folders) == 1:
        figures = figures_for(read_result(folders[0]), length_unit, model_unit, norm, zoom, point, titles, labels)
    else:
        factor = length_factor(length_unit, model_unit)
        figures = overlay_figures([scale_lengths(read_result(f), factor) for f in folders], length_unit)
    if not titles:
        _without_titles(figures)
    files = []
    for stem, figure in figures.items():
        files += plots.save_figure(figure, os.path.join(out, stem))
    return files


def main(argv=None):
    """`hbtrack plot DIR [DIR2 ...] [-o OUT] [--units U] [--norm] [--no-zoom] [--point K] ...`.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default sys.argv[1:]).

    Returns
    -------
    int
        The exit code: 0 on success, 2 for a folder that is not a result or a bad option.

    Examples
    --------
    >>> main(["out/duffing"])
    >>> main(["out/r67", "--units", "mm", "--norm", "--point", "LP3"])
    """
    parser = argparse.ArgumentParser(prog="hbtrack plot", description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", help="result folder; several: drawn over each other")
    parser.add_argument("-o", "--output", help="folder for the figures (default: the (first) result folder)")
    parser.add_argument("--units", help="the unit of lengths in the figures: m, cm, mm, um, nm or in convert from "
                                        "--model-units; any other text only labels the axes")
    parser.add_argument("--model-units", default="m", help="the unit of the model's lengths (default m)")
    parser.add_argument("--norm", action="store_true", help="NFRC of ||r(t)||_inf = max(|max|, |min|), all outputs in one axes")
    parser.add_argument("--no-zoom", action="store_true", help="the NFRC's whole range, not zoomed on the resonance")
    parser.add_argument("--zoom", type=float, default=0.1, help="zoom on where the response exceeds this fraction of its peak (default 0.1)")
    parser.add_argument("--point", help="the Fourier figure's point: a row of branch.csv or LPk (default LP1)")
    parser.add_argument("--titles", action="store_true", help="titles on the figures (default none)")
    parser.add_argument("--label", action="append", default=[], metavar="NAME=TEXT", help="describe output NAME (repeatable)")
    parser.add_argument("-q", "--quiet", action="store_true", help="do not list the files written (errors are still reported)")
    args = parser.parse_args(argv)
    try:
        files = make_figures(args.folders, args.output, args.units, args.model_units, args.titles, norm=args.norm,
                             zoom=None if args.no_zoom else args.zoom, point=args.point, labels=parse_labels(args.label))
    except (ValueError, OSError, KeyError) as error:
        print(f"hbtrack plot: {error}", file=sys.stderr)
        return 2
    if not args.quiet:
        for f in files:
            print(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
