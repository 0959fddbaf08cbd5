"""branch.csv's harmonic columns recomputed from states.csv on a two-dof case whose first output
is condensed out of the unknowns (so the check goes through the expansion), and stability.csv
against the branch's `stable`."""
import os

import numpy as np
import pytest

import hbtrack

from conftest import ROOT, run_cli

TWO_DOF = os.path.join(ROOT, "examples", "two_dof_contact.toml")


@pytest.fixture(scope="module")
def two_dof(results_dir):
    folder = str(results_dir / "two_dof")
    run_cli("frc", TWO_DOF, "-o", folder)
    return hbtrack.load_case(TWO_DOF), hbtrack.read_result(folder)


def test_harmonic_columns_are_those_of_the_states(two_dof):
    case, result = two_dof
    branch, states = result["branch"], result["states"]
    harmonics = case.harmonic_balance.harmonics
    assert list(branch)[:8] == ["omega", "stable", "max_x1", "min_x1", "h1_x1", "max_x2", "min_x2", "h1_x2"]
    for i, state in enumerate(states):
        coefficients = hbtrack.output_harmonics(case, state)
        # x2, the contact's dof, is the only unknown left by the condensation: its coefficients
        # are the state's own [a0, a1, b1, ...] (the same doubles, so exactly).
        np.testing.assert_array_equal(coefficients["x2"], state[1:])
        for name, c in coefficients.items():
            magnitudes = np.concatenate([[0.5 * c[0]], np.hypot(c[1::2], c[2::2])])
            # The same expansion of the same 17-digit state: agreement to round-off, 1e-13 of the
            # largest harmonic (the expansion sums over the condensed dofs).
            tolerance = 1e-13 * np.abs(magnitudes).max()
            for k in range(harmonics + 1):
                assert branch[f"h{k}_{name}"][i] == pytest.approx(magnitudes[k], abs=tolerance), (i, name, k)
            for k in range(1, harmonics + 1):
                phase = branch[f"phase{k}_{name}"][i]
                if magnitudes[k] <= 1e-11 * np.abs(magnitudes).max():
                    continue  # round-off harmonics: the phase is reported as 0 (docs/outputs.md)
                # a_k cos + b_k sin = h_k cos(k w t - phase_k): at t = 0 and at k w t = pi/2.
                assert magnitudes[k] * np.cos(phase) == pytest.approx(c[2 * k - 1], abs=10 * tolerance)
                assert magnitudes[k] * np.sin(phase) == pytest.approx(c[2 * k], abs=10 * tolerance)


def test_stability_table_decides_stable(two_dof):
    _, result = two_dof
    table, branch = result["stability"], result["branch"]
    points = table["point"].astype(int)
    assert set(points) == set(range(len(branch["omega"])))
    for i in range(len(branch["omega"])):
        rows = points == i
        real = table["exponent_real"][rows]
        assert table["k"][rows][0] == 0 and real[0] == real.max()
        assert branch["stable"][i] == float(real[0] <= 1e-9 * branch["omega"][i])  # finish_floquet's rule
    assert 0 < branch["stable"].sum() < len(branch["stable"])  # the contact fold is unstable between its LPs
    # The `method` code of each point (0 hill, 1 monodromy, 2 shooting) agrees with summary.json's
    # count of what decided the points, one method per point (a C0 contact law on 2 dofs: the
    # cross-check, not Hill, decides most of them). A 2-dof model is evaluated at every point:
    # none takes its verdict from its neighbours ("bracketed", which has no rows here).
    codes = {"hill": 0, "monodromy": 1, "shooting": 2}
    per_point = []
    for i in range(len(branch["omega"])):
        methods = set(table["method"][points == i])
        assert len(methods) == 1, (i, methods)
        per_point.append(methods.pop())
    decided = result["summary"]["stability_methods"]["points"]
    assert set(decided) == set(codes) | {"bracketed"}
    assert decided["bracketed"] == 0
    for name, code in codes.items():
        assert per_point.count(code) == decided[name], name
    assert per_point.count(codes["hill"]) < len(per_point)


