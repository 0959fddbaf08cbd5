"""A list of harmonics wherever H is accepted (harmonic_balance.harmonics = [1, 3, 5, 7]): the
odd Duffing gives the full basis' folds with fewer unknowns, the columns are named by the
harmonics balanced, and a bad list is refused naming the rule."""
import pytest

import hbtrack

from conftest import DUFFING


def test_the_odd_harmonics_give_the_full_folds_with_fewer_unknowns(duffing_frc):
    odd = hbtrack.frc(hbtrack.load_case(DUFFING, set={"harmonic_balance.harmonics": [1, 3, 5, 7]}))
    assert odd["summary"]["options"]["harmonic_balance"]["harmonics"] == [1, 3, 5, 7]
    assert odd["summary"]["options"]["harmonic_balance"]["unknowns"] == 8
    assert duffing_frc["summary"]["options"]["harmonic_balance"]["unknowns"] == 15
    folds = [[p["omega"] for p in r["special_points"] if p["type"] == "LP"] for r in (odd, duffing_frc)]
    assert len(folds[0]) == 2
    assert folds[0] == pytest.approx(folds[1], abs=1e-8)  # tests/test_harmonic_selection.cpp: 1e-8
    assert {"h3_x", "h7_x", "phase3_x"} <= set(odd["branch"]) and not {"h0_x", "h2_x", "phase2_x"} & set(odd["branch"])


def test_the_case_option_takes_a_list_or_h():
    case = hbtrack.load_case(DUFFING)
    case.harmonic_balance.harmonics = [1, 3, 5]
    assert case.harmonic_balance.harmonics == [1, 3, 5]
    assert hbtrack.backbone(case, mode=1, range=(0.01, 1))["summary"]["options"]["harmonic_balance"]["unknowns"] == 6
    cont = hbtrack.continuation(case, param="amplitude", omega=1.2, range=(0.05, 1))
    assert "h5_x" in cont["branch"] and "h2_x" not in cont["branch"]
    case.harmonic_balance.harmonics = 7  # H again: 0..7
    assert case.harmonic_balance.harmonics == 7
    with pytest.raises(ValueError, match="must be sorted and unique"):
        case.harmonic_balance.harmonics = [3, 1]
    with pytest.raises(ValueError, match="harmonic_balance.harmonics"):
        hbtrack.load_case(DUFFING, set={"harmonic_balance.harmonics": [0, 2]})
