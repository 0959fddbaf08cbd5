"""track, switch, simulate and isolas from a result run on that result's parameters and harmonic balance,
as their `--from DIR` does (the keywords still win): a start computed at a non-default amplitude
or number of harmonics is followed on the system it was computed on, not on the case's.

Tolerance 1e-12 relative against the CLI, as test_same_as_cli.py: the same library code on the
same doubles, states.csv's %.17g reading back to the same doubles."""
import os

import numpy as np
import pytest

import hbtrack
from hbtrack.results import read_result

from conftest import DUFFING, ROOT, run_cli

COUPLED = os.path.join(ROOT, "examples", "coupled_duffing.toml")
RELATIVE = 1e-12
LOUD = 2.0  # the Duffing case's amplitude is 1.0; at 2.0 the NFRC still has both folds
FEW_HARMONICS = 3  # the case's are 7
TRACK = dict(lp=1, param="amplitude", range=(0.1, 3.0))
POINT = 20  # a row of the Duffing NFRC below the resonance


def assert_same_columns(api, cli):
    assert list(api) == list(cli), "column names differ"
    for name in cli:
        assert len(api[name]) == len(cli[name]) > 0, name
        np.testing.assert_allclose(api[name], cli[name], rtol=RELATIVE, atol=0, err_msg=name)


def frc_pair(results_dir, name, flags, **settings):
    """The Duffing NFRC with settings: computed, and the CLI's folder of it read back."""
    folder = str(results_dir / name)
    run_cli("frc", DUFFING, "-o", folder, *flags)
    return hbtrack.frc(hbtrack.load_case(DUFFING), **settings), read_result(folder)


@pytest.fixture(scope="module")
def loud(results_dir):
    return frc_pair(results_dir, "duffing_loud", ["--set", f"amplitude={LOUD}"], parameters={"amplitude": LOUD})


@pytest.fixture(scope="module")
def few_harmonics(results_dir):
    return frc_pair(results_dir, "duffing_h3", ["--set", f"harmonic_balance.harmonics={FEW_HARMONICS}"],
                    harmonic_balance={"harmonics": FEW_HARMONICS})


@pytest.mark.parametrize("start", ["loud", "few_harmonics"])
def test_track_from_a_result_is_track_from_its_folder(start, request, results_dir, duffing_case):
    computed, folder = request.getfixturevalue(start)
    out = str(results_dir / f"track_{start}")
    low, high = TRACK["range"]
    run_cli("track", DUFFING, "--from", folder["folder"], "--lp", "1", "--param", "amplitude", "--range", f"{low}:{high}", "-o", out)
    cli = read_result(out)
    for source in (computed, folder):
        api = hbtrack.track(duffing_case, source, **TRACK)
        assert api["summary"]["options"]["parameters"] == cli["summary"]["options"]["parameters"]
        assert api["summary"]["options"]["harmonic_balance"] == cli["summary"]["options"]["harmonic_balance"]
        assert api["summary"]["start"] == pytest.approx(cli["summary"]["start"], rel=RELATIVE)
        assert_same_columns(api["branch"], cli["branch"])
    # The curve starts at the fold of the result's system: the result's amplitude, not the case's 1.0.
    expected = LOUD if start == "loud" else 1.0
    assert api["summary"]["start"]["amplitude"] == expected


def test_track_keywords_win_over_the_results_settings(few_harmonics, duffing_case):
    computed, _ = few_harmonics
    api = hbtrack.track(duffing_case, computed, **TRACK, harmonic_balance={"samples": 32}, continuation={"max_points": 5})
    hb = api["summary"]["options"]["harmonic_balance"]
    assert (hb["harmonics"], hb["samples"]) == (FEW_HARMONICS, 32)  # the result's harmonics, the keyword's samples
    # The case's own harmonics (7) do not fit the result's states: a keyword that undoes the
    # result's settings is the caller's choice, and refused as a result of another system.
    with pytest.raises(ValueError, match="a result of another case"):
        hbtrack.track(duffing_case, computed, **TRACK, harmonic_balance={"harmonics": 7})


@pytest.fixture(scope="module")
def coupled_loud(results_dir):
    folder = str(results_dir / "coupled_loud")
    run_cli("frc", COUPLED, "-o", folder, "--set", "amplitude=1.5", "--set", "harmonic_balance.harmonics=3")
    return read_result(folder)


