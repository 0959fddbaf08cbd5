"""The figures of an `hbtrack study` folder, PNG and PDF in DIR/figures (the study runs this last):

    /usr/bin/python3 python/plot_study.py STUDY_DIR [--units m]

nfrc: the nominal NFRC, with the backbones and switched branches the study computed drawn over
it; period_doubled_K: each branch switched at a PD K, zoomed on its band; torus_nsK: each torus
born at NS point K over the nominal NFRC, the envelope between the NS points; per tracked parameter
P: tracking_P (the curves on (omega, P) with the limit points of the validation NFRCs, which
they must pass through), tracking_3d_P (omega, P, ||r(t)||_inf of the first output, validation NFRCs at
their own value, isolas in colour), validation_P (the curves and the validation NFRCs and isolas on (omega, ||r||_inf of
the first output)); nfrc_isolas_simulation (the paper's Fig. 12: the nominal NFRC, the isolated
branches at the nominal values and the time integrations as dots, ||r(t)||_inf of every output;
study_paper_figures.py); simulation: time signals and harmonic amplitudes, time integration
against the HBM orbit it started from.
"""
import argparse
import json
import os
import sys

from . import plots
from .analysis_figures import period_doubled_figure
from .figure_style import MODEL_LENGTH, PARAMETER_UNITS
from .overlay_figures import overlay_figure
from .plot import figures_for
from .results import read_result
from .special_points import SpecialPointType
from .study_paper_figures import nfrc_isolas_simulation_figure, simulation_folder
from .torus_figures import torus_figure
from .units import length_factor, scale_lengths


def _nfrc_figures(study_dir, summary, length_unit, read=read_result):
    """The nominal NFRC, alone or with the branches beside it (backbones, switched branches)."""
    nfrc = read(os.path.join(study_dir, "nfrc"))
    entries = summary.get("backbones", []) + [w for w in summary.get("switched", []) if "folder" in w]
    beside = [read(os.path.join(study_dir, e["folder"])) for e in entries
              if os.path.exists(os.path.join(study_dir, e["folder"], "branch.csv"))]
    if not beside:
        return {"nfrc": plots.nfrc_figure(nfrc, length_unit=length_unit, title="nominal NFRC")}
    nfrc["label"] = "nominal NFRC"
    figures = {"nfrc": overlay_figure([nfrc, *beside], length_unit=length_unit,
                                      title="nominal NFRC and the branches beside it")}
    for result in beside:
        options = result["summary"]["options"]
        if result["kind"] == "switch" and options["switch"]["type"] == SpecialPointType.PERIOD_DOUBLING and len(result["branch"]["omega"]):
            figures[f"period_doubled_{options['switch']['point']}"] = period_doubled_figure(result, nfrc, length_unit)
    return figures


def _torus_figures(study_dir, summary, length_unit, read=read_result):
    """Each torus of the study (summary "tori": torus_nsK) over the nominal NFRC with its NS points;
    a skipped torus, or one without a row, has none."""
    drawn = [t for t in summary.get("tori", []) if os.path.exists(os.path.join(study_dir, t["folder"], "branch.csv"))]
    if not drawn:
        return {}
    nfrc = read(os.path.join(study_dir, "nfrc"))
    figures = {}
    for entry in drawn:
        torus = read(os.path.join(study_dir, entry["folder"]))
        if len(torus["branch"]["omega"]):
            figures[entry["folder"]] = torus_figure(torus, nfrc=nfrc, length_unit=length_unit)
    return figures


def curve_label(curve, entry, scale=1.0, unit=None):
    """The legend text of a tracking curve the study started from a validation NFRC's limit
    point (its summary's "from", e.g. "validate_mu_1 LP2"): that NFRC named by its parameter
    value, not by its folder (the nominal NFRC's numbering does not apply to it); a validation
    computed again over a wider range (its "beyond" folder) says so.

    Parameters
    ----------
    curve : dict
        An entry of the study summary's tracking[].curves.
    entry : dict
        Its tracking[] entry (parameter, validations).
    scale : float, optional
        The factor from the model's value to the figure's (a clearance in mm: 1000).
    unit : str, optional
        The value's unit in the figure, written after it.

    Returns
    -------
    str or None
        E.g. "LP2 of the NFRC at mu = 0.0001, tracked"; None for a curve from the nominal NFRC.

    Examples
    --------
    >>> curve_label({"from": "validate_mu_1 LP2"}, {"parameter": "mu", "validations": [{"folder": "validate_mu_1", "value": 1e-4}]})
    'LP2 of the NFRC at mu = 0.0001, tracked'
    >>> curve_label({"from": "validate_clearance_1_beyond LP1"}, {"parameter": "clearance", "validations": [
    ...     {"folder": "validate_clearance_1", "value": 1e-4, "beyond": {"folder": "validate_clearance_1_beyond"}}]}, 1000.0, "mm")
    'LP1 of the NFRC at clearance = 0.1 mm (wider range), tracked'
    """
    if not curve.get("from"):
        return None
    folder, _, point = curve["from"].partition(" ")
    for v in entry.get("validations", []):
        wider = (v.get("beyond") or {}).get("folder") == folder
        if v["folder"] == folder or wider:
            value = f"{v['value'] * scale:.4g}" + (f" {unit}" if unit else "")
            return f"{point} of the NFRC at {entry['parameter']} = {value}{' (wider range)' if wider else ''}, tracked"
    return f"{point} of another NFRC, tracked"


