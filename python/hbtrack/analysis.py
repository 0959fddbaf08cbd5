"""NFRC, one solution, limit-point tracking and isolated branches: `hbtrack frc`, `solve`, `track`
and `isolas` as functions (the same runs, src/runs/, in memory). Results are dicts holding what the CLI writes to a result folder:

    branch          {column: 1-D array}, the columns and numbers of branch.csv
    states          2-D array: omega (or leg, omega, parameter), then the harmonic-balance unknowns
    dof_states      {column: array}, states.csv: every dof's harmonics (docs/outputs.md)
    stability       {column: 1-D array}, stability.csv (frc and isola branches, with stability on)
    special_points  list of dicts, as summary.json's special_points
    special_states  2-D array, special_states.csv (frc only)
    summary         dict, as summary.json
    kind            "frc", "continue", "backbone", "switch", "track", "isolas" (as hbtrack.results.read_result
                    names folders)

A run that stops early (summary["stop_reason"]) still returns what it computed, as the CLI keeps
its points; bad arguments raise ValueError naming the argument. The columns are described in
docs/outputs.md. Every computation takes the case's settings for that run as keywords
(``continuation={...}``, ``set={...}``: hbtrack.with_settings) and ``progress=callable``.
"""
import math

import numpy as np

from ._core import require_core
from .cases import toml_value
from .progress import checked_progress
from .settings import case_with, settings_overrides
from .special_points import SpecialPointType
from .starts import result_overrides, start_state

# The case's own check of the range, which a start at omega_end breaks.
_EMPTY_RANGE = "omega_end: must differ from omega_start"


def frc(case, *, start=None, point=None, progress=None, element_forces=False, **settings):
    """The NFRC of `case` over its frequency range, with stability and special points.

    What ``hbtrack frc CASE -o DIR`` computes, returned instead of written; with `start`, what
    ``hbtrack frc CASE --from DIR --point K`` computes.

    Parameters
    ----------
    case : hbtrack.Case
        From :func:`hbtrack.load_case` or :func:`hbtrack.case_from_arrays`; not changed.
    start : dict or array_like, optional
        Start from a point of an earlier result instead of the linear solution at omega_start:
        a result (frc, solve, continue, switch, an isola branch; from a computation or
        :func:`hbtrack.read_result`), whose parameters and harmonic balance are then used, as
        ``--from``; or a state row [omega, x0, x1, ...] of the case. The NFRC goes from the
        point's omega towards ``continuation.omega_end``.
    point : int, optional
        The row of ``start["states"]`` (0-based; default the last), as ``--point``.
    progress : callable, optional
        Called after every accepted point as ``progress(fraction, point, omega)``: `fraction`
        the part of the frequency range covered so far (0 to 1, as the CLI's progress line),
        `point` the 0-based row, `omega` its frequency (rad/s). Return False to stop the
        continuation there (stop_reason "stopped_by_callback"); None or True go on.
    element_forces : bool, optional
        Also return ``element_forces`` (as ``frc --element-forces`` writes element_forces.csv).
    **settings : dict, optional
        The case's settings for this run only (`case` unchanged), as :func:`hbtrack.with_settings`
        takes them: ``continuation={"omega_start": 0.5}``, ``harmonic_balance={...}``,
        ``stability={...}``, ``parameters={...}`` or ``set={"continuation.step": 0.01}``.

    Returns
    -------
    dict
        ``branch`` ({column: array}: omega, stable, max_NAME, min_NAME, h1_NAME, then hK_NAME and
        phaseK_NAME per output), ``states`` (rows [omega, x0, ...]), ``stability`` ({column:
        array}, the Floquet exponents and multipliers per point; absent with stability "none"),
        ``special_points`` (list of dicts: type LP/BP/PD/NS, index, omega, located, outputs),
        ``special_states``, ``dof_states``, ``dof_special_states`` ({column: array}: every dof's
        harmonics, as states.csv and special_states.csv), ``element_forces`` ({column: array},
        when asked), ``summary`` (as summary.json: ``warnings``, and ``friction_loop_gain`` for
        contacts with friction, docs/outputs.md; with `start`, ``started_from`` = {point, omega}
        and ``folder`` for a result read from one) and ``kind`` = "frc".

    Raises
    ------
    ValueError
        A bad argument, or an unknown or bad setting (naming the key and the rule).

    Examples
    --------
    >>> case = hbtrack.load_case("examples/duffing.toml")
    >>> nfrc = hbtrack.frc(case)
    >>> nfrc["branch"]["max_x"].max()                      # the peak
    >>> [p["omega"] for p in nfrc["special_points"] if p["type"] == "LP"]
    >>> wide = hbtrack.frc(case, continuation={"omega_end": 2.5}, harmonic_balance={"harmonics": 7})
    >>> rest = hbtrack.frc(case, start=nfrc, point=20)     # as hbtrack frc --from DIR --point 20
    """
    core = require_core()
    progress = checked_progress(progress)
    overrides = settings_overrides(**settings)
    x = None
    if start is None:
        if point is not None:
            raise ValueError("point: needs start")
    else:
        state, row, from_result = start_state(start, point)
        omega = float(state[0])
        if not (np.isfinite(omega) and omega > 0):
            raise ValueError(f"start: point {row}: omega must be > 0 and finite, got {omega}")
        # As --from: the result's settings, then the caller's, then the point's frequency.
        overrides = from_result + overrides + [f"continuation.omega_start={toml_value(omega)}"]
        x = state[1:]
    try:
        run_case = case_with(case, overrides, "frc")
    except ValueError as error:
        if start is None or _EMPTY_RANGE not in str(error):
            raise
        raise ValueError(f"start: point {row} is at omega_end = {omega}: give the new end with "
                         "continuation={'omega_end': VALUE}") from None
    result = core.frc(run_case, progress, x, bool(element_forces))
    if start is not None:
        result["summary"]["started_from"] = {"point": row, "omega": omega}
        if isinstance(start, dict) and "folder" in start:
            result["summary"]["started_from"]["folder"] = start["folder"]
    result["kind"] = "frc"
    return result


