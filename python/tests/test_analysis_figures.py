"""The figures of backbones, continuations and switched branches (`hbtrack plot`), several
result folders drawn over each other, and the study's NFRC figure with the backbone and switched
branches its [study] section asked for: what is drawn (the curves' data against the folders'
branch.csv, a legend entry naming each folder, unstable parts dashed, special points marked),
not only that a file exists. One study of the coupled Duffing oscillators (about 3 s) provides
the NFRC, backbone and switched-branch folders."""
import os
import subprocess

import numpy as np
import pytest

import hbtrack
from hbtrack import analysis_figures, plots
from hbtrack.plots import plt
from hbtrack.overlay_figures import distinct_part, overlay_figure
from hbtrack.plot import figures_for
from hbtrack.results import read_result
from hbtrack.study_figures import study_figures

from conftest import DUFFING, ROOT, cli_path, run_cli
from test_plots import assert_labelled_with_units, assert_written
from test_same_as_cli import assert_same_columns, assert_same_special_points

COUPLED = os.path.join(ROOT, "examples", "coupled_duffing.toml")


@pytest.fixture(scope="module")
def coupled_study(tmp_path_factory):
    """`hbtrack study` of the coupled Duffing example: its [study] asks for the backbone of mode 1
    and switch = true."""
    out = str(tmp_path_factory.mktemp("coupled_study") / "out")
    run_cli("study", COUPLED, "-o", out)
    summary = read_result(out)["summary"]
    switched = [w["folder"] for w in summary["switched"] if "folder" in w]
    assert switched, summary["switched"]
    return {"dir": out, "summary": summary, "nfrc": os.path.join(out, "nfrc"), "backbone": os.path.join(out, "backbone_mode1"),
            "switched": [os.path.join(out, f) for f in switched]}


@pytest.fixture(scope="module")
def continue_cli(tmp_path_factory):
    folder = str(tmp_path_factory.mktemp("cont") / "cont")
    run_cli("continue", DUFFING, "--param", "amplitude", "--omega", "1.2", "--range", "0.05:3", "-o", folder)
    return folder


def legend_texts(where):
    """The legend's texts of an axes, or of a figure (whose legend is below its panels)."""
    legends = where.legends if hasattr(where, "legends") and where.legends else [where.get_legend()]
    return [t.get_text() for legend in legends for t in legend.get_texts()]


def line_labelled(ax, label):
    lines = [line for line in ax.get_lines() if line.get_label() == label]
    assert len(lines) == 1, f"{label!r} among {[line.get_label() for line in ax.get_lines()]}"
    return lines[0]


def drawn_curve(ax, label):
    """(x, y) of the curve with this legend label: its stable points (the labelled solid line,
    NaN elsewhere) joined with its unstable ones (the dashed line drawn next, same colour)."""
    lines = ax.get_lines()
    solid = line_labelled(ax, label)
    k = lines.index(solid)
    y = np.asarray(solid.get_ydata(), float)
    after = lines[k + 1] if k + 1 < len(lines) else None
    if after is not None and after.get_linestyle() == "--" and after.get_color() == solid.get_color():
        y = np.where(np.isfinite(y), y, np.asarray(after.get_ydata(), float))
    return np.asarray(solid.get_xdata(), float), y


@pytest.mark.parametrize("kind, expected", [("backbone", {"backbone", "backbone_outputs"}), ("continue", {"continuation", "harmonics"}),
                                            ("switch", {"nfrc", "fourier", "harmonics", "switched"})])
def test_hbtrack_plot_knows_backbone_continue_and_switch_folders(kind, expected, coupled_study, continue_cli, tmp_path):
    folder = {"backbone": coupled_study["backbone"], "continue": continue_cli, "switch": coupled_study["switched"][0]}[kind]
    result = read_result(folder)
    assert result["kind"] == kind
    figures = figures_for(result)
    assert set(figures) == expected
    for figure in figures.values():
        assert_labelled_with_units(figure)
    stem = sorted(expected)[0]  # written as PNG and PDF (one: each costs a second)
    assert_written(plots.save_figure(figures[stem], str(tmp_path / stem)))
    for figure in figures.values():
        plt.close(figure)


def test_backbone_figure_draws_omega_and_damping_against_amplitude(coupled_study):
    bb = read_result(coupled_study["backbone"])
    left, right = analysis_figures.backbone_figure(bb).get_axes()
    line = line_labelled(left, "backbone of mode 1")
    np.testing.assert_array_equal(line.get_xdata(), bb["branch"]["amplitude"])
    np.testing.assert_array_equal(line.get_ydata(), bb["branch"]["omega"])
    # The damping is C = 0.02 M: a modal damping ratio of 0.02 / (2 omega), in percent.
    damping = right.get_lines()[0]
    np.testing.assert_allclose(damping.get_ydata(), 100 * 0.02 / (2 * bb["branch"]["omega"]), rtol=1e-8)


