"""`hbtrack export DIR`: a result folder as a MATLAB .mat file, read back with scipy.io.loadmat
(as MATLAB and Octave would): every table column bit for bit (the states' too, a field per column),
the special points and summary.json as the folder holds them."""
import json
import os
import subprocess

import numpy as np
import scipy.io

from conftest import cli_path, run_cli
from hbtrack.results import read_columns


def test_export_writes_every_table_special_point_and_the_summary(duffing_frc_cli, tmp_path):
    folder = duffing_frc_cli["folder"]
    mat = str(tmp_path / "duffing.mat")
    run_cli("export", folder, "-o", mat)
    m = scipy.io.loadmat(mat, squeeze_me=True, struct_as_record=False)
    assert {"branch", "states", "special_states", "special_points", "summary_json"} <= set(m)

    branch = read_columns(os.path.join(folder, "branch.csv"))
    for name, values in branch.items():
        np.testing.assert_array_equal(getattr(m["branch"], name), values)  # doubles written as read

    states = read_columns(os.path.join(folder, "states.csv"))  # every dof's harmonics, a field per column
    assert list(states)[:4] == ["omega", "x_h0", "x_c1", "x_s1"]
    for name, values in states.items():
        np.testing.assert_array_equal(getattr(m["states"], name), values)

    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    assert json.loads(m["summary_json"]) == summary
    points = np.atleast_1d(m["special_points"])
    assert [p.type for p in points] == [p["type"] for p in summary["special_points"]]
    assert [p.omega for p in points] == [p["omega"] for p in summary["special_points"]]
    assert [int(p.index) for p in points] == [p["index"] for p in summary["special_points"]]


def test_export_refuses_a_missing_folder_and_an_unknown_format_in_one_line(tmp_path):
    for args, message in [([str(tmp_path / "absent")], "not a result folder"),
                          ([str(tmp_path), "--format", "hdf"], "--format: must be mat or h5")]:
        done = subprocess.run([cli_path(), "export", *args], capture_output=True, text=True)
        assert done.returncode == 2
        assert message in done.stderr
        assert done.stderr.count("\n") == 1
    assert not list(tmp_path.iterdir())  # nothing half-written
