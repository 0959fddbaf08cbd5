"""A torus row against a long time integration at its omega: each output's extremes, the second
frequency, and whether the integration's modulation has doubled its period (python/compare_torus.py,
docs/analyses.md, "Rotor 67's band")."""
import numpy as np

from .modulation_lines import _lines, _second_frequency
from .torus_figures import simulated_extreme

# A line counts as omega + (j + 1/2) omega2 when its offset is that within 2 % of omega2: lines of
# a torus, k omega2, are then at least 0.48 omega2 away.
_HALF_LINE_TOLERANCE = 0.02
# Weaker than a thousandth of the strongest line, a peak is within the floor of a record of a few
# hundred periods (rotor 67's: 1e-4 to 1e-3), and is not counted.
_HALF_LINE_FLOOR = 1e-3


def _torus_row(torus, omega):
    omegas = np.asarray(torus["branch"]["omega"], float)
    row = int(np.argmin(np.abs(omegas - omega)))
    if abs(omegas[row] - omega) > 1e-9 * abs(omega):
        raise ValueError(f"omega: the torus has no row at the simulation's omega = {omega!r} (nearest {omegas[row]!r}); "
                         "end a torus run there (--range LO:OMEGA) or simulate at a row's omega")
    return row


def torus_against_simulation(torus, simulation, names=None):
    """Compare the torus row at a simulation's omega with that simulation.

    Parameters
    ----------
    torus : dict
        A torus result (``hbtrack torus`` folder read by :func:`hbtrack.read_result`, or
        :func:`hbtrack.torus`) with a row at the simulation's omega (to 1e-9 relative).
    simulation : dict
        A simulate result at that omega whose record follows the transient and spans many
        modulation periods.
    names : list of str, optional
        The outputs compared: default every output the torus' branch has extremes of.

    Returns
    -------
    dict
        ``omega``; ``omega2`` (the torus row's) and ``omega2_simulated``
        (:func:`~hbtrack.modulation_lines.modulation_frequency` of the first output); ``extremes``: one dict per output
        and extreme (``name``, ``extreme`` "max"/"min", ``simulated``, ``torus``, ``difference`` =
        (torus - simulated) / |simulated|); ``half_lines``: the simulation's lines at omega +-
        (j + 1/2) omega2_simulated ((frequency, amplitude relative to the strongest), strongest
        first; those above a thousandth of the strongest), which no torus of (omega, omega2)
        has: present, the integration's modulation has doubled its period (a torus doubling)
        and the row is not its attractor.

    Examples
    --------
    >>> c = torus_against_simulation(read_result("out/r67_torus"), read_result("out/r67_sim_2094"))
    >>> [(e["name"], e["extreme"], round(100 * e["difference"], 2)) for e in c["extremes"]]
    """
    omega = float(simulation["summary"]["omega"])
    row = _torus_row(torus, omega)
    branch = torus["branch"]
    if names is None:
        names = [c[4:] for c in branch if c.startswith("max_")]
    if not names:
        raise ValueError("names: no output to compare (the torus' branch has no max_NAME column: give the case [[outputs]])")
    extremes = []
    for name in names:
        for extreme in ("max", "min"):
            column = f"{extreme}_{name}"
            if column not in branch:
                raise ValueError(f"names: the torus has no column {column!r}")
            simulated = simulated_extreme(simulation, name, extreme)
            value = float(branch[column][row])
            extremes.append({"name": name, "extreme": extreme, "simulated": simulated, "torus": value,
                             "difference": (value - simulated) / abs(simulated)})
    lines, resolution = _lines(simulation, names[0])  # one spectrum for omega2 and the half lines
    omega2_simulated = _second_frequency(lines, omega, resolution, names[0])
    half_lines = []
    for f, size in lines:
        halves = abs(f - omega) / (0.5 * omega2_simulated)
        nearest_odd = 2 * np.floor(halves / 2) + 1
        if size >= _HALF_LINE_FLOOR and abs(halves - nearest_odd) * 0.5 < _HALF_LINE_TOLERANCE:
            half_lines.append((f, size))
    return {"omega": omega, "omega2": float(branch["omega2"][row]), "omega2_simulated": omega2_simulated, "extremes": extremes,
            "half_lines": half_lines}
