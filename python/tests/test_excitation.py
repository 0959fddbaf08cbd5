"""The excitations beside [[forcing]] from Python: a forcing growing as omega^k and an imposed
base motion, read from a case file or given to case_from_arrays, exposed on the Case and solved
as the closed-form linear response says."""
import os

import numpy as np
import pytest

import hbtrack

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
UNBALANCE = os.path.join(ROOT, "examples", "unbalanced_disc_jenkins.toml")
SHAKER = os.path.join(ROOT, "examples", "shaker_base_motion.toml")

ONE_DOF = dict(M=[[2.0]], K=[[3.0]], C=[[0.1]], dofs=["z"], parameters={"amplitude": 1.5},
               harmonic_balance={"harmonics": 3}, continuation={"omega_start": 0.5, "omega_end": 2.0})


def first_harmonic(case, omega):
    """a1 - i b1 of dof z from hbtrack.solve."""
    states = hbtrack.solve(case, omega)["dof_states"]
    return states["z_c1"][0] - 1j * states["z_s1"][0]


def test_the_examples_expose_their_excitation():
    growth = hbtrack.load_case(UNBALANCE).forcing_growth
    assert growth == {"exponent": 2.0, "reference_frequency": 1.0}
    shaker = hbtrack.load_case(SHAKER)
    assert shaker.forcing_growth is None
    assert shaker.base_motion["kind"] == "displacement"
    assert shaker.base_motion["harmonic"] == 1


def test_growing_forcing_solves_to_the_closed_form_response():
    # 2 z'' + 0.1 z' + 3 z = 1.5 (w / 1.2)^2 0.4 cos(w t): exact at H = 3 (linear).
    case = hbtrack.case_from_arrays(**ONE_DOF, forcing=[{"dof": "z", "cos": 0.4}],
                                    forcing_growth={"exponent": 2, "reference_frequency": 1.2})
    assert case.forcing_growth == {"exponent": 2.0, "reference_frequency": 1.2}
    for omega in (0.7, 1.3):
        expected = 1.5 * (omega / 1.2) ** 2 * 0.4 / (3.0 - 2.0 * omega**2 + 0.1j * omega)
        assert abs(first_harmonic(case, omega) - expected) < 1e-10 * abs(expected)


def test_base_displacement_solves_to_the_closed_form_relative_response():
    # z = x - u_b: 2 z'' + 0.1 z' + 3 z = 2 w^2 U cos(w t), U = 1.5 * 0.3.
    case = hbtrack.case_from_arrays(**ONE_DOF, base_motion={"kind": "displacement", "dofs": ["z"], "cos": 0.3})
    assert case.base_motion == {"kind": "displacement", "dofs": ["z"], "harmonic": 1, "cos": 0.3, "sin": 0.0}
    for omega in (0.7, 1.3):
        expected = 2.0 * omega**2 * 1.5 * 0.3 / (3.0 - 2.0 * omega**2 + 0.1j * omega)
        assert abs(first_harmonic(case, omega) - expected) < 1e-10 * abs(expected)


@pytest.mark.parametrize("keywords, message", [
    (dict(forcing=[{"dof": "z", "cos": 0.4}], forcing_growth={"exponent": -1, "reference_frequency": 1.0}),
     "forcing_growth.exponent: must be >= 0"),
    (dict(forcing=[{"dof": "z", "cos": 0.4}], forcing_growth={"exponent": 2}), "forcing_growth.reference_frequency: missing"),
    (dict(base_motion={"kind": "displacement", "dofs": ["y"], "cos": 0.3}), "base_motion.dofs[0]: unknown dof 'y'"),
])
def test_bad_excitation_names_the_field(keywords, message):
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("]", r"\]")):
        hbtrack.case_from_arrays(**ONE_DOF, **keywords)
