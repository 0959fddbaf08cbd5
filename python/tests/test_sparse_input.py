"""Matrices may be scipy.sparse matrices or any array-like (nested lists): the same results as
numpy arrays, to the last bit (the same doubles reach the library)."""
import numpy as np
import pytest

import hbtrack
from hbtrack.arrays import as_matrix

sparse = pytest.importorskip("scipy.sparse")

DUFFING_ARRAYS = dict(dofs=["x"], forcing=[{"dof": "x", "harmonic": 1, "cos": 0.18}], parameters={"amplitude": 1.0},
                      elements=[{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": 0.1}],
                      harmonic_balance={"harmonics": 5, "samples": 64},
                      continuation={"omega_start": 0.5, "omega_end": 1.6, "step": 0.02})

TWO_DOF_K = np.array([[2.0, -1.0], [-1.0, 1.0]])


def test_case_from_sparse_and_list_matrices_is_the_dense_case():
    dense = hbtrack.frc(hbtrack.case_from_arrays(np.eye(1), np.eye(1), C=np.array([[0.05]]), **DUFFING_ARRAYS))["branch"]
    for M, K, C in ((sparse.identity(1, format="csr"), sparse.csc_matrix(np.eye(1)), sparse.coo_matrix([[0.05]])),
                    ([[1.0]], [[1]], [[0.05]])):
        branch = hbtrack.frc(hbtrack.case_from_arrays(M, K, C=C, **DUFFING_ARRAYS))["branch"]
        assert list(branch) == list(dense)
        for name in dense:
            np.testing.assert_array_equal(branch[name], dense[name], err_msg=name)


def test_normal_modes_of_sparse_matrices():
    dense = hbtrack.normal_modes(np.eye(2), TWO_DOF_K)
    from_sparse = hbtrack.normal_modes(sparse.identity(2, format="csr"), sparse.csr_matrix(TWO_DOF_K))
    np.testing.assert_array_equal(from_sparse[0], dense[0])
    np.testing.assert_array_equal(from_sparse[1], dense[1])
    # (3 -+ sqrt 5)/2 are the eigenvalues of K: the frequencies are their roots.
    np.testing.assert_allclose(dense[0] ** 2, [(3 - 5 ** 0.5) / 2, (3 + 5 ** 0.5) / 2], rtol=1e-12)


def test_bad_matrices_name_the_argument():
    with pytest.raises(ValueError, match="K: expected a square matrix, got 2 x 3"):
        hbtrack.normal_modes(np.eye(2), sparse.csr_matrix(np.ones((2, 3))))
    with pytest.raises(ValueError, match="M: expected a 2-D matrix"):
        as_matrix([1.0, 2.0], "M")
    with pytest.raises(ValueError, match="C: expected a matrix of numbers"):
        as_matrix([["a"]], "C")


def test_reduce_keeps_a_sparse_model_sparse(monkeypatch):
    from test_arrays_and_model import chain_3d
    M, K = chain_3d(4)
    dense = hbtrack.reduce(M, K, [[9, 10, 11]], modes=5)

    # The sparse path must never densify M or K (a finite-element model of 10^5 dofs would need
    # tens of GB): as_matrix, the densifying conversion, refuses sparse input for this call.
    def no_densifying(value, name, **kwargs):
        assert not hbtrack.arrays.is_sparse(value), f"{name} densified"
        return as_matrix(value, name, **kwargs)
    monkeypatch.setattr(hbtrack.model, "as_matrix", no_densifying)
    monkeypatch.setattr(hbtrack.arrays, "as_matrix", no_densifying)
    for m, k in ((sparse.csr_matrix(M), sparse.csc_matrix(K)), (sparse.coo_matrix(M), K)):
        reduced = hbtrack.reduce(m, k, [[9, 10, 11]], modes=5)
        # The same nonzeros reach the same sparse factorisation as sparseView() of the dense
        # matrices gives: the same numbers to the last bit.
        for key in ("mass", "stiffness", "transformation", "fixed_interface_frequencies"):
            np.testing.assert_array_equal(reduced[key], dense[key], err_msg=key)
        assert reduced["dof_names"] == dense["dof_names"]


def test_bad_sparse_matrices_name_the_argument():
    M, K = np.eye(3), 2 * np.eye(3)
    with pytest.raises(ValueError, match="K: expected a square matrix, got 3 x 2"):
        hbtrack.reduce(sparse.csr_matrix(M), sparse.csr_matrix(np.ones((3, 2))), [[0, 1, 2]], modes=0)
    with pytest.raises(ValueError, match="M: complex values"):
        hbtrack.reduce(sparse.csr_matrix(M * 1j), sparse.csr_matrix(K), [[0, 1, 2]], modes=0)
