"""Time integration to the periodic steady state: `hbtrack simulate` as a function."""
from ._core import require_core
from .progress import checked_progress
from .settings import case_with, settings_overrides
from .starts import start_state


def simulate(case, omega=None, *, start=None, point=None, method="newmark", steps_per_period=256,
             max_periods=2000, record_periods=1, progress=None, **settings):
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
    method : {"newmark", "dopri5"}, optional
        HHT-alpha Newmark (stiff contact, default) or adaptive Dormand-Prince 5(4).
    steps_per_period : int, optional
        Newmark's steps per period (default 256; 512 or more near lightly damped resonances).
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
        summary["start"] with the HBM orbit's values) and ``kind`` = "simulate".

    Examples
    --------
    >>> sim = hbtrack.simulate(case, start=nfrc, point=20, steps_per_period=512)
    >>> sim["summary"]["converged"], sim["summary"]["max_x"]
    >>> louder = hbtrack.simulate(case, 1.2, parameters={"amplitude": 2.0}, progress=lambda f, k, t: k < 500)
    """
    core = require_core()
    progress = checked_progress(progress)
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
    result = core.simulate(run_case, 0.0 if omega is None else float(omega), state, method, steps_per_period, steady, progress)
    result["kind"] = "simulate"
    return result
