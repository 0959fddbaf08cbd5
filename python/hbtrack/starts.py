"""Where a computation starts from a point of an earlier result: its state row and the settings
that point was computed with, as ``hbtrack frc --from DIR --point K`` reads them from DIR."""
import numpy as np

from .cases import toml_value

# Results whose states rows are [omega, x0, x1, ...] of the case's harmonic balance.
BRANCH_KINDS = ("frc", "solve", "continue", "switch", "isola_branch")


def result_overrides(result):
    """The parameters and harmonic balance a result was computed with, as ``--set`` strings.

    What the CLI's ``--from DIR`` applies before the user's ``--set`` (apps/hbtrack/result_folder.cpp).

    Parameters
    ----------
    result : dict
        A result with ``summary["options"]`` (from a computation or :func:`hbtrack.read_result`).

    Returns
    -------
    list of str
        "NAME=VALUE" per parameter, then the harmonic_balance keys.

    Raises
    ------
    ValueError
        When the summary lacks its options.

    Examples
    --------
    >>> result_overrides({"summary": {"options": {"parameters": {"amplitude": 2.0}, "harmonic_balance":
    ...     {"harmonics": 5, "samples": 64, "condensation": "auto"}}}})
    ['amplitude=2.0', 'harmonic_balance.harmonics=5', 'harmonic_balance.samples=64', 'harmonic_balance.condensation="auto"']
    """
    options = result.get("summary", {}).get("options", {})
    if "parameters" not in options or "harmonic_balance" not in options:
        raise ValueError("start: the result's summary has no options.parameters or options.harmonic_balance")
    overrides = [f"{name}={toml_value(value)}" for name, value in options["parameters"].items()]
    hb = options["harmonic_balance"]
    for key in ("harmonics", "subharmonic", "samples", "condensation"):
        if key in hb:
            overrides.append(f"harmonic_balance.{key}={toml_value(hb[key])}")
    return overrides


def start_state(start, point):
    """The state a computation starts from, and the settings it was computed with.

    Parameters
    ----------
    start : dict or array_like
        A result whose ``states`` rows are [omega, x0, ...] (frc, solve, continue, switch, an
        isola branch), or one such row.
    point : int or None
        The row of ``start["states"]`` (0-based; None: the last); only with a result.

    Returns
    -------
    tuple
        (state row [omega, x0, ...], the row index or None, the result's overrides (empty for a row)).

    Raises
    ------
    ValueError
        Naming `start` or `point` and the rule.

    Examples
    --------
    >>> start_state([1.2, 0.1, 0.0], None)
    (array([1.2, 0.1, 0. ]), None, [])
    """
    if not isinstance(start, dict):
        if point is not None:
            raise ValueError("point: only with a result as start (a state row is one point)")
        state = np.asarray(start, dtype=float)
        if state.ndim != 1 or state.size < 2:
            raise ValueError(f"start: expected a result or a state row [omega, x0, x1, ...], got shape {state.shape}")
        return state, None, []
    if "states" not in start or start.get("kind", "frc") not in BRANCH_KINDS:
        raise ValueError(f"start: expected a result whose states are [omega, x0, ...] ({', '.join(BRANCH_KINDS)}), "
                         f"got kind {start.get('kind')!r}")
    states = np.asarray(start["states"], dtype=float)
    row = len(states) - 1 if point is None else point
    if isinstance(row, bool) or not isinstance(row, (int, np.integer)) or not 0 <= row < len(states):
        raise ValueError(f"point: must be a row of start's states, 0 to {len(states) - 1}, got {point!r}")
    return states[row], int(row), result_overrides(start)
