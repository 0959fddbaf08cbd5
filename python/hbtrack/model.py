"""Model building blocks: Craig-Bampton reduction, normal modes (of matrices, or of a case as
`hbtrack modes`), harmonics of a solution.
Matrices may be numpy arrays, any array-like or scipy.sparse matrices (hbtrack.arrays)."""
import numpy as np

from ._core import require_core
from .arrays import as_matrix, as_sparse_matrix, is_sparse
from .settings import case_with, settings_overrides


def reduce(M, K, boundary, *, frames=None, modes=12):
    """Craig-Bampton reduction (``hbtrack reduce``) onto boundary nodes' translations plus modes.

    Parameters
    ----------
    M, K : array_like or scipy.sparse matrix
        Mass and stiffness of the finite-element model (n x n). Sparse ones stay sparse (a
        large model is never densified); dense ones are factorised sparsely inside too.
    boundary : sequence of (int, int, int)
        Per boundary node, its three rows x, y, z (0-based).
    frames : sequence of 3x3 array_like, optional
        Per boundary node, a matrix whose columns are its local r, t, z axes (default identity).
    modes : int, optional
        Number of fixed-interface modes kept (default 12).

    Returns
    -------
    dict
        ``mass``, ``stiffness`` (reduced matrices), ``transformation`` (n x reduced),
        ``fixed_interface_frequencies`` (rad/s) and ``dof_names``.

    Examples
    --------
    >>> rom = hbtrack.reduce(M, K, [(0, 1, 2)], modes=4)
    >>> rom["stiffness"].shape
    (7, 7)
    """
    frames = [] if frames is None else [as_matrix(f, "frames") for f in frames]
    boundary = [list(b) for b in boundary]
    if is_sparse(M) or is_sparse(K):  # a finite-element model stays sparse all the way
        return require_core().reduce_sparse(as_sparse_matrix(M, "M"), as_sparse_matrix(K, "K"), boundary, frames, int(modes))
    return require_core().reduce(as_matrix(M, "M"), as_matrix(K, "K"), boundary, frames, int(modes))


def normal_modes(M, K):
    """Undamped normal modes of (M, K).

    Parameters
    ----------
    M, K : array_like or scipy.sparse matrix
        n x n mass (positive definite) and stiffness matrices.

    Returns
    -------
    frequencies : numpy.ndarray
        The n natural frequencies in rad/s, increasing.
    shapes : numpy.ndarray
        n x n, the mass-normalised mode shapes as columns.

    Examples
    --------
    >>> frequencies, shapes = hbtrack.normal_modes(np.eye(2), [[2.0, -1.0], [-1.0, 2.0]])
    """
    return require_core().normal_modes(as_matrix(M, "M"), as_matrix(K, "K"))


def modes(case, count=10, **settings):
    """The lowest natural frequencies of a case's linear model (``hbtrack modes``).

    Parameters
    ----------
    case : hbtrack.Case
        The case (its mass and stiffness; not changed).
    count : int, optional
        How many modes, from the lowest (default 10; fewer when the model has fewer dofs).
    **settings : dict, optional
        The case's settings for this run only, as :func:`hbtrack.frc` takes them.

    Returns
    -------
    dict
        ``summary`` as the CLI's summary.json: ``natural_frequencies`` (rad/s, increasing),
        ``dominant_dofs`` (the dof that moves most in each mass-normalised shape), ``dofs``;
        and ``kind`` = "modes".

    Raises
    ------
    ValueError
        count < 1.
    RuntimeError
        A mass matrix that is not positive definite.

    Examples
    --------
    >>> hbtrack.modes(case, count=3)["summary"]["natural_frequencies"]
    """
    run_case = case_with(case, settings_overrides(**settings), "modes")
    result = require_core().modes(run_case, int(count))
    result["kind"] = "modes"
    return result


