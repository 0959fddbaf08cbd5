"""The figures of an `hbtrack study` folder, PNG and PDF in DIR/figures (the study runs this last):

    /usr/bin/python3 python/plot_study.py STUDY_DIR [--units m]

nfrc: the nominal NFRC, with the backbones and switched branches the study computed drawn over
it; period_doubled_K: each branch switched at a PD K, zoomed on its band; per tracked parameter
P: tracking_P (the curves on (omega, P) with the limit points of the validation NFRCs, which
they must pass through), tracking_3d_P (omega, P, max of the first output, validation NFRCs at
their own value), validation_P (the curves and the validation NFRCs and isolas on (omega, max of
the first output)); simulation: time signals and harmonic amplitudes, time integration against
the HBM orbit it started from.
"""
import argparse
import json
import os
import sys

from . import plots
from .analysis_figures import period_doubled_figure
from .overlay_figures import overlay_figure
from .plot import figures_for
from .results import read_result


def _nfrc_figures(study_dir, summary, length_unit):
    """The nominal NFRC, alone or with the branches beside it (backbones, switched branches)."""
    nfrc = read_result(os.path.join(study_dir, "nfrc"))
    entries = summary.get("backbones", []) + [w for w in summary.get("switched", []) if "folder" in w]
    beside = [read_result(os.path.join(study_dir, e["folder"])) for e in entries
              if os.path.exists(os.path.join(study_dir, e["folder"], "branch.csv"))]
    if not beside:
        return {"nfrc": plots.nfrc_figure(nfrc, length_unit=length_unit, title="nominal NFRC (solid: stable, dashed: unstable)")}
    nfrc["label"] = "nfrc: nominal NFRC"
    figures = {"nfrc": overlay_figure([nfrc, *beside], length_unit=length_unit,
                                      title="nominal NFRC and the branches beside it (solid: stable, dashed: unstable)")}
    for result in beside:
        options = result["summary"]["options"]
        if result["kind"] == "switch" and options["switch"]["type"] == "PD" and len(result["branch"]["omega"]):
            figures[f"period_doubled_{options['switch']['point']}"] = period_doubled_figure(result, nfrc, length_unit)
    return figures


def study_figures(study_dir, length_unit=None):
    """The figures of a study folder.

    Parameters
    ----------
    study_dir : str
        An `hbtrack study` folder.
    length_unit : str, optional
        The model's length unit for the labels.

    Returns
    -------
    dict
        {file stem: matplotlib.figure.Figure}.

    Examples
    --------
    >>> figures = study_figures("out/blade-study", length_unit="m")
    """
    with open(os.path.join(study_dir, "summary.json")) as f:
        summary = json.load(f)
    figures = {}
    if os.path.exists(os.path.join(study_dir, "nfrc", "summary.json")):
        figures.update(_nfrc_figures(study_dir, summary, length_unit))
    for entry in summary.get("tracking", []):
        param = entry["parameter"]
        tracks = [read_result(os.path.join(study_dir, c["folder"])) for c in entry["curves"] if "folder" in c]
        if not tracks:
            continue
        nfrcs = [read_result(os.path.join(study_dir, v["folder"])) for v in entry.get("validations", [])]
        isolas = []
        for v in entry.get("validations", []):
            for branch in v.get("isola_branches", []):
                result = read_result(os.path.join(study_dir, branch["folder"]))
                result["summary"].setdefault("options", {}).setdefault("parameters", {})[param] = v["value"]
                isolas.append(result)
        figures[f"tracking_{param}"] = plots.tracking_plane_figure(tracks, validations=nfrcs, length_unit=length_unit)
        figures[f"tracking_3d_{param}"] = plots.tracking_3d_figure(tracks, validations=nfrcs + isolas, length_unit=length_unit)
        if nfrcs or isolas:
            figures[f"validation_{param}"] = plots.validation_figure(tracks, nfrcs + isolas, length_unit=length_unit)
    if os.path.exists(os.path.join(study_dir, "simulate", "summary.json")):
        for stem, figure in figures_for(read_result(os.path.join(study_dir, "simulate")), length_unit).items():
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
    parser.add_argument("--units", help="the model's length unit for the labels (e.g. m)")
    args = parser.parse_args(argv)
    out = os.path.join(args.folder, "figures")
    os.makedirs(out, exist_ok=True)
    try:
        figures = study_figures(args.folder, args.units)
    except (ValueError, OSError, KeyError) as error:
        print(f"plot_study.py: {error}", file=sys.stderr)
        return 2
    for stem, figure in figures.items():
        for f in plots.save_figure(figure, os.path.join(out, stem)):
            print(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
