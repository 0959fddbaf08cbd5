"""Time integration to the periodic steady state: `hbtrack simulate` as a function."""
import numpy as np

from ._core import require_core
from .progress import checked_progress
from .settings import case_with, settings_overrides
from .starts import start_state


def simulate(case, omega=None, *, start=None, point=None, near_lp=None, distances=(0.2, 0.5, 1, 2, 3, 5), method="newmark",
             steps_per_period=256, element_steps=0, max_periods=2000, record_periods=1, progress=None, **settings):
    """Time integration to the periodic steady state (``hbtrack simulate``).

    Parameters
    ----------
    case : hbtrack.Case
        The case.
    omega : float, optional
        Forcing frequency in rad/s, to start from rest; not needed with `start`.
    start : dict, optional
        A result of `case` to start from (frc, solve, continue, switch, an isola branch; from a
        computation or :func:`hbtrack.read_result`), whose parameters and harmonic balance
        (harmonics, subharmonic, samples, condensation) are then used, as ``--from``; the
        keywords below still win over them ...
    point : int, optional
        ... at this row of its ``states`` (0-based).
    near_lp : int, optional
        Instead of `point`: where the full model's fold lies next to limit point `near_lp` of
        `start` (an NFRC with stability), as ``simulate --near-lp``: integrations from its stable
        side at `distances`, closest first, until one holds the orbit (docs/time-integration.md).
    distances : sequence of float, optional
        With `near_lp`: the starts' distances from the LP, in percent of omega, increasing.
    method : {"newmark", "dopri5"}, optional
        HHT-alpha Newmark (stiff contact, default) or adaptive Dormand-Prince 5(4).
    steps_per_period : int, optional
        Newmark's steps per period (default 256; 512 or more near lightly damped resonances).
    element_steps : int, optional
        Newmark: a step is halved while the elements' fastest rate has fewer steps per its
        period than this (``--element-steps``; 0, the default: `steps_per_period`).
    max_periods : int, optional
        Give up after this many periods (summary["converged"] False).
    record_periods : int, optional
        Periods kept in the signals.
    progress : callable, optional
        ``progress(fraction, period, time)`` after every period: `fraction` the periods done
        out of `max_periods` (a run that converges stops before 1), `period` from 0, `time` (s)
        at its end; return False to stop (stop_reason "stopped_by_callback").
    **settings : dict, optional
        The case's settings for this run only, as :func:`hbtrack.frc` takes them
        (``parameters={"amplitude": 2.0}``, ``set={...}``; :func:`hbtrack.with_settings`).

    Returns
    -------
    dict
        ``signals`` ({"time": array, NAME: array} per output, as signals.csv), ``summary``
        (converged, periods, max_NAME, min_NAME, h1_NAME, harmonics_NAME, and with `start`
        summary["start"] with the HBM orbit's values) and ``kind`` = "simulate". With `near_lp`:
        ``summary["fold_search"]`` (the runs, ``held``, ``left``) and ``branches``
        ({"point_R": each run's result}).

    Examples
    --------
    >>> sim = hbtrack.simulate(case, start=nfrc, point=20, steps_per_period=512)
    >>> sim["summary"]["converged"], sim["summary"]["max_x"]
    >>> louder = hbtrack.simulate(case, 1.2, parameters={"amplitude": 2.0}, progress=lambda f, k, t: k < 500)
    >>> fold = hbtrack.simulate(case, start=nfrc, near_lp=2)
    >>> fold["summary"]["fold_search"]["held"]["omega"]
    """
    core = require_core()
    progress = checked_progress(progress)
    if near_lp is not None:
        return _simulate_near_fold(core, case, start, point, omega, near_lp, distances, method, (steps_per_period, element_steps),
                                   core.SteadyStateOptions(max_periods=max_periods, record_periods=record_periods), progress, settings)
    if (start is None) != (point is None):
        raise ValueError("point: needs start" if start is None else "start: needs point")
    state, from_result = None, []
    if start is not None:
        state, _, from_result = start_state(start, point)
    elif omega is None:
        raise ValueError("omega: required unless start gives the point")
    # As simulate --from: the start's parameters and harmonic balance, then the caller's.
    run_case = case_with(case, from_result + settings_overrides(**settings), "simulate")
    steady = core.SteadyStateOptions(max_periods=max_periods, record_periods=record_periods)
    result = core.simulate(run_case, 0.0 if omega is None else float(omega), state, method, steps_per_period, element_steps, steady,
                           progress)
    result["kind"] = "simulate"
    return result


def _simulate_near_fold(core, case, start, point, omega, near_lp, distances, method, steps, steady, progress, settings):
    """simulate(near_lp=K): the checks of its arguments, then the search in the core; steps is
    (steps_per_period, element_steps)."""
    if not isinstance(start, dict) or point is not None or omega is not None:
        raise ValueError("near_lp: needs start (an NFRC result), and neither point nor omega (it chooses its own points)")
    if isinstance(near_lp, bool) or not isinstance(near_lp, (int, np.integer)) or near_lp < 1:
        raise ValueError(f"near_lp: must be an integer >= 1, got {near_lp!r}")
    fractions = np.asarray(distances, dtype=float) / 100
    if fractions.ndim != 1 or not len(fractions) or np.any(fractions <= 0) or np.any(np.diff(fractions) <= 0):
        raise ValueError(f"distances: must be increasing percentages > 0, got {distances!r}")
    branch = start.get("branch", {})
    if "stable" not in branch:
        raise ValueError("start: has no stability (near_lp needs an NFRC computed with stability on)")
    _, _, from_result = start_state(start, 0)  # checks start's kind; its settings
    states = np.asarray(start["states"], dtype=float)
    run_case = case_with(case, from_result + settings_overrides(**settings), "simulate")
    names = [o["name"] for o in start["summary"].get("outputs", [])]
    amplitude = np.asarray(branch[f"h1_{names[0]}"], dtype=float) if names else np.zeros(len(states))
    stable = [bool(v == 1) for v in branch["stable"]]
    result = core.simulate_near_fold(run_case, states, stable, amplitude, start["summary"].get("special_points", []), int(near_lp),
                                     list(fractions), method, *steps, steady, progress)
    result["kind"] = "simulate"
    return result
