"""The publication figures of `hbtrack plot` (branch_figures.py): no two texts of an axes overlap
(measured by the renderer), the special points labelled once each, LP1..LPn in omega order, LP
and BP at one point merged rather than printed over each other; --units mm multiplies the drawn
data by 1000; the Fourier figure's bars are branch.csv's hK_ values; outputs named by their
descriptions, never by a column name. On the Duffing NFRC of conftest and the coupled Duffing
oscillators' (about 1 s; their LP and BP coincide)."""
import os
import re

import numpy as np
import pytest

from hbtrack import branch_figures
from hbtrack.output_descriptions import output_descriptions, parse_labels
from hbtrack.plot import figures_for, main
from hbtrack.plots import plt
from hbtrack.results import read_result
from hbtrack.units import length_factor, scale_lengths

from conftest import ROOT, run_cli

COUPLED = os.path.join(ROOT, "examples", "coupled_duffing.toml")


@pytest.fixture(scope="module")
def coupled_frc(tmp_path_factory):
    folder = str(tmp_path_factory.mktemp("publication") / "coupled")
    run_cli("frc", COUPLED, "-o", folder)
    return read_result(folder)


@pytest.fixture(params=["duffing", "coupled"])
def branch_result(request, duffing_frc_cli, coupled_frc):
    return duffing_frc_cli if request.param == "duffing" else coupled_frc


def text_boxes(figure):
    """{axes: [(text, pixel box)]} of every non-empty text drawn in the axes (labels of special
    points, legend entries), the text's own box (not a leader line's)."""
    figure.canvas.draw()  # the legend's place is decided when drawn
    renderer = figure.canvas.get_renderer()
    boxes = {}
    for ax in figure.get_axes():
        texts = list(ax.texts)
        if ax.get_legend():
            texts += ax.get_legend().get_texts()
        boxes[ax] = [(t.get_text(), plt.Text.get_window_extent(t, renderer)) for t in texts if t.get_text() and t.get_visible()]
    return boxes


@pytest.mark.parametrize("norm", [False, True])
def test_no_two_texts_overlap_and_special_points_are_labelled_once(branch_result, norm):
    figure = branch_figures.nfrc_figure(branch_result, norm=norm)
    expected = {label for label, _ in branch_figures.numbered_special_points(branch_result["special_points"])}
    for ax, boxes in text_boxes(figure).items():
        for i, (text, box) in enumerate(boxes):
            for other, other_box in boxes[i + 1:]:
                assert not box.overlaps(other_box), f"{text!r} overlaps {other!r}"
        labels = [t for t in ax.texts if t.get_text()]
        shown = [name for t in labels for name in t.get_text().split(", ")]
        assert len(shown) == len(set(shown)), shown  # each special point once per axes
        assert all(re.fullmatch(r"(LP|BP|PD|NS)\d+", name) for name in shown), shown
        assert set(shown) <= expected
        frame = ax.get_window_extent(figure.canvas.get_renderer())
        for t in labels:  # inside the axes
            box = plt.Text.get_window_extent(t, figure.canvas.get_renderer())
            assert frame.x0 <= box.x0 and box.x1 <= frame.x1 and frame.y0 <= box.y0 and box.y1 <= frame.y1, t.get_text()
    plt.close(figure)


def test_limit_points_numbered_in_omega_order_and_coincident_points_merged(coupled_frc):
    numbered = branch_figures.numbered_special_points(coupled_frc["special_points"])
    lps = [sp["omega"] for label, sp in numbered if label.startswith("LP")]
    assert lps == sorted(lps) and [label for label, _ in numbered if label.startswith("LP")] == [f"LP{k}" for k in range(1, len(lps) + 1)]
    figure = branch_figures.nfrc_figure(coupled_frc, norm=True, zoom=None)
    texts = [t.get_text() for t in figure.get_axes()[0].texts]
    # coupled_duffing.toml: the LP and the BP at omega = 1.082 share a point; one label names both
    assert any("LP" in t and "BP" in t for t in texts), texts
    plt.close(figure)