def solve(case, omega, **settings):
    """One periodic solution at a fixed frequency (``hbtrack solve``).

    Newton from the linear solution at `omega`, with the solution's stability when the case
    computes it.

    Parameters
    ----------
    case : hbtrack.Case
        The case (not changed).
    omega : float
        The forcing frequency (rad/s), > 0.
    **settings : dict, optional
        The case's settings for this run only, as :func:`frc` takes them.

    Returns
    -------
    dict
        ``branch`` (one row, the columns of branch.csv), ``states`` (one row [omega, x0, ...]),
        ``dof_states`` (every dof's harmonics), ``summary`` (converged, newton_iterations, the
        outputs and, with stability, stable and floquet_multipliers) and ``kind`` = "solve". A
        solve that did not converge returns its summary (converged False) and no rows.

    Examples
    --------
    >>> point = hbtrack.solve(case, 1.2)
    >>> point["summary"]["converged"], point["branch"]["max_x"][0]
    """
    run_case = case_with(case, settings_overrides(**settings), "solve")
    try:
        omega = float(omega)
    except (TypeError, ValueError):
        raise ValueError(f"omega: expected a number, got {omega!r}") from None
    result = require_core().solve(run_case, omega)
    result["kind"] = "solve"
    return result


def continuation(case, *, param, omega, range, progress=None, **settings):  # noqa: A002 - the CLI's --range
    """The periodic solution at a fixed frequency followed in a named parameter (``hbtrack continue``).

    Parameters
    ----------
    case : hbtrack.Case
        From :func:`hbtrack.load_case` or :func:`hbtrack.case_from_arrays`.
    param : str
        The named parameter to vary ("amplitude", "mu", "clearance", ...).
    omega : float
        The fixed forcing frequency (rad/s).
    range : tuple of float
        (start, end): the parameter goes from start towards end (the case's value is not used).
    progress : callable, optional
        ``progress(fraction, point, value)`` after every accepted point: the part of (start, end)
        covered and the parameter's value; return False to stop (stop_reason "stopped_by_callback").
    **settings : dict, optional
        The case's settings for this run only, as :func:`frc` takes them (``continuation={...}``,
        ``set={...}``; :func:`hbtrack.with_settings`).

    Returns
    -------
    dict
        ``branch`` ({column: array}: omega, PARAM, stable, max_NAME, min_NAME, h1_NAME, then
        hK_NAME and phaseK_NAME per output), ``states`` (rows [omega, x0, ...]),
        ``special_points`` (LPs in the parameter, located; BP, PD, NS), ``special_states``,
        ``dof_states``, ``dof_special_states`` ({column: array}: omega, then every dof's
        harmonics NAME_h0, NAME_cK, NAME_sK, the condensed dofs recovered at each point's value
        of PARAM; as states.csv and special_states.csv), ``summary`` (as summary.json) and
        ``kind`` = "continue".

    Examples
    --------
    >>> branch = hbtrack.continuation(case, param="amplitude", omega=1.2, range=(0.05, 3.0))
    >>> [p["amplitude"] for p in branch["special_points"] if p["type"] == "LP"]
    >>> fine = hbtrack.continuation(case, param="amplitude", omega=1.2, range=(0.05, 3.0),
    ...                             continuation={"step_max": 0.02})
    """
    try:
        start, end = (float(v) for v in range)
    except (TypeError, ValueError):
        raise ValueError(f"range: expected (LO, HI), got {range!r}") from None
    progress = checked_progress(progress)
    run_case = case_with(case, settings_overrides(**settings), "continuation")
    result = require_core().continuation(run_case, param, float(omega), start, end, progress)
    result["kind"] = "continue"
    return result


