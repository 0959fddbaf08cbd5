"""Elements written in Python.

    def cubic(x, v):                       # x, v: (N, k) samples of the element's dofs over a period
        return 0.1 * x**3, 0.3 * x[:, :, None]**2     # forces (N, k) and d f_i/d x_j as (N, k, k)
    hbtrack.add_python_element(case, ["x"], cubic)
    nfrc = hbtrack.frc(case)

The callable gets the N time samples of one period of the element's displacements and velocities
(the AFT's time half) and returns the forces, shape (N, k) (or (N,) for one dof), or a tuple
(forces, dforce_dx[, dforce_dv]) with dforce_dx[t, i, j] = d f_i(t) / d x_j(t). Derivatives it
does not return are central differences (2k more calls each, step `step` relative to the
signal's size), which cost accuracy: Newton then converges linearly. Parameters live in the
callable (a closure or an object); they are not case parameters and cannot be tracked.
"""
from ._core import require_core


def add_python_element(case, dofs, force, *, uses_velocity=False, step=1e-6):
    """Appends to a case an element whose forces a Python callable computes.

    Parameters
    ----------
    case : hbtrack.Case
        The case, modified in place (and returned).
    dofs : sequence of str
        The names of the element's k dofs.
    force : callable
        ``force(x, v)`` with x, v the (N, k) samples of one period of the dofs' displacements and
        velocities; returns the forces (N, k) (or (N,) for one dof), or a tuple
        (forces, dforce_dx[, dforce_dv]) with dforce_dx[t, i, j] = d f_i(t) / d x_j(t).
    uses_velocity : bool, optional
        Whether the forces depend on v (otherwise dforce_dv is taken as zero).
    step : float, optional
        Relative central-difference step for the derivatives `force` does not return.

    Returns
    -------
    hbtrack.Case
        `case`, with the element appended.

    Examples
    --------
    >>> def cubic(x, v):
    ...     return 0.1 * x**3, 0.3 * x[:, :, None]**2
    >>> nfrc = hbtrack.frc(hbtrack.add_python_element(case, ["x"], cubic))
    """
    require_core().add_python_element(case, list(dofs), force, uses_velocity, float(step))
    return case