def test_units_mm_multiply_the_drawn_lengths_by_1000(duffing_frc_cli):
    plain = figures_for(duffing_frc_cli, zoom=None)
    in_mm = figures_for(duffing_frc_cli, "mm", "m", zoom=None)
    for stem in ("nfrc", "fourier"):
        for ax, ax_mm in zip(plain[stem].get_axes(), in_mm[stem].get_axes()):
            assert "[mm]" in ax_mm.get_ylabel()
            lines, lines_mm = ax.get_lines(), ax_mm.get_lines()
            assert len(lines) == len(lines_mm) and (lines or ax.patches)
            for line, line_mm in zip(lines, lines_mm):
                np.testing.assert_array_equal(line_mm.get_xdata(), line.get_xdata())  # omega stays
                np.testing.assert_allclose(line_mm.get_ydata(), 1e3 * np.asarray(line.get_ydata()), rtol=1e-12)
            heights = [p.get_height() for p in ax.patches]
            np.testing.assert_allclose([p.get_height() for p in ax_mm.patches], 1e3 * np.asarray(heights), rtol=1e-12)
    assert length_factor("mm") == 1e3 and length_factor("m", "mm") == 1e-3 and length_factor("model units") == 1.0
    assert scale_lengths(duffing_frc_cli, 1.0) is duffing_frc_cli
    for figures in (plain, in_mm):
        for figure in figures.values():
            plt.close(figure)


@pytest.mark.parametrize("point", [None, "LP2", 7])
def test_fourier_bars_are_the_branch_csv_magnitudes(duffing_frc_cli, point):
    branch = duffing_frc_cli["branch"]
    figure = branch_figures.fourier_figure(duffing_frc_cli, point)
    row = {None: None, "LP2": None, 7: 7}[point]
    if row is None:  # LP1 by default: the point of the first limit point in omega order
        numbered = dict(branch_figures.numbered_special_points(duffing_frc_cli["special_points"]))
        row = numbered[point or "LP1"]["index"]
    harmonics = sorted((c for c in branch if re.fullmatch(r"h\d+_x", c)), key=lambda c: int(c[1:-2]))
    (ax,) = figure.get_axes()
    np.testing.assert_array_equal([p.get_height() for p in ax.patches], [abs(branch[c][row]) for c in harmonics])
    assert [t.get_text() for t in ax.get_xticklabels()] == [c[1:-2] for c in harmonics]
    plt.close(figure)
    with pytest.raises(ValueError, match="LP9"):
        branch_figures.chosen_point(duffing_frc_cli, "LP9")


def test_outputs_named_by_their_descriptions_never_by_columns(coupled_frc):
    labels = {"x1": "first mass"}
    figure = branch_figures.nfrc_figure(coupled_frc, descriptions=labels)
    ylabels = [ax.get_ylabel() for ax in figure.get_axes()]
    assert ylabels[0].startswith("first mass [") and not any("max_" in y or "min_" in y for y in ylabels)
    legend = [t.get_text() for ax in figure.get_axes() for t in ax.get_legend().get_texts()]
    assert not any(re.match(r"(max|min)_", t) for t in legend), legend
    plt.close(figure)
    assert parse_labels(["le=leading edge"]) == {"le": "leading edge"}
    with pytest.raises(ValueError):
        parse_labels(["le"])
    # summary.json's descriptions (the case file's [[outputs]] description), else name and dof
    rotor = {"summary": {"outputs": [{"name": "le", "dof": "n1_r", "description": "leading-edge tip, radial"},
                                     {"name": "te", "dof": "n9_r"}]}}
    assert output_descriptions(rotor) == {"le": "leading-edge tip, radial", "te": "te (n9_r)"}
    assert output_descriptions(rotor, {"te": "trailing edge"})["te"] == "trailing edge"