def backbone(case, *, mode=1, range, progress=None, **settings):  # noqa: A002 - the CLI's --range
    """The nonlinear mode of a linear mode by the extended periodic motion concept (``hbtrack backbone``).

    Parameters
    ----------
    case : hbtrack.Case
        The case; its forcing is ignored and every dof is an unknown (no condensation).
    mode : int, optional
        Which linear mode, counted from 1 (default 1).
    range : tuple of float
        (LO, HI), 0 < LO < HI: the modal amplitude a goes from LO (near the linear mode) to HI.
    progress : callable, optional
        ``progress(fraction, point, amplitude)`` after every accepted point: the part of (LO, HI)
        covered on a log scale (the steps are in log10 a) and a; return False to stop (stop_reason
        "stopped_by_callback").
    **settings : dict, optional
        The case's settings for this run only, as :func:`frc` takes them (``continuation={...}``,
        ``set={...}``; :func:`hbtrack.with_settings`).

    Returns
    -------
    dict
        ``branch`` ({column: array}: amplitude, omega, damping_ratio, xi, then per output
        max_NAME, min_NAME and h0_NAME .. hH_NAME, h0 the mean), ``states`` (rows [omega, x0,
        ...]: the motion, a times the mode's unknowns), ``dof_states`` ({column: array}: omega,
        then every dof's harmonics NAME_h0, NAME_cK, NAME_sK of that motion, as states.csv),
        ``special_points`` (no special states: the CLI writes none for a backbone), ``summary``
        (as summary.json) and ``kind`` = "backbone".

    Examples
    --------
    >>> mode = hbtrack.backbone(case, mode=1, range=(0.01, 5.0))
    >>> mode["branch"]["omega"][-1], mode["branch"]["damping_ratio"][-1]
    >>> finer = hbtrack.backbone(case, range=(0.01, 5.0), harmonic_balance={"harmonics": 9})
    """
    if isinstance(mode, bool) or not isinstance(mode, (int, np.integer)) or mode < 1:
        raise ValueError(f"mode: must be an integer >= 1, got {mode!r}")
    try:
        start, end = (float(v) for v in range)
    except (TypeError, ValueError):
        raise ValueError(f"range: expected (LO, HI), got {range!r}") from None
    if not 0 < start < end:
        raise ValueError(f"range: must be (LO, HI) with 0 < LO < HI, got {range!r}")
    progress = checked_progress(progress)
    run_case = case_with(case, settings_overrides(**settings), "backbone")
    result = require_core().backbone(run_case, int(mode), start, end, progress)
    result["kind"] = "backbone"
    return result


