"""Every figure type is made for every result type, from result folders and from API results:
files non-empty (PNG and PDF), every axis labelled with its unit."""
import os
import subprocess

import numpy as np
import pytest

import hbtrack
from hbtrack import plots, view_angle
from hbtrack.plots import plt
from hbtrack.plot import figures_for, make_figures

from conftest import DUFFING, ROOT, cli_path, run_cli

EXPECTED = {  # result kind: figures made for it
    "frc": {"nfrc", "fourier", "harmonics"},
    "solve": {"nfrc", "fourier", "harmonics"},
    "track": {"tracking_3d", "tracking"},
    "isolas": {"isolas", "tracking"},
    "isola_branch": {"nfrc", "fourier", "harmonics"},  # one branch folder of an isolas result
    "simulate": {"signals", "harmonics_x"},
}


def assert_labelled_with_units(figure):
    axes = figure.get_axes()
    assert axes
    for ax in axes:
        labels = [ax.get_xlabel(), ax.get_ylabel()] + ([ax.get_zlabel()] if hasattr(ax, "get_zlabel") else [])
        if ax.get_label() == "<colorbar>":  # a colour bar has one label, along it
            labels = [ax.get_ylabel() or ax.get_xlabel()]
        for label in labels:
            assert "[" in label and label.endswith("]") and len(label.split("[")[1]) > 1, f"no unit in {label!r}"
        assert ax.has_data()


def assert_written(files):
    assert {os.path.splitext(f)[1] for f in files} == {".png", ".pdf"}
    for f in files:
        assert os.path.getsize(f) > 1000, f  # an empty matplotlib PNG/PDF is smaller than this


@pytest.fixture(scope="module")
def solve_cli(results_dir):
    folder = str(results_dir / "duffing_solve")
    run_cli("solve", DUFFING, "--omega", "1.2", "-o", folder)
    return folder


@pytest.mark.parametrize("kind", sorted(EXPECTED))
def test_figures_of_each_result_folder(kind, request, tmp_path, solve_cli):
    if kind == "solve":
        folder = solve_cli
    elif kind == "isola_branch":
        isolas = request.getfixturevalue("duffing_isolas_cli")
        folder = os.path.join(isolas["folder"], sorted(isolas["branches"])[0])
    else:
        folder = request.getfixturevalue({"frc": "duffing_frc_cli", "track": "duffing_track_cli", "isolas": "duffing_isolas_cli",
                                          "simulate": "duffing_simulate_cli"}[kind])["folder"]
    result = hbtrack.read_result(folder)
    assert result["kind"] == kind
    figures = figures_for(result)
    assert set(figures) == EXPECTED[kind]
    for stem, figure in figures.items():
        assert_labelled_with_units(figure)
        assert_written(plots.save_figure(figure, str(tmp_path / stem)))


def test_track_figures_overlay_the_nfrc_it_started_from(duffing_track_cli):
    plane = figures_for(hbtrack.read_result(duffing_track_cli["folder"]))["tracking"]
    labels = [line.get_label() for line in plane.get_axes()[0].get_lines()]
    assert "LPs of NFRCs" in labels


def test_figures_of_api_results(duffing_frc, duffing_track, tmp_path):
    validation = plots.validation_figure(duffing_track, [duffing_frc])
    for figure in (plots.nfrc_figure(duffing_frc), plots.tracking_3d_figure(duffing_track, validations=[duffing_frc]),
                   validation, plots.tracking_plane_figure(duffing_track, validations=[duffing_frc])):
        assert_labelled_with_units(figure)
    assert_written(plots.save_figure(validation, str(tmp_path / "validation")))


def test_unstable_points_are_dashed(duffing_frc):
    # README: the Duffing points between the folds are unstable, drawn dashed.
    lines = plots.nfrc_figure(duffing_frc).get_axes()[0].get_lines()
    assert {"-", "--"} <= {line.get_linestyle() for line in lines}


def test_hbtrack_plot_verb(duffing_frc_cli, tmp_path):
    done = subprocess.run([cli_path(), "plot", duffing_frc_cli["folder"], "-o", str(tmp_path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert sorted(os.listdir(tmp_path)) == ["fourier.pdf", "fourier.png", "harmonics.pdf", "harmonics.png", "nfrc.pdf", "nfrc.png"]
    assert sorted(done.stdout.split()) == sorted(str(tmp_path / f) for f in os.listdir(tmp_path))  # the files written, listed
    quiet = subprocess.run([cli_path(), "plot", duffing_frc_cli["folder"], "-o", str(tmp_path / "q"), "-q"], capture_output=True, text=True)
    assert quiet.returncode == 0 and quiet.stdout == "" and len(os.listdir(tmp_path / "q")) == 6, quiet.stderr
    refused = subprocess.run([cli_path(), "plot", ROOT], capture_output=True, text=True)
    assert refused.returncode == 2 and "no summary.json" in refused.stderr


def test_make_figures_of_a_simulation(duffing_simulate_cli, tmp_path):
    files = make_figures(duffing_simulate_cli["folder"], str(tmp_path))
    assert sorted(os.path.basename(f) for f in files) == ["harmonics_x.pdf", "harmonics_x.png", "signals.pdf", "signals.png"]


def test_3d_view_turns_away_from_where_two_curves_would_be_drawn_on_each_other():
    # A segment and its copy moved along the line of sight of the default view (elevation 25,
    # azimuth -60; the box is 4 x 4 x 3): drawn on each other from there, apart from the view chosen.
    e, a = np.radians(view_angle.ELEVATION), np.radians(view_angle.DEFAULT_AZIMUTH)
    sight = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)]) / view_angle.BOX
    t = np.linspace(0.1, 0.4, 40)
    first = np.column_stack([t, 0.8 + 0 * t, 0.2 + 0 * t])
    second = first + 0.5 * sight
    box = [(0, 1), (0, 1), (0, 1)]
    assert view_angle.least_hidden_view([first.T, second.T], box)[1] != view_angle.DEFAULT_AZIMUTH
    # Apart by more than the segments' own width from any side: the default view stays.
    assert view_angle.least_hidden_view([first.T, (first + [0.5, -0.6, 0.5]).T], box) == (view_angle.ELEVATION, view_angle.DEFAULT_AZIMUTH)
    # The figure applies it.
    track = {"summary": {"options": {"tracking": {"parameter": "p", "lp": 1}}, "outputs": [{"name": "x"}]}, "special_points": [],
             "branch": {"omega": np.r_[first[:, 0], second[::-1, 0]], "p": np.r_[first[:, 1], second[::-1, 1]],
                        "max_x": np.r_[first[:, 2], second[::-1, 2]], "leg": np.full(2 * len(t), 2)}}
    figure = plots.tracking_3d_figure(track)
    ax = figure.get_axes()[0]
    assert (ax.elev, ax.azim) == view_angle.least_hidden_view([(track["branch"]["omega"], track["branch"]["p"], track["branch"]["max_x"])],
                                                               [ax.get_xlim3d(), ax.get_ylim3d(), ax.get_zlim3d()])
    plt.close(figure)
