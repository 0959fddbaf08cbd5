"""Each kind of figure docs/figures ships (docs/figures.md lists them), drawn from a small run as
its page draws it, checked for the counts it claims: the branches drawn (lines of the data's
length), every special point marked on its curves and named once, the stability styles, a legend
entry per marker type, no legend text that is a folder's name and no two texts overlapping. The
runs are the examples' (Duffing, coupled Duffing, two-dof contact, absorber), about 10 s in all.
"""
import os
import re

import numpy as np
import pytest

from hbtrack import analysis_figures, branch_figures, plots
from hbtrack.overlay_figures import distinct_part, overlay_figure
from hbtrack.plot import figures_for
from hbtrack.plots import plt
from hbtrack.results import read_result
from hbtrack.special_points import distinct_special_points, numbered_special_points
from hbtrack.torus_figures import torus_figure

from conftest import DUFFING, NLTVA, ROOT, run_cli
from test_publication_figures import text_boxes

COUPLED = os.path.join(ROOT, "examples", "coupled_duffing.toml")
CONTACT = os.path.join(ROOT, "examples", "two_dof_contact.toml")
MARKERS = {"o": "LP", "s": "BP", "D": "PD", "P": "NS"}  # figure_style.SPECIAL_MARKERS' shapes


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The small runs the shipped figures are drawn from (docs/analyses.md's and tracking.md's commands)."""
    out = str(tmp_path_factory.mktemp("shipped"))
    commands = {
        "duffing": ("frc", DUFFING), "duffing_odd": ("frc", DUFFING, "--set", "harmonic_balance.harmonics=[1, 3, 5, 7]"),
        "bb": ("backbone", DUFFING, "--mode", "1", "--range", "0.01:5"),
        "cont": ("continue", DUFFING, "--param", "amplitude", "--omega", "1.2", "--range", "0.05:3"),
        "coupled": ("frc", COUPLED), "two_dof": ("frc", CONTACT), "nltva": ("frc", NLTVA),
    }
    for name, command in commands.items():
        run_cli(command[0], command[1], *command[2:], "-o", f"{out}/{name}")
    run_cli("switch", COUPLED, "--from", f"{out}/coupled", "--point", "2", "-o", f"{out}/switched")
    run_cli("switch", CONTACT, "--from", f"{out}/two_dof", "--point", "3", "-o", f"{out}/two_dof_pd")
    run_cli("track", DUFFING, "--from", f"{out}/duffing", "--lp", "1", "--param", "amplitude", "--range", "0.1:2", "-o", f"{out}/lp1")
    run_cli("track", NLTVA, "--from", f"{out}/nltva", "--lp", "1", "--param", "amplitude", "--range", "0.01:0.4", "-o", f"{out}/nltva_track")
    run_cli("isolas", NLTVA, "--from", f"{out}/nltva_track", "--at", "0.15", "-o", f"{out}/isolas")
    run_cli("torus", NLTVA, "--from", f"{out}/nltva", "--ns", "1", "--range", "1.0:1.3", "-o", f"{out}/torus")
    return {name: read_result(f"{out}/{name}") for name in [*commands, "switched", "two_dof_pd", "lp1", "nltva_track", "isolas", "torus"]}


def assert_no_text_overlaps(figure):
    """Catches a label printed over another (the blade study's "min (...)" over an x marker's label)."""
    for ax, boxes in text_boxes(figure).items():
        for i, (text, box) in enumerate(boxes):
            for other, other_box in boxes[i + 1:]:
                assert not box.overlaps(other_box), f"{text!r} overlaps {other!r}"


def legend_texts(figure):
    return [t.get_text() for legend in figure.legends + [ax.get_legend() for ax in figure.get_axes() if ax.get_legend()]
            for t in legend.get_texts()]


def assert_no_folder_names(figure, runs_used):
    """Catches a legend entry that is a folder's or a column's name ("bb: backbone", "duffing_odd",
    "isola_1", "max_x"): a reader has neither; an identifier with "_" is one of them."""
    for text in legend_texts(figure):
        assert not re.search(r"\w_\w", text), text
        assert not any(text == n or text.startswith(f"{n}:") or f"({n})" in text for n in runs_used), text


def marker_points(ax):
    """{type: [(x, y)]} of the special-point markers drawn (lines of markers only, not legend proxies)."""
    found = {}
    for line in ax.get_lines():
        kind = MARKERS.get(line.get_marker())
        x, y = (np.asarray(v, float) for v in line.get_data())
        if kind and line.get_linestyle() in ("None", "", " ") and len(x):
            found.setdefault(kind, []).extend(zip(x, y))
    return found


def named(ax):
    return [name for t in ax.texts if t.get_text() for name in t.get_text().split(", ")]


@pytest.mark.parametrize("name", ["duffing", "coupled", "two_dof"])
def test_nfrc_figure_marks_every_special_point_on_its_curves_and_names_it_once(runs, name):
    result = runs[name]
    figure = branch_figures.nfrc_figure(result)
    expected = [label for label, sp in numbered_special_points(result["special_points"])]
    for ax in figure.get_axes():
        # Catches a point drawn as an unexplained dot or left unnamed (rotor 67's five black dots)
        assert sorted(named(ax)) == sorted(expected), (named(ax), expected)
        points = marker_points(ax)
        for kind in {sp["type"] for sp in result["special_points"]}:
            # each point on the max and the min curve: 2 markers a point (one would leave a curve without its fold)
            assert len(points.get(kind, [])) == 2 * sum(sp["type"] == kind for sp in result["special_points"]), kind
        legend = [t.get_text() for t in ax.get_legend().get_texts()]
        assert {"stable", "unstable"} <= set(legend) and {"max over a period", "min over a period"} <= set(legend)
        assert {f"{k} (" for k in points} <= {t[:len(k) + 2] for t in legend for k in points}  # a legend entry per marker type
    assert_no_text_overlaps(figure)
    plt.close(figure)


def test_two_branches_on_each_other_both_drawn_and_their_folds_counted_once(runs):
    # duffing_odd_harmonics.png: the odd-harmonic NFRC equals the full one; it hid it, and its two
    # LPs were numbered LP3, LP4 beside LP1, LP2 of the same folds
    full, odd = runs["duffing"], dict(runs["duffing_odd"], label="odd harmonics")
    figure = branch_figures.nfrc_figure(dict(full, label="H = 7"), others=[odd])
    ax = figure.get_axes()[0]
    widths = sorted({line.get_linewidth() for line in ax.get_lines() if len(line.get_xdata()) > 10})
    assert len(widths) == 2 and widths[1] > widths[0] + 1.0  # the first wider, underneath: both visible
    assert sorted(named(ax)) == ["LP1", "LP2"]
    assert len(distinct_special_points(full["special_points"] + odd["special_points"])) == 2
    plt.close(figure)


def test_overlay_draws_the_continuation_in_its_own_axes_and_names_no_folder(runs):
    # duffing_overlay.png: the S-curve at omega = 1.2 was a vertical segment on the NFRC's axes
    figure = overlay_figure([runs["duffing"], runs["bb"], runs["cont"]])
    plane, beside = figure.get_axes()
    assert "amplitude" in beside.get_xlabel() and "omega" in plane.get_xlabel().replace(r"$\omega$", "omega")
    cont = runs["cont"]["branch"]
    assert not any(np.allclose(line.get_xdata(), 1.2) for line in plane.get_lines() if len(line.get_xdata()) == len(cont["omega"]))
    assert len(marker_points(beside)["LP"]) == 2 * len(runs["cont"]["special_points"])  # its folds on both envelopes
    assert_no_folder_names(figure, runs)
    assert {"stable", "unstable"} <= set(legend_texts(figure))
    assert_no_text_overlaps(figure)
    plt.close(figure)


def test_switched_branch_drawn_once_as_one_mirror_half(runs):
    # coupled_duffing_switched.png: both legs went round the same loop (28 special points for 14)
    # and the loop holds the branch and its mirror image, so the x1 and x2 panels were identical
    switched = runs["switched"]
    part, swapped = distinct_part(switched)
    assert swapped == ("x1", "x2") and len(part["branch"]["omega"]) < len(switched["branch"]["omega"]) / 2
    figure = overlay_figure([runs["coupled"], switched])
    x1, x2 = figure.get_axes()
    colour = "C1"
    curves = [ax_line.get_ydata() for ax_line in x1.get_lines() if ax_line.get_color() == colour and len(ax_line.get_xdata()) > 5]
    others = [ax_line.get_ydata() for ax_line in x2.get_lines() if ax_line.get_color() == colour and len(ax_line.get_xdata()) > 5]
    # the panels differ: max x1 and max x2 of the half differ by more than 10 % of the peak somewhere
    assert np.nanmax(np.abs(curves[0] - others[0])) > 0.1 * np.nanmax(np.abs(curves[0]))
    assert any("mirror swaps x1, x2" in t for t in legend_texts(figure))
    assert_no_folder_names(figure, runs)
    plt.close(figure)


def test_tracking_figure_counts_its_extrema_and_start_and_keeps_texts_apart(runs):
    # nltva_tracking.png: one curve, its min, max and min of the amplitude, its start, in the legend
    track = runs["nltva_track"]
    figure = plots.tracking_plane_figure(track)
    ax = figure.get_axes()[0]
    curves = [line for line in ax.get_lines() if len(line.get_xdata()) > 5]
    assert len(curves) == 1
    extrema = [sp for sp in track["special_points"] if sp["type"] in ("min", "max")]
    drawn = [line for line in ax.get_lines() if line.get_marker() in ("v", "^") and len(line.get_xdata())]
    assert len(drawn) == len(extrema) and len(extrema) == 3
    assert len([t for t in ax.texts if t.get_text()]) == len(extrema)  # each extremum's coordinates once
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(t.startswith("start") for t in legend) and any(t.startswith("min of amplitude") for t in legend)
    assert ax.get_ylabel() == "amplitude [-]"  # a name and a unit, not a sentence
    assert_no_text_overlaps(figure)
    plt.close(figure)


def test_isolas_figure_names_each_fold_once_and_its_branches_by_what_they_are(runs):
    # nltva_isola.png (the tutorial's): LP1-LP8 for 4 folds, the main branch found twice hid itself,
    # legend entries "isola_1", "open_1"
    figure = figures_for(runs["isolas"], titles=False)["isolas"]
    branches = list(runs["isolas"]["branches"].values())
    distinct = numbered_special_points(distinct_special_points([sp for b in branches for sp in b["special_points"]]))
    for ax in figure.get_axes():
        assert sorted(named(ax)) == sorted(label for label, _ in distinct)
    texts = legend_texts(figure)
    assert any(t.startswith("isolated branch 1") for t in texts) and any(t.startswith("main branch") for t in texts)
    assert_no_folder_names(figure, runs)
    assert_no_text_overlaps(figure)
    plt.close(figure)


def test_period_doubled_and_torus_figures_mark_every_fold(runs):
    # nltva_torus.png had no LP on its NFRC though its dashes change there
    figure = torus_figure(runs["torus"], nfrc=runs["nltva"])
    lps = [sp for sp in runs["nltva"]["special_points"] if sp["type"] == "LP"]
    for ax in figure.get_axes():
        drawn = [line for line in ax.get_lines() if line.get_label() == "LP (fold)"]
        assert len(drawn) == 1 and len(drawn[0].get_xdata()) == len(lps)
    plt.close(figure)
    figure = analysis_figures.period_doubled_figure(runs["two_dof_pd"], runs["two_dof"])
    left = figure.get_axes()[0]
    points = marker_points(left)
    assert "PD" in points and "LP" in points
    assert_no_folder_names(figure, runs)
    plt.close(figure)


def test_backbone_and_continue_figures_name_no_folder_and_state_stability(runs):
    figure = analysis_figures.backbone_figure(runs["bb"])
    assert_no_folder_names(figure, runs)
    plt.close(figure)
    figure = analysis_figures.continuation_figure(runs["cont"])
    ax = figure.get_axes()[0]
    assert {"stable", "unstable"} <= {t.get_text() for t in ax.get_legend().get_texts()}
    assert len(marker_points(ax)["LP"]) == 2 * len(runs["cont"]["special_points"])
    assert_no_folder_names(figure, runs)
    plt.close(figure)


def test_unknown_stability_is_said_not_drawn_as_stable():
    # a study's validation NFRCs and DLFT have no stability: solid lines claimed they were stable
    branch = {"omega": np.linspace(1, 2, 20), "max_x": np.linspace(0, 1, 20), "min_x": -np.linspace(0, 1, 20)}
    figure = branch_figures.nfrc_figure({"kind": "frc", "branch": branch, "special_points": [], "summary": {"outputs": [{"name": "x"}]}},
                                        outputs=["x"], zoom=None)
    legend = [t.get_text() for t in figure.get_axes()[0].get_legend().get_texts()]
    assert "stability not computed" in legend and "stable" not in legend
    plt.close(figure)


def test_overlaid_nfrcs_differing_in_a_parameter_are_named_by_it():
    # Rotor 67 at rest and at design speed both read "NFRC"; the second has the named parameter
    # speed, the first none: numbering them ("branch 2") said nothing a reader could use.
    from hbtrack.overlay_figures import legend_labels
    at_rest = {"kind": "frc", "summary": {"options": {"parameters": {"amplitude": 140.0}}}}
    at_speed = {"kind": "frc", "summary": {"options": {"parameters": {"amplitude": 140.0, "speed": 1680.0}}}}
    assert legend_labels([at_rest, at_speed]) == ["NFRC", "NFRC, speed = 1680"]
    louder = {"kind": "frc", "summary": {"options": {"parameters": {"amplitude": 200.0}}}}
    assert legend_labels([at_rest, louder]) == ["NFRC, amplitude = 140", "NFRC, amplitude = 200"]
    # Equal parameters and harmonics: told apart by number, as before.
    assert legend_labels([at_rest, dict(at_rest)]) == ["NFRC", "NFRC, branch 2"]


def test_tracking_figure_names_and_marks_every_fold_of_the_nfrc_on_a_curve(runs):
    # The absorber's LP1 curve runs through the cusp to LP2 at the nominal amplitude: a study
    # tracks it once, and rotor 67's "LP1 tracked" left LP3 unnamed and unmarked on it.
    from hbtrack.special_points import numbered_limit_points
    nfrc = runs["nltva"]
    figure = plots.tracking_plane_figure(runs["nltva_track"], nfrc_special_points=nfrc["special_points"])
    ax = figure.get_axes()[0]
    assert "LP1, LP2 tracked (one curve)" in legend_texts(figure)
    value = runs["nltva_track"]["summary"]["start"]["amplitude"]
    marked = [float(line.get_xdata()[0]) for line in ax.get_lines() if line.get_marker() == "o" and len(line.get_xdata()) == 1
              and float(line.get_ydata()[0]) == value]
    lps = [sp["omega"] for _, sp in numbered_limit_points(nfrc["special_points"])]
    assert sorted(marked) == pytest.approx(sorted(lps))  # each fold of the NFRC marked once, where the curve crosses its value
    plt.close("all")


def test_a_curve_too_small_to_see_gets_an_inset_and_outputs_are_named_by_their_description(runs):
    from hbtrack.figure_style import zoom_small_curves
    fig, ax = plt.subplots()
    ax.plot([0.0, 100.0], [0.0, 1.0])
    ax.plot([50.0, 50.5, 50.2], [0.5, 0.502, 0.505])  # rotor 67's closed curve in mu: 1.5 % of each span
    assert len(zoom_small_curves(ax, [([0.0, 100.0], [0.0, 1.0]), ([50.0, 50.5, 50.2], [0.5, 0.502, 0.505])])) == 1
    track = {**runs["nltva_track"], "summary": dict(runs["nltva_track"]["summary"])}
    name = plots.output_names(track)[0]
    track["summary"]["outputs"] = [{"name": name, "description": "absorber mass"}]  # as a case's [[outputs]] description gives it
    for norm in (True, False):
        figure = plots.validation_figure(track, [runs["nltva"]], norm=norm)
        assert "absorber mass" in figure.get_axes()[0].get_ylabel()  # not the CSV stem (rotor 67's "le", set as a mathtext product)
    plt.close("all")
