"""The Python API computes what the CLI writes: same columns, same numbers.

Tolerance 1e-12 relative: both run the same library code on the same input, and the CLI's
%.17g text reads back to the same doubles, so the numbers should agree to the last bit; the
margin only allows for a last-bit difference from a different instruction order between the
two builds (the extension is compiled as position-independent code)."""
import numpy as np
import pytest

import hbtrack
from hbtrack.plot import figures_for
from hbtrack.results import read_result

from conftest import BLADE, BLADE_CHEAP, BLADE_CLEARANCE, DUFFING, assert_same_columns, run_cli, set_flags

RELATIVE = 1e-12


def assert_same_special_points(api, cli):
    assert [sp["type"] for sp in api] == [sp["type"] for sp in cli]
    for a, c in zip(api, cli):
        assert a["index"] == c["index"]
        for key, value in c.items():
            if isinstance(value, float):
                assert a[key] == pytest.approx(value, rel=RELATIVE, abs=0), key


def test_duffing_frc_matches_cli(duffing_frc, duffing_frc_cli):
    assert_same_columns(duffing_frc["branch"], duffing_frc_cli["branch"])
    np.testing.assert_allclose(duffing_frc["states"], duffing_frc_cli["states"], rtol=RELATIVE, atol=1e-300)
    assert_same_columns(duffing_frc["dof_states"], duffing_frc_cli["dof_states"])
    assert_same_columns(duffing_frc["dof_special_states"], duffing_frc_cli["dof_special_states"])
    assert_same_special_points(duffing_frc["special_points"], duffing_frc_cli["special_points"])
    assert [sp["type"] for sp in duffing_frc["special_points"]].count("LP") == 2  # README: both folds
    for key in ("stop_reason", "points", "newton_iterations", "failed_steps", "options", "outputs"):
        assert duffing_frc["summary"][key] == duffing_frc_cli["summary"][key], key


def test_duffing_with_overrides_matches_cli(results_dir):
    overrides = {"amplitude": 2.0, "harmonic_balance.harmonics": 3}
    api = hbtrack.frc(hbtrack.load_case(DUFFING, set=overrides))
    folder = str(results_dir / "duffing_overrides")
    run_cli("frc", DUFFING, "-o", folder, *set_flags(overrides))
    cli = read_result(folder)
    assert cli["summary"]["options"]["parameters"]["amplitude"] == 2.0
    assert cli["summary"]["options"]["harmonic_balance"]["harmonics"] == 3
    assert_same_columns(api["branch"], cli["branch"])


def test_duffing_tracking_matches_cli(duffing_track, duffing_track_cli):
    assert_same_columns(duffing_track["branch"], duffing_track_cli["branch"])
    assert_same_special_points(duffing_track["special_points"], duffing_track_cli["special_points"])
    assert duffing_track["summary"]["stop_reason"] == duffing_track_cli["summary"]["stop_reason"]
    assert duffing_track["summary"]["options"]["tracking"]["lp"] == 1


def test_duffing_isolas_match_cli(duffing_case, duffing_track, duffing_isolas_cli):
    api = hbtrack.isolas(duffing_case, duffing_track, at=1.5)
    api_crossings, cli_crossings = api["summary"]["crossings"], duffing_isolas_cli["summary"]["crossings"]
    # README: at A = 1.5 both crossings of the Duffing curve are limit points of the main branch.
    assert [c["status"] for c in cli_crossings] == [c["status"] for c in api_crossings]
    assert {c["status"] for c in cli_crossings} <= {"open", "duplicate"}
    for a, c in zip(api_crossings, cli_crossings):
        assert a["omega"] == pytest.approx(c["omega"], rel=RELATIVE, abs=0)
    for name, branch in duffing_isolas_cli["branches"].items():
        assert_same_columns(api["branches"][name]["branch"], branch["branch"])


def test_duffing_simulation_matches_cli(duffing_frc, duffing_simulate_cli):
    api = hbtrack.simulate(hbtrack.load_case(DUFFING), start=duffing_frc, point=20, max_periods=200)
    assert_same_columns(api["signals"], duffing_simulate_cli["signals"])
    a, c = api["summary"], duffing_simulate_cli["summary"]
    assert (a["converged"], a["periods"], a["stop_reason"]) == (c["converged"], c["periods"], c["stop_reason"])
    for key in ("omega", "max_x", "min_x", "harmonics_x"):
        np.testing.assert_allclose(a[key], c[key], rtol=RELATIVE, atol=0, err_msg=key)
    cli_settings = {k: v for k, v in c["options"]["simulation"].items() if k not in ("from", "point")}  # the CLI's flags
    assert a["options"]["simulation"] == cli_settings
    for key in ("omega", "max_x", "harmonics_x"):  # the HBM orbit it started from
        np.testing.assert_allclose(a["start"][key], c["start"][key], rtol=RELATIVE, atol=0, err_msg=key)


