"""The paper's Figs 6, 7 and 12 from a study folder (study_figures, study_paper_figures): the
NFRC, the isola and the time integrations drawn with the folders' values; births and merges in
the tracking projection's legend, its texts never overlapping; --units mm converting the study's
figures too. The study folder is assembled from the verbs a study runs, on the nonlinear
absorber (examples/nltva.toml: an isola at A = 0.15; about 2 s), not by `hbtrack study`."""
import json
import os

import numpy as np
import pytest

from hbtrack import plots
from hbtrack.branch_figures import norm_of
from hbtrack.plots import plt
from hbtrack.results import read_result
from hbtrack.study_figures import study_figures
from hbtrack.study_paper_figures import nfrc_isolas_simulation_figure

from conftest import NLTVA, run_cli
from test_publication_figures import text_boxes


@pytest.fixture(scope="module")
def small_study(tmp_path_factory):
    """nfrc/ at the nominal A = 0.12, its LP1 tracked in A, the isola at A = 0.15, time
    integrations from the NFRC and from the isola, and the summary.json a study would write."""
    out = str(tmp_path_factory.mktemp("small_study"))
    run_cli("frc", NLTVA, "-o", f"{out}/nfrc")
    run_cli("track", NLTVA, "--from", f"{out}/nfrc", "--lp", "1", "--param", "amplitude", "--range", "0.05:0.3",
            "-o", f"{out}/track_amplitude_lp1")
    run_cli("isolas", NLTVA, "--from", f"{out}/track_amplitude_lp1", "--at", "0.15", "-o", f"{out}/isolas")
    assert os.path.exists(f"{out}/isolas/isola_1/branch.csv")
    run_cli("simulate", NLTVA, "--from", f"{out}/nfrc", "--point", "15", "--max-periods", "20", "-o", f"{out}/simulate")
    # 20 periods do not settle on the isola (exit 1): the folder is kept and drawn all the same
    run_cli("simulate", NLTVA, "--set", "amplitude=0.15", "--from", f"{out}/isolas/isola_1", "--point", "36",
            "--max-periods", "20", "-o", f"{out}/simulate_isola", check=False)
    track = read_result(f"{out}/track_amplitude_lp1")
    extrema = [{"type": sp["type"], "omega": sp["omega"], "value": sp["amplitude"], "curve": "track_amplitude_lp1"}
               for sp in track["special_points"] if sp["type"] in ("min", "max")]
    summary = {"verb": "study", "isola_simulation": {"folder": "isolas/isola_1"},
               "tracking": [{"parameter": "amplitude", "curves": [{"lp": 1, "folder": "track_amplitude_lp1"}], "extrema": extrema,
                             "validations": [{"value": 0.15, "folder": "nfrc", "isola_branches": [{"folder": "isolas/isola_1"}]}]}]}
    with open(f"{out}/summary.json", "w") as f:
        json.dump(summary, f)
    return out


def test_fig12_draws_the_nfrc_the_isola_and_the_time_integrations(small_study):
    figure = nfrc_isolas_simulation_figure(small_study, zoom=None)
    # The isola lies at A = 0.15, not the nominal 0.12: another system, in its own panel (on the
    # nominal NFRC's axes it read as a branch of that NFRC) with the NFRC at its own value
    nominal_ax, isola_ax = figure.get_axes()
    assert isola_ax.get_title(loc="left") == "amplitude = 0.15"
    lines = {line.get_label(): line for line in nominal_ax.get_lines()}
    nfrc = read_result(f"{small_study}/nfrc")["branch"]
    isola = read_result(f"{small_study}/isolas/isola_1")["branch"]
    solid = lines["NFRC, x1"].get_ydata()
    drawn = np.where(np.isnan(solid), nominal_ax.get_lines()[1].get_ydata(), solid)  # unstable parts are the dashed line's
    np.testing.assert_allclose(drawn, norm_of(nfrc, "x1"))
    isola_lines = {line.get_label(): line for line in isola_ax.get_lines()}
    np.testing.assert_array_equal(isola_lines["isolated branch, x1"].get_xdata(), isola["omega"])
    assert "NFRC, x1" in isola_lines  # the NFRC at the isola's value, beside it
    for ax, folder, label in ((nominal_ax, "simulate", "time integration"), (isola_ax, "simulate_isola", "time integration on the isola")):
        s = read_result(f"{small_study}/{folder}")["summary"]
        x, y = {line.get_label(): line for line in ax.get_lines()}[label].get_data()
        np.testing.assert_allclose(x, s["omega"])
        np.testing.assert_allclose(y, [max(abs(s[f"max_{n}"]), abs(s[f"min_{n}"])) for n in ("x1", "x2")])
    plt.close(figure)


