"""The rotating blade from Python: hbtrack.campbell gives the numbers `hbtrack modes --speeds`
writes (the same library code: 1e-12, as test_same_as_cli.py), names the modes it is given, the
speed's parameter cannot be changed on a loaded case, and the figure draws one line per mode."""
import os

import numpy as np
import pytest

import hbtrack
from hbtrack.campbell_figures import campbell_figure
from hbtrack.results import read_result

from conftest import ROOT, run_cli

ROTOR67_AT_SPEED = os.path.join(ROOT, "examples", "rotor67", "design_speed.toml")


def test_campbell_matches_the_cli_and_the_figure_draws_it(tmp_path):
    out = str(tmp_path / "campbell")
    run_cli("modes", ROTOR67_AT_SPEED, "--speeds", "0:1680:8", "--count", "4", "-o", out)
    cli = read_result(out)
    assert cli["kind"] == "campbell"
    case = hbtrack.load_case(ROTOR67_AT_SPEED)
    api = hbtrack.campbell(case, np.linspace(0, 1680, 8), count=4, names=cli["summary"]["mode_names"])
    assert list(api["campbell"]) == list(cli["campbell"]) == ["speed", "1B", "2B", "1T", "2T"]
    for name in cli["campbell"]:
        np.testing.assert_allclose(api["campbell"][name], cli["campbell"][name], rtol=1e-12, atol=0, err_msg=name)
    # Centrifugal stiffening: every mode stiffens, 1B the most.
    change = {n: api["campbell"][n][-1] / api["campbell"][n][0] - 1 for n in ["1B", "2B", "1T"]}
    assert all(c > 0 for c in change.values()) and change["1B"] == max(change.values())
    figure = campbell_figure(cli, engine_orders=4, path=str(tmp_path / "campbell.png"))
    assert len(figure.axes[0].get_legend().get_texts()) == 4
    assert os.path.getsize(tmp_path / "campbell.png") > 0


def test_the_speed_of_a_loaded_case_does_not_change():
    case = hbtrack.load_case(ROTOR67_AT_SPEED)
    with pytest.raises(ValueError, match="'speed' is the rotation speed"):
        case.set_parameter("speed", 100.0)
    at_rest = hbtrack.load_case(ROTOR67_AT_SPEED, set={"speed": 0.0})
    with pytest.raises(ValueError, match="no \\[rotation\\]"):
        hbtrack.campbell(hbtrack.load_case(os.path.join(ROOT, "examples", "duffing.toml")), [0.0, 1.0])
    assert hbtrack.modes(at_rest, count=1)["summary"]["natural_frequencies"][0] < hbtrack.modes(case, count=1)["summary"]["natural_frequencies"][0]