def test_switch_from_a_result_is_switch_from_its_folder(results_dir, coupled_loud):
    case = hbtrack.load_case(COUPLED)
    computed = hbtrack.frc(case, parameters={"amplitude": 1.5}, harmonic_balance={"harmonics": 3})
    bp = 1 + [p["type"] for p in coupled_loud["special_points"]].index("BP")
    out = str(results_dir / "coupled_loud_switch")
    run_cli("switch", COUPLED, "--from", coupled_loud["folder"], "--point", str(bp), "-o", out)
    cli = read_result(out)
    assert cli["summary"]["options"]["parameters"]["amplitude"] == 1.5
    for source in (computed, coupled_loud):
        api = hbtrack.switch(case, source, point=bp)
        assert api["summary"]["options"]["parameters"] == cli["summary"]["options"]["parameters"]
        assert api["summary"]["options"]["harmonic_balance"] == cli["summary"]["options"]["harmonic_balance"]
        assert api["summary"]["stop_reason"] == cli["summary"]["stop_reason"]
        assert_same_columns(api["branch"], cli["branch"])
    # The keywords win: the same switch with the case's amplitude is another branch.
    quiet = hbtrack.switch(case, computed, point=bp, parameters={"amplitude": 1.0})
    assert quiet["summary"]["options"]["parameters"]["amplitude"] == 1.0
    assert quiet["branch"]["max_x1"].max() < api["branch"]["max_x1"].max()


@pytest.mark.parametrize("start", ["loud", "few_harmonics"])
def test_simulate_from_a_result_is_simulate_from_its_folder(start, request, results_dir, duffing_case):
    computed, folder = request.getfixturevalue(start)
    out = str(results_dir / f"simulate_{start}")
    run_cli("simulate", DUFFING, "--from", folder["folder"], "--point", str(POINT), "--max-periods", "200", "-o", out)
    cli = read_result(out)
    for source in (computed, folder):
        api = hbtrack.simulate(duffing_case, start=source, point=POINT, max_periods=200)
        assert_same_columns(api["signals"], cli["signals"])
        for key in ("omega", "max_x", "harmonics_x"):
            np.testing.assert_allclose(api["summary"][key], cli["summary"][key], rtol=RELATIVE, atol=0, err_msg=key)
            np.testing.assert_allclose(api["summary"]["start"][key], cli["summary"]["start"][key], rtol=RELATIVE, atol=0, err_msg=key)
    # Passing the result's settings explicitly gives the same run; the case's defaults another.
    explicit = {"parameters": {"amplitude": LOUD}} if start == "loud" else {"harmonic_balance": {"harmonics": FEW_HARMONICS}}
    same = hbtrack.simulate(duffing_case, start=computed, point=POINT, max_periods=200, **explicit)
    np.testing.assert_array_equal(same["signals"]["x"], api["signals"]["x"])
    if start == "loud":
        # What simulate ran before it took the start's settings: the case's amplitude 1.0.
        default = hbtrack.simulate(duffing_case, start=computed, point=POINT, max_periods=200, parameters={"amplitude": 1.0})
        assert abs(default["summary"]["max_x"] - api["summary"]["max_x"]) > 0.05 * api["summary"]["max_x"]
    else:
        # The orbit it starts from has the result's harmonics: the mean, then cos and sin of 1..3.
        assert len(api["summary"]["start"]["harmonics_x"]) == 2 * FEW_HARMONICS + 1


def test_isolas_run_on_the_first_curves_system_as_isolas_from(results_dir, few_harmonics, duffing_case):
    _, folder = few_harmonics
    track_dir, isolas_dir = str(results_dir / "track_h3_for_isolas"), str(results_dir / "isolas_h3")
    low, high = TRACK["range"]
    run_cli("track", DUFFING, "--from", folder["folder"], "--lp", "1", "--param", "amplitude", "--range", f"{low}:{high}", "-o", track_dir)
    run_cli("isolas", DUFFING, "--from", track_dir, "--at", "1.5", "-o", isolas_dir)
    cli = read_result(isolas_dir)
    api = hbtrack.isolas(duffing_case, read_result(track_dir), at=1.5)
    # The curve's 3 harmonics, not the case's 7 (whose states the curve's rows do not fit).
    assert api["summary"]["options"]["harmonic_balance"] == cli["summary"]["options"]["harmonic_balance"]
    assert api["summary"]["options"]["harmonic_balance"]["harmonics"] == FEW_HARMONICS
    assert [c["status"] for c in api["summary"]["crossings"]] == [c["status"] for c in cli["summary"]["crossings"]]
    assert len(cli["summary"]["crossings"]) > 0
    for a, c in zip(api["summary"]["crossings"], cli["summary"]["crossings"]):
        assert a["omega"] == pytest.approx(c["omega"], rel=RELATIVE)