def switch(case, start, *, point, progress=None, **settings):
    """The branch born at a BP or PD of an frc result (``hbtrack switch``).

    At a BP the other branch through the point (its tangent from the null space of the extended
    Jacobian), continued both ways; at a PD the period-doubled branch (harmonic balance at
    omega / 2 from the critical Floquet eigenvector), across the PD band (docs/analyses.md).

    Parameters
    ----------
    case : hbtrack.Case
        The case `start` was computed on.
    start : dict
        An frc result (:func:`frc` or :func:`hbtrack.read_result` of an frc folder); its
        parameters and harmonic balance (harmonics, subharmonic, samples, condensation) are
        used, as ``switch --from``, before the keywords' settings.
    point : int
        Which special point, counted from 1 in the order of ``start["special_points"]``; a BP
        or a PD.
    progress : callable, optional
        ``progress(fraction, point, omega)`` after every accepted point: each of the two legs counts
        for half, by the part of the frequency range between the point and the end it heads for that
        it has covered; `point` counts on over both legs; return False to stop (stop_reason
        "stopped_by_callback").
    **settings : dict, optional
        The case's settings for this run only, as :func:`frc` takes them (``continuation={...}``,
        ``set={...}``; :func:`hbtrack.with_settings`).

    Returns
    -------
    dict
        As :func:`frc` returns (``branch`` with stability, ``states``, ``special_points``,
        ``special_states``, ``dof_states`` and ``dof_special_states`` ({column: array}: every
        dof's harmonics NAME_h0, NAME_cK, NAME_sK, as states.csv and special_states.csv),
        ``summary`` with ``options.switch`` = {point, type, omega} and ``legs``), ``kind`` =
        "switch". At a PD the harmonics are multiples of omega / 2: ``branch`` has
        ``h0.5_NAME``, ``h1_NAME``, ``h1.5_NAME``, ..., ``dof_states`` NAME_c0.5, NAME_s0.5, ...

    Examples
    --------
    >>> case = hbtrack.load_case("examples/coupled_duffing.toml")
    >>> nfrc = hbtrack.frc(case)
    >>> bp = 1 + [p["type"] for p in nfrc["special_points"]].index("BP")
    >>> branch = hbtrack.switch(case, nfrc, point=bp)
    >>> abs(branch["branch"]["max_x1"] - branch["branch"]["max_x2"]).max()   # asymmetric
    >>> longer = hbtrack.switch(case, nfrc, point=bp, continuation={"max_points": 200})
    """
    if not isinstance(start, dict) or "special_points" not in start or "special_states" not in start or "states" not in start:
        raise ValueError("start: expected an frc result (from hbtrack.frc, or read_result of an frc folder)")
    if isinstance(point, bool) or not isinstance(point, (int, np.integer)) or point < 1:
        raise ValueError(f"point: must be an integer >= 1, got {point!r}")
    states = np.asarray(start["states"])
    # The point and its neighbours chosen as switch --point chooses them (the library's code).
    at = require_core().switch_point(start["special_points"], int(point), len(states), "point", "the frc result")
    bp = np.asarray(start["special_states"])[at["special_row"]]
    before, after = states[at["before_row"]], states[at["after_row"]]
    progress = checked_progress(progress)
    # As switch --from: the frc result's parameters and harmonic balance, then the caller's.
    run_case = case_with(case, result_overrides(start) + settings_overrides(**settings), "switch")
    result = require_core().switch(run_case, at["type"], int(point), bp[0], bp[1:], before[0], before[1:], after[0], after[1:],
                                   progress)
    result["kind"] = "switch"
    return result


def limit_point(result, lp):
    """The state of the lp-th limit point of an frc result.

    Parameters
    ----------
    result : dict
        An frc result (:func:`frc` or :func:`hbtrack.read_result` of an frc folder).
    lp : int
        Which limit point: LP `lp`, counted from 1 in increasing omega (as the figures and
        ``hbtrack track --lp`` number them, whatever order ``result["special_points"]`` lists
        them in).

    Returns
    -------
    numpy.ndarray
        The row [omega, x0, x1, ...] of ``result["special_states"]``.

    Examples
    --------
    >>> state = hbtrack.limit_point(nfrc, 1)
    >>> omega, x = state[0], state[1:]
    """
    return _special_point_state(result, SpecialPointType.LIMIT_POINT, lp)


