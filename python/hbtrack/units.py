"""Lengths in the unit the figures ask for: `hbtrack plot DIR --units mm` multiplies every length
of the result (extremes, harmonic magnitudes, clearances, time signals) by 1000 when the model is
in metres, so that the ticks read 1.2 rather than 0.0012, and says mm on the axes.

A unit this module does not know (e.g. "-" or "model units") only labels the axes, as before.
"""
import copy
import re

import numpy as np

# Metres per unit.
LENGTH_UNITS = {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "μm": 1e-6, "nm": 1e-9, "in": 0.0254}
# Tracked or swept parameters that are lengths (plots.PARAMETER_UNITS: in the model's unit).
LENGTH_PARAMETERS = ("clearance", "gap")
# Branch columns that are lengths: extremes and harmonic magnitudes of an output (hK_NAME, with
# K = 0.5, 1.5, ... on a period-doubled branch). phaseK_ columns are angles and stay.
_LENGTH_COLUMN = re.compile(r"^(max|min|h\d+(\.\d+)?)_")


def length_factor(unit, model_unit="m"):
    """What the model's lengths are multiplied by to be in `unit`.

    Parameters
    ----------
    unit : str or None
        The unit asked for (m, cm, mm, um, nm, in).
    model_unit : str, optional
        The unit of the model's lengths (default m: the blade and rotor 67 are in SI units).

    Returns
    -------
    float
        The factor; 1.0 when either unit is not a known length unit (the unit then only labels).

    Examples
    --------
    >>> length_factor("mm")
    1000.0
    >>> length_factor("-")
    1.0
    """
    if not unit or unit not in LENGTH_UNITS or model_unit not in LENGTH_UNITS:
        return 1.0
    return LENGTH_UNITS[model_unit] / LENGTH_UNITS[unit]


def is_length_column(name, length_parameters=LENGTH_PARAMETERS):
    """Whether a branch/special-point column is a length.

    Parameters
    ----------
    name : str
        The column.
    length_parameters : sequence of str, optional
        The parameters that are lengths.

    Returns
    -------
    bool
        True for max_, min_, hK_ columns and the length parameters.

    Examples
    --------
    >>> [is_length_column(c) for c in ("max_le", "h3_le", "phase3_le", "omega", "clearance")]
    [True, True, False, False, True]
    """
    return bool(_LENGTH_COLUMN.match(name)) or name in length_parameters


def _scale_columns(columns, factor, extra=()):
    """{name: value} with the lengths (and the `extra` names, the outputs' signals) scaled."""
    return {k: (np.asarray(v) * factor if isinstance(v, (list, np.ndarray)) else v * factor)
            if (is_length_column(k) or k in extra) and isinstance(v, (int, float, list, np.ndarray)) and not isinstance(v, bool)
            else v for k, v in columns.items()}


def _scale_summary(summary, factor, outputs):
    summary = copy.deepcopy(summary)
    harmonics = [f"harmonics_{name}" for name in outputs]
    output_column = re.compile(r"^(max|min|h\d+(\.\d+)?)_(" + "|".join(re.escape(n) for n in outputs) + r")$")
    for part in (summary, summary.get("start") or {}):
        for key in harmonics:
            if key in part:
                part[key] = list(np.asarray(part[key]) * factor)
        for key, value in part.items():  # simulate: the extremes and harmonics of the last period
            if outputs and output_column.match(key) and isinstance(value, (int, float)):
                part[key] = value * factor
        for name in LENGTH_PARAMETERS:  # the tracked parameter's start value
            if isinstance(part.get(name), (int, float)):
                part[name] *= factor
    parameters = summary.get("options", {}).get("parameters", {})
    for name in LENGTH_PARAMETERS:
        if isinstance(parameters.get(name), (int, float)):
            parameters[name] *= factor
    return summary


def scale_lengths(result, factor):
    """A copy of a result with its lengths multiplied by `factor`.

    Parameters
    ----------
    result : dict
        A result (read_result or the API) of any verb; an isolas result's branches too.
    factor : float
        From length_factor.

    Returns
    -------
    dict
        The result itself when factor is 1, else a copy: branch columns max_, min_, hK_ and the
        length parameters, the special points' same values, the outputs' signals, the summary's
        harmonics and length parameters, the states' harmonic unknowns. Omega, phases,
        stability, counts stay.

    Examples
    --------
    >>> in_mm = scale_lengths(read_result("out/r67"), length_factor("mm"))
    """
    if factor == 1.0:
        return result
    from .results import output_names
    outputs = output_names(result)
    scaled = dict(result)
    if "branch" in result:
        scaled["branch"] = _scale_columns(result["branch"], factor)
        # states.csv: omega (track: leg, omega, parameter) then the harmonic unknowns
        first = 3 if "leg" in result["branch"] else 1
        for key in ("states", "special_states"):
            if key in result and len(result[key]):
                states = np.array(result[key], dtype=float)
                states[:, first:] *= factor
                scaled[key] = states
            if "dof_" + key in result:  # every dof's harmonics: lengths after the leading columns
                columns = result["dof_" + key]
                scaled["dof_" + key] = {c: v if j < first else v * factor for j, (c, v) in enumerate(columns.items())}
    if "signals" in result:
        scaled["signals"] = _scale_columns(result["signals"], factor, extra=outputs)
    scaled["special_points"] = [_scale_columns(sp, factor) for sp in result.get("special_points", [])]
    scaled["summary"] = _scale_summary(result["summary"], factor, outputs)
    scaled["summary"]["special_points"] = scaled["special_points"]
    if "branches" in result:
        scaled["branches"] = {name: scale_lengths(branch, factor) for name, branch in result["branches"].items()}
    return scaled
