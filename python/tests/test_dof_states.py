"""continuation, backbone and switch return every dof's harmonics (dof_states, and
dof_special_states where they have special states) as frc does: the keys, columns and numbers
of read_result of the CLI's folder of the same run, and the same solutions as their `states`.

Tolerances: API against CLI 1e-12 relative, as test_same_as_cli.py (the same library code on the
same doubles, and states.csv's %.17g reads back to the same doubles). dof_states against states
1e-15 relative: the retained dofs are copied from the unknowns and the mean is stored as a0 / 2,
both exact in binary, so reading them back into unknowns gives the same doubles."""
import os

import numpy as np
import pytest

import hbtrack
from hbtrack.results import read_result, state_unknowns

from conftest import DUFFING, ROOT, run_cli

TWO_DOF = os.path.join(ROOT, "examples", "two_dof_contact.toml")
COUPLED = os.path.join(ROOT, "examples", "coupled_duffing.toml")
RELATIVE = 1e-12
CONTINUE_OMEGA = 0.7  # on the contact resonance's flank: one fold in the amplitude


def assert_same_columns(api, cli):
    assert list(api) == list(cli), "column names differ"
    for name in cli:
        assert len(api[name]) == len(cli[name]), name
        np.testing.assert_allclose(api[name], cli[name], rtol=RELATIVE, atol=1e-300, err_msg=name)


def assert_same_dof_states(api, cli, special):
    assert "dof_states" in cli, "the CLI folder has no dof columns"
    assert_same_columns(api["dof_states"], cli["dof_states"])
    assert ("dof_special_states" in api) == ("dof_special_states" in cli) == special
    if special:
        assert_same_columns(api["dof_special_states"], cli["dof_special_states"])


def assert_states_are_the_retained_dofs(result, key="states"):
    """The unknowns read back from dof_states (the retained dofs' columns) are `states`."""
    table = result["dof_" + key]
    rows = np.column_stack(list(table.values())) if len(table["omega"]) else np.zeros((0, len(table)))
    np.testing.assert_allclose(state_unknowns(list(table), rows, result["summary"]), result[key], rtol=1e-15, atol=1e-300)


@pytest.fixture(scope="module")
def two_dof_continuation(results_dir):
    """The two-mass contact case continued in the amplitude at omega = 0.7 (over one fold):
    computed, and the CLI's folder read back. The contact is on x2 only, so x1 is condensed
    (schur) and its columns are recovered, which depends on the amplitude along the branch."""
    api = hbtrack.continuation(hbtrack.load_case(TWO_DOF), param="amplitude", omega=CONTINUE_OMEGA, range=(0.2, 3.0))
    folder = str(results_dir / "two_dof_continue")
    # Past the fold the branch heads back out of the range's low end: the CLI keeps its points
    # and exits 1 (stop_reason left_range), the API returns them.
    run_cli("continue", TWO_DOF, "--param", "amplitude", "--omega", str(CONTINUE_OMEGA), "--range", "0.2:3", "-o", folder, check=False)
    cli = read_result(folder)
    assert api["summary"]["stop_reason"] == cli["summary"]["stop_reason"] == "left_range"
    return api, cli


def test_continuation_dof_states_match_cli_with_condensed_dofs(two_dof_continuation):
    api, cli = two_dof_continuation
    assert api["summary"]["options"]["harmonic_balance"]["retained_dofs"] == ["x2"]
    assert [sp["type"] for sp in api["special_points"]] == ["LP"]
    assert list(api["dof_states"])[:3] == ["omega", "x1_h0", "x1_c1"]
    assert_same_dof_states(api, cli, special=True)
    assert len(api["dof_special_states"]["omega"]) == 1
    assert_states_are_the_retained_dofs(api)
    assert_states_are_the_retained_dofs(api, "special_states")


def x1_first_harmonic_residual(table, row, amplitude):
    """x1's equation of motion in examples/two_dof_contact.toml, its cos(omega t) and sin(omega t)
    balance, relative to the forcing: M = I, K = [[2, -1], [-1, 1]], C = 0.02 K (rayleigh),
    0.1 * amplitude * cos(omega t) on x1, no element on x1."""
    w = table["omega"][row]
    c1, s1, c2, s2 = (table[name][row] for name in ("x1_c1", "x1_s1", "x2_c1", "x2_s1"))
    force = 0.1 * amplitude
    cos_balance = (2 - w * w) * c1 + 0.04 * w * s1 - c2 - 0.02 * w * s2 - force
    sin_balance = (2 - w * w) * s1 - 0.04 * w * c1 - s2 + 0.02 * w * c2
    return np.hypot(cos_balance, sin_balance) / force


@pytest.mark.parametrize("source", ["api", "cli"])
def test_condensed_dofs_are_recovered_at_each_points_parameter(source, two_dof_continuation):
    # 1e-9: a linear solve per harmonic of a well-conditioned 1x1 block, far above rounding; the
    # case's amplitude instead of the point's (what continue's special_states.csv used) leaves
    # the forcing's difference, 0.15 of it at the fold (amplitude 1.15).
    result = two_dof_continuation[0 if source == "api" else 1]
    for row, amplitude in enumerate(result["branch"]["amplitude"]):
        assert x1_first_harmonic_residual(result["dof_states"], row, amplitude) < 1e-9, row
    fold = result["special_points"][0]["amplitude"]
    assert x1_first_harmonic_residual(result["dof_special_states"], 0, fold) < 1e-9
    assert x1_first_harmonic_residual(result["dof_special_states"], 0, 1.0) > 0.1  # the check can fail


def test_backbone_dof_states_match_cli(results_dir):
    api = hbtrack.backbone(hbtrack.load_case(COUPLED), mode=1, range=(0.01, 2.0))
    folder = str(results_dir / "coupled_backbone")
    run_cli("backbone", COUPLED, "--mode", "1", "--range", "0.01:2", "-o", folder)
    cli = read_result(folder)
    assert_same_dof_states(api, cli, special=False)
    assert_states_are_the_retained_dofs(api)
    # The in-phase mode: both masses move alike, with the modal amplitude a as large as x.
    np.testing.assert_allclose(api["dof_states"]["x1_c1"], api["dof_states"]["x2_c1"], rtol=1e-8)


@pytest.fixture(scope="module")
def coupled_frc_cli(results_dir):
    folder = str(results_dir / "coupled_frc")
    run_cli("frc", COUPLED, "-o", folder)
    return read_result(folder)


def test_switch_dof_states_match_cli(results_dir, coupled_frc_cli):
    bp = 1 + [p["type"] for p in coupled_frc_cli["special_points"]].index("BP")
    api = hbtrack.switch(hbtrack.load_case(COUPLED), coupled_frc_cli, point=bp)
    folder = str(results_dir / "coupled_switch")
    run_cli("switch", COUPLED, "--from", coupled_frc_cli["folder"], "--point", str(bp), "-o", folder)
    cli = read_result(folder)
    assert_same_columns(api["branch"], cli["branch"])
    assert_same_dof_states(api, cli, special=True)
    assert_states_are_the_retained_dofs(api)
    assert_states_are_the_retained_dofs(api, "special_states")
    # The switched branch is the asymmetric one: x1 and x2 differ.
    assert np.abs(api["dof_states"]["x1_c1"] - api["dof_states"]["x2_c1"]).max() > 0.1