def test_zoom_on_the_resonance():
    omega = np.linspace(0.0, 10.0, 1001)
    peak = 1.0 / np.hypot(1.0 - (omega / 5.0) ** 2, 0.02)  # a sharp resonance at 5
    branch = {"omega": omega, "max_x": peak, "min_x": -peak}
    lo, hi = branch_figures.resonance_window([branch], ["x"])
    assert 3.5 < lo < 5.0 < hi < 6.5
    flat = {"omega": omega, "max_x": np.ones_like(omega), "min_x": -np.ones_like(omega)}
    assert branch_figures.resonance_window([flat], ["x"]) is None  # nothing to zoom on
    result = {"kind": "frc", "summary": {"outputs": [{"name": "x", "dof": "x"}]}, "branch": branch, "special_points": []}
    figure = branch_figures.nfrc_figure(result)
    assert figure.get_axes()[0].get_xlim() == (lo, hi)
    assert branch_figures.nfrc_figure(result, zoom=None).get_axes()[0].get_xlim()[1] > 9.0
    plt.close("all")


def test_plot_options_write_png_and_pdf(coupled_frc, tmp_path):
    out = str(tmp_path / "figures")
    code = main([coupled_frc["folder"], "-o", out, "--units", "mm", "--norm", "--no-zoom", "--point", "LP2",
                 "--label", "x1=first mass", "--titles"])
    assert code == 0
    assert sorted(os.listdir(out)) == sorted(f"{stem}.{ext}" for stem in ("nfrc", "fourier", "harmonics") for ext in ("png", "pdf"))
    assert main([coupled_frc["folder"], "-o", out, "--point", "LP7"]) == 2  # no such point: said, not a traceback


def test_long_legend_labels_do_not_run_into_each_other():
    # Rotor 67's Fig. 12: "isolated branch, mu = 0.1236, leading-edge tip, radial" beside "time
    # integration on the isola" in two columns ran into each other.
    figure, ax = plt.subplots(figsize=(6.5, 4.2))
    for label in ("NFRC, leading-edge tip, radial", "isolated branch, mu = 0.1236, leading-edge tip, radial",
                  "NFRC, trailing-edge tip, radial", "isolated branch, mu = 0.1236, trailing-edge tip, radial"):
        ax.plot([0, 1], [0, 1], label=label)
    extra = [ax.plot([], [], "o", label=name)[0] for name in ("time integration", "time integration on the isola")]
    for line in extra:
        line.remove()
    branch_figures._legend(ax, extra)
    boxes = text_boxes(figure)[ax]
    assert len(boxes) == 6
    for i, (text, box) in enumerate(boxes):
        for other, other_box in boxes[i + 1:]:
            assert not box.overlaps(other_box), f"{text!r} overlaps {other!r}"
    plt.close(figure)


def test_the_overlap_check_sees_texts_printed_over_each_other():
    # What the figure printed before: LP and NS at one point as 'LP' over 'NS' ("LNS")
    figure, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    for text in ("LP", "NS"):
        ax.annotate(text, (0.5, 0.5), textcoords="offset points", xytext=(4, 4), fontsize=8)
    (a, box_a), (b, box_b) = text_boxes(figure)[ax]
    assert box_a.overlaps(box_b)
    plt.close(figure)


def test_the_binary_passes_every_plot_option_on(coupled_frc, tmp_path):
    """`hbtrack plot` takes the options of `python -m hbtrack.plot` and passes them on: the same
    figures, and a bad value refused by the binary in one line with a non-zero exit."""
    import subprocess
    from conftest import cli_path

    def run_cli(*args, check=True):
        return subprocess.run([cli_path(), *args], capture_output=True, text=True, check=check)
    out = str(tmp_path / "figures")
    run_cli("plot", coupled_frc["folder"], "-o", out, "--units", "mm", "--norm", "--no-zoom", "--point", "LP2",
            "--label", "x1=first mass", "--label", "x2=second mass", "--titles", "--zoom", "0.2")
    assert sorted(os.listdir(out)) == sorted(f"{stem}.{ext}" for stem in ("nfrc", "fourier", "harmonics") for ext in ("png", "pdf"))
    refused = run_cli("plot", coupled_frc["folder"], "--zoom", "2", check=False)
    assert refused.returncode != 0 and "--zoom" in refused.stderr and refused.stderr.count("\n") == 1
    missing = run_cli("plot", coupled_frc["folder"], "-o", out, "--point", "LP7", check=False)
    assert missing.returncode == 2  # no such point: said, not a traceback
