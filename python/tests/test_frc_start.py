"""frc(case, start=...): the NFRC from a point of an earlier result, as `hbtrack frc --from DIR
--point K` computes it (the result's parameters and harmonic balance, from the point's omega
towards omega_end)."""
import numpy as np
import pytest

import hbtrack
from hbtrack.results import read_result

from conftest import DUFFING, run_cli

# On the way up to the resonance: from there the branch goes over both folds to omega_end.
POINT = 10  # omega 0.955, where point 20 was when the steps were capped at 0.1


def test_start_reproduces_frc_from(results_dir, duffing_case, duffing_frc_cli):
    folder = str(results_dir / "duffing_from")
    run_cli("frc", DUFFING, "--from", duffing_frc_cli["folder"], "--point", str(POINT), "--set", "continuation.step=0.03", "-o", folder)
    cli = read_result(folder)
    api = hbtrack.frc(duffing_case, start=duffing_frc_cli, point=POINT, continuation={"step": 0.03})
    assert api["summary"]["options"] == cli["summary"]["options"]
    assert api["summary"]["started_from"] == cli["summary"]["started_from"]
    assert api["summary"]["stop_reason"] == cli["summary"]["stop_reason"]
    # 1e-12 relative: the same library code on the same doubles (test_same_as_cli.py).
    for name in cli["branch"]:
        np.testing.assert_allclose(api["branch"][name], cli["branch"][name], rtol=1e-12, atol=0, err_msg=name)
    assert api["states"][0][0] == duffing_frc_cli["states"][POINT][0]


def test_start_takes_the_results_settings_and_the_keywords_win(duffing_frc):
    # As --from: the source's parameters beat the case's, --set (the keywords) beats both.
    louder = hbtrack.load_case(DUFFING, set={"amplitude": 2.0})
    few = {"max_points": 3}
    assert hbtrack.frc(louder, start=duffing_frc, point=POINT, continuation=few)["summary"]["options"]["parameters"]["amplitude"] == 1.0
    again = hbtrack.frc(louder, start=duffing_frc, point=POINT, continuation=few, parameters={"amplitude": 2.0})
    assert again["summary"]["options"]["parameters"]["amplitude"] == 2.0
    assert louder.parameters["amplitude"] == 2.0 and louder.continuation.omega_start == 0.5  # the case is not changed


def test_a_state_row_starts_as_its_result_does(duffing_case, duffing_frc):
    from_result = hbtrack.frc(duffing_case, start=duffing_frc, point=POINT)
    from_row = hbtrack.frc(duffing_case, start=duffing_frc["states"][POINT])
    for name in from_result["branch"]:
        np.testing.assert_array_equal(from_row["branch"][name], from_result["branch"][name], err_msg=name)
    assert from_row["summary"]["started_from"] == {"point": None, "omega": duffing_frc["states"][POINT][0]}
    # The default point is the last, which lies at omega_end: there is no range left.
    with pytest.raises(ValueError, match=r"start: point \d+ is at omega_end = .*continuation=\{'omega_end': VALUE\}"):
        hbtrack.frc(duffing_case, start=duffing_frc)
    back = hbtrack.frc(duffing_case, start=duffing_frc, continuation={"omega_end": 1.0}, progress=lambda f, p, w: p < 5)
    assert back["branch"]["omega"][-1] < back["branch"]["omega"][0]  # towards the new end


def test_bad_starts_are_refused(duffing_case, duffing_frc, duffing_track):
    with pytest.raises(ValueError, match="point: needs start"):
        hbtrack.frc(duffing_case, point=3)
    with pytest.raises(ValueError, match="point: must be a row of start's states"):
        hbtrack.frc(duffing_case, start=duffing_frc, point=10**6)
    with pytest.raises(ValueError, match="start: expected a result whose states are"):
        hbtrack.frc(duffing_case, start=duffing_track)
    with pytest.raises(ValueError, match="start: holds 3 unknowns"):
        hbtrack.frc(duffing_case, start=[1.0, 0.1, 0.2, 0.3])
    with pytest.raises(ValueError, match="point: only with a result"):
        hbtrack.frc(duffing_case, start=duffing_frc["states"][3], point=3)