def test_fig7_births_and_merges_in_the_legend_and_no_text_over_another(small_study):
    track = read_result(f"{small_study}/track_amplitude_lp1")
    figure = plots.tracking_plane_figure(track, validations=[read_result(f"{small_study}/nfrc")])
    (ax,) = figure.get_axes()
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(t.startswith("min of amplitude") for t in legend) and any(t.startswith("max of amplitude") for t in legend)
    boxes = text_boxes(figure)[ax]
    assert len([t for t in ax.texts if t.get_text()]) >= 2  # the extrema's coordinates
    for i, (text, box) in enumerate(boxes):
        for other, other_box in boxes[i + 1:]:
            assert not box.overlaps(other_box), f"{text!r} overlaps {other!r}"
    plt.close(figure)


def test_study_figures_include_fig12_and_convert_to_mm(small_study):
    in_mm = study_figures(small_study, "mm", "m")  # every figure of the study: about 2 s
    assert {"nfrc_isolas_simulation", "tracking_amplitude", "tracking_3d_amplitude", "validation_amplitude"} <= set(in_mm)
    ax, ax_mm = nfrc_isolas_simulation_figure(small_study).get_axes()[0], in_mm["nfrc_isolas_simulation"].get_axes()[0]
    assert "[mm]" in ax_mm.get_ylabel()
    for line, line_mm in zip(ax.get_lines(), ax_mm.get_lines()):
        np.testing.assert_allclose(line_mm.get_ydata(), 1e3 * np.asarray(line.get_ydata()))
    labels = [t.get_text() for legend in in_mm["tracking_3d_amplitude"].legends for t in legend.get_texts()]  # the figure's legend
    assert "isolated branches" in labels
    plt.close("all")


def test_a_curve_the_study_started_from_a_validation_nfrc_is_named_by_it(small_study, tmp_path):
    # Its limit point is that NFRC's, not the nominal one's: "LP1 tracked" would name the wrong point.
    import shutil
    study = str(tmp_path / "study")
    shutil.copytree(small_study, study)
    with open(f"{study}/summary.json") as f:
        summary = json.load(f)
    summary["tracking"][0]["curves"].append({"lp": 0, "folder": "track_amplitude_lp1", "from": "nfrc LP3"})  # the validation NFRC's folder
    with open(f"{study}/summary.json", "w") as f:
        json.dump(summary, f)
    figure = study_figures(study)["tracking_amplitude"]
    labels = [t.get_text() for t in figure.get_axes()[0].get_legend().get_texts()]
    # The absorber's LP1 curve runs through the cusp to the nominal NFRC's LP2: one curve, both named
    assert "LP1, LP2 tracked (one curve)" in labels and "LP3 of the NFRC at amplitude = 0.15, tracked" in labels  # its value, not its folder
    plt.close("all")


def test_a_validation_figure_of_many_nfrcs_keeps_its_legend_off_the_curves(small_study):
    # Rotor 67's study draws 23 NFRCs of the clearance: a legend inside covered the axes, and an
    # entry per NFRC repeated the ten colours of the cycle (two values read as one).
    track = read_result(f"{small_study}/track_amplitude_lp1")
    nfrc = read_result(f"{small_study}/nfrc")
    figure = plots.validation_figure(track, [nfrc] * 12)
    figure.canvas.draw()
    ax, bar = figure.get_axes()
    legend_box = ax.get_legend().get_window_extent()
    assert legend_box.y1 <= ax.get_window_extent().y0  # below the axes, not over them
    assert legend_box.x1 <= figure.bbox.x1 and legend_box.y0 >= figure.bbox.y0  # and inside the figure
    assert len(ax.get_legend().get_texts()) < 12  # kinds of curves, not one entry per NFRC
    assert bar.get_label() == "<colorbar>" and bar.get_ylabel().startswith("amplitude")  # the value by colour
    plt.close(figure)
