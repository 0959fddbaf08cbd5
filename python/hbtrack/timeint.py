"""Time integration to the periodic steady state: `hbtrack simulate` as a function."""
from ._core import require_core


def simulate(case, omega=None, *, start=None, point=None, method="newmark", steps_per_period=256,
             max_periods=2000, record_periods=1):
    """From rest at `omega` (rad/s), or from row `point` of the states of a result `start` (frc,
    solve, a branch of isolas) of the same case. Returns {"signals": {"time": ..., NAME: ...},
    "summary": {...}} as signals.csv and summary.json; summary["start"]["harmonics_NAME"] holds
    the HBM orbit's coefficients when started from one."""
    core = require_core()
    if (start is None) != (point is None):
        raise ValueError("point: needs start" if start is None else "start: needs point")
    state = None
    if start is not None:
        states = start["states"]
        if not 0 <= point < len(states):
            raise ValueError(f"point: must be a row of start's states, 0 to {len(states) - 1}, got {point}")
        state = states[point]
    elif omega is None:
        raise ValueError("omega: required unless start gives the point")
    steady = core.SteadyStateOptions(max_periods=max_periods, record_periods=record_periods)
    result = core.simulate(case, 0.0 if omega is None else float(omega), state, method, steps_per_period, steady)
    result["kind"] = "simulate"
    return result
