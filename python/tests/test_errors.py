"""Bad arguments raise ValueError (TypeError for unknown keywords) whose message names the
argument or the case field, as the CLI's one-line errors do."""
import numpy as np
import pytest

import hbtrack

from conftest import DUFFING


def test_unknown_parameter_override_names_it_and_suggests():
    with pytest.raises(ValueError, match=r"amplitdue: unknown parameter \(did you mean 'amplitude'\?\)"):
        hbtrack.load_case(DUFFING, set={"amplitdue": 2.0})


def test_bad_case_key_names_the_field():
    with pytest.raises(ValueError, match=r"harmonic_balance.*harmonics"):
        hbtrack.load_case(DUFFING, set={"harmonic_balance.harmonics": -1})


def test_missing_case_file():
    with pytest.raises(ValueError, match="nowhere.toml: file does not exist"):
        hbtrack.load_case("nowhere.toml")


def test_set_must_be_a_mapping_or_list():
    with pytest.raises(TypeError, match="set: expected a dict"):
        hbtrack.load_case(DUFFING, set="amplitude=2")


def test_unknown_option_keyword():
    with pytest.raises(TypeError, match=r"ContinuationOptions: unknown option 'stpe' \(known: step, "):
        hbtrack.ContinuationOptions(stpe=0.1)


def test_validate_names_the_field():
    options = hbtrack.ContinuationOptions(step=-1.0)
    with pytest.raises(ValueError, match="step"):
        options.validate()


def test_frc_rejects_bad_options_naming_the_field():
    case = hbtrack.load_case(DUFFING)
    # Refused where it is set: the option holds one of the method names, not any text.
    with pytest.raises(ValueError, match="stability.method: must be hill, monodromy, shooting or none, got 'hilll'"):
        case.stability.method = "hilll"
    with pytest.raises(ValueError, match="stability.method"):
        hbtrack.frc(case, stability={"method": "hilll"})


def test_track_arguments(duffing_case, duffing_frc):
    with pytest.raises(ValueError, match="lp: 3 is beyond the 2 limit points"):
        hbtrack.track(duffing_case, duffing_frc, lp=3, param="amplitude", range=(0.1, 2))
    with pytest.raises(ValueError, match=r"lp: must be an integer >= 1, got 0"):
        hbtrack.track(duffing_case, duffing_frc, lp=0, param="amplitude", range=(0.1, 2))
    with pytest.raises(ValueError, match=r"param: unknown parameter 'mu' \(the case has: amplitude\)"):
        hbtrack.track(duffing_case, duffing_frc, lp=1, param="mu", range=(0.1, 2))
    with pytest.raises(ValueError, match="range: must be"):
        hbtrack.track(duffing_case, duffing_frc, lp=1, param="amplitude", range=(2, 0.1))
    with pytest.raises(ValueError, match="range: must contain amplitude = 1"):
        hbtrack.track(duffing_case, duffing_frc, lp=1, param="amplitude", range=(1.5, 2))
    with pytest.raises(ValueError, match="method: must be bordered or extended, got 'minimal'"):
        hbtrack.track(duffing_case, duffing_frc, lp=1, param="amplitude", range=(0.1, 2), method="minimal")


def test_simulate_arguments(duffing_case, duffing_frc):
    with pytest.raises(ValueError, match="method: must be newmark or dopri5, got 'rk4'"):
        hbtrack.simulate(duffing_case, 1.0, method="rk4")
    with pytest.raises(ValueError, match="omega: required unless start gives the point"):
        hbtrack.simulate(duffing_case)
    with pytest.raises(ValueError, match="point: must be a row of start's states"):
        hbtrack.simulate(duffing_case, start=duffing_frc, point=10**6)
    with pytest.raises(ValueError, match=r"steps_per_period: must be >= 2\*harmonics\+1 = 15"):
        hbtrack.simulate(duffing_case, 1.0, steps_per_period=8)


def test_case_from_arrays_reports_the_field_not_a_temporary_file():
    with pytest.raises(ValueError, match=r"^case_from_arrays:\d+: elements\[0\]\.cubic_stiffness: missing"):
        hbtrack.case_from_arrays(np.eye(1), np.eye(1), ["x"], elements=[{"type": "cubic_spring", "dofs": ["x"]}],
                                 continuation={"omega_start": 0.5, "omega_end": 1.6})


def test_result_of_another_case_is_rejected(duffing_frc):
    two_dofs = hbtrack.load_case(DUFFING.replace("duffing", "two_dof_contact"))
    with pytest.raises(ValueError, match="a result of another case"):
        hbtrack.simulate(two_dofs, start=duffing_frc, point=0)
