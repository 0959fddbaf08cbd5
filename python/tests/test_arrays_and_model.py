"""Models from numpy arrays, and the Craig-Bampton reduction."""
import numpy as np
import pytest

import hbtrack

from conftest import DUFFING


def test_duffing_from_arrays_is_the_case_file():
    # examples/duffing.toml written as arrays: the same NFRC to the last bit (same input doubles).
    case = hbtrack.case_from_arrays(
        M=np.array([[1.0]]), K=np.array([[1.0]]), C=np.array([[0.05]]), dofs=["x"],
        forcing=[{"dof": "x", "harmonic": 1, "cos": 0.18}], parameters={"amplitude": 1.0},
        elements=[{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": 0.1}],
        harmonic_balance={"harmonics": 7, "samples": 64},
        continuation={"omega_start": 0.5, "omega_end": 1.6, "step": 0.02})
    assert case.path == "<arrays>"
    from_arrays, from_file = hbtrack.frc(case)["branch"], hbtrack.frc(hbtrack.load_case(DUFFING))["branch"]
    assert list(from_arrays) == list(from_file)
    for name in from_file:
        np.testing.assert_array_equal(from_arrays[name], from_file[name], err_msg=name)


def chain_3d(nodes):
    """A chain of point masses moving in x, y, z, springs of stiffness 1000 + 10 i between
    neighbours and to the ground at node 0: 3 * nodes dofs, distinct frequencies."""
    n = 3 * nodes
    K = np.zeros((n, n))
    for i in range(nodes):
        k = 1000.0 + 10 * i
        for d in range(3):
            a = 3 * i + d
            K[a, a] += k
            if i > 0:
                b = a - 3
                K[b, b] += k
                K[a, b] -= k
                K[b, a] -= k
    M = np.diag(np.linspace(1.0, 2.0, n))
    return M, K


def test_reduction_keeping_every_interior_mode_is_exact():
    # Craig-Bampton with all fixed-interface modes kept spans the whole space: its frequencies
    # are the full model's. 1e-8 relative: the eigen-solvers' accuracy on a 12-dof model.
    M, K = chain_3d(4)
    boundary = [[9, 10, 11]]  # the free end node
    rom = hbtrack.reduce(M, K, boundary, modes=9)
    assert rom["mass"].shape == (12, 12)
    assert rom["dof_names"][:3] == ["n1_r", "n1_t", "n1_z"] and rom["dof_names"][3] == "m1"
    full, _ = hbtrack.normal_modes(M, K)
    reduced, _ = hbtrack.normal_modes(rom["mass"], rom["stiffness"])
    np.testing.assert_allclose(reduced, full, rtol=1e-8)


def test_fewer_modes_bound_the_frequencies_from_above():
    # A Ritz reduction: each reduced frequency is an upper bound of the full one of the same rank.
    M, K = chain_3d(4)
    rom = hbtrack.reduce(M, K, [[9, 10, 11]], modes=3)
    full, _ = hbtrack.normal_modes(M, K)
    reduced, _ = hbtrack.normal_modes(rom["mass"], rom["stiffness"])
    assert len(reduced) == 6
    assert np.all(reduced >= full[:6] * (1 - 1e-10))  # 1e-10: eigen-solver round-off only
    # Three interior modes and the free end's constraint modes hold the first chain mode well:
    # measured 0.12 % above; 1 % leaves room for solver changes, not for a lost mode.
    assert reduced[0] < full[0] * 1.01


def test_output_harmonics_give_the_recorded_first_harmonic(duffing_case, duffing_frc):
    point = 20
    harmonics = hbtrack.output_harmonics(duffing_case, duffing_frc["states"][point])["x"]
    assert len(harmonics) == 15  # H = 7
    # Exact: the same hypot of the same expanded coefficients as the recorded h1_x.
    assert np.hypot(harmonics[1], harmonics[2]) == duffing_frc["branch"]["h1_x"][point]


def test_residual_is_at_tolerance_on_the_branch_and_grows_off_it(duffing_case, duffing_frc):
    state = np.array(duffing_frc["states"][20], dtype=float)
    on_branch = hbtrack.residual(duffing_case, state)
    # frc stops Newton at ||r||inf <= tolerance (1e-9 by default) x force_scale.
    assert on_branch["relative"] <= 1e-9
    assert on_branch["residual"].shape == (state.size - 1,)
    # Moving the first harmonic's cosine by 1e-3 of the response moves the balance by about
    # |K - omega^2 M| x 1e-3, orders of magnitude above the tolerance.
    moved = state.copy()
    moved[2] += 1e-3 * np.abs(state[1:]).max()
    assert hbtrack.residual(duffing_case, moved)["relative"] > 1e-6
    with pytest.raises(ValueError, match="state: holds"):
        hbtrack.residual(duffing_case, state[:-1])


def test_boundary_frames_change_only_the_basis():
    # A rotated local frame at the boundary node is an orthonormal change of basis: the same
    # frequencies (to 1e-8, as above), the boundary dofs' rows rotated.
    M, K = chain_3d(4)
    angle = np.radians(30.0)
    frame = np.array([[np.cos(angle), -np.sin(angle), 0.0], [np.sin(angle), np.cos(angle), 0.0], [0.0, 0.0, 1.0]])
    rom = hbtrack.reduce(M, K, [[9, 10, 11]], frames=[frame], modes=9)
    np.testing.assert_allclose(hbtrack.normal_modes(rom["mass"], rom["stiffness"])[0], hbtrack.normal_modes(M, K)[0], rtol=1e-8)
    np.testing.assert_allclose(rom["transformation"][9:12, :3], frame, atol=1e-12)
    with pytest.raises(ValueError, match=r"frames\[0\]: expected 3x3"):
        hbtrack.reduce(M, K, [[9, 10, 11]], frames=[np.eye(2)], modes=3)
