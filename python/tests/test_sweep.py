"""`hbtrack sweep` seen from Python: the figure of a sweep folder (what `hbtrack plot DIR` draws),
and the README's thread-pool example, which must run and agree with the CLI."""
import os
import subprocess
import sys

import numpy as np

import hbtrack
from hbtrack import plots
from hbtrack.plot import figures_for

from conftest import DUFFING, ROOT, run_cli

DUFFING_TWO_PARAMETERS = os.path.join(ROOT, "tests", "data", "duffing_two_parameters.toml")


def test_sweep_folder_figure_maps_the_peak_over_the_grid(tmp_path):
    folder = str(tmp_path / "sweep")
    run_cli("sweep", DUFFING_TWO_PARAMETERS, "--param", "amplitude", "--values", "0.8,1.2", "--param", "cubic", "--values",
            "0.05:0.15:3", "--jobs", "2", "-o", folder)
    result = hbtrack.read_result(folder)
    assert result["kind"] == "sweep"
    figures = figures_for(result)
    assert set(figures) == {"sweep_peaks"}
    maps = [ax for ax in figures["sweep_peaks"].get_axes() if ax.get_images()]
    assert len(maps) == 2  # the peak, and the first limit point's frequency (every NFRC folds)
    peak = maps[0].get_images()[0].get_array()
    assert peak.shape == (3, 2)  # cubic on the rows, amplitude on the columns
    assert np.all(peak[:, 1] > peak[:, 0])  # more forcing, larger peak
    for ax in maps:
        assert ax.get_xlabel().startswith("amplitude [") and ax.get_ylabel().startswith("cubic [")
    files = plots.save_figure(figures["sweep_peaks"], str(tmp_path / "sweep_peaks"))
    assert all(os.path.getsize(f) > 1000 for f in files)


def test_thread_pool_example_gives_the_cli_numbers(tmp_path):
    example = os.path.join(ROOT, "examples", "python", "sweep_threads.py")
    done = subprocess.run([sys.executable, example, "2"], capture_output=True, text=True, check=True)
    rows = [line.split(",") for line in done.stdout.splitlines()[1:]]
    assert len(rows) == 9 and all(row[2] == "reached_end" for row in rows)
    # Row 8: amplitude 1.4, H = 7, the case as it is but for the amplitude.
    folder = str(tmp_path / "frc")
    run_cli("frc", DUFFING, "--set", "amplitude=1.4", "-o", folder)
    peak = hbtrack.read_result(folder)["branch"]["max_x"].max()
    # The same library computes both; the example prints 10 significant digits.
    assert rows[8][:2] == ["1.4", "7"] and abs(float(rows[8][3]) - peak) <= 1e-9 * peak


def test_sweep_map_marks_nfrcs_that_left_the_range_and_says_no_fold(tmp_path):
    # The blade sweep of sweeps.md: 34 of 64 NFRCs leave the frequency range (their peak and
    # folds are the part computed) and one has no fold: the map must say both, not draw them
    # as complete results and a blank.
    import json
    from hbtrack.sweep_figures import sweep_figure
    folder = tmp_path / "sweep"
    (folder / "tasks" / "0000").mkdir(parents=True)
    (folder / "sweep.json").write_text(json.dumps({"parameters": ["clearance", "mu"]}))
    (folder / "tasks" / "0000" / "summary.json").write_text(json.dumps({"outputs": [{"name": "le", "description": "leading edge"}]}))
    rows = ["task,clearance,mu,status,points,peak_max_le,lps,lp1_omega",
            "0,1,1,reached_end,9,0.5,0,", "1,1,2,left_range,9,0.4,1,2000", "2,2,1,reached_end,9,0.6,2,2010", "3,2,2,reached_end,9,0.7,2,2020"]
    (folder / "sweep.csv").write_text("\n".join(rows) + "\n")
    figure = sweep_figure(str(folder))
    maps = [ax for ax in figure.get_axes() if ax.get_images()]
    texts = [[t.get_text() for t in ax.texts] for ax in maps]
    assert "0.4*" in texts[0] and "2000*" in texts[1] and "no fold" in texts[1]
    assert any("left the frequency range" in t.get_text() for t in figure.texts)
    assert "leading edge" in figure.get_axes()[2].get_ylabel()  # the peak's colour bar: the output's description
    plots.plt.close("all")