def test_duffing_fold_search_matches_cli(duffing_frc, duffing_frc_cli, results_dir):
    """simulate(near_lp=K) runs the CLI's `--near-lp K` search: the same starts, the same verdicts."""
    api = hbtrack.simulate(hbtrack.load_case(DUFFING), start=duffing_frc, near_lp=1, distances=(0.1, 1, 3), max_periods=300)
    folder = str(results_dir / "duffing_fold")
    run_cli("simulate", DUFFING, "--from", duffing_frc_cli["folder"], "--near-lp", "1", "--distances", "0.1,1,3", "--max-periods",
            "300", "-o", folder)
    cli = read_result(folder)
    a, c = api["summary"]["fold_search"], cli["summary"]["fold_search"]
    assert a["held"]["point"] == c["held"]["point"]
    assert [(r["point"], r["held"], r["periods"]) for r in a["runs"]] == [(r["point"], r["held"], r["periods"]) for r in c["runs"]]
    for x, y in zip(a["runs"], c["runs"]):
        assert x["departure"] == pytest.approx(y["departure"], rel=1e-9, abs=1e-15)
    held = c["held"]["folder"]
    cli_run = read_result(f"{folder}/{held}")
    np.testing.assert_allclose(api["branches"][held]["signals"]["x"], cli_run["signals"]["x"], rtol=RELATIVE, atol=1e-300)
    # The figures of `hbtrack plot` on the search's folder are the held run's.
    assert set(figures_for(cli)) == set(figures_for(cli_run))


def test_fold_search_refuses_what_it_cannot_do(duffing_frc):
    case = hbtrack.load_case(DUFFING)
    with pytest.raises(ValueError, match="near_lp: needs start"):
        hbtrack.simulate(case, near_lp=1)
    with pytest.raises(ValueError, match="near_lp: needs start .*neither point"):
        hbtrack.simulate(case, start=duffing_frc, point=3, near_lp=1)
    with pytest.raises(ValueError, match="distances: must be increasing percentages > 0"):
        hbtrack.simulate(case, start=duffing_frc, near_lp=1, distances=(1, 0.5))
    with pytest.raises(Exception, match="near_lp: 3 is beyond the 2 limit points of start"):
        hbtrack.simulate(case, start=duffing_frc, near_lp=3)


def test_blade_frc_matches_cli(results_dir):
    api = hbtrack.frc(hbtrack.load_case(BLADE, set=BLADE_CHEAP))
    folder = str(results_dir / "blade")
    run_cli("frc", BLADE, "-o", folder, *set_flags(BLADE_CHEAP))
    cli = read_result(folder)
    assert "stable" in cli["branch"] and len(cli["branch"]["omega"]) > 5
    assert cli["summary"]["stop_reason"] == "reached_end"
    # Down the resonance into contact: the branch starts clear of the casing and ends rubbing.
    in_contact = cli["branch"]["max_le"] > BLADE_CLEARANCE
    assert not in_contact[0] and in_contact[-1]
    assert_same_columns(api["branch"], cli["branch"])
    assert_same_special_points(api["special_points"], cli["special_points"])
    # The friction loop gain of the 9 tip nodes, and its warnings (n2 and n3 above 1), as the CLI's.
    assert len(api["summary"]["friction_loop_gain"]) == 9
    assert api["summary"]["friction_loop_gain"] == cli["summary"]["friction_loop_gain"]
    assert [g["node"] for g in api["summary"]["friction_loop_gain"] if g["self_energising"]] == ["n2", "n3"]
    assert api["summary"]["warnings"] == cli["summary"]["warnings"]


def test_api_starts_from_a_cli_result_folder(duffing_case, duffing_frc_cli, duffing_track_cli):
    # read_result gives the API's dict: tracking from the CLI's frc folder is the CLI's tracking.
    api = hbtrack.track(duffing_case, duffing_frc_cli, lp=1, param="amplitude", range=(0.1, 2.0))
    assert_same_columns(api["branch"], duffing_track_cli["branch"])


def test_duffing_continuation_matches_cli(results_dir):
    api = hbtrack.continuation(hbtrack.load_case(DUFFING), param="amplitude", omega=1.2, range=(0.05, 3.0))
    folder = str(results_dir / "duffing_continue")
    run_cli("continue", DUFFING, "--param", "amplitude", "--omega", "1.2", "--range", "0.05:3", "-o", folder)
    cli = read_result(folder)
    assert api["kind"] == cli["kind"] == "continue"
    assert_same_columns(api["branch"], cli["branch"])
    np.testing.assert_allclose(api["special_states"], cli["special_states"], rtol=RELATIVE, atol=1e-300)
    assert [sp["type"] for sp in api["special_points"]] == [sp["type"] for sp in cli["special_points"]] == ["LP", "LP"]


def test_duffing_backbone_matches_cli(results_dir):
    api = hbtrack.backbone(hbtrack.load_case(DUFFING), mode=1, range=(0.01, 5.0))
    folder = str(results_dir / "duffing_backbone")
    run_cli("backbone", DUFFING, "--mode", "1", "--range", "0.01:5", "-o", folder)
    cli = read_result(folder)
    assert api["kind"] == cli["kind"] == "backbone"
    assert_same_columns(api["branch"], cli["branch"])
    np.testing.assert_allclose(api["states"], cli["states"], rtol=RELATIVE, atol=1e-300)
    assert api["summary"]["linear_mode"] == pytest.approx(cli["summary"]["linear_mode"], rel=RELATIVE)


def test_element_forces_match_cli(results_dir):
    case_set = {"continuation.omega_end": 1.0}
    api = hbtrack.frc(hbtrack.load_case(DUFFING, set=case_set), element_forces=True)
    folder = str(results_dir / "duffing_element_forces")
    run_cli("frc", DUFFING, "--element-forces", "-o", folder, *set_flags(case_set))
    cli = read_result(folder)
    assert list(cli["element_forces"])[:3] == ["omega", "element0_x_h0", "element0_x_c1"]
    assert_same_columns(api["element_forces"], cli["element_forces"])
    assert "element_forces" not in hbtrack.frc(hbtrack.load_case(DUFFING, set=case_set))
