"""Result folders read back into the dicts the Python API returns (see hbtrack.analysis), so the
figures take either. The kind of folder comes from summary.json's "verb" and the files present."""
import csv
import json
import os
import warnings

import numpy as np


def read_table(path):
    """A CSV file of numbers: (header, 2-D array with one row per data row)."""
    with open(path, newline="") as f:
        header = next(csv.reader(f))
    with warnings.catch_warnings():  # a header-only file (e.g. no special points) is an empty table
        warnings.simplefilter("ignore", UserWarning)
        rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return header, rows.reshape(-1, len(header))


def read_columns(path):
    header, rows = read_table(path)
    return {name: rows[:, j] for j, name in enumerate(header)}


def result_kind(folder):
    """frc | solve | track | isolas | isola_branch | simulate | modes | reduce."""
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
    """The result in `folder` as the API's dict, with "kind" and "folder" added. An isolas
    result holds its branches (isola_K/, open_K/) under "branches"."""
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
    """A track result's columns in curve order: leg 1 runs from the start towards the range's
    low end and leg 2 towards the high end, so the curve is leg 1 reversed, then leg 2."""
    branch = result["branch"]
    leg = branch["leg"]
    order = np.concatenate([np.flatnonzero(leg == 1)[::-1], np.flatnonzero(leg == 2)])
    return {name: values[order] for name, values in branch.items()}


def output_names(result):
    names = [o["name"] for o in result["summary"].get("outputs", [])]
    if not names and "branch" in result:  # folders whose summary does not list them
        names = [c[4:] for c in result["branch"] if c.startswith("max_")]
    if not names and "signals" in result:  # simulate: a column per output after the time
        names = [c for c in result["signals"] if c != "time"]
    return names
