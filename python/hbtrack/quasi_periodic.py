"""The quasi-periodic response past a Neimark-Sacker point: ``hbtrack torus`` from Python.

The results are dicts as the other runs return (:func:`hbtrack.read_result` of the CLI's folder
gives the same keys): ``branch`` ({column: array} of branch.csv), ``dof_states`` (states.csv's
columns: the torus coefficients of every dof), ``summary`` and ``kind`` = "torus"."""

from ._core import require_core
from .analysis import _special_point_state
from .progress import checked_progress
from .settings import case_with, settings_overrides
from .special_points import SpecialPointType
from .starts import result_overrides


def _integer_pair(name, value):
    """(A, B) as two ints, 0 for None; ValueError naming the keyword otherwise."""
    if value is None:
        return 0, 0
    try:
        a, b = value
        if any(isinstance(v, bool) or int(v) != v for v in (a, b)):
            raise TypeError
        return int(a), int(b)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected two integers (A, B), got {value!r}") from None


def torus(case, start, *, ns, range, harmonics=None, samples=None, progress=None, **settings):  # noqa: A002 - the CLI's --range
    """The torus born at a Neimark-Sacker point, continued in omega (``hbtrack torus``).

    Two-frequency harmonic balance: the response x(omega t, omega2 t) over the harmonic pairs
    (k1, k2), |k1| <= H1, |k2| <= H2, the elements evaluated on a grid of the two phases
    (docs/analyses.md, "The quasi-periodic response past an NS point").

    Parameters
    ----------
    case : hbtrack.Case
        The case `start` was computed on.
    start : dict
        An frc result of `case` (computed or :func:`hbtrack.read_result`); its parameters and
        harmonic balance are used, as ``torus --from``, before the keywords' settings.
    ns : int
        Which of its Neimark-Sacker points: from 1 in increasing omega.
    range : tuple of float
        (LO, HI): the omega interval the branch may explore; it must contain the NS point.
    harmonics : tuple of int, optional
        (H1, H2): harmonics in the forcing's phase and in the NS phase; default (the case's H, 4).
    samples : tuple of int, optional
        (N1, N2): the grid of the two phases; default the case's samples and the power of two above 4 H2.
    progress : callable, optional
        ``progress(fraction, point, omega)`` after every accepted point; return False to stop
        (stop_reason "stopped_by_callback").
    **settings : dict, optional
        The case's settings for this run only, as :func:`hbtrack.frc` takes them
        (``continuation={...}``, ``set={...}``; :func:`hbtrack.with_settings`).

    Returns
    -------
    dict
        ``branch`` ({column: array}: omega, omega2, size, max_NAME, min_NAME; row 0 the NS point),
        ``dof_states`` ({column: array}: omega, omega2, then NAME_h0, NAME_cK1_K2, NAME_sK1_K2),
        ``special_points`` (folds of the torus branch in omega), ``summary`` (stop_reason
        "reached_ns_point" when the torus closes at another NS point, ns_point, ...) and
        ``kind`` = "torus".

    Examples
    --------
    >>> case = hbtrack.load_case("examples/nltva.toml")
    >>> nfrc = hbtrack.frc(case)
    >>> band = hbtrack.torus(case, nfrc, ns=1, range=(1.0, 1.3))
    >>> band["branch"]["max_x2"].max()                       # the largest absorber motion on the torus
    """
    state = _special_point_state(start, SpecialPointType.NEIMARK_SACKER, ns)
    try:
        low, high = (float(v) for v in range)
    except (TypeError, ValueError):
        raise ValueError(f"range: expected (LO, HI), got {range!r}") from None
    h1, h2 = _integer_pair("harmonics", harmonics)
    n1, n2 = _integer_pair("samples", samples)
    if harmonics is None:
        h2 = 4
    progress = checked_progress(progress)
    run_case = case_with(case, result_overrides(start) + settings_overrides(**settings), "torus")
    result = require_core().torus(run_case, state[1:], state[0], low, high, h1, h2, n1, n2, progress)
    result["summary"]["options"]["torus"].update({"ns": ns, "ns_order": "omega"})
    result["kind"] = "torus"
    return result
