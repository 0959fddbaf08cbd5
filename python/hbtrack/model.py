"""Model building blocks: Craig-Bampton reduction, normal modes, harmonics of a solution."""
import numpy as np

from ._core import require_core


def reduce(M, K, boundary, *, frames=None, modes=12):
    """Craig-Bampton reduction (`hbtrack reduce`) of dense M, K onto the translations of boundary
    nodes (boundary: per node its three rows x, y, z; frames: per node a 3x3 matrix whose columns
    are its local r, t, z axes, default identity) plus `modes` fixed-interface modes. Returns
    {mass, stiffness, transformation, fixed_interface_frequencies (rad/s), dof_names}."""
    frames = [] if frames is None else [np.asarray(f, dtype=float) for f in frames]
    return require_core().reduce(np.asarray(M, dtype=float), np.asarray(K, dtype=float),
                                 [list(b) for b in boundary], frames, int(modes))


def normal_modes(M, K):
    """Undamped modes: (frequencies in rad/s, mass-normalised shapes as columns)."""
    return require_core().normal_modes(np.asarray(M, dtype=float), np.asarray(K, dtype=float))


def output_harmonics(case, state):
    """{output name: [a0, a1, b1, ..., aH, bH]} (x = a0/2 + sum a_j cos j wt + b_j sin j wt) of a
    state row [omega, x0, x1, ...] of a result of `case`."""
    return require_core().output_harmonics(case, np.asarray(state, dtype=float))