# What each of track's keywords starts from.
_TRACKED = {"lp": SpecialPointType.LIMIT_POINT, "ns": SpecialPointType.NEIMARK_SACKER, "pd": SpecialPointType.PERIOD_DOUBLING}


def _special_point_state(result, kind, k):
    """The row [omega, x0, ...] of the k-th special point of type `kind` (LP, NS, PD) of an frc
    result, counted from 1 in increasing omega; ValueError naming the keyword otherwise. The
    library chooses the point, as for the CLI's --lp, --ns and --pd."""
    keyword = next(name for name, tracked in _TRACKED.items() if tracked == kind)
    if not isinstance(result, dict) or "special_points" not in result or "special_states" not in result:
        raise ValueError("start: expected an frc result (from hbtrack.frc, or read_result of an frc folder)")
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 1:
        raise ValueError(f"{keyword}: must be an integer >= 1, got {k!r}")
    row = require_core().special_point_index(result["special_points"], kind.value, int(k), keyword, "the frc result")
    return result["special_states"][row]


def track(case, start, *, lp=None, ns=None, pd=None, param, range, method="bordered", progress=None, **settings):  # noqa: A002 - the CLI's --range
    """A limit point (or a Neimark-Sacker or period-doubling point) followed in a second parameter (``hbtrack track``).

    Parameters
    ----------
    case : hbtrack.Case
        The case `start` was computed on.
    start : dict
        An frc result of `case` (computed or :func:`hbtrack.read_result`); its parameters and
        harmonic balance (harmonics, subharmonic, samples, condensation) are used, as ``track
        --from``, before the keywords' settings: the tracked parameter starts at the result's value.
    lp : int, optional
        Which of its limit points: LP `lp`, from 1 in increasing omega (as the figures number
        them). One of `lp`, `ns`, `pd` is given.
    ns : int, optional
        Or which of its Neimark-Sacker points (from 1 in increasing omega): the NS curve, with the
        NS frequency as the branch's ``ns_frequency`` (docs/tracking.md).
    pd : int, optional
        Or which of its period-doubling points: the PD curve.
    param : str
        The named parameter to vary ("amplitude", "mu", "clearance", ...).
    range : tuple of float
        (LO, HI): leg 1 goes from the start towards LO, leg 2 towards HI.
    method : {"bordered", "extended"}, optional
        The defining system of a limit point (docs/tracking.md); NS and PD: bordered only.
    progress : callable, optional
        ``progress(fraction, point, value)`` after every accepted point: the part of (LO, HI)
        covered, each leg for its share as the CLI's progress line, `point` the row and `value` the
        parameter's; return False to stop (stop_reason "stopped_by_callback").
    **settings : dict, optional
        The case's settings for this run only, as :func:`frc` takes them (``continuation={...}``,
        ``set={...}``; :func:`hbtrack.with_settings`).

    Returns
    -------
    dict
        ``branch`` ({column: array}: leg, omega, PARAM, (NS, PD) ns_frequency, max_NAME,
        min_NAME, h1_NAME, then the harmonics' columns), ``states`` (rows [leg, omega, PARAM, x0,
        ...]), ``special_points`` (the located extrema of PARAM: type "min" or "max"; an NS
        curve's ends on a fold, "resonance_1_1"), ``summary`` (stop_reason, closed, legs, ...) and
        ``kind`` = "track".

    Examples
    --------
    >>> curve = hbtrack.track(case, nfrc, lp=1, param="amplitude", range=(0.1, 2.0))
    >>> curve["branch"]["amplitude"].min()                  # where the fold is born
    >>> coarse = hbtrack.track(case, nfrc, lp=1, param="amplitude", range=(0.1, 2.0), continuation={"step": 0.05})
    >>> band = hbtrack.track(case, nfrc, ns=1, param="amplitude", range=(0.05, 0.35))   # an NS curve
    """
    given = [(name, k) for name, k in (("lp", lp), ("ns", ns), ("pd", pd)) if k is not None]
    if len(given) != 1:
        raise ValueError("lp, ns or pd: give exactly one point to track" + (f", got {', '.join(n for n, _ in given)}" if given else ""))
    keyword, k = given[0]
    point = _TRACKED[keyword]
    state = _special_point_state(start, point, k)
    try:
        low, high = (float(v) for v in range)
    except (TypeError, ValueError):
        raise ValueError(f"range: expected (LO, HI), got {range!r}") from None
    progress = checked_progress(progress)
    # As track --from: the frc result's parameters and harmonic balance, then the caller's.
    run_case = case_with(case, result_overrides(start) + settings_overrides(**settings), "track")
    if point != SpecialPointType.LIMIT_POINT and method != "bordered":
        raise ValueError(f"method: {keyword} tracks on the bordered Hill pencil only, got {method!r}")
    result = require_core().track(run_case, state[1:], state[0], param, low, high, method, progress, point.value)
    result["summary"]["options"]["tracking"].update({keyword: k, f"{keyword}_order": "omega"})
    result["kind"] = "track"
    return result


