"""Result folders read back into the dicts the Python API returns (see hbtrack.analysis), so the
figures take either. The kind of folder comes from summary.json's "verb" and the files present."""
import csv
import json
import os
import warnings

import numpy as np


def read_table(path):
    """A CSV file of numbers.

    Parameters
    ----------
    path : str
        The file (branch.csv, states.csv, ...).

    Returns
    -------
    header : list of str
        The column names.
    rows : numpy.ndarray
        2-D, one row per data row (0 rows for a header-only file).

    Examples
    --------
    >>> header, rows = read_table("out/duffing/states.csv")
    """
    with open(path, newline="") as f:
        header = next(csv.reader(f))
    with warnings.catch_warnings():  # a header-only file (e.g. no special points) is an empty table
        warnings.simplefilter("ignore", UserWarning)
        rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return header, rows.reshape(-1, len(header))


def read_columns(path):
    """A CSV file of numbers as columns.

    Parameters
    ----------
    path : str
        The file.

    Returns
    -------
    dict
        {column name: 1-D numpy.ndarray}, in the file's column order.

    Examples
    --------
    >>> read_columns("out/duffing/branch.csv")["h3_x"]
    """
    header, rows = read_table(path)
    return {name: rows[:, j] for j, name in enumerate(header)}


def result_kind(folder):
    """Which verb wrote a result folder.

    Parameters
    ----------
    folder : str
        A result folder (with summary.json).

    Returns
    -------
    str
        frc, solve, track, isolas, isola_branch, torus, simulate, modes, campbell (modes --speeds),
        reduce, sweep or study.

    Examples
    --------
    >>> result_kind("out/duffing")
    'frc'
    """
    summary_path = os.path.join(folder, "summary.json")
    if not os.path.exists(summary_path):
        raise ValueError(f"{folder}: no summary.json (not an hbtrack result folder)")
    with open(summary_path) as f:
        summary = json.load(f)
    verb = summary.get("verb")
    if verb == "isolas" and "crossings" not in summary:
        return "isola_branch"  # one branch folder of an isolas result
    if verb == "modes" and summary.get("kind") == "campbell":
        return "campbell"  # modes --speeds
    if verb:
        return verb
    if os.path.exists(os.path.join(folder, "signals.csv")):
        return "simulate"
    if os.path.exists(os.path.join(folder, "branch.csv")):
        return "frc"
    raise ValueError(f"{folder}: cannot tell which verb wrote it (summary.json has no verb)")


def read_result(folder):
    """A result folder read back into the dict the API returns.

    Parameters
    ----------
    folder : str
        A result folder of any verb.

    Returns
    -------
    dict
        ``kind``, ``folder``, ``summary`` (summary.json), ``special_points``, and as present:
        ``branch``, ``signals``, ``stability``, ``element_forces``, ``campbell`` ({column: array} of
        branch.csv, signals.csv, stability.csv, element_forces.csv, campbell.csv), ``states``, ``special_states`` (2-D arrays: the leading columns, then
        the harmonic balance unknowns, as the API holds them), ``dof_states``,
        ``dof_special_states`` ({column: array} of the files as written: every dof's harmonics,
        docs/outputs.md; absent for folders written before those columns); an isolas result
        holds its branches (isola_K/, open_K/) under ``branches``.

    Examples
    --------
    >>> nfrc = read_result("out/duffing")
    >>> nfrc["branch"]["phase1_x"]
    """
    kind = result_kind(folder)
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    result = {"kind": kind, "folder": folder, "summary": summary,
              "special_points": summary.get("special_points", [])}
    for name, key in (("branch.csv", "branch"), ("signals.csv", "signals"), ("stability.csv", "stability"),
                      ("element_forces.csv", "element_forces"), ("campbell.csv", "campbell")):
        path = os.path.join(folder, name)
        if os.path.exists(path):
            result[key] = read_columns(path)
    for name, key in (("states.csv", "states"), ("special_states.csv", "special_states")):
        path = os.path.join(folder, name)
        if kind == "torus" and os.path.exists(path):  # torus coefficients, not periodic unknowns
            result["dof_" + key] = read_columns(path)
        elif os.path.exists(path):
            header, rows = read_table(path)
            result[key] = state_unknowns(header, rows, summary)
            if not is_unknown_layout(header):
                result["dof_" + key] = {column: rows[:, j] for j, column in enumerate(header)}
    if kind == "isolas":
        result["branches"] = {c["folder"]: read_result(os.path.join(folder, c["folder"]))
                              for c in summary.get("crossings", []) if "folder" in c}
    return result


def _leading_columns(header):
    """How many columns precede the state: omega, or leg, omega and the tracked parameter."""
    return 3 if header and header[0] == "leg" else 1


def is_unknown_layout(header):
    """Whether a states.csv header is the layout written before the dof columns (x0, x1, ...).

    Parameters
    ----------
    header : list of str
        The columns of states.csv or special_states.csv.

    Returns
    -------
    bool
        True for ``omega, x0, x1, ...`` (the unknowns, the mean as a0 with x = a0/2 + ...).

    Examples
    --------
    >>> is_unknown_layout(["omega", "x0", "x1"])
    True
    """
    lead = _leading_columns(header)
    return len(header) > lead and header[lead] == "x0"