def test_continuation_figure_dashes_the_unstable_middle_of_the_s_curve(continue_cli):
    result = read_result(continue_cli)
    ax = analysis_figures.continuation_figure(result).get_axes()[0]
    assert {"-", "--"} <= {line.get_linestyle() for line in ax.get_lines()}
    assert "LP (fold)" in legend_texts(ax)
    assert ax.get_xlabel().startswith("amplitude [")


def test_plot_of_several_folders_overlays_nfrc_backbone_and_switched_branch(coupled_study, tmp_path):
    folders = [coupled_study["nfrc"], coupled_study["backbone"], coupled_study["switched"][0]]
    done = subprocess.run([cli_path(), "plot", *folders, "-o", str(tmp_path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert sorted(os.listdir(tmp_path)) == ["overlay.pdf", "overlay.png"]

    results = [read_result(f) for f in folders]
    figure = overlay_figure(results)
    assert_labelled_with_units(figure)
    axes = figure.get_axes()
    assert len(axes) == 2  # x1 and x2
    nfrc, bb, switched = results
    # Named by what they are, never by folder; the switched branch by its first mirror image
    # (distinct_part: drawn whole, x1's envelope was x2's)
    names = ["NFRC", "backbone of mode 1",
             f"branch switched at the BP at ω = {switched['summary']['options']['switch']['omega']:.5g} (one half; its mirror swaps x1, x2)"]
    drawn_switched = distinct_part(switched)[0]
    texts = legend_texts(figure)
    assert texts[:3] == names
    assert "BP (branch point)" in texts and "LP (fold)" in texts
    for ax, output in zip(axes, ("x1", "x2")):
        # Each curve is its folder's branch.csv; the switched branch is asymmetric (x1 != x2).
        np.testing.assert_array_equal(line_labelled(ax, names[1]).get_ydata(), bb["branch"][f"max_{output}"])
        for label, result in ((names[0], nfrc), (names[2], drawn_switched)):
            x, y = drawn_curve(ax, label)
            np.testing.assert_array_equal(x, result["branch"]["omega"])
            np.testing.assert_array_equal(y, result["branch"][f"max_{output}"])
        colour = line_labelled(ax, names[2]).get_color()
        assert {"-", "--"} <= {line.get_linestyle() for line in ax.get_lines() if line.get_color() == colour}
        # The x range is the NFRC's; the backbone, which goes further, is clipped to it.
        assert ax.get_xlim()[1] < 1.05 * nfrc["branch"]["omega"].max()
    x1 = switched["branch"]["max_x1"]
    x2 = switched["branch"]["max_x2"]
    assert np.max(np.abs(x1 - x2)) > 0.1 * np.max(x1)


def test_plot_refuses_to_overlay_a_result_without_branch(coupled_study, tmp_path):
    done = subprocess.run([cli_path(), "plot", coupled_study["nfrc"], coupled_study["dir"], "-o", str(tmp_path)],
                          capture_output=True, text=True)
    assert done.returncode == 2
    assert "a 'study' result has no branch in the (omega, output) plane" in done.stderr
    assert done.stderr.count("\n") == 1


def test_study_nfrc_figure_draws_the_backbone_and_switched_branches(coupled_study):
    figures = study_figures(coupled_study["dir"])
    ax = figures["nfrc"].get_axes()[0]
    texts = legend_texts(figures["nfrc"])
    assert texts[0] == "nominal NFRC"
    assert "backbone of mode 1" in texts
    for folder in coupled_study["switched"]:
        switched = read_result(folder)
        label = [t for t in texts if t.startswith(f"branch switched at the BP at ω = {switched['summary']['options']['switch']['omega']:.5g}")]
        assert len(label) == 1, texts
        np.testing.assert_array_equal(drawn_curve(ax, label[0])[1], distinct_part(switched)[0]["branch"]["max_x1"])
    # The study drew this figure into its folder (a PNG of the overlay, not the plain NFRC).
    assert os.path.getsize(os.path.join(coupled_study["dir"], "figures", "nfrc.png")) > 20000
    assert "figures/nfrc.png" in coupled_study["summary"]["figures"]


def test_switch_from_python_equals_the_cli(coupled_study):
    # The same library code from the same states (the CLI's %.17g CSV reads back to the same
    # doubles): test_same_as_cli.py's tolerance.
    folder = coupled_study["switched"][0]
    cli = read_result(folder)
    point = cli["summary"]["options"]["switch"]["point"]
    case = hbtrack.load_case(COUPLED)
    api = hbtrack.switch(case, read_result(coupled_study["nfrc"]), point=point)
    assert api["kind"] == "switch" and api["summary"]["stop_reason"] == "completed"
    assert_same_columns(api["branch"], cli["branch"])
    assert_same_special_points(api["special_points"], cli["special_points"])
    with pytest.raises(ValueError, match="special point 1 of the frc result is a LP"):
        hbtrack.switch(case, read_result(coupled_study["nfrc"]), point=1)