def isolas(case, tracks, *, at, progress=None, **settings):
    """Isolated branches at one parameter value, from limit-point tracking curves (``hbtrack isolas``).

    Parameters
    ----------
    case : hbtrack.Case
        The case the curves were tracked on.
    tracks : dict or list of dict
        One or more track results of the same parameter. The branches are computed with the
        first one's parameters and harmonic balance (as ``isolas --from``), then `settings`.
    at : float
        The parameter value where the curves are cut.
    progress : callable, optional
        ``progress(fraction, point, omega)`` after every accepted point: per branch followed, the
        part of the frequency range its points span so far (an isola closes inside it); `point`
        counts on over the branches; return False to stop (stop_reason "stopped_by_callback").
    **settings : dict, optional
        The case's settings for this run only, as :func:`frc` takes them (``continuation={...}``,
        ``set={...}``; :func:`hbtrack.with_settings`).

    Returns
    -------
    dict
        ``summary`` (with ``crossings``: status isola/open/duplicate/outside_range per crossing),
        ``branches`` ({"isola_1": branch result, ...}, each as :func:`frc` returns plus
        ``label``) and ``kind`` = "isolas".

    Examples
    --------
    >>> found = hbtrack.isolas(case, curve, at=0.15)
    >>> sorted(found["branches"])
    >>> hill = hbtrack.isolas(case, curve, at=0.15, stability={"method": "hill"})
    """
    # As the CLI's --at: nan ran and reported "completed" with nothing found.
    if not math.isfinite(float(at)):
        raise ValueError(f"at: must be a finite number, got {at!r}")
    if isinstance(tracks, dict):
        tracks = [tracks]
    if not tracks:
        raise ValueError("tracks: needs at least one track result")
    for t in tracks:
        if not isinstance(t, dict) or "states" not in t or "tracking" not in t.get("summary", {}).get("options", {}):
            raise ValueError("tracks: expected track results (from hbtrack.track, or read_result of a track folder)")
    for t in tracks:  # an NS (PD) curve's points are not limit points: no branch through them
        point = t["summary"]["options"]["tracking"].get("point", SpecialPointType.LIMIT_POINT.value)
        if point != SpecialPointType.LIMIT_POINT:
            raise ValueError(f"tracks: a curve of {point} points; isolas takes limit-point curves (track with lp=K)")
    names = {t["summary"]["options"]["tracking"]["parameter"] for t in tracks}
    if len(names) != 1:
        raise ValueError(f"tracks: the curves track different parameters: {', '.join(sorted(names))}")
    progress = checked_progress(progress)
    # As `isolas --from`: the first curve's parameters and harmonic balance, then the caller's.
    run_case = case_with(case, result_overrides(tracks[0]) + settings_overrides(**settings), "isolas")
    result = require_core().isolas(run_case, [np.asarray(t["states"]) for t in tracks], names.pop(), float(at), progress)
    result["kind"] = "isolas"
    for name, branch in result["branches"].items():
        branch["kind"], branch["label"] = "isola_branch", name
    return result