def harmonic_label(k, subharmonic=1):
    """The name of basis harmonic k in result columns: its multiple of omega, k / nu ("3", "0.5").

    Parameters
    ----------
    k : int
        The harmonic of the basis (0 the mean), in multiples of omega / nu.
    subharmonic : int, optional
        nu, the basis' subharmonic order (1: harmonics of omega; 2 on a period-doubled branch).

    Returns
    -------
    str
        k / nu as the column names write it: an integer, or a decimal for a subharmonic.

    Examples
    --------
    >>> harmonic_label(3), harmonic_label(1, subharmonic=2), harmonic_label(4, subharmonic=2)
    ('3', '0.5', '2')
    """
    if subharmonic <= 1 or k % subharmonic == 0:
        return str(k if subharmonic <= 1 else k // subharmonic)
    return "%.6g" % (k / subharmonic)


def unknown_columns(summary):
    """The states.csv columns of the harmonic balance unknowns, in the unknowns' order.

    The unknowns are harmonic-major over the retained dofs: per harmonic balanced (the mean
    ``NAME_h0``, then ``NAME_cK``, ``NAME_sK``), the retained dofs in model order.

    Parameters
    ----------
    summary : dict
        summary.json of the result (``options.harmonic_balance``: harmonics, subharmonic,
        retained_dofs).

    Returns
    -------
    list of str

    Examples
    --------
    >>> unknown_columns(read_result("out/duffing")["summary"])[:3]
    ['x_h0', 'x_c1', 'x_s1']
    """
    hb = summary["options"]["harmonic_balance"]
    listed = hb["harmonics"]
    listed = list(range(listed + 1)) if isinstance(listed, int) else listed
    nu = hb.get("subharmonic", 1)
    suffixes = [s for k in listed for s in (["h0"] if k == 0 else ["c" + harmonic_label(k, nu), "s" + harmonic_label(k, nu)])]
    return [f"{name}_{suffix}" for suffix in suffixes for name in hb["retained_dofs"]]


def state_unknowns(header, rows, summary):
    """A state table as the API holds it: the leading columns, then the harmonic balance unknowns.

    Reads both layouts of states.csv: the dof columns (``NAME_h0``, ``NAME_cK``, ``NAME_sK`` of
    every dof, the mean stored as the mean) and the earlier ``x0, x1, ...`` (the unknowns
    themselves, returned as they are).

    Parameters
    ----------
    header : list of str
        The file's columns.
    rows : numpy.ndarray
        Its rows.
    summary : dict
        The folder's summary.json.

    Returns
    -------
    numpy.ndarray
        rows x (leading columns + unknowns); the mean as a0 = 2 NAME_h0, so the rows restart an
        analysis exactly.

    Examples
    --------
    >>> header, rows = read_table("out/duffing/states.csv")
    >>> states = state_unknowns(header, rows, summary)
    """
    if is_unknown_layout(header):
        return rows
    lead = _leading_columns(header)
    position = {column: j for j, column in enumerate(header)}
    columns = unknown_columns(summary)
    missing = [c for c in columns if c not in position]
    if missing:
        raise ValueError(f"states: no column {missing[0]} (results of another case or harmonic balance?)")
    unknowns = rows[:, [position[c] for c in columns]].copy()
    unknowns[:, [i for i, c in enumerate(columns) if c.endswith("_h0")]] *= 2.0  # the mean is a0 / 2
    return np.hstack([rows[:, :lead], unknowns])


def tracking_curve(result):
    """A track result's columns in curve order.

    Leg 1 runs from the start towards the range's low end and leg 2 towards the high end, so
    the curve is leg 1 reversed, then leg 2.

    Parameters
    ----------
    result : dict
        A track result (API or read_result).

    Returns
    -------
    dict
        {column: 1-D array} of its branch, reordered along the curve.

    Examples
    --------
    >>> curve = tracking_curve(read_result("out/lp1"))
    """
    branch = result["branch"]
    leg = branch["leg"]
    order = np.concatenate([np.flatnonzero(leg == 1)[::-1], np.flatnonzero(leg == 2)])
    return {name: values[order] for name, values in branch.items()}


def output_names(result):
    """The names of a result's recorded outputs.

    Parameters
    ----------
    result : dict
        Any result dict.

    Returns
    -------
    list of str
        From summary["outputs"], else from the max_NAME columns or the signals' columns.

    Examples
    --------
    >>> output_names(nfrc)
    ['x']
    """
    names = [o["name"] for o in result["summary"].get("outputs", [])]
    if not names and "branch" in result:  # folders whose summary does not list them
        names = [c[4:] for c in result["branch"] if c.startswith("max_")]
    if not names and "signals" in result:  # simulate: a column per output after the time
        names = [c for c in result["signals"] if c != "time"]
    return names
