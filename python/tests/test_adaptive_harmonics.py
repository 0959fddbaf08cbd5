"""Harmonics chosen as the run goes (harmonic_balance.adaptive) through hbtrack.frc: the H of
each point reaches the result as the CLI writes it, and the limit points are the CLI's."""
import numpy as np
import pytest

import hbtrack
from hbtrack.results import read_result

from conftest import DUFFING, assert_same_columns, run_cli

ADAPTIVE = {"min": 3, "max": 9, "add_above": 1e-4, "drop_below": 1e-7}


def test_the_harmonics_column_reaches_the_python_result_as_the_cli_writes_it(tmp_path):
    case = hbtrack.load_case(DUFFING)
    api = hbtrack.frc(case, harmonic_balance={"harmonics": 3, "adaptive": ADAPTIVE})
    h = api["branch"]["harmonics"]
    assert h.min() == 3 and h.max() > 3  # rises towards the peak from the start's minimum
    summary = api["summary"]
    assert summary["adaptive_harmonics"]["harmonics"]["max"] == h.max()
    assert summary["options"]["harmonic_balance"]["adaptive"] == ADAPTIVE
    assert [p["harmonics"] for p in summary["special_points"]] == [h[p["index"]] for p in summary["special_points"]]
    # Every row has the columns of max = 9, zeros above its own H.
    for k in range(2, 10):
        above = h < k
        assert np.all(api["branch"][f"h{k}_x"][above] == 0)
    out = tmp_path / "adaptive"
    run_cli("frc", DUFFING, "-o", str(out), "--set", "harmonic_balance.harmonics=3",
            "--set", "harmonic_balance.adaptive={min = 3, max = 9, add_above = 1e-4, drop_below = 1e-7}")
    cli = read_result(str(out))
    assert_same_columns(api["branch"], cli["branch"])
    assert [p["omega"] for p in api["summary"]["special_points"]] == pytest.approx(
        [p["omega"] for p in cli["summary"]["special_points"]], rel=1e-12)


def test_options_class_and_other_analyses_refuse_it():
    options = hbtrack.HarmonicBalanceOptions()
    assert options.adaptive.max == 0  # off
    options.adaptive = hbtrack.AdaptiveHarmonics(min=3, max=9)
    assert options.adaptive.add_above == 1e-4
    case = hbtrack.load_case(DUFFING)
    with pytest.raises(ValueError, match="harmonic_balance.adaptive: only frc changes H along a branch"):
        hbtrack.solve(case, 1.0, harmonic_balance={"adaptive": ADAPTIVE})