def campbell(case, speeds, count=6, names=None, engine_orders=8):
    """The Campbell diagram of a rotating case (``hbtrack modes CASE --speeds LO:HI:N``).

    At each speed W the lowest frequencies of (K + W^2 (Kg1 - Mspin)) phi + i w W G phi = w^2 M phi,
    the case's ``[rotation]`` matrices at that speed (G when the case gives it), each mode followed
    from speed to speed by the correlation of its shape.

    Parameters
    ----------
    case : hbtrack.Case
        A case with ``[rotation]`` and ``[model]`` Kg1, Mspin (and optionally G); not changed.
    speeds : array_like
        Rotation speeds in rad/s, >= 0 and increasing.
    count : int, optional
        How many modes, from the lowest at the first speed (default 6).
    names : list of str, optional
        The modes' names at the first speed, lowest first (e.g. ["1B", "2B", "1T"]); unnamed
        modes are "mode K".
    engine_orders : int, optional
        The summary lists where each mode meets the lines k W, k = 1 .. engine_orders (default 8).

    Returns
    -------
    dict
        ``campbell``: {"speed": array, NAME: array per mode}; ``summary`` as the CLI's
        summary.json (``mode_names``, ``engine_order_crossings``, ``lowest_mac_between_speeds``);
        ``kind`` = "campbell".

    Raises
    ------
    ValueError
        A case without [rotation], speeds negative or not increasing, count < 1.
    RuntimeError
        The stiffness at a speed is not positive definite.

    Examples
    --------
    >>> case = hbtrack.load_case("examples/rotor67/design_speed.toml")
    >>> diagram = hbtrack.campbell(case, np.linspace(0, 1680, 43), names=["1B", "2B", "1T"])
    >>> diagram["campbell"]["1B"][-1]                          # 1B at 1680 rad/s
    """
    result = require_core().campbell(case, [float(s) for s in np.atleast_1d(speeds)], int(count), list(names or []),
                                     int(engine_orders))
    result["kind"] = "campbell"
    return result


def output_harmonics(case, state):
    """Fourier coefficients of every output dof of a solution.

    Parameters
    ----------
    case : hbtrack.Case
        The case the state was computed on.
    state : array_like
        A state row [omega, x0, x1, ...] (a row of a result's ``states``).

    Returns
    -------
    dict
        {output name: numpy.ndarray [a0, a1, b1, ..., aH, bH]} with
        x = a0/2 + sum a_j cos(j w t) + b_j sin(j w t); branch.csv's hK_NAME is |(a_K, b_K)|
        (h0 = a0/2) and phaseK_NAME is atan2(b_K, a_K).

    Examples
    --------
    >>> harmonics = hbtrack.output_harmonics(case, nfrc["states"][20])
    >>> harmonics["x"][1:3]                                  # a1, b1
    """
    return require_core().output_harmonics(case, np.asarray(state, dtype=float))


def residual(case, state):
    """Harmonic balance residual of a state: how far a point is from solving the case's equations.

    Use it to put another tool's points into hbtrack's equations (convert them to the layout of
    ``states`` first: harmonic-major [a0, a1, b1, ...] per retained dof, a0 twice the mean).

    Parameters
    ----------
    case : hbtrack.Case
        The case whose equations are evaluated.
    state : array_like
        A state row [omega, x0, x1, ...] (the layout of a result's ``states``).

    Returns
    -------
    dict
        ``residual`` (numpy.ndarray, the balance of every retained dof's harmonics), ``force_scale``
        (the force unit ``frc``'s tolerance is relative to: the forcing's largest coefficient times
        the amplitude) and ``relative`` (max |residual| / force_scale, what ``frc`` compares with
        ``continuation.tolerance``).

    Examples
    --------
    >>> nfrc = hbtrack.frc(case)
    >>> hbtrack.residual(case, nfrc["states"][20])["relative"] < 1e-8
    True
    """
    return require_core().residual(case, np.asarray(state, dtype=float))
