"""The element catalogue, one helper per element type, and elements written in Python.

`element_types()` lists the element types a case file may name, with their keys and properties
(unit, range, default, doc) as the case reader checks them. For each type there is a function of
that name here that writes the element's ``[[elements]]`` table (its signature and docstring come
from the catalogue: ``help(hbtrack.elements.tip_contact)``):

    spring = hbtrack.elements.cubic_spring(["x"], cubic_stiffness=0.1)
    case = hbtrack.case_from_arrays(M, K, ["x"], elements=[spring], ...)

Elements written in Python:

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
from ._core import core, require_core
from ._element_helpers import element_helpers


def element_types():
    """The element types a case file may name (``[[elements]]``), from hbtrack's element catalogue.

    Parameters
    ----------
    None

    Returns
    -------
    dict
        {type: {"summary": the force law in one line, "dofs": the names of the dofs it takes
        ([] for any number), "weighted": whether it acts along d = w.x (`weights`), "directions": the rows of
        `weights` of a weighted type (2: a slider in the plane u = W x), "keys":
        {name: {"kind", "values" or "range", "default", "doc"}} (the keys that decide how it is
        built: law, friction, sliders, ...), "variants": [{"choices": {key: value},
        "properties": {name: {"unit", "range", "default", "doc"}}}]}}. Units are the model's:
        F force, L length, s time, 1 none; a range is "" (any), "> 0", ">= 0", "!= 0", "> -1"
        or ">= 1"; a default None means required.

    Examples
    --------
    >>> types = hbtrack.element_types()
    >>> types["regularized_contact"]["variants"][0]["properties"]["width"]["range"]
    '> 0'
    """
    return require_core().element_types()


if core is not None:  # without the compiled part there is no catalogue to build them from
    globals().update(element_helpers(core.element_types()))


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
