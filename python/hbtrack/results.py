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
        frc, solve, track, isolas, isola_branch, simulate, modes, reduce, sweep or study.

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
        ``branch``, ``signals``, ``stability`` ({column: array} of branch.csv, signals.csv,
        stability.csv), ``states``, ``special_states`` (2-D arrays); an isolas result holds its
        branches (isola_K/, open_K/) under ``branches``.

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
    for name, key in (("branch.csv", "branch"), ("signals.csv", "signals"), ("stability.csv", "stability")):
        path = os.path.join(folder, name)
        if os.path.exists(path):
            result[key] = read_columns(path)
    for name, key in (("states.csv", "states"), ("special_states.csv", "special_states")):
        path = os.path.join(folder, name)
        if os.path.exists(path):
            result[key] = read_table(path)[1]
    if kind == "isolas":
        result["branches"] = {c["folder"]: read_result(os.path.join(folder, c["folder"]))
                              for c in summary.get("crossings", []) if "folder" in c}
    return result


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