def test_api_returns_the_stability_table_of_the_cli(duffing_frc, duffing_frc_cli):
    cli = duffing_frc_cli["stability"]
    assert list(duffing_frc["stability"]) == list(cli)
    # As the branch columns (test_same_as_cli): 1e-12 relative, and round-off of the largest
    # entry for the parts that are zero up to round-off (imaginary parts of real exponents).
    for name, values in cli.items():
        np.testing.assert_allclose(duffing_frc["stability"][name], values, rtol=1e-12,
                                   atol=1e-12 * np.abs(values).max(), err_msg=name)


def _coefficients(columns, name, harmonics):
    """[mean, a1, b1, ..., aH, bH] of dof `name` from the columns of states.csv."""
    return np.array([columns[f"{name}_h0"]] + [columns[f"{name}_{p}{k}"] for k in range(1, harmonics + 1) for p in "cs"])


def test_branch_columns_recomputed_from_the_dof_columns_of_states_csv(two_dof):
    # x1 is recovered from the condensation, x2 is the retained contact dof: both are columns of
    # states.csv, and branch.csv's magnitudes and phases are theirs.
    case, result = two_dof
    branch, columns = result["branch"], result["dof_states"]
    harmonics = case.harmonic_balance.harmonics
    assert list(columns)[:4] == ["omega", "x1_h0", "x1_c1", "x1_s1"]
    np.testing.assert_array_equal(columns["omega"], branch["omega"])
    for name in ("x1", "x2"):
        c = _coefficients(columns, name, harmonics)  # rows: coefficients, columns: points
        magnitudes = np.vstack([c[0], np.hypot(c[1::2], c[2::2])])
        # Both files print 17 digits of doubles computed by the same expansion: round-off, 1e-13 of
        # the point's largest harmonic (the recovery sums over the condensed dofs).
        tolerance = 1e-13 * np.abs(magnitudes).max(axis=0)
        for k in range(harmonics + 1):
            np.testing.assert_array_less(np.abs(branch[f"h{k}_{name}"] - magnitudes[k]), tolerance + 1e-300, err_msg=f"h{k}_{name}")
        for k in range(1, harmonics + 1):
            phase = branch[f"phase{k}_{name}"]
            resolved = magnitudes[k] > 1e-11 * np.abs(magnitudes).max(axis=0)  # else the phase is reported as 0
            # a_k cos + b_k sin = h_k cos(k w t - phase_k): at t = 0 and at k w t = pi/2.
            np.testing.assert_allclose((magnitudes[k] * np.cos(phase))[resolved], c[2 * k - 1][resolved], rtol=0, atol=10 * tolerance.max())
            np.testing.assert_allclose((magnitudes[k] * np.sin(phase))[resolved], c[2 * k][resolved], rtol=0, atol=10 * tolerance.max())


def test_a_folder_with_the_earlier_unknown_columns_reads_as_the_new_one(two_dof, tmp_path):
    # The layout before the dof columns: omega, x0, x1, ... the unknowns (x2's [a0, a1, b1, ...],
    # x2 the only retained dof), the mean as a0 = 2 x2_h0. read_result gives the same states.
    case, result = two_dof
    columns = result["dof_states"]
    old = np.column_stack([columns["omega"], _coefficients(columns, "x2", case.harmonic_balance.harmonics).T])
    old[:, 1] *= 2.0
    folder = tmp_path / "old"
    folder.mkdir()
    for name in ("summary.json", "branch.csv", "special_states.csv"):
        (folder / name).write_bytes(open(os.path.join(result["folder"], name), "rb").read())
    header = "omega," + ",".join(f"x{i}" for i in range(old.shape[1] - 1))
    np.savetxt(folder / "states.csv", old, delimiter=",", header=header, comments="", fmt="%.17g")
    earlier = hbtrack.read_result(str(folder))
    assert "dof_states" not in earlier
    np.testing.assert_array_equal(earlier["states"], result["states"])  # the same doubles: a0 = 2 (a0 / 2) exactly