def _study_curve(read, study_dir, curve, entry, factor=1.0, length_unit=None):
    """A tracking curve of the study's summary, read and named (curve_label), a length
    parameter's value in the figure's unit."""
    track = read(os.path.join(study_dir, curve["folder"]))
    length = PARAMETER_UNITS.get(entry["parameter"]) == MODEL_LENGTH
    label = curve_label(curve, entry, factor if length else 1.0, length_unit if length else None)
    if label:
        track["label"] = label
    return track


def _validation_folder(study_dir, validation):
    """A validation NFRC's folder; its "beyond" folder when the study computed it again over a wider
    range (its limit points are the ones the study compares, study.md)."""
    beyond = (validation.get("beyond") or {}).get("folder")
    if beyond and os.path.exists(os.path.join(study_dir, beyond, "branch.csv")):
        return beyond
    return validation["folder"]


def study_figures(study_dir, length_unit=None, model_unit=None):
    """The figures of a study folder.

    Parameters
    ----------
    study_dir : str
        An `hbtrack study` folder.
    length_unit : str, optional
        The unit of the lengths in the figures: with model_unit, what they are converted to
        (units.length_factor), else only the labels' unit.
    model_unit : str, optional
        The unit of the model's lengths (e.g. "m"); None: drawn as they are.

    Returns
    -------
    dict
        {file stem: matplotlib.figure.Figure}.

    Examples
    --------
    >>> figures = study_figures("out/blade-study", length_unit="m")
    >>> figures = study_figures("out/r67-study", "mm", "m")   # lengths times 1000
    """
    factor = length_factor(length_unit, model_unit) if model_unit else 1.0

    def read(folder):
        return scale_lengths(read_result(folder), factor)

    with open(os.path.join(study_dir, "summary.json")) as f:
        summary = json.load(f)
    figures = {}
    nominal_points = None  # the curves are named by the nominal NFRC's limit points, as its figure has them
    if os.path.exists(os.path.join(study_dir, "nfrc", "summary.json")):
        figures.update(_nfrc_figures(study_dir, summary, length_unit, read))
        figures.update(_torus_figures(study_dir, summary, length_unit, read))
        nominal_points = read(os.path.join(study_dir, "nfrc"))["special_points"]  # lengths scaled: drawn on the curves
    for entry in summary.get("tracking", []):
        param = entry["parameter"]
        tracks = [_study_curve(read, study_dir, c, entry, factor, length_unit) for c in entry["curves"] if "folder" in c]
        if not tracks:
            continue
        # A validation computed again over a wider range (its "beyond" folder) holds the folds compared
        nfrcs = [read(os.path.join(study_dir, _validation_folder(study_dir, v))) for v in entry.get("validations", [])]
        isolas = []
        for v, nfrc in zip(entry.get("validations", []), nfrcs):
            for branch in v.get("isola_branches", []):
                result = read(os.path.join(study_dir, branch["folder"]))
                # The validation NFRC's value, in the figures' units as read (v["value"] is the model's)
                value = nfrc["summary"].get("options", {}).get("parameters", {}).get(param, v["value"])
                result["summary"].setdefault("options", {}).setdefault("parameters", {})[param] = value
                isolas.append(result)
        figures[f"tracking_{param}"] = plots.tracking_plane_figure(tracks, validations=nfrcs, length_unit=length_unit,
                                                                   nfrc_special_points=nominal_points)
        # The paper's Figs 6 and 11: ||r(t)||_inf, which an inward (negative) extreme dominates on a blade
        figures[f"tracking_3d_{param}"] = plots.tracking_3d_figure(tracks, validations=nfrcs, length_unit=length_unit, isolas=isolas,
                                                                   norm=True, nfrc_special_points=nominal_points)
        if nfrcs or isolas:
            figures[f"validation_{param}"] = plots.validation_figure(tracks, nfrcs + isolas, length_unit=length_unit, norm=True)
    if summary.get("tracking") and os.path.exists(os.path.join(study_dir, "nfrc", "summary.json")):
        figures["nfrc_isolas_simulation"] = nfrc_isolas_simulation_figure(study_dir, length_unit=length_unit, read=read)
    simulated = os.path.join(study_dir, simulation_folder(summary))
    if os.path.exists(os.path.join(simulated, "signals.csv")):
        for stem, figure in figures_for(read(simulated), length_unit).items():
            figures[f"simulation_{stem}"] = figure
    return figures


def main(argv=None):
    """`plot_study.py STUDY_DIR [--units U]`: the study's figures into STUDY_DIR/figures.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default sys.argv[1:]).

    Returns
    -------
    int
        The exit code.

    Examples
    --------
    >>> main(["out/blade-study", "--units", "m"])
    """
    parser = argparse.ArgumentParser(prog="plot_study.py", description=__doc__.splitlines()[0])
    parser.add_argument("folder", help="study folder")
    parser.add_argument("--units", help="the unit of lengths in the figures: m, cm, mm, um, nm or in convert from "
                                        "--model-units; any other text only labels the axes")
    parser.add_argument("--model-units", default="m", help="the unit of the model's lengths (default m)")
    args = parser.parse_args(argv)
    out = os.path.join(args.folder, "figures")
    os.makedirs(out, exist_ok=True)
    try:
        figures = study_figures(args.folder, args.units, args.model_units)
    except (ValueError, OSError, KeyError) as error:
        print(f"plot_study.py: {error}", file=sys.stderr)
        return 2
    for stem, figure in figures.items():
        for f in plots.save_figure(figure, os.path.join(out, stem)):
            print(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
