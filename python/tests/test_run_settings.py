"""One name per option: case.continuation holds the case file's whole [continuation] section,
case.nfrc is its deprecated alias, and every computation takes the case's settings as keywords
(the case file's sections, or set= as --set) without changing the case it is given."""
import warnings

import numpy as np
import pytest

import hbtrack
from hbtrack.results import read_result

from conftest import DUFFING, run_cli, set_flags

# The same computation on the same settings, in one process: the numbers agree to the bit.
SETTINGS = {"continuation": {"omega_start": 0.6, "omega_end": 1.9, "max_points": 400, "step": 0.03},
            "harmonic_balance": {"harmonics": 5}, "parameters": {"amplitude": 0.8}}


def edited_duffing():
    """The Duffing case with SETTINGS written into it attribute by attribute."""
    case = hbtrack.load_case(DUFFING)
    case.harmonic_balance.harmonics = 5
    case.continuation.omega_start, case.continuation.omega_end = 0.6, 1.9
    case.continuation.max_points, case.continuation.step = 400, 0.03
    case.set_parameter("amplitude", 0.8)
    return case


def assert_same(a, b):
    assert list(a["branch"]) == list(b["branch"])
    for name in a["branch"]:
        np.testing.assert_array_equal(a["branch"][name], b["branch"][name], err_msg=name)
    np.testing.assert_array_equal(a["states"], b["states"])
    assert a["summary"]["options"] == b["summary"]["options"]


def test_continuation_is_the_whole_case_file_section():
    case = hbtrack.load_case(DUFFING)
    section = case.continuation
    assert isinstance(section, hbtrack.ContinuationSection)
    assert {"omega_start", "omega_end", "length_scale", "step", "max_points"} <= set(section.fields)
    section.omega_start = 0.7  # a view: the case changes
    assert case.continuation.omega_start == 0.7
    assert hbtrack.frc(case, continuation={"max_points": 3})["summary"]["options"]["continuation"]["omega_start"] == 0.7
    assert "omega_start=0.7" in repr(section)
    case.continuation = hbtrack.ContinuationOptions(step=0.01)  # the arc-length settings only
    assert (case.continuation.step, case.continuation.omega_start) == (0.01, 0.7)
    case.continuation.omega_end = 0.7
    with pytest.raises(ValueError, match="omega_end"):
        case.continuation.validate()


def test_nfrc_is_a_deprecated_alias():
    case = hbtrack.load_case(DUFFING)
    with pytest.warns(DeprecationWarning, match="case.continuation"):
        options = case.nfrc
    assert options.omega_start == case.continuation.omega_start
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        case.continuation.step = 0.03  # the new names warn of nothing
        case.stability.method = "hill"


def test_keywords_give_what_editing_the_case_gives_and_leave_the_case_alone(duffing_case):
    before = repr(duffing_case.continuation), duffing_case.harmonic_balance.harmonics, duffing_case.parameters
    by_keywords = hbtrack.frc(duffing_case, **SETTINGS)
    assert (repr(duffing_case.continuation), duffing_case.harmonic_balance.harmonics, duffing_case.parameters) == before
    assert_same(by_keywords, hbtrack.frc(edited_duffing()))
    by_set = hbtrack.frc(duffing_case, set={"continuation.omega_start": 0.6, "continuation.omega_end": 1.9,
                                            "continuation.max_points": 400, "continuation.step": 0.03,
                                            "harmonic_balance.harmonics": 5, "amplitude": 0.8})
    assert_same(by_keywords, by_set)


def test_keywords_give_what_the_cli_gives_with_set(results_dir, duffing_case):
    overrides = {"continuation.omega_end": 1.9, "continuation.step": 0.03, "harmonic_balance.harmonics": 5}
    folder = str(results_dir / "duffing_run_settings")
    run_cli("frc", DUFFING, "-o", folder, *set_flags(overrides))
    cli = read_result(folder)
    api = hbtrack.frc(duffing_case, continuation={"omega_end": 1.9, "step": 0.03}, harmonic_balance={"harmonics": 5})
    assert api["summary"]["options"] == cli["summary"]["options"]
    # 1e-12: the CLI's %.17g text reads back to the same doubles; the margin is for a last-bit
    # difference between the two builds (test_same_as_cli.py).
    for name in cli["branch"]:
        np.testing.assert_allclose(api["branch"][name], cli["branch"][name], rtol=1e-12, atol=0, err_msg=name)


def test_every_computation_takes_the_keywords(duffing_case, duffing_frc, duffing_track):
    # continuation: the step bound changes the branch; the keyword and an edited case agree.
    edited = hbtrack.load_case(DUFFING)
    edited.continuation.step_max = 0.02
    args = dict(param="amplitude", omega=1.2, range=(0.05, 1.0))
    assert_same(hbtrack.continuation(duffing_case, **args, continuation={"step_max": 0.02}),
                hbtrack.continuation(edited, **args))
    assert_same(hbtrack.backbone(duffing_case, range=(0.01, 1.0), continuation={"step_max": 0.02}),
                hbtrack.backbone(edited, range=(0.01, 1.0)))
    track = dict(lp=1, param="amplitude", range=(0.1, 2.0))
    assert_same(hbtrack.track(duffing_case, duffing_frc, **track, continuation={"step_max": 0.02}),
                hbtrack.track(edited, duffing_frc, **track))
    found = hbtrack.isolas(duffing_case, duffing_track, at=1.5, stability={"method": "none"})
    assert found["summary"]["options"]["stability"]["method"] == "none"
    louder = hbtrack.simulate(duffing_case, 1.2, parameters={"amplitude": 2.0}, max_periods=50)
    assert louder["summary"]["options"]["parameters"]["amplitude"] == 2.0


@pytest.mark.parametrize("settings, message", [
    ({"continuation": {"omega_strat": 0.5}}, r"^frc: continuation\.omega_strat: unknown key \(did you mean 'omega_start'\?\)"),
    ({"set": {"harmonic_balance.harmonic": 3}}, r"^frc: harmonic_balance\.harmonic: unknown key \(did you mean 'harmonics'\?\)"),
    ({"parameters": {"amplitdue": 2}}, r"^frc: amplitdue: unknown parameter \(did you mean 'amplitude'\?\)"),
    ({"continuation": {"step": -1.0}}, r"continuation\.step"),
    ({"set": {"elements[0].cubic_stiffness": 2}}, r"'elements' is the case's \(change it with load_case"),
])
def test_unknown_or_bad_keys_are_refused_as_the_case_file_refuses_them(duffing_case, settings, message):
    with pytest.raises(ValueError, match=message):
        hbtrack.frc(duffing_case, **settings)


def test_a_keyword_that_is_no_section_is_a_type_error(duffing_case):
    with pytest.raises(TypeError, match="'hbm'.*harmonic_balance"):
        hbtrack.frc(duffing_case, hbm={"harmonics": 7})
    with pytest.raises(TypeError, match="continuation: expected a dict"):
        hbtrack.frc(duffing_case, continuation=0.5)


def test_with_settings_returns_a_copy(duffing_case):
    copy = hbtrack.with_settings(duffing_case, continuation={"omega_start": 0.7})
    assert copy.continuation.omega_start == 0.7 != duffing_case.continuation.omega_start
    plain = hbtrack.with_settings(duffing_case)
    plain.continuation.step = 0.5
    assert duffing_case.continuation.step != 0.5
